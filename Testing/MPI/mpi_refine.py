"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_refinement.py): distributes a scene as
mpi_deform.py does, deforms it with ChainMailDeformation and one envelope refinement
(RefinementSolver Envelope, Axes region), and writes on rank 0:
  OUT/result.npy  every owned point's (global id, x, y, z, rest x, y, z, malleability),
                  gathered by global id;
  OUT/edges.npy   the undistributed mesh's edges as global id pairs (rank 0's whole copy);
  OUT/stats.json  the filter's figures (all ranks' totals).
Arguments: SCENE OUT [SOLVER] (surface or slab; SOLVER Envelope by default: another one is
refused on more than one rank, and the output is the undeformed input; "Obstacles" keeps
Envelope and connects an obstacle below the scene: the refinement with obstacles is refused on more
than one rank; "Markers" keeps Envelope and honours three markers: HonourMarkers with markers
is refused on more than one rank; "Snap" keeps Envelope, connects three markers (not
honoured) and, after the pull, sends SnapToMarkers: refused on more than one rank; the
command releases the grasp, so the output is the input)."""
import json
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController

scene, out = sys.argv[1], sys.argv[2]
solver = sys.argv[3] if len(sys.argv) > 3 else "Envelope"
obstacles = solver == "Obstacles"
nearest = solver == "Nearest"  # the same point grasped by GraspMode Nearest To Position
markers = solver == "Markers"
snap = solver == "Snap"
solver = "Envelope" if obstacles or nearest or markers or snap else solver
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import distributed, owned_rows  # noqa: E402

if scene == "surface":
    # Painted (Figure 5C): a rigid fault step in soft beds.
    source = FaultStepHorizon(PaintFigure5C=1)  # noqa: F405
    grasp_at, pull = [0.5, 0.5], [0.0, 0.0, 6.0]
elif scene == "slab":
    layers = LayeredFaultScene()  # noqa: F405 (tetrahedra)
    source = Calculator(Input=layers, ResultArrayName="Malleability")  # noqa: F405
    source.Function = "0.25*floor(3.999*abs(sin(0.07*coordsX+0.11*coordsY+0.3*coordsZ)))"
    grasp_at, pull = [0.5, 0.5], [2.0, 0.0, 5.0]
else:
    raise SystemExit("unknown scene " + scene)
# Global ids = the point ids of the undistributed data (as mpi_deform.py).
ids, ghosts = distributed(source)
chain = ChainMailDeformation(Input=ghosts)  # noqa: F405
chain.CandidateQueue = "FIFO Priority"
chain.OutputPointsPrecision = "Double"
chain.RefinementIterations = 1
chain.RefinementSolver = solver
if obstacles:
    chain.Obstacles = [Plane(Origin=[-1e3, -1e3, -1e3], Point1=[1e3, -1e3, -1e3],  # noqa: F405
                             Point2=[-1e3, 1e3, -1e3])]
if markers or snap:
    chain.Markers = [PointSource(NumberOfPoints=3)]  # noqa: F405
    chain.HonourMarkers = int(markers)

ids.UpdatePipeline()
whole = ids.GetClientSideObject().GetOutputDataObject(0)
choice = vtkIdTypeArray()
choice.SetNumberOfTuples(1)
position = vtkDoubleArray()
position.SetNumberOfTuples(3)
os.makedirs(out, exist_ok=True)
if rank == 0:
    xyz = vtk_to_numpy(whole.GetPoints().GetData()).astype(float)
    gid = vtk_to_numpy(whole.GetPointData().GetGlobalIds())
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    target = lo[:2] + np.array(grasp_at) * (hi - lo)[:2]
    chosen = int(np.argmin(((xyz[:, :2] - target) ** 2).sum(axis=1)))
    choice.SetValue(0, int(gid[chosen]))
    for k in range(3):
        position.SetValue(k, xyz[chosen, k])
    # The whole mesh's edges (every pair of points sharing a cell), by global id.
    pairs = set()
    for c in range(whole.GetNumberOfCells()):
        cell = whole.GetCell(c)
        p = [int(gid[cell.GetPointId(k)]) for k in range(cell.GetNumberOfPoints())]
        for a in range(len(p)):
            for b in range(a + 1, len(p)):
                if p[a] != p[b]:  # (paraview.simple shadows min and max)
                    pairs.add((p[a], p[b]) if p[a] < p[b] else (p[b], p[a]))
    np.save(os.path.join(out, "edges.npy"), np.array(sorted(pairs), dtype=np.int64))
controller.Broadcast(choice, 0)
controller.Broadcast(position, 0)
chain.GraspPointId = int(choice.GetValue(0))
if nearest:
    chain.GraspPointId = -1
    chain.GraspMode = "Nearest To Position"
    chain.GraspPosition = [position.GetValue(k) for k in range(3)]
chain.Displacement = pull
chain.UpdatePipeline()
if snap:
    chain.SMProxy.InvokeCommand("SnapToMarkers")
    chain.UpdatePipeline()

rows = owned_rows(chain.GetClientSideObject().GetOutputDataObject(0),
                  ghosts.GetClientSideObject().GetOutputDataObject(0), nranks, ["Malleability"])
np.save(os.path.join(out, "rank%d.npy" % rank), rows)
chain.UpdatePropertyInformation()
stats = {key: chain.GetProperty(name).GetData() for key, name in (
    ("refined", "NumberOfRefinedPoints"), ("displaced", "NumberOfDisplacedPoints"),
    ("supersteps", "NumberOfSupersteps"), ("bytes", "NumberOfBytesExchanged"),
    ("refine_ms", "LastRefinementMilliseconds"), ("deform_ms", "LastDeformationMilliseconds"))}
controller.Barrier()
if rank == 0:
    parts = [np.load(os.path.join(out, "rank%d.npy" % r)) for r in range(nranks)]
    allrows = np.concatenate(parts)
    allrows = allrows[np.argsort(allrows[:, 0], kind="stable")]
    np.save(os.path.join(out, "result.npy"), allrows)
    with open(os.path.join(out, "stats.json"), "w") as text:
        json.dump(stats, text)
    print("rank0: %d points from %d ranks, grasp %d, %s"
          % (len(allrows), nranks, chain.GraspPointId, json.dumps(stats)))
controller.Barrier()
