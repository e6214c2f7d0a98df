"""The Jacksboro fault zone DEM (Tennessee) as a triangulated surface in metres.

Source: Debian's python-matplotlib-data, ``sample_data/jacksboro_fault_dem.npz``
(344 x 403 int16 elevations in metres, 3 arc-second spacing, lon -84.41..-84.08,
lat 36.45..36.73). Projection: the UTM zone of the DEM centre (16N here, WGS84) with
pyproj (Debian's python3-pyproj), independently of the plugin's C++ reader, which asks
PROJ for the same ``+proj=utm +zone=16 +ellps=WGS84``.

``jacksboro_polydata()`` works in pvpython/pvbatch. (ParaView 5.11's Python-plugin
loader is broken on Debian's Python 3.11 -- it imports inspect.getargspec -- so this is
a module, not a Python plugin.)
"""
import glob
import math
import os

import numpy as np
import pyproj
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


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


def utm_of(path=None):
    """The UTM projection (WGS84) of the zone of the full DEM's centre, as pyproj.Proj."""
    dem = np.load(path or find_dem())
    lon0 = 0.5 * (float(dem["xmin"]) + float(dem["xmax"]))
    lat0 = 0.5 * (float(dem["ymin"]) + float(dem["ymax"]))
    zone = min(60, max(1, int(math.floor((lon0 + 180.0) / 6.0)) + 1))
    return pyproj.Proj("+proj=utm +zone=%d%s +ellps=WGS84" % (zone, " +south" if lat0 < 0 else ""))


def lonlat_to_scene(lon, lat, path=None):
    """Scene metres (easting, northing) of lon/lat degrees (scalars or numpy arrays)."""
    return utm_of(path)(np.asarray(lon, dtype=np.float64), np.asarray(lat, dtype=np.float64))


def jacksboro_polydata(path=None, stride=1):
    """The DEM as vtkPolyData triangles, points in double precision metres."""
    path = path or find_dem()
    dem = np.load(path)
    z = dem["elevation"][::stride, ::stride].astype(np.float64)
    rows, cols = z.shape
    lon = np.linspace(float(dem["xmin"]), float(dem["xmax"]), dem["elevation"].shape[1])[::stride]
    lat = np.linspace(float(dem["ymin"]), float(dem["ymax"]), dem["elevation"].shape[0])[::stride]
    lons, lats = np.meshgrid(lon, lat)
    x, y = lonlat_to_scene(lons.ravel(), lats.ravel(), path)
    xyz = np.column_stack([x, y, z.ravel()])

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


def write_geotiff(out_path, path=None, nodata_mask=None):
    """Writes the DEM as a geographic GeoTIFF (EPSG:4326, int16) with GDAL (Debian's
    python3-gdal), pixel centres at the samples the .npz reader uses (numpy.linspace of
    xmin..xmax and ymin..ymax, northern row first), so DEMSurface of the file is the
    Jacksboro Fault DEM source's surface. Pixels where ``nodata_mask`` is true get the
    band's no-data value -32768."""
    from osgeo import gdal, osr

    path = path or find_dem()
    dem = np.load(path)
    z = dem["elevation"].astype(np.int16)
    rows, cols = z.shape
    dx = (float(dem["xmax"]) - float(dem["xmin"])) / (cols - 1)
    dy = (float(dem["ymax"]) - float(dem["ymin"])) / (rows - 1)
    out = gdal.GetDriverByName("GTiff").Create(out_path, cols, rows, 1, gdal.GDT_Int16)
    out.SetGeoTransform([float(dem["xmin"]) - 0.5 * dx, dx, 0.0,
                         float(dem["ymin"]) - 0.5 * dy, 0.0, dy])
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(4326)
    out.SetProjection(srs.ExportToWkt())
    band = out.GetRasterBand(1)
    if nodata_mask is not None:
        z = np.where(nodata_mask, np.int16(-32768), z)
        band.SetNoDataValue(-32768)
    band.WriteArray(z)
    out.FlushCache()
    return out_path
