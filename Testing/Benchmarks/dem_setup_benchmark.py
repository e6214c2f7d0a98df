"""What a big DEM costs before the first pull (docs/benchmarks.md, "The first grasp on a
big DEM"). Not a test: it asserts nothing about time. Each stage is updated on its own
and timed; the peak resident memory after it is the process's (getrusage), so a stage's
figure includes everything before it.

  pvpython dem_setup_benchmark.py FILE.tif [--side 4000] [--write] [--paint]
           [--stages reader,dem,chain,grasp]

--write makes FILE.tif first (osgeo.gdal, Debian's python3-gdal): a side x side float32
GeoTIFF in UTM 16N (EPSG:32616), 10 m pixels, a smooth synthetic relief (a hill, ridges
and a valley, some 400 m of relief), so DEMSurface keeps its coordinates; with
--geographic the same relief in longitude/latitude (EPSG:4326, 1/3600 degree pixels at
the Jacksboro DEM's corner), which DEMSurface reprojects to UTM with PROJ.
Stages, each needing the ones before it:
  reader  GDALRasterReader (ParaView's) reads the file
  dem     DEMSurface makes the triangulated surface (2 (side - 1)^2 triangles)
  paint   MalleabilityPaint with three dabs (only with --paint)
  chain   ChainMailDeformation's first update, no grasp (GraspPointId -1): its setup
  grasp   the first frame, a 30 m pull at the surface's centre (Nearest To Position)
  frame   a second frame (the pull 1 mm longer), what every later frame costs
Prints one line per stage: wall and CPU seconds (user + system: on a busy machine the
wall time is the other processes' too), peak RSS in MB and in bytes per surface vertex."""
import argparse
import os
import resource
import time

import numpy as np
from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("file")
parser.add_argument("--side", type=int, default=4000)
parser.add_argument("--write", action="store_true")
parser.add_argument("--paint", action="store_true")
parser.add_argument("--geographic", action="store_true")
parser.add_argument("--stages", default="reader,dem,paint,chain,grasp,frame")
args = parser.parse_args()

SPACING, ORIGIN, EPSG = (1.0 / 3600.0, (-84.41, 36.45), 4326) if args.geographic else (
    10.0, (500000.0, 4000000.0), 32616)

if args.write:
    from osgeo import gdal, osr

    s = args.side
    u = np.linspace(0.0, 1.0, s)
    x, y = np.meshgrid(u, u)
    z = (300.0 + 120.0 * np.exp(-((x - 0.3) ** 2 + (y - 0.6) ** 2) / 0.02)
         + 80.0 * np.sin(6.0 * x + 2.0 * y) * np.cos(3.0 * y) - 60.0 * np.exp(-(x - 0.7) ** 2 / 0.01))
    out = gdal.GetDriverByName("GTiff").Create(args.file, s, s, 1, gdal.GDT_Float32)
    out.SetGeoTransform([ORIGIN[0], SPACING, 0.0, ORIGIN[1] + s * SPACING, 0.0, -SPACING])
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(EPSG)
    out.SetProjection(srs.ExportToWkt())
    out.GetRasterBand(1).WriteArray(z.astype(np.float32))
    out.FlushCache()
    out = None
    raise SystemExit(0)

stages = args.stages.split(",")
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())
vertices = float(args.side) ** 2


def cpu():
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def timed(name, proxy):
    start, start_cpu = time.perf_counter(), cpu()
    proxy.UpdatePipeline()
    seconds, cpu_seconds = time.perf_counter() - start, cpu() - start_cpu
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024.0  # kB on Linux
    print("%-6s %8.3f s wall %8.3f s cpu  peak RSS %7.0f MB  %6.0f bytes/vertex" % (
        name, seconds, cpu_seconds, peak / 2 ** 20, peak / vertices), flush=True)


reader = GDALRasterReader(FileName=args.file)  # noqa: F405
timed("reader", reader)
if "dem" not in stages:
    raise SystemExit(0)
dem = DEMSurface(Input=reader)  # noqa: F405
timed("dem", dem)
upstream = dem
bounds = dem.GetDataInformation().GetBounds()
centre = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.0]
if args.paint:
    r = 0.1 * (bounds[1] - bounds[0])
    paint = MalleabilityPaint(Input=dem, InitialMalleability=0.2, Dabs=[  # noqa: F405
        centre[0], centre[1], 0.0, r, 0.9, 1.0,
        centre[0] - r, centre[1], 0.0, 0.5 * r, 0.0, 1.0,
        centre[0] + r, centre[1] + r, 0.0, 2.0 * r, 0.6, 1.0])
    timed("paint", paint)
    upstream = paint
if "chain" not in stages:
    raise SystemExit(0)
chain = ChainMailDeformation(Input=upstream)  # noqa: F405
if not args.paint:
    chain.MalleabilityArray = ["POINTS", "None"]
    chain.DefaultMalleability = 0.7
timed("chain", chain)
if "grasp" not in stages:
    raise SystemExit(0)
chain.GraspMode = "Nearest To Position"
chain.GraspPosition = centre
chain.Displacement = [0.0, 0.0, 30.0]
timed("grasp", chain)
if "frame" not in stages:
    raise SystemExit(0)
chain.Displacement = [0.0, 0.0, 30.001]
timed("frame", chain)
chain.UpdatePropertyInformation()
print("displaced %d" % chain.GetProperty("NumberOfDisplacedPoints").GetData())
