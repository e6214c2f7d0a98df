"""GeoShaping demo (pvbatch): paint and deform two geologic surfaces with a replayed
stylus and write the results, pictures and a timing/error report.

    pvbatch Testing/Demo/geoshaping_demo.py --plugin <GeoShaping.so> --out <dir> [--quick]

Scenes (Data/Demo/demo_scene.json): the Jacksboro fault zone DEM (real topography,
Debian's python-matplotlib-data) with a frozen fault scarp and a soft lowland; the same
DEM as a GeoTIFF, written and warped to UTM 16N by GDAL at demo time, opened with
ParaView's GDALRasterReader and made a surface by DEMSurface (the way a user's own DEM
comes in), with the same paint; and the paper's Figure 5 horizon with its black fault
step and white border. Each is painted from the stored dabs with MalleabilityPaint, then
the stored stylus trace
(Data/Demo/grasp_and_drag.trace, the Haptics trace format) is replayed: at the button
press the stylus grasps the scene's grasp point, and while the button is held the
device motion, scaled by `metres_per_device_metre`, is the ChainMailDeformation
Displacement. The replay runs once per candidate queue (FIFO Priority only for the
GeoTIFF, whose other queues the .npz scene shows); the FIFO Priority result is written
(.vtp and GOCAD .ts) and pictured.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, os.pardir, os.pardir))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "ParaViewPlugin", "Python"))

from paraview.simple import *  # noqa: E402,F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

import demo_metrics  # noqa: E402
import jacksboro  # noqa: E402

QUEUES = ["FIFO", "Priority", "FIFO Priority", "Max Violation"]


def read_trace(path):
    """Samples (t, xyz, buttons) of a Haptics trace file."""
    samples = []
    for line in open(path):
        line = line.split("#", 1)[0].strip()
        if line:
            v = line.split()
            samples.append((float(v[0]), np.array([float(x) for x in v[1:4]]), int(v[8])))
    return samples


def dabs_along(lines, to_xyz):
    dabs = []
    for seg in lines:
        a, b = np.array(to_xyz(seg["from"])), np.array(to_xyz(seg["to"]))
        count = max(1, int(np.ceil(np.linalg.norm(b - a) / seg["spacing"])))
        for k in range(count + 1):
            c = a + (b - a) * k / count
            dabs += [c[0], c[1], c[2], seg["radius"], seg["value"], seg["strength"]]
    return dabs


def painted_scene(source, cfg, to_xyz, name):
    """MalleabilityPaint with the scene's stored dabs, and a ChainMailDeformation on it."""
    paint = MalleabilityPaint(registrationName=name + " paint", Input=source)  # noqa: F405
    paint.InitialMalleability = cfg["initial_malleability"]
    paint.Falloff = cfg["falloff"]
    paint.DistanceMode = cfg["distance_mode"]
    paint.Dabs = dabs_along(cfg["dab_lines"], to_xyz)
    paint.UpdatePipeline()
    chain = ChainMailDeformation(registrationName=name + " deform", Input=paint)  # noqa: F405
    chain.MalleabilityArray = ["POINTS", "Malleability"]
    chain.PinnedArray = ["POINTS", "None"]
    return paint, chain


def jacksboro_xyz(dem_data):
    """Maps [lon, lat] to a point on the DEM surface (for dabs and grasps given on a map)."""
    height = demo_metrics.SurfaceHeight(dem_data)

    def to_xyz(lonlat):
        x, y = jacksboro.lonlat_to_scene(*lonlat)
        return (float(x), float(y), height.height(float(x), float(y)))
    return to_xyz


def output_of(proxy):
    proxy.UpdatePipeline()
    return proxy.GetClientSideObject().GetOutputDataObject(0)


def replay(chain, grasp, trace, scale, stride):
    """Replays the trace; returns per-frame core ms, wall ms, displaced counts, frames."""
    chain.GraspMode = "Nearest To Position"
    chain.GraspPosition = list(grasp)
    press, core_ms, wall_ms, displaced, frames, drags = None, [], [], [], [], []
    held = [s for s in trace if s[2] & 1]
    for k, (t, p, buttons) in enumerate(held):
        if press is None:
            press = p
        if k % stride and k != len(held) - 1:
            continue
        d = (p - press) * scale
        chain.Displacement = list(d)
        start = time.perf_counter()
        chain.UpdatePipeline()
        wall_ms.append(1e3 * (time.perf_counter() - start))
        chain.UpdatePropertyInformation()
        core_ms.append(chain.GetPropertyValue("LastDeformationMilliseconds"))
        displaced.append(chain.GetPropertyValue("NumberOfDisplacedPoints"))
        algo = chain.GetClientSideObject()
        frames.append(vtk_to_numpy(algo.GetOutputDataObject(0).GetPoints().GetData()).astype(float).copy())
        drags.append(d)
    return core_ms, wall_ms, displaced, frames, drags


