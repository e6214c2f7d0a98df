"""What the plain pipeline's setup costs (docs/mpi.md, "Setup of the plain pipeline").
Not a test: it asserts nothing about time; run it under farm-bench, which times the
whole process, with one argument changed between the two commands compared.

  mpiexec -n N pvbatch --sym mpi_setup_benchmark.py FILE MODE [--frames 10]

FILE is a .vtp surface (write one with --write FILE --side S: a flat S x S triangle
grid, uniform malleability 0.7, as polydata, optionally --ids for point GlobalIds).
MODE:
  plain    XMLPolyDataReader -> RedistributeDataSet -> ChainMailDeformation (the filter
           makes the ghost ring: numbering by coordinates + vtkGhostCellsGenerator)
  ghosts   the same with GhostCellsGenerator added by hand before the filter (VTK's
           generator alone, matching the pieces by coordinates)
  read     XMLPolyDataReader -> RedistributeDataSet only (no filter)
  reader   XMLPolyDataReader -> ChainMailDeformation (one process: the numbering by
           coordinates is the setup's only new part)
Each mode updates once (setup) then runs --frames frames (the pull varied by 1e-3).
Prints the first update's and the median frame's wall time on rank 0 (one run: a
breakdown, not a comparison)."""
import argparse
import time

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController
import os

parser = argparse.ArgumentParser()
parser.add_argument("file")
parser.add_argument("mode", nargs="?", default="plain")
parser.add_argument("--frames", type=int, default=10)
parser.add_argument("--write", action="store_true")
parser.add_argument("--side", type=int, default=500)
parser.add_argument("--ids", action="store_true")
args = parser.parse_args()

if args.write:
    s = args.side
    j, i = np.mgrid[0:s, 0:s]
    xyz = np.column_stack([i.ravel(), j.ravel(), np.zeros(s * s)]).astype(float)
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(xyz, deep=1))
    a = (j[:-1, :-1] * s + i[:-1, :-1]).ravel()
    tri = np.concatenate([np.column_stack([a, a + 1, a + s + 1]), np.column_stack([a, a + s + 1, a + s])])
    cells = vtkCellArray()
    for t in tri:
        cells.InsertNextCell(3, [int(t[0]), int(t[1]), int(t[2])])
    surface = vtkPolyData()
    surface.SetPoints(pts)
    surface.SetPolys(cells)
    if args.ids:
        gids = numpy_to_vtk(np.arange(s * s, dtype=np.int64), deep=1, array_type=12)
        gids.SetName("GlobalIds")
        surface.GetPointData().SetGlobalIds(gids)
    w = vtkXMLPolyDataWriter()
    w.SetFileName(args.file)
    w.SetInputData(surface)
    w.Write()
    raise SystemExit(0)

controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
upstream = XMLPolyDataReader(FileName=[args.file])  # noqa: F405
if args.mode != "reader":
    upstream = RedistributeDataSet(Input=upstream)  # noqa: F405
if args.mode == "ghosts":
    upstream = GhostCellsGenerator(Input=upstream)  # noqa: F405
if args.mode == "read":
    upstream.UpdatePipeline()
    raise SystemExit(0)
chain = ChainMailDeformation(Input=upstream)  # noqa: F405
chain.MalleabilityArray = ["POINTS", "None"]
chain.DefaultMalleability = 0.7
chain.CandidateQueue = "FIFO Priority"
chain.GraspMode = "Nearest To Position"
chain.GraspPosition = [0.5 * args.side, 0.5 * args.side, 0.0]
times = []
for f in range(args.frames + 1):
    chain.Displacement = [0.0, 0.0, 4.0 + 1e-3 * f]
    controller.Barrier()
    start = time.perf_counter()
    chain.UpdatePipeline()
    controller.Barrier()
    times.append(time.perf_counter() - start)
chain.UpdatePropertyInformation()
if rank == 0:
    print("first update %.3f s, frame median %.1f ms, %d displaced" % (
        times[0], 1e3 * float(np.median(times[1:])), chain.GetProperty("NumberOfDisplacedPoints").GetData()))
