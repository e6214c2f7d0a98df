"""Editing on ParaView's distributed engine (docs/mpi.md, "Edits"): mpi_edit.py run by
`mpiexec -n 1/2/3 pvbatch --sym` on a scene distributed by RedistributeDataSet +
GhostCellsGenerator. Checked:
- drag, commit, drag (GraspMode nearest to a position), commit, drag, undo, redo, reset,
  redo, redo: the gathered owned points of 2 and 3 ranks, with their diagnostics
  (ChainMailDisplacement, ChainMailSponsor as a global id), equal 1 rank's bit for bit at
  every step, the grasp (LastGraspPointId) too;
- LastEdit and the EditHistory length are the same on every rank, and 1 rank's records
  equal 3 ranks' (the same text: records name global ids);
- the 3-rank records loaded through EditHistory (AddEdit) on 1 and 2 ranks give the
  3-rank committed shape;
- a malformed record is refused on every rank with the same error, the edit before it
  applied, the one after it not.
Usage: test_mpi_editing.py SCENE (surface or plane)."""
import json
import os
import sys
import tempfile

import numpy as np
from mpi_driver import fail, one_row_per_point, run_ranks, show

scene = sys.argv[1]


def run(n, out, *args):
    cmd, done, _ = run_ranks(n, "mpi_edit.py", [scene, out] + list(args))
    if done.returncode != 0:  # error lines are expected here: the logs list them
        show(cmd, done)
        fail("%d ranks: exit %d" % (n, done.returncode))
    logs = [json.load(open(os.path.join(out, "rank%d.json" % r))) for r in range(n)]
    steps = len(logs[0]["last"])
    shapes = [one_row_per_point(np.load(os.path.join(out, "step%d.npy" % s)), n, ", step %d" % s)
              for s in range(steps)]
    for key in ("last", "history", "errors", "grasp"):
        for r in range(1, n):
            if logs[r][key] != logs[0][key]:
                fail("%d ranks: rank %d's %s differs from rank 0's: %s vs %s"
                     % (n, r, key, str(logs[r][key])[:300], str(logs[0][key])[:300]))
    return shapes, logs[0]


with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    made = {n: run(n, os.path.join(tmp, "make%d" % n), "make") for n in (1, 2, 3)}
    shapes1, log1 = made[1]
    if any(log1["errors"]):
        fail("1 rank: errors %s" % log1["errors"])
    rest = shapes1[7]  # after reset
    moved = [int(np.count_nonzero(np.any(s[:, 1:4] != rest[:, 1:4], axis=1))) for s in shapes1]
    print("1 rank: points away from rest per step:", moved)
    if min(moved[i] for i in (0, 1, 2, 3, 4, 5, 6, 9)) < 20 or moved[7] != 0:
        fail("1 rank: the steps did not move what they should")
    same = lambda a, b: np.array_equal(shapes1[a][:, :4], shapes1[b][:, :4])  # noqa: E731
    if same(2, 1) or same(3, 1) or same(4, 3):
        fail("1 rank: a drag did not change the shape")
    if not (same(5, 1) and same(6, 3) and same(9, 3)):
        fail("1 rank: undo/redo do not give the committed shapes back")
    if log1["history"] != [0, 1, 1, 2, 2, 1, 2, 0, 1, 2]:
        fail("1 rank: EditHistory lengths %s" % log1["history"])
    if scene == "plane" and log1["grasp"][2] != 475:
        fail("1 rank: the grasp nearest (10.5, 15, 0) is %d, not 475 (tie to the lower id)"
             % log1["grasp"][2])
    if not (log1["last"][1].startswith("GSE2 ") and log1["last"][3].startswith("GSE2 ")):
        fail("1 rank: records are not GSE2")
    for n in (2, 3):
        shapes, log = made[n]
        for s in range(len(shapes1)):
            if shapes[s].shape != shapes1[s].shape or not np.array_equal(shapes[s], shapes1[s]):
                fail("%d ranks, step %d: differs from 1 rank" % (n, s))
        if log["last"] != log1["last"] or log["grasp"] != log1["grasp"] or any(log["errors"]):
            fail("%d ranks: LastEdit, grasp or errors differ from 1 rank" % n)
        print("ok: %d ranks equal 1 rank bit for bit at all %d steps; the same LastEdit on every"
              " rank and as on 1 rank" % (n, len(shapes1)))
    records = os.path.join(tmp, "make3", "records.json")
    with open(records) as f:
        if json.load(f) != [log1["last"][1], log1["last"][3]]:
            fail("the 3-rank EditHistory is not 1 rank's records")
    for n in (1, 2):
        shapes, log = run(n, os.path.join(tmp, "load%d" % n), "load", records)
        if any(log["errors"]) or not np.array_equal(shapes[0][:, :4], made[3][0][3][:, :4]):
            fail("%d ranks: the 3-rank records do not give the 3-rank shape (%s)" % (n, log["errors"]))
        print("ok: the 3-rank records loaded on %d rank(s) give the 3-rank shape" % n)
    bad = {}
    for n in (1, 3):
        shapes, log = run(n, os.path.join(tmp, "bad%d" % n), "bad", records)
        message = log["errors"][0]
        if len(message) != 1 or "EditHistory: edit 1: malformed edit record" not in message[0]:
            fail("%d ranks: the bad record's error is %s" % (n, message))
        if not np.array_equal(shapes[0][:, :4], made[3][0][1][:, :4]):
            fail("%d ranks: not the shape of the edit before the bad record" % n)
        bad[n] = message
    if bad[1] != bad[3]:
        fail("the error differs between 1 and 3 ranks")
    print("ok: a malformed record is refused on every rank alike: %s" % bad[1][0].strip()[:160])
