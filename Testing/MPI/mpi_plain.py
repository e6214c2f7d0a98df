"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_plain_pipeline.py): the pipeline a user
builds, with nothing added for MPI: a file reader, optionally RedistributeDataSet or D3
(or point GlobalIds given first, or MalleabilityPaint with geodesic dabs), then
ChainMailDeformation grasping the point nearest a position. No GhostCellsGenerator: the
filters make the ghost ring they need. Writes every owned point's (rest x, y, z,
deformed x, y, z, malleability) to OUT/result.npy on rank 0 (one row per position on several
ranks: the copies of a seam point that D3 leaves unflagged on every rank must agree). Arguments: CASE FILE OUT (CASE: reader, redistribute, d3, ids, paint)."""
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkParallelCore import vtkMultiProcessController

case, path, out = sys.argv[1:4]
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import POINT_INDEX_IDS  # noqa: E402

if path.endswith(".ts"):
    reader = GOCADTSurfReader(FileName=path)  # noqa: F405
else:
    reader = (XMLPolyDataReader if path.endswith(".vtp") else XMLUnstructuredGridReader)(  # noqa: F405
        FileName=[path])
upstream = reader
if case == "ids":  # point GlobalIds (the file's point ids), then distributed
    upstream = ProgrammableFilter(Input=reader)  # noqa: F405
    upstream.Script = POINT_INDEX_IDS
if case in ("redistribute", "ids", "paint"):
    upstream = RedistributeDataSet(Input=upstream)  # noqa: F405
elif case == "d3":
    upstream = D3(Input=upstream)  # noqa: F405
if case == "paint":
    upstream = MalleabilityPaint(Input=upstream)  # noqa: F405
    upstream.InitialMalleability = 0.6
    upstream.Falloff = "Smooth"
    upstream.DistanceMode = "Geodesic"
    upstream.Dabs = [float(x) for x in os.environ["PLAIN_DABS"].split()]
chain = ChainMailDeformation(Input=upstream)  # noqa: F405
chain.CandidateQueue = os.environ.get("PLAIN_QUEUE", "FIFO Priority")
chain.ValidRegionFrame = os.environ.get("PLAIN_FRAME", "Axes")
chain.OutputPointsPrecision = "Double"
chain.GraspMode = "Nearest To Position"
chain.GraspPosition = [float(x) for x in os.environ["PLAIN_GRASP"].split()]
chain.Displacement = [float(x) for x in os.environ["PLAIN_PULL"].split()]
chain.UpdatePipeline()

# Owned points: not flagged DUPLICATEPOINT (all of them without vtkGhostType).
data = chain.GetClientSideObject().GetOutputDataObject(0)
rest = upstream.GetClientSideObject().GetOutputDataObject(0)
n = data.GetNumberOfPoints()
rows = np.zeros((0, 7))
if n:
    ghost = data.GetPointData().GetArray("vtkGhostType")
    owned = np.ones(n, dtype=bool) if ghost is None else (vtk_to_numpy(ghost).astype(int) & 1) == 0
    pts = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    # A ring the filter made: the input's points first, the received ghosts after them.
    x0 = vtk_to_numpy(rest.GetPoints().GetData()).astype(float)
    if np.any(owned[len(x0):]):
        raise RuntimeError("an owned point is not one of the input's points")
    paint = data.GetPointData().GetArray("Malleability")
    m = np.zeros(n) if paint is None else vtk_to_numpy(paint).astype(float)
    rows = np.column_stack([x0[owned[:len(x0)]], pts[owned], m[owned]])
os.makedirs(out, exist_ok=True)
np.save(os.path.join(out, "rank%d.npy" % rank), rows)
chain.UpdatePropertyInformation()
moved = chain.GetProperty("NumberOfDisplacedPoints").GetData()
grasped = chain.GetProperty("LastGraspMalleability").GetData()
controller.Barrier()
if rank == 0:
    rows = np.concatenate([np.load(os.path.join(out, "rank%d.npy" % r)) for r in range(nranks)])
    rows = rows[np.lexsort(rows.T[::-1])]  # by the rest position
    # D3 leaves a seam point unflagged on every process holding it: its copies must agree.
    rest_only, first = np.unique(rows[:, 0:3], axis=0, return_index=True)
    if nranks > 1 and len(rest_only) < len(rows) and not np.array_equal(np.unique(rows, axis=0), rows[first]):
        raise RuntimeError("the copies of a point differ")
    rows = rows[first] if nranks > 1 else rows
    np.save(os.path.join(out, "result.npy"), rows)
    print("rank0: %d owned points from %d ranks, %d displaced" % (len(rows), nranks, moved))
    print("grasp malleability %r" % grasped)
controller.Barrier()
