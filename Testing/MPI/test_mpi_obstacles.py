"""Obstacles on distributed data (docs/obstacles.md, "On several processes"):
`mpiexec -n 1/2/3 pvbatch --sym` runs mpi_obstacles.py (a plane pulled up into a tilted
ceiling); the gathered points of 2 and 3 ranks must equal the 1-rank result bit for bit,
with the same held-back count, grasp fraction and LastGraspDisplacement (the grasp's
output minus rest, fraction x the pull), and no point's path from rest to
deformed may cross a ceiling triangle (Cramer's rule, computed here with numpy) or, with
a clearance, end closer than it to the ceiling's plane.
Usage: test_mpi_obstacles.py [CLEARANCE]."""
import json
import os
import sys
import tempfile

import numpy as np
from mpi_driver import expect_same, fail, run_clean

clearance = sys.argv[1] if len(sys.argv) > 1 else "0"


def crossings(rest, moved, tris):
    """How many segments rest -> moved cross a triangle: ends strictly on opposite sides
    of its plane and the crossing point inside it (barycentric, Cramer's rule)."""
    count = 0
    for a, b, c in tris:
        n = np.cross(b - a, c - a)
        sp, sq = (rest - a) @ n, (moved - a) @ n
        cut = sp * sq < 0.0
        if not cut.any():
            continue
        p, q = rest[cut], moved[cut]
        t = (sp[cut] / (sp[cut] - sq[cut]))[:, None]
        x = p + t * (q - p) - a
        e1, e2 = b - a, c - a
        d11, d12, d22 = e1 @ e1, e1 @ e2, e2 @ e2
        r1, r2 = x @ e1, x @ e2
        det = d11 * d22 - d12 * d12
        u, v = (r1 * d22 - r2 * d12) / det, (r2 * d11 - r1 * d12) / det
        count += int(np.count_nonzero((u >= 0) & (v >= 0) & (u + v <= 1)))
    return count


results, stats = {}, {}
with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    for n in (1, 2, 3):
        out = os.path.join(tmp, "n%d" % n)
        run_clean(n, "mpi_obstacles.py", [out, clearance])
        rows = np.load(os.path.join(out, "result.npy"))
        ids, first = np.unique(rows[:, 0], return_index=True)
        results[n] = rows[first]
        with open(os.path.join(out, "stats.json")) as text:
            stats[n] = json.load(text)
        if n == 1:
            tris = np.load(os.path.join(out, "ceiling.npy"))
        print("%d ranks: %d points, %s" % (n, len(results[n]), stats[n]))

one = results[1]
rest, moved = one[:, 4:7], one[:, 1:4]
displaced = int(np.count_nonzero(np.any(moved != rest, axis=1)))
if len(one) != 31 * 31 or displaced < 50:
    fail("%d points, %d displaced on 1 rank" % (len(one), displaced))
if not (stats[1]["blocked"] > 0 and stats[1]["fraction"] < 1.0):
    fail("the ceiling held nothing back on 1 rank: %s" % stats[1])
# Where the grasp landed: the grasp's output minus rest (to the output's rounding),
# fraction x the pull.
grasp = int(np.searchsorted(one[:, 0], 15 * 31 + 15))
landed = np.array(stats[1]["landed"])
if not (np.allclose(landed, moved[grasp] - rest[grasp], rtol=0.0, atol=1e-12)
        and np.allclose(landed, stats[1]["fraction"] * np.array([1.0, 0.0, 10.0]), atol=1e-12)):
    fail("LastGraspDisplacement %s is not where the grasp landed (%s)"
         % (landed, moved[grasp] - rest[grasp]))
crossed = crossings(rest, moved, tris)
# The ceiling's plane: z = 2 + 0.2 (x + 5); its distance below it, for the clearance.
below = ((2.0 + 0.2 * (moved[:, 0] + 5.0)) - moved[:, 2]) / np.sqrt(1.0 + 0.2 ** 2)
if crossed or below.min() < float(clearance):
    fail("%d paths cross the ceiling; nearest point %.6g below it (clearance %s)"
         % (crossed, below.min(), clearance))
print("ok: %d displaced, %d held back, grasp at %.4f of its pull, 0 crossings, %.4g below"
      % (displaced, stats[1]["blocked"], stats[1]["fraction"], below.min()))
for n in (2, 3):
    expect_same(results[n], one, n)
    for key in ("displaced", "blocked", "fraction", "landed"):
        if stats[n][key] != stats[1][key]:
            fail("%d ranks report %s %s, 1 rank %s" % (n, key, stats[n][key], stats[1][key]))
    print("ok: %d ranks equal 1 rank bit for bit (%d held back, %d supersteps)"
          % (n, stats[n]["blocked"], stats[n]["supersteps"]))