def picture(proxy, path, title, z_exaggeration, camera=None):
    import geoshaping_presets
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1200, 800]
    view.OrientationAxesVisibility = 0
    view.Background = [0.32, 0.34, 0.43]
    for rep in GetRepresentations().values():
        rep.Visibility = 0
    display = Show(proxy, view)
    display.Scale = [1.0, 1.0, z_exaggeration]
    geoshaping_presets.show_malleability(display)
    display.SetScalarBarVisibility(view, True)
    text = Text(Text=title)
    text_display = Show(text, view)
    text_display.FontSize = 14
    if camera is None:
        # From the south-south-west, 40 degrees above the horizon, z up.
        b = proxy.GetDataInformation().GetBounds()
        centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) * z_exaggeration]
        size = max(b[1] - b[0], b[3] - b[2])
        camera = {"CameraFocalPoint": centre, "CameraViewUp": [0.0, 0.0, 1.0],
                  "CameraPosition": [centre[0] - 0.35 * size, centre[1] - 1.3 * size,
                                     centre[2] + 1.1 * size], "CameraViewAngle": 30.0}
    for key, value in camera.items():
        setattr(view, key, value)
    SaveScreenshot(path, view, ImageResolution=[1200, 800])
    Hide(text, view)
    Delete(text)
    Hide(proxy, view)
    return camera


