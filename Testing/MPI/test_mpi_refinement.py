"""Refinement on distributed data (docs/mpi.md, "Refinement on distributed data"):
`mpiexec -n 1/2/3 pvbatch --sym` runs mpi_refine.py (ChainMail + one envelope refinement,
Axes region) on a scene; the gathered points of 2 and 3 ranks must equal the 1-rank result
bit for bit, the refined point counts agree, and E_link of the gathered output, computed
here with numpy from the points, the malleability and the filter's default transfer
curves (an independent computation), is <= 1e-9 L. Then Dykstra on 2 ranks must be
refused with an error naming what works, leaving the input undeformed, and so must
the refinement with obstacles on 2 ranks (docs/obstacles.md, "Refused"), and HonourMarkers
with markers and SnapToMarkers (docs/markers.md). And 2 ranks grasping the same point
by position (GraspMode Nearest To Position) must equal the 1-rank result.
Usage: test_mpi_refinement.py SCENE (surface or slab)."""
import json
import os
import sys
import tempfile

import numpy as np
from mpi_driver import expect_same, fail, one_row_per_point, run_clean, run_ranks, show

scene = sys.argv[1]


def link_error(rows, edges):
    """E_link / L of the gathered output: per directed edge (c, s) the distance of
    w = u_c - u_s to c's box (valid_region.h) with the default linear curves
    t = 1 + m, k = 1 - m / 2, h = m / 2, the worst over both directions."""
    index = {int(g): i for i, g in enumerate(rows[:, 0])}
    a = np.array([index[int(e)] for e in edges[:, 0]])
    b = np.array([index[int(e)] for e in edges[:, 1]])
    x, x0, m = rows[:, 1:4], rows[:, 4:7], np.clip(rows[:, 7], 0.0, 1.0)
    u = x - x0
    t, k, h = np.maximum(1.0, 1.0 + m), np.clip(1.0 - 0.5 * m, 0.0, 1.0), np.maximum(0.0, 0.5 * m)
    worst = 0.0
    for c, s in ((a, b), (b, a)):
        o, w = x0[c] - x0[s], u[c] - u[s]
        side = np.abs(o).sum(axis=1)[:, None] - np.abs(o)
        near, far = (k[c] - 1.0)[:, None] * o, (t[c] - 1.0)[:, None] * o
        lo = np.where(o >= 0.0, near, far) - h[c][:, None] * side
        hi = np.where(o >= 0.0, far, near) + h[c][:, None] * side
        excess = np.maximum(0.0, np.maximum(lo - w, w - hi))
        worst = max(worst, float(np.sqrt((excess ** 2).sum(axis=1)).max()))
    length = np.linalg.norm(x0[a] - x0[b], axis=1).mean()
    return worst / length


results, stats = {}, {}
with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    for n in (1, 2, 3):
        out = os.path.join(tmp, "n%d" % n)
        run_clean(n, "mpi_refine.py", [scene, out])
        results[n] = one_row_per_point(np.load(os.path.join(out, "result.npy")), n)
        with open(os.path.join(out, "stats.json")) as text:
            stats[n] = json.load(text)
        if n == 1:
            edges = np.load(os.path.join(out, "edges.npy"))
        print("%d ranks: %d points, %s" % (n, len(results[n]), stats[n]))

    # Dykstra, obstacles and honoured markers on 2 ranks: refused on every rank with an error naming
    # what works (or what is missing), the input undeformed. SnapToMarkers too: no edit, and
    # the command releases the grasp as every edit command does, so the input again.
    for option, wanted in (("Dykstra", "use RefinementSolver Envelope with ValidRegionFrame Axes"),
                           ("Obstacles", "refinement with Obstacles"),
                           ("Markers", "HonourMarkers with markers"),
                           ("Snap", "SnapToMarkers: not on data split across processes yet")):
        cmd, result, errors = run_ranks(2, "mpi_refine.py", [scene, os.path.join(tmp, option), option])
        if result.returncode != 0 or len(errors) < 2 or not all(wanted in e for e in errors):
            show(cmd, result)
            fail("%s on 2 ranks: expected an error naming '%s' on each rank" % (option, wanted))
        refused = np.load(os.path.join(tmp, option, "result.npy"))
        if not np.array_equal(refused[:, 1:4], refused[:, 4:7]):
            fail("the refused update (%s) deformed its input" % option)
        print("ok: %s on 2 ranks refused on every rank (%s), input unchanged"
              % (option, errors[0].strip()[:120]))

    # The same point grasped by position on 2 ranks: the refinement fixes the grasp the
    # frame resolved (it fixed GraspPointId, -1 here, before the stages were shared).
    run_clean(2, "mpi_refine.py", [scene, os.path.join(tmp, "nearest"), "Nearest"])
    rows = np.load(os.path.join(tmp, "nearest", "result.npy"))
    results["nearest"] = rows[np.unique(rows[:, 0], return_index=True)[1]]

one = results[1]
moved = int(np.count_nonzero(np.any(one[:, 1:4] != one[:, 4:7], axis=1)))
if moved < 50 or stats[1]["refined"] < 1:
    fail("%d points moved, %d refined on 1 rank" % (moved, stats[1]["refined"]))
error = link_error(one, edges)
print("ok: %d of %d points moved, %d refined; E_link %.3g L" % (moved, len(one), stats[1]["refined"], error))
if not error <= 1e-9:
    fail("E_link %.3g L > 1e-9 L after the envelope" % error)
for n in (2, 3):
    expect_same(results[n], one, n)
    if stats[n]["refined"] != stats[1]["refined"] or stats[n]["displaced"] != stats[1]["displaced"]:
        fail("%d ranks report %s, 1 rank %s" % (n, stats[n], stats[1]))
    print("ok: %d ranks equal 1 rank bit for bit (%d supersteps, %d bytes exchanged)"
          % (n, stats[n]["supersteps"], stats[n]["bytes"]))
if not np.array_equal(results["nearest"], one):
    fail("2 ranks grasping by position differ from 1 rank grasping by id "
         "(%d points differ)" % np.count_nonzero(np.any(results["nearest"] != one, axis=1)))
print("ok: 2 ranks grasping the point by position equal 1 rank grasping it by id")
