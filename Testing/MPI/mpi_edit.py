"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_editing.py): edits a distributed scene
with ChainMailDeformation's commands and writes, after every step, every owned point's
(global id, x, y, z, ChainMailDisplacement, ChainMailSponsor) to OUT/stepK.npy (gathered on rank 0), and each rank's LastEdit,
EditHistory length and error messages to OUT/rankR.json.
Arguments: SCENE OUT make | SCENE OUT load RECORDS.json | SCENE OUT bad RECORDS.json.
  make: drag, commit, drag (nearest to a position), commit, drag, undo, redo, reset, redo,
        redo; OUT/records.json is EditHistory at the end.
  load: EditHistory = the records (what a state file does), no grasp.
  bad:  EditHistory = [first record, a malformed one, the second record]."""
import json
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkParallelCore import vtkMultiProcessController

scene, out, mode = sys.argv[1], sys.argv[2], sys.argv[3]
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import distributed  # noqa: E402
os.makedirs(out, exist_ok=True)

if scene == "surface":
    source = FaultStepHorizon()  # noqa: F405 (painted: a rigid fault block in soft beds)
    # (grasp at a fraction of the bounds, pull) for the three drags
    drags = [([0.5, 0.5], [0.0, 0.0, 6.0]), ([0.3, 0.6], [2.0, 0.0, 4.0]),
             ([0.7, 0.4], [0.0, 1.0, -5.0])]
else:  # plane: 31 x 31 points, spacing 1, uniform malleability 0.7
    source = Triangulate(Input=Plane(XResolution=30, YResolution=30, Origin=[0, 0, 0],  # noqa: F405
                                     Point1=[30.0, 0, 0], Point2=[0, 30.0, 0]))  # noqa: F405
    drags = [([0.5, 0.5], [1.0, 0.0, 4.0]), ([0.35, 0.5], [0.0, 0.0, 3.0]),
             ([0.6, 0.3], [0.0, 1.0, -2.0])]
# Global ids = the point ids of the undistributed data (mpi_deform.py).
ids, ghosts = distributed(source)
chain = ChainMailDeformation(Input=ghosts)  # noqa: F405
chain.CandidateQueue = "FIFO Priority"
chain.OutputPointsPrecision = "Double"
chain.GenerateDiagnostics = 1  # ChainMailDisplacement and ChainMailSponsor (a global id)
if scene != "surface":
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7
errors = []  # this rank's filter's errors since the last dump


@calldata_type(VTK_STRING)
def on_error(obj, event, message):
    errors.append(message.split("): ", 1)[-1].strip())  # without the object's address


chain.GetClientSideObject().AddObserver("ErrorEvent", on_error)

ids.UpdatePipeline()
whole = ids.GetClientSideObject().GetOutputDataObject(0)
xyz = vtk_to_numpy(whole.GetPoints().GetData()).astype(float) if rank == 0 else None


def position(frac):
    """The point of the undistributed data nearest a fraction of the bounds (rank 0's copy
    holds all; every rank runs the same script, so rank 0's answer is broadcast), 0.01
    above it. The plane: exactly between points (10, 15) and (11, 15), a tie that the
    lower global id (475) wins, on any number of ranks."""
    if scene == "plane":
        return [10.5, 15.0, 0.0]
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    a = vtkDoubleArray()
    a.SetNumberOfTuples(3)
    if rank == 0:
        lo, hi = xyz.min(axis=0), xyz.max(axis=0)
        target = lo[:2] + np.array(frac) * (hi - lo)[:2]
        i = int(np.argmin(((xyz[:, :2] - target) ** 2).sum(axis=1)))
        for k in range(3):
            a.SetValue(k, xyz[i, k])
        a.SetValue(2, xyz[i, 2] + 0.01)  # above it: nearest, not on it
    controller.Broadcast(a, 0)
    return [a.GetValue(k) for k in range(3)]


def grasp_id(frac):
    from vtkmodules.vtkCommonCore import vtkIdTypeArray
    a = vtkIdTypeArray()
    a.SetNumberOfTuples(1)
    if rank == 0:
        lo, hi = xyz.min(axis=0), xyz.max(axis=0)
        target = lo[:2] + np.array(frac) * (hi - lo)[:2]
        a.SetValue(0, int(np.argmin(((xyz[:, :2] - target) ** 2).sum(axis=1))))
    controller.Broadcast(a, 0)
    return int(a.GetValue(0))


log = {"last": [], "history": [], "errors": [], "grasp": []}
step = [0]


def dump():
    chain.UpdatePipeline()
    chain.UpdatePropertyInformation()
    data = chain.GetClientSideObject().GetOutputDataObject(0)
    n = data.GetNumberOfPoints()
    rows = np.zeros((0, 8))
    if n:
        ghost = data.GetPointData().GetArray("vtkGhostType")
        owned = ((vtk_to_numpy(ghost).astype(int) & 1) == 0) if ghost else np.ones(n, bool)
        gid = vtk_to_numpy(data.GetPointData().GetGlobalIds())[owned]
        pts = vtk_to_numpy(data.GetPoints().GetData()).astype(float)[owned]
        pd = data.GetPointData()
        disp = vtk_to_numpy(pd.GetArray("ChainMailDisplacement"))[owned]
        sponsor = vtk_to_numpy(pd.GetArray("ChainMailSponsor"))[owned].astype(float)
        rows = np.column_stack([gid.astype(float), pts, disp, sponsor])
    np.save(os.path.join(out, "s%d_r%d.npy" % (step[0], rank)), rows)
    log["last"].append(chain.GetPropertyValue("LastEdit"))  # this rank's filter
    log["history"].append(len(chain.EditHistory))
    log["errors"].append(list(errors))
    del errors[:]
    log["grasp"].append(int(chain.GetPropertyValue("LastGraspPointId")))
    step[0] += 1


def release():
    chain.GraspMode = "Point Id"
    chain.GraspPointId = -1
    chain.Displacement = [0.0, 0.0, 0.0]


if mode == "make":
    chain.GraspPointId = grasp_id(drags[0][0])
    chain.Displacement = drags[0][1]
    dump()                                   # 0 drag
    chain.InvokeCommand("CommitEdit")
    release()
    dump()                                   # 1 committed
    chain.GraspMode = "Nearest To Position"
    chain.GraspPosition = position(drags[1][0])
    chain.Displacement = drags[1][1]
    dump()                                   # 2 drag, nearest to a position
    chain.InvokeCommand("CommitEdit")
    release()
    dump()                                   # 3 committed
    chain.GraspPointId = grasp_id(drags[2][0])
    chain.Displacement = drags[2][1]
    dump()                                   # 4 drag, not committed
    release()
    chain.InvokeCommand("UndoEdit")
    dump()                                   # 5 undo
    chain.InvokeCommand("RedoEdit")
    dump()                                   # 6 redo
    chain.InvokeCommand("ResetEdits")
    dump()                                   # 7 reset
    chain.InvokeCommand("RedoEdit")
    dump()                                   # 8 redo
    chain.InvokeCommand("RedoEdit")
    dump()                                   # 9 redo
    if rank == 0:
        with open(os.path.join(out, "records.json"), "w") as f:
            json.dump(list(chain.EditHistory), f)
else:
    with open(sys.argv[4]) as f:
        records = json.load(f)
    chain.GraspPointId = -1
    if mode == "bad":
        records = [records[0], "GSE2 1 junk", records[1]]
    chain.EditHistory = records
    dump()

with open(os.path.join(out, "rank%d.json" % rank), "w") as f:
    json.dump(log, f)
controller.Barrier()
if rank == 0:
    for s in range(step[0]):
        parts = [np.load(os.path.join(out, "s%d_r%d.npy" % (s, r))) for r in range(nranks)]
        rows = np.concatenate(parts)
        rows = rows[np.argsort(rows[:, 0], kind="stable")]
        np.save(os.path.join(out, "step%d.npy" % s), rows)
controller.Barrier()
