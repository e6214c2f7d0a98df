"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_obstacles.py): a 31 x 31 triangulated
plane distributed over the ranks (GlobalIds = its point ids, RedistributeDataSet, one
ghost level) is pulled up into a tilted ceiling, an obstacle given on port 1
(docs/obstacles.md, "On several processes"). Writes on rank 0:
  OUT/result.npy    every owned point's (global id, x, y, z, rest x, y, z), by global id;
  OUT/ceiling.npy   the ceiling's triangles as (a, b, c) corner rows (rank 0's whole copy);
  OUT/stats.json    the filter's figures (all ranks' totals).
Arguments: OUT [CLEARANCE]."""
import json
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkParallelCore import vtkMultiProcessController

out = sys.argv[1]
clearance = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import distributed, owned_rows  # noqa: E402

source = Triangulate(Input=Plane(XResolution=30, YResolution=30, Origin=[0, 0, 0],  # noqa: F405
                                 Point1=[30.0, 0, 0], Point2=[0, 30.0, 0]))  # noqa: F405
ids, ghosts = distributed(source)
# The ceiling z = 2 + 0.2 (x + 5), over the whole plane; its own pipeline, so each rank
# holds what the source gives it (here the whole on rank 0, nothing elsewhere).
ceiling = Triangulate(Input=Plane(XResolution=8, YResolution=8, Origin=[-5, -5, 2],  # noqa: F405
                                  Point1=[35, -5, 10], Point2=[-5, 35, 2]))  # noqa: F405
chain = ChainMailDeformation(Input=ghosts)  # noqa: F405
chain.CandidateQueue = "FIFO Priority"
chain.OutputPointsPrecision = "Double"
chain.DefaultMalleability = 0.2
chain.Obstacles = [ceiling]
chain.ObstacleClearance = clearance
chain.GraspPointId = 15 * 31 + 15  # the centre (15, 15)
chain.Displacement = [1.0, 0.0, 10.0]
chain.UpdatePipeline()

rows = owned_rows(chain.GetClientSideObject().GetOutputDataObject(0),
                  ghosts.GetClientSideObject().GetOutputDataObject(0), nranks)
os.makedirs(out, exist_ok=True)
np.save(os.path.join(out, "rank%d.npy" % rank), rows)
chain.UpdatePropertyInformation()
stats = {key: chain.GetProperty(name).GetData() for key, name in (
    ("displaced", "NumberOfDisplacedPoints"), ("blocked", "NumberOfObstacleBlockedPoints"),
    ("fraction", "LastGraspObstacleFraction"), ("supersteps", "NumberOfSupersteps"),
    ("landed", "LastGraspDisplacement"))}
if rank == 0:
    tris = ceiling.GetClientSideObject().GetOutputDataObject(0)
    xyz = vtk_to_numpy(tris.GetPoints().GetData()).astype(float)
    cells = vtk_to_numpy(tris.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    np.save(os.path.join(out, "ceiling.npy"), xyz[cells])
controller.Barrier()
if rank == 0:
    allrows = np.concatenate([np.load(os.path.join(out, "rank%d.npy" % r)) for r in range(nranks)])
    allrows = allrows[np.argsort(allrows[:, 0], kind="stable")]
    np.save(os.path.join(out, "result.npy"), allrows)
    with open(os.path.join(out, "stats.json"), "w") as text:
        json.dump(stats, text)
    print("rank0: %d points from %d ranks, %s" % (len(allrows), nranks, json.dumps(stats)))
controller.Barrier()
