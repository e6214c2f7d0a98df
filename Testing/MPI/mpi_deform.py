"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_deformation.py): distributes a scene,
deforms it with ChainMailDeformation and writes every owned point's (global id, x, y,
z, rest x, y, z) to OUT/result.npy, gathered on rank 0, and (surfaces) SaveData's
TSurf to OUT/deformed.ts. Arguments: SCENE OUT [noids].
With noids the data is distributed without point GlobalIds, so on N > 1 ranks the
filter numbers the points itself (by coordinates); on 1 rank the same numbering is
given by numpy here (the rank of each point among the distinct coordinates, an
independent computation), so the results must still be equal."""
import os
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdTypeArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController

scene, out = sys.argv[1], sys.argv[2]
noids = sys.argv[3:] == ["noids"]
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import COORDINATE_RANKS, POINT_INDEX_IDS, owned_rows  # noqa: E402

if scene == "surface":
    source = FaultStepHorizon()  # noqa: F405 (painted: a rigid fault block in soft beds)
    grasp_at, pull = [0.5, 0.5], [0.0, 0.0, 6.0]
elif scene == "slab":
    layers = LayeredFaultScene()  # noqa: F405 (tetrahedra)
    # Painted in four bands, the lowest rigid (0).
    source = Calculator(Input=layers, ResultArrayName="Malleability")  # noqa: F405
    source.Function = "0.25*floor(3.999*abs(sin(0.07*coordsX+0.11*coordsY+0.3*coordsZ)))"
    grasp_at, pull = [0.5, 0.5], [2.0, 0.0, 5.0]
elif scene == "plane":  # test_pvserver_loopback's scene, uniform malleability 0.7
    source = Triangulate(Input=Plane(XResolution=30, YResolution=30, Origin=[0, 0, 0],  # noqa: F405
                                     Point1=[30.0, 0, 0], Point2=[0, 30.0, 0]))  # noqa: F405
    grasp_at, pull = [0.5, 0.5], [1.0, 0.0, 4.0]
else:
    source = GOCADTSurfReader(FileName=scene)  # noqa: F405
    grasp_at, pull = [0.5, 0.5], [0.0, 0.0, 80000.0]  # UTM metres, ~10 km spacing
# Global ids = the point ids of the undistributed data (all on rank 0). Not
# GenerateGlobalIds: it merges coincident points, and a fault's two sides must stay apart.
ids = ProgrammableFilter(Input=source)  # noqa: F405
ids.Script = COORDINATE_RANKS if noids else POINT_INDEX_IDS
spread = RedistributeDataSet(Input=source if noids and nranks > 1 else ids)  # noqa: F405
ghosts = GhostCellsGenerator(Input=spread)  # noqa: F405
chain = ChainMailDeformation(Input=ghosts)  # noqa: F405
chain.CandidateQueue = "FIFO Priority"
# RedistributeDataSet may turn float points into double: compare in double.
chain.OutputPointsPrecision = "Double"
if scene == "plane":
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7

# The grasp: the global id of the point nearest a fraction of the bounds, found on the
# undistributed data (all on rank 0, whatever the rank count) and broadcast.
ids.UpdatePipeline()
whole = ids.GetClientSideObject().GetOutputDataObject(0)
choice = vtkIdTypeArray()
choice.SetNumberOfTuples(1)
if rank == 0:
    xyz = vtk_to_numpy(whole.GetPoints().GetData()).astype(float)
    gid = vtk_to_numpy(whole.GetPointData().GetGlobalIds())
    if noids and len(np.unique(gid)) != len(gid):
        raise RuntimeError("coincident points: the coordinate numbering joins them")
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    target = lo[:2] + np.array(grasp_at) * (hi - lo)[:2]
    choice.SetValue(0, int(gid[np.argmin(((xyz[:, :2] - target) ** 2).sum(axis=1))]))
controller.Broadcast(choice, 0)
chain.GraspPointId = int(choice.GetValue(0))
chain.Displacement = pull
chain.UpdatePipeline()

os.makedirs(out, exist_ok=True)
if scene not in ("slab",):
    # SaveData of a TSurf from N ranks: rank 0 writes one file (GocadTSurfWriter is a
    # vtkParallelSerialWriter); test_mpi_deformation.py compares it to the 1-rank file.
    # RedistributeDataSet made the surface an unstructured grid: ExtractSurface makes it
    # polydata again, as a user must before saving a TSurf.
    SaveData(os.path.join(out, "deformed.ts"), proxy=ExtractSurface(Input=chain))  # noqa: F405

rows = owned_rows(chain.GetClientSideObject().GetOutputDataObject(0),
                  ghosts.GetClientSideObject().GetOutputDataObject(0), nranks)
np.save(os.path.join(out, "rank%d.npy" % rank), rows)
controller.Barrier()
if rank == 0:
    parts = [np.load(os.path.join(out, "rank%d.npy" % r)) for r in range(nranks)]
    allrows = np.concatenate(parts)
    allrows = allrows[np.argsort(allrows[:, 0], kind="stable")]
    np.save(os.path.join(out, "result.npy"), allrows)
    print("rank0: %d points from %d ranks, grasp %d" % (len(allrows), nranks, chain.GraspPointId))
controller.Barrier()
