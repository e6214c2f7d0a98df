"""The plugin's Jacksboro Fault DEM source (C++ vtkNpzDEMReader: libzip + .npy + PROJ)
against the demo's independent numpy/pyproj converter (Testing/Demo/jacksboro.py): the same
surface point for point and triangle for triangle; and clear errors on bad archives."""
import os
import sys
import zipfile

from geoshaping_testing import check, check_same_dem_surface, load
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Demo"))
import jacksboro  # noqa: E402

load(ns=globals())
path = jacksboro.find_dem()
for stride in (1, 3):
    dem = JacksboroFaultDEM(Stride=stride)  # noqa: F405 (defined by the plugin)
    check(dem.FileName == path or os.path.samefile(dem.FileName, path),
          "the source's default file is matplotlib's DEM")
    ours = sm.Fetch(dem)
    ref = jacksboro.jacksboro_polydata(path, stride=stride)
    check_same_dem_surface(ours, ref, "stride %d" % stride, "numpy converter")
    q = vtk_to_numpy(ref.GetPoints().GetData())
    if stride == 1:
        check(len(q) == 344 * 403, "the full DEM has 344 x 403 vertices")
        bounds = ours.GetBounds()
        centre = (0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]))
        check(abs(centre[0] - 745000) < 2000 and abs(centre[1] - 4055000) < 8000,
              "UTM zone 16N puts the DEM centre near 745,000 E, 4,055,000 N (%.0f, %.0f)"
              % centre)
        about = ours.GetFieldData().GetAbstractArray("Projection").GetValue(0)
        check(about.startswith("UTM zone 16N (WGS84, PROJ "), "Projection says " + about)
        span = (bounds[1] - bounds[0], bounds[3] - bounds[2])
        # The 30 x 31.9 km tile, turned by the meridian convergence (about 1.6 degrees
        # 2.8 degrees east of zone 16's central meridian): a box of about 31 x 32.7 km.
        check(30000 < span[0] < 32000 and 31500 < span[1] < 33500,
              "a box of about 31 km x 32.7 km (%.0f x %.0f m)" % span)
    Delete(dem)

# Bad archives: an error naming what is wrong, and no points.
tmp = os.environ["GEOSHAPING_TEST_TMP"]
cases = {}
cases["empty.npz"] = b""
cases["junk.npz"] = bytes(range(256)) * 4
with zipfile.ZipFile(os.path.join(tmp, "noelev.npz"), "w") as z:
    z.writestr("xmin.npy", open(path, "rb").read()[:0])
with zipfile.ZipFile(path) as src, zipfile.ZipFile(os.path.join(tmp, "truncated.npz"), "w",
                                                   zipfile.ZIP_DEFLATED) as z:
    for name in src.namelist():
        data = src.read(name)
        z.writestr(name, data[: len(data) // 2] if name == "elevation.npy" else data)
for name, data in cases.items():
    with open(os.path.join(tmp, name), "wb") as f:
        f.write(data)
for name in ["empty.npz", "junk.npz", "noelev.npz", "truncated.npz", "absent.npz"]:
    reader = NumPyDEMReader(FileName=os.path.join(tmp, name))  # noqa: F405
    out = sm.Fetch(reader)
    check(out.GetNumberOfPoints() == 0, "%s: no points" % name)
    Delete(reader)
print("all DEM checks passed")
