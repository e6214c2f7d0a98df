"""The GUI tests of DEMs (run_gui_test.py modes dem_*). dem_ready: a DEM ready to shape
(check_ready). dem_exaggerated, the vertical exaggeration: a 9 km
GeoTIFF hill (1.2 km high, 100 m pixels, UTM 16N, written by gdal_translate) through DEM
Surface, shown with the display Scale (1, 1, 5) (and an obstacle under the hill's foot);
the mouse hovers, paints and pulls
through the plugin's test hook (GEOSHAPING_HAPTICS_SCRIPT, TestHook/pqHapticsTestScript.h),
then the dock's Vertical exaggeration sets 2. Checked against VTK's own picker on the
drawn geometry and the hook's snapshots."""
import os
import subprocess

import numpy as np

from brush_checks import INITIAL, distance_to_segment, snapshot, stroke_cover, vector

EXAGGERATION = 5.0
CELL = 100.0  # m
COLS = ROWS = 91  # 9 km square
XLL, YLL = 745000.0, 4040000.0
PIXEL = 1.0  # the grasped vertex shows within a pixel of the cursor

SCRIPT = ("hover 0.5 0.45 ctrl; snapshot hover; press 0.42 0.42 ctrl; move 0.47 0.43; "
          "move 0.52 0.44; release; wait; snapshot stroke; press 0.5 0.5; wait; "
          "snapshot grasped; move 0.5 0.53; move 0.51 0.56; wait; snapshot pull; release; "
          "wait; snapshot released; exaggeration 2; wait; snapshot two")


