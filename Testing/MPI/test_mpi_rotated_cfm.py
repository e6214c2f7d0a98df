"""The Link region's promise on real meshes through pvbatch (issue 36): the plain pipeline
a user builds (a CRESCENT TSurf file or the same surface turned and saved, the reader,
RedistributeDataSet, ChainMailDeformation with the Link region, no GlobalIds, the grasp
nearest a position) on 1, 2 and 3 ranks. The turned surface pulled by the turned pull
(grasped at the turned position) gives, turned back, the 1-rank result on the file within
1e-9 of the mean edge length on every rank count, and 2 and 3 ranks give 1 rank's bits.
Usage: test_mpi_rotated_cfm.py FILE QUEUE (FILE a .ts under ../shared/data/crescent-cfm;
skipped when absent; QUEUE "FIFO" or "FIFO Priority")."""
import os
import sys
import tempfile

import numpy as np
from mpi_driver import ENV, expect_same, fail, run_ranks, show
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

path, queue = sys.argv[1], sys.argv[2]
if not os.path.exists(path):
    print("skipped: %s is absent" % path)
    sys.exit(0)
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())  # noqa: F405

# A fixed rotation (angles in degrees about x, y, z, as vtkTransform composes them).
ANGLES = [23.0, -41.0, 67.0]
reader = GOCADTSurfReader(FileName=path)  # noqa: F405
turn = Transform(Input=reader)  # noqa: F405
turn.Transform = "Transform"
turn.Transform.Rotate = ANGLES
turn.UpdatePipeline()
rest = vtk_to_numpy(reader.GetClientSideObject().GetOutputDataObject(0).GetPoints().GetData())
turned = vtk_to_numpy(turn.GetClientSideObject().GetOutputDataObject(0).GetPoints().GetData())
rest, turned = rest.astype(float), turned.astype(float)
# R from the points themselves (least squares about the centroids: the transform is exact
# up to rounding), so the test needs no convention for the angles.
a, b = rest - rest.mean(axis=0), turned - turned.mean(axis=0)
u, _, vt = np.linalg.svd(a.T @ b)
R = (u @ vt).T
t = turned.mean(axis=0) - R @ rest.mean(axis=0)
if np.abs(rest @ R.T + t - turned).max() > 1e-6 * np.abs(rest).max():
    fail("could not recover the rotation")
# The mean edge length (the tolerance's unit).
cells = reader.GetClientSideObject().GetOutputDataObject(0).GetPolys()
conn = vtk_to_numpy(cells.GetConnectivityArray()).reshape(-1, 3)
edges = np.concatenate([conn[:, [0, 1]], conn[:, [1, 2]], conn[:, [2, 0]]])
edge = float(np.linalg.norm(rest[edges[:, 0]] - rest[edges[:, 1]], axis=1).mean())

lo, hi = rest.min(axis=0), rest.max(axis=0)
grasp = lo + np.array([0.5, 0.5, 1.0]) * (hi - lo)
pull = 12.0 * edge * np.array([0.3, -0.5, 0.81]) / np.linalg.norm([0.3, -0.5, 0.81])
ENV["PLAIN_FRAME"] = "Link"
ENV["PLAIN_QUEUE"] = queue
ENV["PLAIN_DABS"] = ""


def run(n, file, g, d, out):
    ENV["PLAIN_GRASP"] = " ".join(repr(float(x)) for x in g)
    ENV["PLAIN_PULL"] = " ".join(repr(float(x)) for x in d)
    cmd, done, errors = run_ranks(n, "mpi_plain.py", ["redistribute", file, out], timeout=280)
    if done.returncode != 0 or errors:
        show(cmd, done)
        fail("%d ranks: exit %d, %d error lines" % (n, done.returncode, len(errors)))
    return np.load(os.path.join(out, "result.npy"))


def by_position(rows, key):
    """rows sorted by `key` (n x 3) rounded to a thousandth of the mean edge length."""
    k = np.round(key / (1e-3 * edge)).astype(np.int64)
    return rows[np.lexsort(k.T[::-1])]


with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    turned_file = os.path.join(tmp, "turned.vtp")
    SaveData(turned_file, proxy=turn)  # noqa: F405
    base = run(1, path, grasp, pull, os.path.join(tmp, "base"))
    moved = int(np.count_nonzero(np.any(base[:, 0:3] != base[:, 3:6], axis=1)))
    if moved < 50:
        fail("only %d points moved" % moved)
    # The base result turned: rest and deformed positions.
    want = np.column_stack([base[:, 0:3] @ R.T + t, base[:, 3:6] @ R.T + t, base[:, 6]])
    want = by_position(want, want[:, 0:3])
    results = {}
    for n in (1, 2, 3):
        rows = run(n, turned_file, R @ grasp + t, R @ pull, os.path.join(tmp, "n%d" % n))
        results[n] = rows
        got = by_position(rows, rows[:, 0:3])
        if got.shape != want.shape:
            fail("%d ranks: %s rows against %s" % (n, got.shape, want.shape))
        off = float(np.linalg.norm(got[:, 3:6] - want[:, 3:6], axis=1).max())
        print("%d ranks: the turned result is %.3g mean edge lengths from the result turned "
              "(%d of %d points moved)" % (n, off / edge, moved, len(base)))
        if not off <= 1e-9 * edge:
            fail("%d ranks: off by %.3g mean edge lengths" % (n, off / edge))
    for n in (2, 3):
        expect_same(results[n], results[1], n)
        print("ok: %d ranks equal 1 rank bit for bit" % n)
    print("ok: the Link result turns with the surface on 1, 2 and 3 ranks")
