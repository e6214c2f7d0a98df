"""DEMSurface on GeoTIFFs written at test time by GDAL's own tools (gdal_translate, Debian's
gdal-bin; osgeo.gdal, python3-gdal), read by ParaView's GDALRasterReader: the Jacksboro grid
as a geographic GeoTIFF gives the .npz source's surface; a projected raster keeps its
coordinates (feet become metres); no-data pixels are holes, counted independently; a raster
without CRS, with two bands, a corrupt file and a mesh get an error and an empty output."""
import os
import subprocess
import sys

import numpy as np
from geoshaping_testing import check, check_same_dem_surface, load
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Demo"))
import jacksboro  # noqa: E402

load(ns=globals())
tmp = os.environ["GEOSHAPING_TEST_TMP"]


def surface(tif, stride=1):
    dem = DEMSurface(Input=GDALRasterReader(FileName=tif), Stride=stride)  # noqa: F405
    return sm.Fetch(dem)


def field(data, name):
    array = data.GetFieldData().GetAbstractArray(name)
    return array.GetVariantValue(0).ToString() if array else None


def ascii_grid(name, z, xll, yll, cell, nodata=None):
    """An Esri ASCII grid (rows north first): the text GDAL's AAIGrid driver reads."""
    path = os.path.join(tmp, name)
    with open(path, "w") as f:
        f.write("ncols %d\nnrows %d\nxllcorner %.17g\nyllcorner %.17g\ncellsize %.17g\n"
                % (z.shape[1], z.shape[0], xll, yll, cell))
        if nodata is not None:
            f.write("NODATA_value %g\n" % nodata)
        for row in z:
            f.write(" ".join("%.17g" % v for v in row) + "\n")
    return path


def translate(src, dst, *options):
    subprocess.run(["gdal_translate", "-q", *options, src, os.path.join(tmp, dst)], check=True)
    return os.path.join(tmp, dst)


# 1. The Jacksboro grid as a geographic GeoTIFF = the .npz path, point for point.
tif = jacksboro.write_geotiff(os.path.join(tmp, "jacksboro_4326.tif"))
for stride in (1, 3):
    ours = surface(tif, stride)
    npz = sm.Fetch(JacksboroFaultDEM(Stride=stride))  # noqa: F405
    check_same_dem_surface(ours, npz, "stride %d" % stride, ".npz source")
    about = field(ours, "Projection")
    check(about.startswith("UTM zone 16N (WGS84, PROJ ") and
          "reprojected from longitude/latitude" in about, "Projection says " + about)
    check("+proj=longlat" in field(ours, "SourceCRS"), "SourceCRS is the raster's")

# 2. A projected raster (UTM 16N, made by gdal_translate from an ASCII grid) keeps its
# coordinates: pixel centres at xll + (c + 1/2) 30, yll + (rows - r - 1/2) 30.
rows, cols, cell, xll, yll = 30, 40, 30.0, 745000.0, 4040000.0
r, c = np.mgrid[0:rows, 0:cols]
z = 300.0 + 2.0 * c + 0.5 * r * r
expected = np.column_stack([(xll + (c + 0.5) * cell).ravel(),
                            (yll + (rows - r - 0.5) * cell).ravel(), z.ravel()])
utm = translate(ascii_grid("utm.asc", z, xll, yll, cell), "utm_32616.tif",
                "-a_srs", "EPSG:32616", "-ot", "Float64")
ours = surface(utm)
p = vtk_to_numpy(ours.GetPoints().GetData())
check(p.shape == expected.shape and float(np.abs(p - expected).max()) < 1e-6,
      "UTM raster: every pixel centre at its own easting and northing, z its value")
check(field(ours, "Projection").startswith("the raster's projected CRS, kept (metre)"),
      "Projection says the CRS was kept: " + field(ours, "Projection"))
# The same grid in US survey feet (Tennessee State Plane, EPSG:2274): converted to metres.
ft = translate(ascii_grid("ft.asc", z, 1.8e6, 5.0e5, 100.0), "ft_2274.tif",
               "-a_srs", "EPSG:2274", "-ot", "Float64")
