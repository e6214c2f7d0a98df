"""ChainMailDeformation on ParaView's distributed engine: `mpiexec -n 1/2/3 pvbatch --sym`
runs mpi_deform.py on a scene (distributed by RedistributeDataSet, ghost cells by
GhostCellsGenerator, point GlobalIds generated before distributing) and the gathered
points of 2 and 3 ranks must equal the 1-rank result bit for bit.
Usage: test_mpi_deformation.py SCENE [noids] (surface, slab or a TSurf file; a missing
file skips). With noids the data has no point GlobalIds: 2 and 3 ranks number the points
by coordinates in the filter, 1 rank gets the same numbering from numpy (mpi_deform.py)."""
import os
import sys
import tempfile

import numpy as np
from mpi_driver import expect_same, fail, one_row_per_point, run_clean

scene = sys.argv[1]
extra = sys.argv[2:]  # [noids]
if scene not in ("surface", "slab", "plane") and not os.path.exists(scene):
    print("skipped: %s is absent" % scene)
    sys.exit(0)


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
        run_clean(n, "mpi_deform.py", [scene, out] + extra)
        results[n] = one_row_per_point(np.load(os.path.join(out, "result.npy")), n)
        saved = os.path.join(out, "deformed.ts")
        if os.path.exists(saved):
            surfaces[n] = tsurf_geometry(saved)
        print("%d ranks: %d points" % (n, len(results[n])))
one = results[1]
moved = int(np.count_nonzero(np.any(one[:, 1:4] != one[:, 4:7], axis=1)))
if moved < 50:
    fail("only %d points moved on 1 rank" % moved)
print("ok: %d of %d points moved" % (moved, len(one)))
for n in (2, 3):
    expect_same(results[n], one, n)
    print("ok: %d ranks equal 1 rank bit for bit" % n)
    if 1 in surfaces:
        same = n in surfaces and all(a.shape == b.shape and np.array_equal(a, b)
                                     for a, b in zip(surfaces[n], surfaces[1]))
        if not same:
            fail("the TSurf saved from %d ranks differs from the 1-rank file" % n)
        print("ok: SaveData from %d ranks wrote the 1-rank TSurf (%d points, %d triangles)"
              % (n, len(surfaces[1][0]), len(surfaces[1][1])))
