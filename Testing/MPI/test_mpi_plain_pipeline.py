"""The pipeline a user builds on an MPI server, with nothing added for MPI (docs/mpi.md):
a file read by ParaView's reader, optionally RedistributeDataSet or D3, into
ChainMailDeformation (MalleabilityPaint with geodesic dabs before it in one case), no
GhostCellsGenerator, no point GlobalIds unless the case gives them, the grasp nearest a
position. `mpiexec -n 1, 2, 3 pvbatch --sym mpi_plain.py`: the owned points of 2 and 3
ranks (rest and deformed positions, malleability) equal 1 rank's bit for bit, at least
50 points moved, and LastGraspMalleability is the 1-rank value on every rank count.
Usage: test_mpi_plain_pipeline.py CASE, CASE one of
  surface-reader, surface-redistribute, surface-ids, surface-paint (polydata),
  volume-redistribute, volume-d3 (an unstructured grid of tetrahedra),
  split (a surface whose fault has split nodes, no GlobalIds: 1 rank deforms it, 2 and 3
  ranks refuse it on every rank with an error naming GlobalIds),
  cascadia-redistribute (the CRESCENT Cascadia interface, a TSurf file, pulled 80 km;
  skipped when ../shared/data/crescent-cfm is absent),
  dem-paint (a GeoTIFF written by gdal_translate, read by GDALRasterReader into DEMSurface:
  the reader gives the raster to rank 0 alone, so DEMSurface has an empty raster on the
  other ranks, which is a piece and no error: issue 39, item 5),
  dem-unsplitpaint (the same without RedistributeDataSet: MalleabilityPaint and
  ChainMailDeformation get an empty piece on every rank but the first).
A run that hangs is killed after 280 s and fails the test."""
import os
import sys
import tempfile

import numpy as np
from mpi_driver import ENV, HERE, expect_same, fail, plain_parameters, run_ranks, show, write_dem
from paraview.simple import *  # noqa: F401,F403

case = sys.argv[1]
scene, _, pipeline = case.partition("-")
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], ns=globals())  # noqa: F405


def write_scene(path):
    """The scene as a file: what the readers then read (pvpython, one process)."""
    if scene == "surface":
        source = FaultStepHorizon(PaintFigure5C=1)  # noqa: F405 (a rigid block in soft beds)
    elif scene == "volume":
        box = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 16, 0, 16, 0, 10]))  # noqa: F405
        source = Calculator(Input=box, ResultArrayName="Malleability")  # noqa: F405
        source.Function = "0.25*floor(3.999*abs(sin(0.3*coordsX+0.2*coordsY+0.5*coordsZ)))"
    elif scene == "dem":
        write_dem(path)  # GDAL's gdal_translate
        return
    else:
        source = LayeredFaultScene()  # noqa: F405 (horizons cut by a fault: split nodes)
    SaveData(path, proxy=source)  # noqa: F405


def run(n, path, out):
    return run_ranks(n, "mpi_plain.py", [pipeline or "redistribute", path, out], timeout=280)


cascadia = os.path.join(HERE, "..", "..", "..", "shared", "data", "crescent-cfm",
                        "mccrory_2012_cascadia_interface.ts")
if scene == "cascadia" and not os.path.exists(cascadia):
    print("skipped: %s is absent" % cascadia)
    sys.exit(0)
with tempfile.TemporaryDirectory(dir=os.environ.get("GEOSHAPING_TEST_TMP")) as tmp:
    if scene == "cascadia":
        path = cascadia
    else:
        path = os.path.join(tmp, scene + {"volume": ".vtu", "dem": ".tif"}.get(scene, ".vtp"))
        write_scene(path)
    # Parameters from the scene (to the ranks through the environment)'s bounds: grasp at the top middle, pull up by 8 % of the size.
    scene_file = OpenDataFile(path)  # noqa: F405
    if scene == "dem":
        scene_file = DEMSurface(Input=scene_file)  # noqa: F405
    scene_file.UpdatePipeline()
    plain_parameters(scene_file.GetDataInformation().GetBounds(),
                     80000.0 if scene == "cascadia" else None)  # UTM metres
    results, grasped = {}, {}
    for n in (1, 2, 3):
        out = os.path.join(tmp, "n%d" % n)
        cmd, done, errors = run(n, path, out)
        if scene == "split" and n > 1:
            named = [e for e in errors if "GlobalIds" in e and "split nodes" in e]
            if done.returncode != 0 or len(named) < n:
                show(cmd, done)
                fail("%d ranks: expected the split-node error on every rank, got %d" % (n, len(named)))
            rows = np.load(os.path.join(out, "result.npy"))
            if np.any(rows[:, 0:3] != rows[:, 3:6]):
                fail("%d ranks: refused, but points moved" % n)
            print("ok: %d ranks refuse the split nodes on every rank: %s" % (n, named[0][-160:]))
            continue
        if done.returncode != 0 or errors:
            show(cmd, done)
            fail("%d ranks: exit %d, %d error lines" % (n, done.returncode, len(errors)))
        results[n] = np.load(os.path.join(out, "result.npy"))
        print([line for line in done.stdout.splitlines() if line.startswith("rank0")][0])
        grasped[n] = [line for line in done.stdout.splitlines() if line.startswith("grasp")][0]
    one = results[1]
    moved = int(np.count_nonzero(np.any(one[:, 0:3] != one[:, 3:6], axis=1)))
    if moved < 50:
        fail("only %d points moved on 1 rank" % moved)
    print("ok: %d of %d points moved on 1 rank" % (moved, len(one)))
    if scene != "split" and len(np.unique(one[:, 0:3], axis=0)) != len(one):
        fail("the scene has coincident points")
    for n in results:
        if n == 1:
            continue
        expect_same(results[n], one, n)
        print("ok: %d ranks equal 1 rank bit for bit" % n)
        if grasped[n] != grasped[1] or "nan" in grasped[1]:
            fail("LastGraspMalleability: %s on %d ranks, %s on 1" % (grasped[n], n, grasped[1]))
        print("ok: %d ranks report the 1-rank %s" % (n, grasped[1]))
