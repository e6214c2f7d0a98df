"""What the MPI test scripts (mpi_*.py) share: the undistributed data's point ids as
GlobalIds, then ParaView's own distribution (RedistributeDataSet + one ghost level), as a
user's pipeline on an MPI server gives it to the GeoShaping filters."""
import os

from paraview.simple import GhostCellsGenerator, ProgrammableFilter, RedistributeDataSet

# A ProgrammableFilter script: point GlobalIds = the point ids of its input.
POINT_INDEX_IDS = """
from vtkmodules.vtkCommonCore import vtkIdTypeArray
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
gids = vtkIdTypeArray()
gids.SetName("GlobalIds")
gids.SetNumberOfTuples(out.GetNumberOfPoints())
for i in range(out.GetNumberOfPoints()):
    gids.SetValue(i, i)
out.GetPointData().SetGlobalIds(gids)
"""

# A ProgrammableFilter script: point GlobalIds = the rank of each point's coordinates (x,
# then y, then z) among the distinct coordinates, computed by numpy: independently of
# the filters' own numbering of points without GlobalIds (coordinate_ids.h), which it
# must equal.
COORDINATE_RANKS = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
if out.GetNumberOfPoints():
    xyz = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    order = np.lexsort((xyz[:, 2], xyz[:, 1], xyz[:, 0]))
    s = xyz[order]
    new = np.ones(len(s), dtype=bool)
    new[1:] = np.any(s[1:] != s[:-1], axis=1)
    rank = np.empty(len(s), dtype=np.int64)
    rank[order] = np.cumsum(new) - 1
    gids = numpy_to_vtkIdTypeArray(rank, deep=1)
    gids.SetName("GlobalIds")
    out.GetPointData().SetGlobalIds(gids)
"""


def distributed(source):
    """(ids, ghosts): `source` with GlobalIds = its point ids (on rank 0, the whole data),
    and that redistributed over the ranks with one ghost level."""
    ids = ProgrammableFilter(Input=source)
    ids.Script = POINT_INDEX_IDS
    return ids, GhostCellsGenerator(Input=RedistributeDataSet(Input=ids))


def owned_rows(output, rest, nranks, extra=()):
    """Rows (global id, x, y, z, rest x, y, z, then the point arrays of `rest` named in
    `extra`) of the points of `output` this rank owns (not flagged DUPLICATEPOINT in
    vtkGhostType; all of them on one rank); `rest` is the filter's input, same points."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy

    n = output.GetNumberOfPoints()
    if not n:
        return np.zeros((0, 7 + len(extra)))
    ghost = vtk_to_numpy(output.GetPointData().GetArray("vtkGhostType")) if nranks > 1 else np.zeros(n)
    owned = (ghost.astype(int) & 1) == 0  # vtkDataSetAttributes::DUPLICATEPOINT
    columns = [vtk_to_numpy(output.GetPointData().GetGlobalIds())[owned].astype(float),
               vtk_to_numpy(output.GetPoints().GetData()).astype(float)[owned],
               vtk_to_numpy(rest.GetPoints().GetData()).astype(float)[owned]]
    columns += [vtk_to_numpy(rest.GetPointData().GetArray(name)).astype(float)[owned]
                for name in extra]
    return np.column_stack(columns)


def plain_pipeline(case, path, simple):
    """(upstream, chain): the pipeline of mpi_plain.py (CASE: reader, redistribute, d3,
    ids, paint, unsplitpaint) on the file `path` (.vtp, .vtu, .ts, or a GeoTIFF into
    DEMSurface), its parameters from the environment (PLAIN_GRASP, PLAIN_PULL,
    PLAIN_DABS: mpi_driver.plain_parameters; PLAIN_QUEUE and PLAIN_FRAME, default FIFO
    Priority and Axes). `simple`: the namespace holding
    paraview.simple and the plugin's proxies (the caller's globals() after LoadPlugin)."""
    def floats(name):
        return [float(x) for x in os.environ[name].split()]

    if path.endswith(".ts"):
        reader = simple["GOCADTSurfReader"](FileName=path)
    elif path.endswith(".tif"):  # the raster on rank 0 alone: an empty one on the others
        reader = simple["DEMSurface"](Input=simple["GDALRasterReader"](FileName=path))
    else:
        reader = simple["XMLPolyDataReader" if path.endswith(".vtp") else "XMLUnstructuredGridReader"](
            FileName=[path])
    upstream = reader
    if case == "ids":  # point GlobalIds (the file's point ids), then distributed
        upstream = ProgrammableFilter(Input=reader)
        upstream.Script = POINT_INDEX_IDS
    if case in ("redistribute", "ids", "paint"):
        upstream = RedistributeDataSet(Input=upstream)
    elif case == "d3":
        upstream = simple["D3"](Input=upstream)
    if case in ("paint", "unsplitpaint"):  # unsplit: the ranks but the reading one have nothing
        upstream = simple["MalleabilityPaint"](Input=upstream)
        upstream.InitialMalleability = 0.6
        upstream.Falloff = "Smooth"
        upstream.DistanceMode = "Geodesic"
        upstream.Dabs = floats("PLAIN_DABS")
    chain = simple["ChainMailDeformation"](Input=upstream)
    chain.CandidateQueue = os.environ.get("PLAIN_QUEUE", "FIFO Priority")
    chain.ValidRegionFrame = os.environ.get("PLAIN_FRAME", "Axes")
    chain.OutputPointsPrecision = "Double"
    chain.GraspMode = "Nearest To Position"
    chain.GraspPosition = floats("PLAIN_GRASP")
    chain.Displacement = floats("PLAIN_PULL")
    return upstream, chain
