"""Error figures (docs/design.md, Error against run time) computed from VTK data with numpy (demo only;
the core's error_metrics.h is the reference implementation)."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator


def edges(polydata):
    """Unique undirected edges of the triangles of `polydata` (n x 2)."""
    conn = vtk_to_numpy(polydata.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    e = np.concatenate([conn[:, [0, 1]], conn[:, [1, 2]], conn[:, [2, 0]]])
    e.sort(axis=1)
    return np.unique(e, axis=0)


def rigid_error(rest, deformed, e, malleability):
    """E_rigid: max change of a rigid-rigid edge vector / mean edge length."""
    mean_edge = np.linalg.norm(rest[e[:, 0]] - rest[e[:, 1]], axis=1).mean()
    rigid = (malleability[e[:, 0]] == 0) & (malleability[e[:, 1]] == 0)
    if not rigid.any():
        return 0.0
    r = e[rigid]
    change = (deformed[r[:, 0]] - deformed[r[:, 1]]) - (rest[r[:, 0]] - rest[r[:, 1]])
    return float(np.linalg.norm(change, axis=1).max() / mean_edge)


def temporal_error(frames, drags):
    """E_temporal: max over consecutive frames of |dX|_inf / |d drag|."""
    worst = 0.0
    for a, b, da, db in zip(frames, frames[1:], drags, drags[1:]):
        step = np.linalg.norm(np.asarray(db) - np.asarray(da))
        if step > 0:
            worst = max(worst, float(np.linalg.norm(b - a, axis=1).max() / step))
    return worst


class SurfaceHeight:
    """z of the nearest surface vertex to (x, y) (for placing dabs given in map coordinates)."""

    def __init__(self, polydata):
        self.points = vtk_to_numpy(polydata.GetPoints().GetData())
        flat = polydata.NewInstance()
        flat.DeepCopy(polydata)
        self.locator = vtkStaticPointLocator()
        self.locator.SetDataSet(flat)
        self.locator.BuildLocator()
        self.flat = flat

    def height(self, x, y):
        # Search in 3D from a point at the surface's mean height: the DEM is a height
        # field, and its relief (< 1 km) is small against the dab spacing in the tile.
        z0 = float(self.points[:, 2].mean())
        return float(self.points[self.locator.FindClosestPoint(x, y, z0), 2])
