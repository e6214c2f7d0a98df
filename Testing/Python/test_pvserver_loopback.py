"""The plugin on a pvserver over loopback gives the builtin result, on 1 rank and on 2
MPI ranks with the surface distributed (RedistributeDataSet, ghost cells, point
GlobalIds = the builtin point ids), bit for bit (docs/mpi.md): every rank's points,
gathered on rank 0 and fetched, each copy of a point (owned or ghost, on either rank)
equal to the builtin one."""
import os

import numpy as np

import pvserver_process
from geoshaping_testing import check, load, points, triangulated_plane
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

TMP = os.environ["GEOSHAPING_TEST_TMP"]


# Every rank's points and global ids sent to rank 0, which outputs them as one point
# cloud (sm.Fetch from this 2-rank pvserver brought rank 0's piece only, ParaView 5.11,
# already for RedistributeDataSet's output: the gather is done here instead).
GATHER = """
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray, vtkPoints
from vtkmodules.vtkParallelCore import vtkMultiProcessController
c = vtkMultiProcessController.GetGlobalController()
data = self.GetInputDataObject(0, 0)
xyz, gid = vtkDoubleArray(), vtkIdTypeArray()
xyz.SetNumberOfComponents(3)
xyz.DeepCopy(data.GetPoints().GetData())
gid.DeepCopy(data.GetPointData().GetGlobalIds())
out = self.GetOutputDataObject(0)
if c.GetLocalProcessId() == 0:
    for r in range(1, c.GetNumberOfProcesses()):
        more_xyz, more_gid = vtkDoubleArray(), vtkIdTypeArray()
        c.Receive(more_xyz, r, 4711)
        c.Receive(more_gid, r, 4712)
        for i in range(more_gid.GetNumberOfTuples()):
            xyz.InsertNextTuple(more_xyz.GetTuple(i))
            gid.InsertNextValue(more_gid.GetValue(i))
    points = vtkPoints()
    points.SetData(xyz)
    out.SetPoints(points)
    gid.SetName("GlobalIds")
    out.GetPointData().SetGlobalIds(gid)
else:
    c.Send(xyz, 0, 4711)
    c.Send(gid, 0, 4712)
"""

GLOBAL_IDS = """
from vtkmodules.vtkCommonCore import vtkIdTypeArray
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
ids = vtkIdTypeArray()
ids.SetName("GlobalIds")
ids.SetNumberOfTuples(out.GetNumberOfPoints())
for i in range(out.GetNumberOfPoints()):
    x, y, _ = out.GetPoint(i)
    ids.SetValue(i, int(round(y)) * 31 + int(round(x)))  # the builtin point id
out.GetPointData().SetGlobalIds(ids)
"""


def deformed(remote, distribute=False):
    load(remote=remote, ns=globals())
    surface = triangulated_plane(30)
    source = surface
    if distribute:
        ids = ProgrammableFilter(Input=surface, Script=GLOBAL_IDS)  # noqa: F405
        source = GhostCellsGenerator(Input=RedistributeDataSet(Input=ids))  # noqa: F405
    chain = ChainMailDeformation(Input=source)  # noqa: F405
    # RedistributeDataSet may turn float points into double: compare in double.
    chain.OutputPointsPrecision = "Double"
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7
    chain.GraspPointId = 15 * 31 + 15
    chain.Displacement = [1.0, 0.0, 4.0]
    if distribute:
        # Positions by global id, from every rank's piece (GATHER): a point no rank
        # brings stays NaN; copies of a point that differ are reported.
        gather = ProgrammableFilter(Input=chain, Script=GATHER, OutputDataSetType="vtkPolyData")  # noqa: F405
        data = sm.Fetch(gather, 0)
        Delete(gather)
        gid = vtk_to_numpy(data.GetPointData().GetGlobalIds())
        xyz = vtk_to_numpy(data.GetPoints().GetData())
        result = np.full((31 * 31, 3), np.nan), points(surface)
        result[0][gid] = xyz
        copies_agree[0] = bool(np.array_equal(result[0][gid], xyz))
        copies[0] = len(gid)
    else:
        result = points(chain), points(surface)
    chain.UpdatePropertyInformation()
    grasped = chain.GetProperty("LastGraspMalleability").GetData()
    if ranks_now[0] < 2:
        check(abs(grasped - 0.7) < 1e-6,
              "the grasp's malleability (0.7) reads back through the proxy (%s)"
              % ("remote" if remote else "builtin"))
    Delete(chain)
    Delete(surface)
    return result


ranks_now = [1]
copies_agree, copies = [False], [0]
builtin, rest = deformed(remote=False)
check(np.abs(builtin - rest).max() > 1.0, "builtin session deforms")

for ranks in (1, 2):
    ranks_now[0] = ranks
    proc, port, log = pvserver_process.start(ranks, os.path.join(TMP, "pvserver-%d.log" % ranks))
    try:
        Connect("127.0.0.1", port)
        remote, remote_rest = deformed(remote=True, distribute=ranks > 1)
        Disconnect()
    finally:
        pvserver_process.stop(proc, 20)  # pvserver ends when its client disconnects
    log.seek(0)
    server_log = log.read()
    if ranks == 1:
        check(np.array_equal(remote, builtin), "pvserver (1 rank) result equals the builtin one")
    else:
        held = ~np.isnan(remote[:, 0])
        moved = np.any(builtin != rest, axis=1).sum()
        check(held.all() and copies[0] > len(held) and copies_agree[0],
              "pvserver (2 ranks, distributed): the client got all %d points from both ranks "
              "(%d copies: owned and ghosts, every copy of a point equal)"
              % (len(held), copies[0]))
        check(moved > 50 and np.array_equal(remote, builtin),
              "pvserver (2 ranks, distributed): every point (%d moved) equals the builtin "
              "result bit for bit" % moved)
        check(" ERR|" not in server_log, "pvserver (2 ranks): no error")
