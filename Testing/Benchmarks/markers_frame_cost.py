"""What honoured well markers cost a shown drag frame (docs/benchmarks.md, "Markers"):
pvbatch, the Cascadia interface (CRESCENT, read in place), malleability 0.5, two
deformations of it in one process, one without markers and one with M markers (points of
the surface, those within 6 mean edge lengths of the grasp left out) connected and
HonourMarkers on; each shown in its own 800 x 600 view. Frames of a growing pull are
timed in turn, A B A B (UpdatePipeline + Render), medians printed per M.
Usage: xvfb-run -a -s -noreset pvbatch markers_frame_cost.py PLUGIN TSURF [M ...]"""
import csv
import os
import statistics
import sys
import tempfile
import time

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

LoadPlugin(sys.argv[1], remote=False, ns=globals())  # noqa: F405
path = sys.argv[2]
counts = [int(a) for a in sys.argv[3:]] or [10, 100, 1000]
FRAMES = 40

reader = GOCADTSurfReader(FileName=path)  # noqa: F405
calc = Calculator(Input=reader, ResultArrayName="Malleability", Function="0.5",  # noqa: F405
                  ResultArrayType="Float")
calc.UpdatePipeline()
surface = calc.GetClientSideObject().GetOutputDataObject(0)
xyz = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
grasp = int(np.argmin(np.linalg.norm(xyz - xyz.mean(axis=0), axis=1)))
polys = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
edge = np.mean(np.linalg.norm(xyz[polys[:, 0]] - xyz[polys[:, 1]], axis=1))
far = np.flatnonzero(np.linalg.norm(xyz - xyz[grasp], axis=1) > 6 * edge)
pull = 12 * edge * np.array([0.3, -0.5, 0.81]) / np.linalg.norm([0.3, -0.5, 0.81])


def chain_in_view(markers=None):
    chain = ChainMailDeformation(Input=calc)  # noqa: F405
    chain.MalleabilityArray = ["POINTS", "Malleability"]
    chain.GraspPointId = grasp
    if markers is not None:
        chain.Markers = markers
        chain.HonourMarkers = 1
    chain.UpdatePipeline()
    view = CreateRenderView(ViewSize=[800, 600])  # noqa: F405
    ColorBy(Show(chain, view), ("POINTS", "Malleability"))  # noqa: F405
    ResetCamera(view)  # noqa: F405
    Render(view)  # noqa: F405
    return chain, view


def frame(chain, view, f):
    chain.Displacement = list((0.2 + 0.02 * f) * pull)
    t0 = time.perf_counter()
    chain.UpdatePipeline()
    Render(view)  # noqa: F405
    return (time.perf_counter() - t0) * 1e3


tmp = tempfile.mkdtemp()
plain, plain_view = chain_in_view()
for m in counts:
    rows = xyz[far[np.linspace(0, len(far) - 1, m).astype(int)]]
    name = os.path.join(tmp, "markers%d.csv" % m)
    with open(name, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["x", "y", "z"])
        w.writerows(rows.tolist())
    table = CSVReader(FileName=[name])  # noqa: F405
    points = TableToPoints(Input=table, XColumn="x", YColumn="y", ZColumn="z")  # noqa: F405
    honoured, honoured_view = chain_in_view(points)
    a, b = [], []
    for f in range(FRAMES):
        a.append(frame(plain, plain_view, f))
        b.append(frame(honoured, honoured_view, f))
    honoured.UpdatePropertyInformation()
    ratios = [y / x for x, y in zip(a, b)]
    print("%d markers (%d honoured): frame without %.2f ms, with %.2f ms (medians of %d), "
          "pair ratios median %.3f, quartiles %.3f-%.3f" % (
              m, honoured.GetPropertyValue("NumberOfHonouredMarkers"), statistics.median(a),
              statistics.median(b), FRAMES, statistics.median(ratios),
              *statistics.quantiles(ratios, n=4)[::2]), flush=True)
    for proxy in (honoured, points, table):
        Delete(proxy)  # noqa: F405
