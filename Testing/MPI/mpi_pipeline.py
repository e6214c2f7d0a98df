"""What the MPI test scripts (mpi_*.py) share: the undistributed data's point ids as
GlobalIds, then ParaView's own distribution (RedistributeDataSet + one ghost level), as a
user's pipeline on an MPI server gives it to the GeoShaping filters."""
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