ours = surface(ft)
p = vtk_to_numpy(ours.GetPoints().GetData())
foot = 1200.0 / 3937.0
xy_ft = np.column_stack([(1.8e6 + (c + 0.5) * 100.0).ravel(),
                         (5.0e5 + (rows - r - 0.5) * 100.0).ravel()])
check(float(np.abs(p[:, :2] - xy_ft * foot).max()) < 1e-6,
      "US-survey-foot raster: x and y times 1200/3937 m")
check("US survey foot" in field(ours, "Projection"), "Projection says " + field(ours, "Projection"))

# 3. No data: pixels equal to the band's no-data value (-9999) are holes; triangles
# counted here from the mask, independently of the filter.
rng = np.random.default_rng(28)
mask = rng.random((rows, cols)) < 0.1
mask[10:14, 20:27] = True
holed = translate(ascii_grid("holes.asc", np.where(mask, -9999.0, z), xll, yll, cell, -9999),
                  "holes_32616.tif", "-a_srs", "EPSG:32616", "-ot", "Float32")


def triangles_without(missing):
    ok = ~missing
    first = ok[:-1, :-1] & ok[:-1, 1:] & ok[1:, 1:]
    second = ok[:-1, :-1] & ok[1:, 1:] & ok[1:, :-1]
    return int(first.sum() + second.sum())


for stride in (1, 2):
    m = mask[::stride, ::stride]
    ours = surface(holed, stride)
    e = vtk_to_numpy(ours.GetPointData().GetArray("Elevation"))
    check(ours.GetNumberOfPoints() == int((~m).sum()),
          "stride %d: %d of %d samples kept" % (stride, (~m).sum(), m.size))
    check(ours.GetNumberOfCells() == triangles_without(m),
          "stride %d: %d triangles, %d left out around the holes"
          % (stride, triangles_without(m), 2 * (m.shape[0] - 1) * (m.shape[1] - 1)
             - triangles_without(m)))
    check(np.array_equal(e, z[::stride, ::stride][~m]), "stride %d: no spike, no NaN: "
          "the kept elevations are the valid pixels" % stride)
    check(int(field(ours, "NoDataSamples")) == int(m.sum()), "NoDataSamples = %d" % m.sum())
# NaN pixels (a float raster without a no-data value) are holes too.
nan_tif = translate(ascii_grid("nan.asc", np.where(mask, np.nan, z), xll, yll, cell),
                    "nan_32616.tif", "-a_srs", "EPSG:32616", "-ot", "Float32")
ours = surface(nan_tif)
check(ours.GetNumberOfCells() == triangles_without(mask), "NaN pixels are holes")

# 4. Bad input: an error naming the problem and an empty output.
bad = {
    "no CRS": (translate(ascii_grid("nocrs.asc", z, xll, yll, cell), "nocrs.tif"), "no CRS"),
    "two bands": (translate(utm, "two_bands.tif", "-b", "1", "-b", "1"), "2 bands"),
    "corrupt": (os.path.join(tmp, "corrupt.tif"), "the raster is empty"),
}
# A TIFF signature, then junk where the directory should be: GDAL refuses it, the reader
# fails and leaves an empty image. (A GeoTIFF cut after its directory makes Debian's
# vtkGDALRasterReader abort on an assert before DEMSurface runs: docs/readers.md.)
with open(bad["corrupt"][0], "wb") as g:
    g.write(b"II*\x00" + bytes(range(7, 256)) * 4)


def errors_of(make):
    """The output of make() and what it wrote to the output window (where pvpython's
    print goes too: the window is restored before anything is checked)."""
    shown = vtkOutputWindow.GetInstance()
    window = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(window)
    try:
        out = make()
    finally:
        vtkOutputWindow.SetInstance(shown)
    return out, window.GetOutput()


for name, (path, message) in bad.items():
    out, text = errors_of(lambda: surface(path))
    check(out.GetNumberOfPoints() == 0 and out.GetNumberOfCells() == 0, name + ": empty output")
    check("DEMSurface: " in text and message in text, "%s: the error says '%s'" % (name, message))
out, text = errors_of(lambda: sm.Fetch(DEMSurface(Input=Sphere())))  # noqa: F405
check(out.GetNumberOfPoints() == 0 and "not vtkPolyData" in text,
      "a mesh: 'takes an elevation raster ..., not vtkPolyData'")
print("all DEM raster checks passed")
