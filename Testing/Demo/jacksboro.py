"""The Jacksboro fault zone DEM (Tennessee) as a triangulated surface in metres.

Source: Debian's python-matplotlib-data, ``sample_data/jacksboro_fault_dem.npz``
(344 x 403 int16 elevations in metres, 3 arc-second spacing, lon -84.41..-84.08,
lat 36.45..36.73). Projection: a local equirectangular projection about the DEM
centre (x east = R cos(lat0) dlon, y north = R dlat, R = 6,371,008.8 m), offset so the
centre lands at the UTM-sized position (745,000 m E, 4,055,000 m N), close to where UTM
zone 16N puts it. Good to about 0.1 % in distances over the 30 km tile: enough to
shape the surface, not a survey-grade UTM conversion.

``jacksboro_polydata()`` works in pvpython/pvbatch. (ParaView 5.11's Python-plugin
loader is broken on Debian's Python 3.11 -- it imports inspect.getargspec -- so this is
a module, not a Python plugin.)
"""
import glob
import math
import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

EARTH_RADIUS = 6371008.8
CENTRE_EN = (745000.0, 4055000.0)


def find_dem():
    """Path of jacksboro_fault_dem.npz from Debian's python-matplotlib-data."""
    candidates = glob.glob("/usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz")
    try:
        import matplotlib
        candidates.append(os.path.join(matplotlib.get_data_path(), "sample_data",
                                       "jacksboro_fault_dem.npz"))
    except ImportError:
        pass
    for path in candidates:
        if os.path.exists(path):
            return path
    raise FileNotFoundError("jacksboro_fault_dem.npz not found: install python-matplotlib-data")


def lonlat_to_scene(lon, lat, path=None):
    """Scene metres (x east, y north) of lon/lat degrees (scalars or numpy arrays), in the
    projection about the centre of the full DEM (whatever stride the surface uses)."""
    dem = np.load(path or find_dem())
    lon0 = 0.5 * (float(dem["xmin"]) + float(dem["xmax"]))
    lat0 = 0.5 * (float(dem["ymin"]) + float(dem["ymax"]))
    x = CENTRE_EN[0] + np.radians(np.asarray(lon) - lon0) * EARTH_RADIUS * math.cos(math.radians(lat0))
    y = CENTRE_EN[1] + np.radians(np.asarray(lat) - lat0) * EARTH_RADIUS
    return x, y


def jacksboro_polydata(path=None, stride=1):
    """The DEM as vtkPolyData triangles, points in double precision metres."""
    path = path or find_dem()
    dem = np.load(path)
    z = dem["elevation"][::stride, ::stride].astype(np.float64)
    rows, cols = z.shape
    lon = np.linspace(float(dem["xmin"]), float(dem["xmax"]), dem["elevation"].shape[1])[::stride]
    lat = np.linspace(float(dem["ymin"]), float(dem["ymax"]), dem["elevation"].shape[0])[::stride]
    x, y = lonlat_to_scene(lon, lat, path)
    xx, yy = np.meshgrid(x, y)
    xyz = np.column_stack([xx.ravel(), yy.ravel(), z.ravel()])

    ids = np.arange(rows * cols).reshape(rows, cols)
    a, b = ids[:-1, :-1].ravel(), ids[:-1, 1:].ravel()
    c, d = ids[1:, 1:].ravel(), ids[1:, :-1].ravel()
    tris = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    offsets = np.arange(0, 3 * len(tris) + 1, 3, dtype=np.int64)

    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(tris.ravel().astype(np.int64), deep=True))
    out = vtkPolyData()
    out.SetPoints(points)
    out.SetPolys(cells)
    elevation = numpy_to_vtk(z.ravel().copy(), deep=True)
    elevation.SetName("Elevation")
    out.GetPointData().AddArray(elevation)
    return out
