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


def distributed(source):
    """(ids, ghosts): `source` with GlobalIds = its point ids (on rank 0, the whole data),
    and that redistributed over the ranks with one ghost level."""
    ids = ProgrammableFilter(Input=source)
    ids.Script = POINT_INDEX_IDS
    return ids, GhostCellsGenerator(Input=RedistributeDataSet(Input=ids))