def write_geotiff(out):
    """The hill: z = 300 + 1200 exp(-r^2 / (2 (2 km)^2)) m about the raster's centre."""
    r, c = np.mgrid[0:ROWS, 0:COLS]
    x, y = (c - COLS // 2) * CELL, (r - ROWS // 2) * CELL
    z = 300.0 + 1200.0 * np.exp(-(x * x + y * y) / (2.0 * 2000.0 ** 2))
    with open(out + ".asc", "w") as f:
        f.write("ncols %d\nnrows %d\nxllcorner %.17g\nyllcorner %.17g\ncellsize %.17g\n"
                % (COLS, ROWS, XLL, YLL, CELL))
        for row in z:
            f.write(" ".join("%.17g" % v for v in row) + "\n")
    subprocess.run(["gdal_translate", "-q", "-a_srs", "EPSG:32616", "-ot", "Float64",
                    out + ".asc", out + ".tif"], check=True)


# Mode dem_ready: DEM Surface applied on the raster shown in 2D, then the paint and the
# deformation; a vertical pull (Z) raises the hill's top.
READY_SCRIPT = ("open GDALRasterReader; wait; wait; snapshot raster; apply DEMSurface; wait; wait; snapshot dem; "
                "apply MalleabilityPaint; apply ChainMailDeformation; wait; wait; "
                "press 0.5 0.5; key Z; move 0.5 0.55; move 0.5 0.6; wait; snapshot pulled; "
                "release; wait; snapshot released; elevation 10; wait; snapshot turned; "
                "open GDALRasterReader; wait; wait; apply DEMSurface; wait; wait; "
                "snapshot second")


def prepare(mode, out, env):
    here = os.path.dirname(os.path.abspath(__file__))
    if os.path.exists(out + ".picks"):
        os.remove(out + ".picks")
    write_geotiff(out)
    env["GEOSHAPING_HAPTICS_REPLAY"] = "mouse"
    env["GEOSHAPING_HAPTICS_SCRIPT"] = READY_SCRIPT if mode == "dem_ready" else SCRIPT
    if mode == "dem_ready":
        env["GEOSHAPING_GUI_BUILDS_PIPELINE"] = "1"  # the hook starts before the deformation
    env["GEOSHAPING_GUI_SETUP"] = os.path.join(
        here, "gui_setup_dem_ready.py" if mode == "dem_ready" else "gui_setup_dem.py")
    env["GEOSHAPING_GUI_SURFACE"] = out + ".tif"
    env["GEOSHAPING_GUI_EXAGGERATION"] = "%g" % EXAGGERATION


def drawn_picks(out):
    """VTK's picker's points (world, as drawn) of the hook's picks, and in data units."""
    scale = np.array([1.0, 1.0, EXAGGERATION])
    rows = [(line.split()[0], np.array([float(v) for v in line.split()[4:7]]))
            for line in open(out + ".picks")]
    return [(kind, p, p / scale) for kind, p in rows]


def check_ready(out):
    """DEM Surface > Apply on the raster ParaView showed in 2D: a 3D view, the raster
    hidden, the surface coloured by Elevation and framed (its bounding box on screen,
    filling 70 % of the view across), seen obliquely from the south; the pull raises the hill and the deformation's Elevation
    is the shaped z, its RestElevation the raster's."""
    from gui_files import read_results
    raster = read_results(out + "-raster.txt")
    dem = read_results(out + "-dem.txt")
    print("raster shown: interaction mode %s; DEM Surface applied: mode %s, %s, %s" % (
        raster["interaction_mode"], dem["interaction_mode"], dem.get("shown_DEMSurface1"),
        {k: v for k, v in dem.items() if k.startswith("shown_") and "DEM" not in k}))
    assert raster["interaction_mode"] == "1", "the raster did not put the view in 2D"
    assert dem["interaction_mode"] == "0", "DEM Surface left the view in 2D"
    shown = dem["shown_DEMSurface1"].split()
    assert shown[0] == "1" and shown[1] == "Elevation", shown
    raster_shown = [v.split() for k, v in dem.items() if k.startswith("shown_") and "DEM" not in k]
    assert all(v[0] == "0" for v in raster_shown), "the raster is still shown: %s" % raster_shown
    x0, x1, y0, y1 = (float(v) for v in shown[2:6])
    w, h = (float(v) for v in dem["view_px"].split())
    print("framed: the surface's box spans x %.0f ... %.0f, y %.0f ... %.0f of %g x %g px" % (
        x0, x1, y0, y1, w, h))
    assert 0 <= x0 and x1 <= w and 0 <= y0 and y1 <= h, "the surface is not all in view"
    assert max((x1 - x0) / w, (y1 - y0) / h) >= 0.7, "the surface is not framed"
    # An oblique first view of the relief: from the south, looking north and down at
    # 35 degrees (30 ... 40) above the horizon, not straight down.
    look = vector(dem, "view_direction")
    elevation = np.degrees(np.arcsin(-look[2] / np.linalg.norm(look)))
    heading = np.degrees(np.arctan2(look[0], look[1]))
    print("first view: looking %.1f degrees down, heading %.1f degrees from north" % (
        elevation, heading))
    assert 30.0 <= elevation <= 40.0, "the first view is not oblique: %s" % look
    assert abs(heading) <= 1.0, "the first view does not look north: %s" % look

    pulled, rows = snapshot(out, "pulled")
    rest, z = rows[:, 2], rows[:, 5]
    elevation, rest_elevation = rows[:, 7], rows[:, 8]
    raised = z > rest + 1.0
    print("pulled: %d vertices raised, top z %.1f m (rest %.1f m); Elevation %.1f ... %.1f m" % (
        raised.sum(), z.max(), rest.max(), elevation.min(), elevation.max()))
    assert raised.sum() >= 1 and z.max() > rest.max() + 10.0, "the pull did not raise the hill"
    assert np.array_equal(elevation, z), "Elevation does not follow the shape"
    assert np.array_equal(rest_elevation, rest), "RestElevation is not the raster's"
    released, rows = snapshot(out, "released")
    assert released["edit_history"] == "1", released
    assert np.array_equal(rows[:, 7], rows[:, 5]), "Elevation after the release"
    # A second DEM Surface shown in the view leaves the camera the user turned.
    before = read_results(out + "-turned.txt")
    turned = vector(before, "view_direction")
    second = read_results(out + "-second.txt")
    print("the user turned the camera to %.1f degrees down; after a second DEM Surface: %s" % (
        np.degrees(np.arcsin(-turned[2])), second["view_direction"]))
    assert second["interaction_mode"] == "0", "the second DEM Surface left the view in 2D"
    assert np.allclose(vector(second, "view_direction"), turned, atol=1e-6), \
        "the second DEM Surface turned the user's camera"
    assert np.array_equal(vector(second, "view_position"), vector(before, "view_position")), \
        "the second DEM Surface moved the user's camera"


def check(mode, out):
    """Hover: the brush cursor where the hill is drawn under the mouse. Ctrl-drag: the
    stroke paints the vertices under its drawn path (in data units). Drag: the grasped
    vertex is the one drawn under the press and stays under the cursor. The dock's
    Vertical exaggeration sets the surface's Scale and its obstacle's."""
    if mode == "dem_ready":
        check_ready(out)
        return
    kinds = [kind for kind, _, _ in drawn_picks(out)]
    assert kinds == ["hover", "press", "move", "move", "press", "move", "move"], kinds
    drawn = drawn_picks(out)
    assert all(np.all(np.isfinite(p)) for _, p, _ in drawn), "VTK's picker missed the hill"

    hover, _ = snapshot(out, "hover")
    radius = float(hover["brush_radius"])
    print("scale %s; brush radius %.1f m; hover: %s cursor(s) %s, drawn point %s" % (
        hover["Scale"], radius, hover["cursors"], hover.get("cursor_0"), drawn[0][1]))
    assert hover["Scale"] == hover["obstacle_scale_0"] == "1 1 %g" % EXAGGERATION, hover
    assert hover["cursors"] == "1", "no brush cursor over the exaggerated hill"
    cursor = vector(hover, "cursor_0")
    off = np.linalg.norm(cursor[:3] - drawn[0][1])
    print("hover: the cursor is %.3f m from the point drawn under the mouse, %g times taller "
          "than wide (the brush as drawn)" % (off, cursor[5]))
    assert off <= 1e-3 * radius, off
    assert cursor[5] == EXAGGERATION, "the cage is not the brush as drawn: %s" % cursor

    results, rows = snapshot(out, "stroke")
    path = [data for _, _, data in drawn[1:4]]
    cover = stroke_cover(rows[:, :3], path, radius)
    m = rows[:, 6]
    painted = m != INITIAL
    far = np.min([distance_to_segment(rows[:, :3], a, b) for a, b in zip(path, path[1:])], axis=0)
    print("stroke: %d vertices painted, %d within 0.98 radius of the drawn path (data units), "
          "%d of them painted; note %r" % (painted.sum(), cover.sum(), painted[cover].sum(),
                                           results["label_BrushNote"]))
    assert cover.sum() >= 10 and np.all(painted[cover]), "the stroke missed where it was drawn"
    assert np.all(far[painted] <= (1 + 1e-6) * radius), "painted away from the drawn stroke"

    grasped, rows = snapshot(out, "grasped")
    pull, _ = snapshot(out, "pull")
    grasp = int(pull["GraspPointId"])
    press = drawn[4][2]
    # The grasped vertex is the one drawn nearest to the press (it shows a few pixels off
    # the cursor, a vertex spacing at most), and its image then moves as the cursor does.
    offset = vector(grasped, "grasp_px") - vector(grasped, "mouse_px")
    moved = vector(pull, "mouse_px") - vector(grasped, "mouse_px")
    error = np.linalg.norm(vector(pull, "grasp_px") - vector(pull, "mouse_px") - offset)
    gap = np.linalg.norm(rows[grasp, :2] - press[:2])
    d = vector(pull, "Displacement")
    print("pull: vertex %d, %.1f m (data, horizontal) from the point drawn under the press, "
          "shown %.2f px off the cursor at the press; after a %.0f px drag the offset changed "
          "%.4f px; Displacement %s m (z drawn %.1f m)" % (
              grasp, gap, np.linalg.norm(offset), np.linalg.norm(moved), error, d,
              EXAGGERATION * d[2]))
    assert grasped["GraspPointId"] == pull["GraspPointId"], (grasped, pull)
    assert gap <= 1.5 * CELL, "grasped a vertex away from the press: %.1f m" % gap
    # A vertex spacing (100 m) shows as about 5 px here; the vertex drawn nearest is taken.
    assert np.linalg.norm(offset) <= 5.0, "the grasp shows %s px off the press" % offset
    assert np.linalg.norm(moved) > 20 and np.linalg.norm(d) > 0, (moved, d)
    assert error <= PIXEL, "the grasped vertex moved %.3f px off the cursor's motion" % error
    released, _ = snapshot(out, "released")
    assert released["edit_history"] == "1", released

    two, _ = snapshot(out, "two")
    print("the dock's Vertical exaggeration 2: Scale %s, the obstacle's %s" % (
        two["Scale"], two["obstacle_scale_0"]))
    assert two["Scale"] == two["obstacle_scale_0"] == "1 1 2", two
