"""Where a shown drag's frame goes, in pvbatch: the deformation core, UpdatePipeline,
Render, and a re-render with nothing changed (rasterising only); overhead beyond raster =
update + render - raster. Like ../shared/tools/frame_cost.py, with the displacement, the
representation and the number of frames as options, and the GeoShaping Surface
representation's counters (sparse / full updates and GPU buffer builds).

Usage: xvfb-run -a -s "-noreset" pvbatch frame_split.py PLUGIN [--lift L] [--frames F]
           [--representation "GeoShaping Surface"|Surface] n [n ...]     (n x n grids)
Prints one line per n: medians over the frames."""
import argparse
import time

from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("sizes", type=int, nargs="+")
parser.add_argument("--lift", type=float, default=8.0)
parser.add_argument("--frames", type=int, default=15)
parser.add_argument("--representation", default=None)
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())


def median(values):
    values = sorted(values)
    return values[len(values) // 2]


for n in args.sizes:
    plane = Plane(XResolution=n - 1, YResolution=n - 1, Origin=[0, 0, 0],
                  Point1=[n - 1, 0, 0], Point2=[0, n - 1, 0])
    tri = Triangulate(Input=plane)
    calc = Calculator(Input=tri, ResultArrayName="Malleability", Function="0.5",
                      ResultArrayType="Float")
    chain = ChainMailDeformation(Input=calc)
    chain.MalleabilityArray = ["POINTS", "Malleability"]
    chain.GraspPointId = (n // 2) * n + n // 2
    chain.UpdatePipeline()
    view = CreateRenderView(ViewSize=[800, 600])
    display = Show(chain, view)
    if args.representation:
        display.Representation = args.representation
    ColorBy(display, ("POINTS", "Malleability"))
    ResetCamera(view)
    Render(view)
    update, render, raster, core, moved = [], [], [], [], []
    for f in range(args.frames):
        chain.Displacement = [0, 0, args.lift + 0.1 * f]
        t0 = time.perf_counter()
        chain.UpdatePipeline()
        t1 = time.perf_counter()
        Render(view)
        t2 = time.perf_counter()
        view.StillRender()  # nothing changed: rasterising only
        t3 = time.perf_counter()
        update.append((t1 - t0) * 1e3)
        render.append((t2 - t1) * 1e3)
        raster.append((t3 - t2) * 1e3)
        chain.UpdatePropertyInformation()
        core.append(chain.GetPropertyValue("LastDeformationMilliseconds"))
        moved.append(chain.GetPropertyValue("NumberOfDisplacedPoints"))
    over = [u + r - d for u, r, d in zip(update, render, raster)]
    counters = ""
    if display.SMProxy.GetProperty("NumberOfSparseBuilds"):
        display.SMProxy.UpdatePropertyInformation()
        counters = " | sparse/full updates %d/%d, builds %d/%d" % tuple(
            display.SMProxy.GetProperty(p).GetElement(0) for p in (
                "NumberOfSparseUpdates", "NumberOfFullUpdates", "NumberOfSparseBuilds",
                "NumberOfFullBuilds"))
    print("n=%d vertices=%d representation=%s displaced=%d | core %.3f ms | update %.2f ms + "
          "render %.2f ms (raster-only %.2f) | overhead beyond raster %.2f ms = %.0fx the core%s"
          % (n, n * n, display.Representation, median(moved), median(core), median(update),
             median(render), median(raster), median(over), median(over) / max(median(core), 1e-3),
             counters), flush=True)
    Delete(display)
    Delete(view)
    for proxy in (chain, calc, tri, plane):
        Delete(proxy)