def run_scene(name, cfg, source, to_xyz, grasp, trace, args, out, queues=QUEUES):
    print("[%s] %s" % (name, cfg["title"]), flush=True)
    paint, chain = painted_scene(source, cfg, to_xyz, name)
    rest_data = output_of(paint)
    n = rest_data.GetNumberOfPoints()
    print("[%s] %d vertices, %d triangles, %d dabs painted" % (
        name, n, rest_data.GetNumberOfCells(), len(paint.Dabs) // 6), flush=True)
    rest = vtk_to_numpy(rest_data.GetPoints().GetData()).astype(float).copy()
    malleability = vtk_to_numpy(rest_data.GetPointData().GetArray("Malleability")).astype(float).copy()
    edges = demo_metrics.edges(rest_data)

    results = {}
    for queue in queues:
        chain.CandidateQueue = queue
        core_ms, wall_ms, displaced, frames, drags = replay(
            chain, grasp, trace, cfg["metres_per_device_metre"], args.stride)
        final = frames[-1]
        results[queue] = {
            "frames": len(frames),
            "core_ms_median": float(np.median(core_ms)),
            "core_ms_max": float(np.max(core_ms)),
            "update_ms_median": float(np.median(wall_ms)),
            "displaced_max": int(np.max(displaced)),
            "E_rigid": demo_metrics.rigid_error(rest, final, edges, malleability),
            "E_temporal": demo_metrics.temporal_error(frames, drags),
        }
        print("[%s] %-13s %3d frames, core %.3f ms median, update %.2f ms median, "
              "displaced up to %d, E_rigid %.3g, E_temporal %.3g" % (
                  name, queue, len(frames), results[queue]["core_ms_median"],
                  results[queue]["update_ms_median"], results[queue]["displaced_max"],
                  results[queue]["E_rigid"], results[queue]["E_temporal"]), flush=True)
    chain.CandidateQueue = "FIFO Priority"
    replay(chain, grasp, trace, cfg["metres_per_device_metre"], args.stride)
    SaveData(os.path.join(out, name + "_deformed.vtp"), proxy=chain)
    SaveData(os.path.join(out, name + "_deformed.ts"), proxy=chain)
    SaveData(os.path.join(out, name + "_painted.vtp"), proxy=paint)
    camera = picture(paint, os.path.join(out, name + "_before.png"),
                     cfg["title"] + ": painted (black rigid ... white soft)", cfg["z_exaggeration"])
    picture(chain, os.path.join(out, name + "_after.png"),
            cfg["title"] + ": after grasp and drag (FIFO Priority)", cfg["z_exaggeration"], camera)
    return {"title": cfg["title"], "vertices": n, "triangles": rest_data.GetNumberOfCells(),
            "queues": results}


def write_summary(out, scenes):
    lines = ["# GeoShaping demo summary", "",
             "Timings: `core` is the deformation in the core (median over the replayed "
             "frames); `update` is the whole pipeline update through the filter. Errors "
             "follow docs/design.md, Error against run time (E_rigid divided by the mean edge length; "
             "E_temporal = max |X(d+delta) - X(d)|_inf / |delta| over the replay).", ""]
    for name, s in scenes.items():
        lines += ["## %s" % s["title"], "",
                  "%d vertices, %d triangles." % (s["vertices"], s["triangles"]), "",
                  "| queue | frames | displaced (max) | core ms (median) | core ms (max) | update ms (median) | E_rigid | E_temporal |",
                  "|---|---:|---:|---:|---:|---:|---:|---:|"]
        for q, r in s["queues"].items():
            lines.append("| %s | %d | %d | %.3f | %.3f | %.2f | %.3g | %.3g |" % (
                q, r["frames"], r["displaced_max"], r["core_ms_median"], r["core_ms_max"],
                r["update_ms_median"], r["E_rigid"], r["E_temporal"]))
        lines += ["", "Pictures: `%s_before.png`, `%s_after.png`; surfaces: `%s_deformed.vtp`, "
                  "`%s_deformed.ts`." % (name, name, name, name), ""]
    open(os.path.join(out, "summary.md"), "w").write("\n".join(lines))
    json.dump(scenes, open(os.path.join(out, "summary.json"), "w"), indent=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--out", default="geoshaping-demo-output")
    parser.add_argument("--quick", action="store_true",
                        help="every 4th frame and a coarser DEM (for the test suite)")
    args = parser.parse_args()
    args.stride = 4 if args.quick else 1
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    LoadPlugin(args.plugin, remote=False, ns=globals())
    config = json.load(open(os.path.join(ROOT, "Data", "Demo", "demo_scene.json")))
    trace = read_trace(os.path.join(ROOT, "Data", "Demo", "grasp_and_drag.trace"))

    scenes = {}
    j = config["jacksboro"]
    # The plugin's source (C++, Filters/IO); jacksboro.py is the numpy reference the tests
    # compare it with, and gives the lon/lat projection of the map-given dabs and grasp.
    dem = JacksboroFaultDEM(registrationName="Jacksboro", FileName=jacksboro.find_dem(),  # noqa: F405
                            Stride=2 if args.quick else 1)
    dem_data = output_of(dem)
    jack_xyz = jacksboro_xyz(dem_data)
    scenes["jacksboro"] = run_scene("jacksboro", j, dem, jack_xyz, jack_xyz(j["grasp_lonlat"]),
                                    trace, args, out)

    # A user's DEM: the Jacksboro grid written as a geographic GeoTIFF by GDAL, warped by
    # gdalwarp to UTM 16N at 90 m (its tilted footprint leaves no-data corners: holes),
    # opened with ParaView's GDALRasterReader, made a surface by DEMSurface. Same paint
    # and grasp (lon/lat through the same UTM 16N).
    geographic = jacksboro.write_geotiff(os.path.join(out, "jacksboro_4326.tif"))
    warped = os.path.join(out, "jacksboro_utm16n.tif")
    subprocess.run(["gdalwarp", "-q", "-overwrite", "-t_srs", "EPSG:32616", "-tr", "90", "90",
                    "-r", "bilinear", "-dstnodata", "-32768", geographic, warped], check=True)
    raster = GDALRasterReader(registrationName="Jacksboro GeoTIFF", FileName=warped)  # noqa: F405
    surface = DEMSurface(registrationName="Jacksboro DEM surface", Input=raster,  # noqa: F405
                         Stride=2 if args.quick else 1)
    geotiff_xyz = jacksboro_xyz(output_of(surface))
    g = dict(j, title="Jacksboro GeoTIFF (gdalwarp to UTM 16N, 90 m; DEMSurface)")
    scenes["jacksboro_geotiff"] = run_scene("jacksboro_geotiff", g, surface, geotiff_xyz,
                                            geotiff_xyz(j["grasp_lonlat"]), trace, args, out,
                                            queues=["FIFO Priority"])

    f = config["fault_step"]
    step = FaultStepHorizon(**f["source"])  # noqa: F405
    scenes["fault_step"] = run_scene("fault_step", f, step, lambda p: tuple(p), f["grasp"],
                                     trace, args, out)
    write_summary(out, scenes)
    print("GeoShaping demo: results, pictures and summary written to %s" % out)
    print(open(os.path.join(out, "summary.md")).read())


if __name__ == "__main__":
    main()
