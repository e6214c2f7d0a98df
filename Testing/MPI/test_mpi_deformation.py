"""ChainMailDeformation on ParaView's distributed engine: `mpiexec -n 1/2/3 pvbatch --sym`
runs mpi_deform.py on a scene (distributed by RedistributeDataSet, ghost cells by
GhostCellsGenerator, point GlobalIds generated before distributing) and the gathered
points of 2 and 3 ranks must equal the 1-rank result bit for bit.
Usage: test_mpi_deformation.py SCENE [noids] (surface, slab or a TSurf file; a missing
file skips). With noids the data has no point GlobalIds: 2 and 3 ranks number the points
by coordinates in the filter, 1 rank gets the same numbering from numpy (mpi_deform.py)."""
import os
import subprocess
import sys
import tempfile

import numpy as np

scene = sys.argv[1]
extra = sys.argv[2:]  # [noids]
if scene not in ("surface", "slab", "plane") and not os.path.exists(scene):
    print("skipped: %s is absent" % scene)
    sys.exit(0)
here = os.path.dirname(os.path.abspath(__file__))
env = dict(os.environ)
env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")  # 3 ranks on 2 cores


def tsurf_geometry(path):
    """A TSurf file's points (sorted rows) and triangles (each the sorted coordinates of
    its three vertices, rows sorted), as written: compared bit for bit."""
    points, triangles, vertex = [], [], {}
    with open(path) as text:
        for line in text:
            word = line.split()
            if not word:
                continue
            if word[0] == "GOCAD":
                vertex = {}
            elif word[0] in ("VRTX", "PVRTX"):
                vertex[word[1]] = tuple(float(x) for x in word[2:5])
                points.append(vertex[word[1]])
            elif word[0] == "TRGL":
                triangles.append(sum(sorted(vertex[v] for v in word[1:4]), ()))
    return np.array(sorted(points)), np.array(sorted(triangles))


results, surfaces = {}, {}
with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    for n in (1, 2, 3):
        out = os.path.join(tmp, "n%d" % n)
        cmd = [env.get("MPIEXEC", "mpiexec"), "--allow-run-as-root", "--oversubscribe", "-n", str(n),
               env.get("PVBATCH", "pvbatch"), "--sym", os.path.join(here, "mpi_deform.py"), scene, out] + extra
        run = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=240)
        errors = [line for line in (run.stdout + run.stderr).splitlines() if "ERR|" in line]
        if run.returncode != 0 or errors:
            print(" ".join(cmd)); print(run.stdout[-3000:], run.stderr[-3000:])
            print("FAILED: %d ranks: exit %d, %d error lines" % (n, run.returncode, len(errors)))
            sys.exit(1)
        rows = np.load(os.path.join(out, "result.npy"))
        # A point held by two ranks as owned (or twice by one) must agree with itself.
        ids, first = np.unique(rows[:, 0], return_index=True)
        for i in range(len(rows)):
            j = first[np.searchsorted(ids, rows[i, 0])]
            if not np.array_equal(rows[i, 1:], rows[j, 1:]):
                print("FAILED: %d ranks: copies of point %d differ" % (n, rows[i, 0]))
                sys.exit(1)
        results[n] = rows[first]
        saved = os.path.join(out, "deformed.ts")
        if os.path.exists(saved):
            surfaces[n] = tsurf_geometry(saved)
        print("%d ranks: %d points" % (n, len(results[n])))
one = results[1]
moved = int(np.count_nonzero(np.any(one[:, 1:4] != one[:, 4:7], axis=1)))
if moved < 50:
    print("FAILED: only %d points moved on 1 rank" % moved)
    sys.exit(1)
print("ok: %d of %d points moved" % (moved, len(one)))
for n in (2, 3):
    if results[n].shape != one.shape or not np.array_equal(results[n], one):
        diff = np.abs(results[n] - one).max() if results[n].shape == one.shape else "shape"
        print("FAILED: %d ranks differ from 1 rank (max difference %s)" % (n, diff))
        sys.exit(1)
    print("ok: %d ranks equal 1 rank bit for bit" % n)
    if 1 in surfaces:
        same = n in surfaces and all(a.shape == b.shape and np.array_equal(a, b)
                                     for a, b in zip(surfaces[n], surfaces[1]))
        if not same:
            print("FAILED: the TSurf saved from %d ranks differs from the 1-rank file" % n)
            sys.exit(1)
        print("ok: SaveData from %d ranks wrote the 1-rank TSurf (%d points, %d triangles)"
              % (n, len(surfaces[1][0]), len(surfaces[1][1])))
