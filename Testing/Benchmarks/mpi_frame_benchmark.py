"""Time and bytes per frame of ChainMailDeformation on ParaView's distributed engine
(docs/mpi.md records a run). Not a test: it asserts nothing
about time.

  mpiexec --oversubscribe -n N pvbatch --sym mpi_frame_benchmark.py [--sides 1000,4000]
      [--frames 15] [--small 2.0] [--large 60.0] [--grasp-row 0.5]

Each rank builds its piece of a flat S x S triangle grid (spacing 1, uniform
malleability 0.7, FIFO Priority) directly: the rows it owns and one ghost row on each
side, point GlobalIds j * S + i, vtkGhostType marking the ghost rows (what
RedistributeDataSet + GhostCellsGenerator give, without their setup cost at 16M). All
grids stay in memory, so the frames run interleaved in one run: for each frame
(the grasp at the centre, the pull varied by 1e-3 per frame so the filter runs again),
every grid x grasp in turn. A frame's time is the slowest rank's wall time of
UpdatePipeline (the filter's whole update: checks, supersteps, output); `core` is the
slowest rank's deformation alone (LastDeformationMilliseconds). Bytes are the moved
frontier sent between ranks (NumberOfBytesExchanged, all ranks' sum). Medians over the
frames; the first update of each grid (setup: adjacency, ghost map) is reported apart.
"""
import argparse
import os
import sys
import time

import numpy as np
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints, vtkTypeInt32Array
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataSetAttributes, vtkPolyData
from vtkmodules.vtkParallelCore import vtkMultiProcessController

parser = argparse.ArgumentParser()
parser.add_argument("--sides", default="1000,4000")
parser.add_argument("--frames", type=int, default=15)
parser.add_argument("--small", type=float, default=2.0)
parser.add_argument("--large", type=float, default=60.0)
parser.add_argument("--grasp-row", type=float, default=0.5,
                    help="the grasp's row as a fraction of the side (0.5: the centre, on a rank "
                         "border for 2 and 4 ranks)")
args = parser.parse_args([a for a in sys.argv[1:] if a.startswith("--") or not a.endswith(".py")])

controller = vtkMultiProcessController.GetGlobalController()
rank, nranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())


def piece(side):
    """This rank's rows and one ghost row each side, as vtkPolyData."""
    r0, r1 = rank * side // nranks, (rank + 1) * side // nranks
    lo, hi = max(r0 - 1, 0), min(r1 + 1, side)
    rows = np.arange(lo, hi)
    i, j = np.meshgrid(np.arange(side, dtype=np.int64), rows)
    xyz = np.column_stack([i.ravel(), j.ravel(), np.zeros(i.size)]).astype(np.float32)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=1))
    # Two triangles per quad between consecutive held rows (local point ids).
    q = (np.arange(hi - lo - 1)[:, None] * side + np.arange(side - 1)[None, :]).ravel()
    tri = np.empty((2 * q.size, 3), dtype=np.int32)
    tri[0::2] = np.column_stack([q, q + 1, q + side + 1])
    tri[1::2] = np.column_stack([q, q + side + 1, q + side])
    offsets = numpy_to_vtk(np.arange(0, 3 * len(tri) + 1, 3, dtype=np.int32), deep=1,
                           array_type=vtkTypeInt32Array().GetDataType())
    conn = numpy_to_vtk(tri.ravel(), deep=1, array_type=vtkTypeInt32Array().GetDataType())
    cells = vtkCellArray()
    cells.SetData(offsets, conn)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(cells)
    gid = (rows[:, None] * side + np.arange(side)[None, :]).ravel().astype(np.int64)
    ids = numpy_to_vtk(gid, deep=1, array_type=16)  # VTK_ID_TYPE
    ids.SetName("GlobalIds")
    poly.GetPointData().SetGlobalIds(ids)
    owned_row = (rows >= r0) & (rows < r1)
    ghost = np.repeat(np.where(owned_row, 0, vtkDataSetAttributes.DUPLICATEPOINT), side)
    ghost_points = numpy_to_vtk(ghost.astype(np.uint8), deep=1)
    ghost_points.SetName("vtkGhostType")
    poly.GetPointData().AddArray(ghost_points)
    # A cell belongs to the owner of its lower row.
    cell_row = np.repeat(rows[:-1], 2 * (side - 1))
    cghost = np.where((cell_row >= r0) & (cell_row < r1), 0, vtkDataSetAttributes.DUPLICATECELL)
    ghost_cells = numpy_to_vtk(cghost.astype(np.uint8), deep=1)
    ghost_cells.SetName("vtkGhostType")
    poly.GetCellData().AddArray(ghost_cells)
    return poly


def slowest(value):
    out = vtkDoubleArray()
    out.SetNumberOfTuples(1)
    mine = vtkDoubleArray()
    mine.SetNumberOfTuples(1)
    mine.SetValue(0, value)
    controller.AllReduce(mine, out, 0)  # vtkCommunicator::MAX_OP
    return out.GetValue(0)


def info(proxy, name):
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty(name).GetData()


grids = []
for side in [int(s) for s in args.sides.split(",")]:
    producer = PVTrivialProducer()  # noqa: F405
    producer.GetClientSideObject().SetOutput(piece(side))
    chain = ChainMailDeformation(Input=producer)  # noqa: F405
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7
    chain.CandidateQueue = "FIFO Priority"
    chain.GraspPointId = int(args.grasp_row * side) * side + side // 2
    controller.Barrier()
    start = time.perf_counter()
    chain.Displacement = [0.0, 0.0, 0.0]
    chain.UpdatePipeline()
    setup = slowest(time.perf_counter() - start)
    grids.append((side, chain, setup))

samples = {}
for frame in range(args.frames):
    for side, chain, _ in grids:
        for name, pull in (("small", args.small), ("large", args.large)):
            chain.Displacement = [0.0, 0.0, pull * (1.0 + 1e-3 * frame)]
            controller.Barrier()
            start = time.perf_counter()
            chain.UpdatePipeline()
            wall = slowest(time.perf_counter() - start)
            core = slowest(info(chain, "LastDeformationMilliseconds")) * 1e-3
            samples.setdefault((side, name), []).append(
                (wall, core, info(chain, "NumberOfDisplacedPoints"),
                 info(chain, "NumberOfBytesExchanged"), info(chain, "NumberOfSupersteps"),
                 info(chain, "NumberOfRounds")))

if rank == 0:
    print("ranks %d, %d frames each, medians" % (nranks, args.frames))
    for side, _, setup in grids:
        print("grid %d x %d = %d vertices: first update (setup) %.2f s" % (side, side, side * side, setup))
    print("%10s %6s %10s %10s %10s %12s %10s %10s %7s" % (
        "vertices", "grasp", "displaced", "frame ms", "core ms", "bytes", "bytes/disp", "supersteps",
        "rounds"))
    for (side, name), rows in samples.items():
        r = np.median(np.array(rows, dtype=float), axis=0)
        print("%10d %6s %10d %10.2f %10.2f %12d %10.2f %10d %7d" % (
            side * side, name, r[2], 1e3 * r[0], 1e3 * r[1], r[3], r[3] / max(r[2], 1), r[4], r[5]))
    for name in ("small", "large"):
        keyed = [(side, np.median([s[0] for s in samples[(side, name)]])) for side, _, _ in grids]
        if len(keyed) > 1:
            print("%s grasp: frame time %d / %d vertices = %.2f" % (
                name, keyed[-1][0] ** 2, keyed[0][0] ** 2, keyed[-1][1] / keyed[0][1]))
controller.Barrier()
