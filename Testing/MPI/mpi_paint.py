"""Run by `mpiexec -n N pvbatch --sym` (test_mpi_paint.py): FaultStepHorizon (a fault
step: a geodesic brush on one side must not paint the other) given point GlobalIds,
distributed by RedistributeDataSet + GhostCellsGenerator, painted by MalleabilityPaint
with Geodesic distance (dabs spread over the surface, some across the rank borders);
writes every owned point's (global id, malleability) to OUT/result.npy on rank 0 and the
filter's figures to OUT/stats.json. Arguments: OUT [noids]: with `noids` the data has
no GlobalIds (the filter numbers the points by coordinates) and the rows are keyed by
(x, y, z, malleability) instead."""
import json
import os
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkParallelCore import vtkMultiProcessController

out = sys.argv[1]
noids = "noids" in sys.argv[2:]
controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_pipeline import distributed  # noqa: E402

source = FaultStepHorizon(Length=40.0, Width=20.0, Throw=8.0, StepRun=2.0, Spacing=0.5)  # noqa: F405
if noids:
    ghosts = GhostCellsGenerator(Input=RedistributeDataSet(Input=source))  # noqa: F405
else:
    ids, ghosts = distributed(source)
paint = MalleabilityPaint(Input=ghosts)  # noqa: F405
paint.InitialMalleability = 0.4
paint.Falloff = "Smooth"
paint.DistanceMode = "Geodesic"
dabs = []
# A stroke along the step's foot, large dabs across the middle, one at a grid point's
# exact position (a tie for the nearest vertex is possible), and an invalid one.
for y in np.arange(0.0, 20.01, 2.5):
    dabs += [19.0, y, 8.0, 2.5, 0.0, 1.0]
dabs += [10.0, 10.0, 8.0, 9.0, 1.0, 0.6, 30.0, 10.0, 0.0, 12.0, 0.9, 0.8, 20.25, 5.25, 4.0, 3.0, 0.2, 1.0]
dabs += [5.0, 5.0, 8.0, -1.0, 0.5, 0.5]
paint.Dabs = dabs
paint.UpdatePipeline()

data = paint.GetClientSideObject().GetOutputDataObject(0)
n = data.GetNumberOfPoints()
rows = np.zeros((0, 4 if noids else 2))
if n:
    ghost = vtk_to_numpy(data.GetPointData().GetArray("vtkGhostType")) if nranks > 1 else np.zeros(n)
    owned = (ghost.astype(int) & 1) == 0
    m = vtk_to_numpy(data.GetPointData().GetArray("Malleability"))[owned]
    if noids:
        xyz = vtk_to_numpy(data.GetPoints().GetData())[owned]
        rows = np.column_stack([xyz.astype(float), m.astype(float)])
    else:
        gid = vtk_to_numpy(data.GetPointData().GetGlobalIds())[owned]
        rows = np.column_stack([gid.astype(float), m.astype(float)])
np.save(os.path.join(out, "rank%d.npy" % rank), rows)
paint.UpdatePropertyInformation()
stats = {key: paint.GetProperty(name).GetData() for key, name in (
    ("applied", "NumberOfAppliedDabs"), ("rejected", "NumberOfRejectedDabs"),
    ("painted", "NumberOfPaintedValues"), ("ms", "LastPaintMilliseconds"))}
controller.Barrier()
if rank == 0:
    rows = np.concatenate([np.load(os.path.join(out, "rank%d.npy" % r)) for r in range(nranks)])
    rows = rows[np.lexsort(rows.T[::-1])]  # by the first column, then the next ...
    np.save(os.path.join(out, "result.npy"), rows)
    with open(os.path.join(out, "stats.json"), "w") as text:
        json.dump(stats, text)
    print("rank0: %d points from %d ranks, %s" % (len(rows), nranks, json.dumps(stats)))
controller.Barrier()
