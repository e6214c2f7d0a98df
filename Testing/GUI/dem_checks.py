"""The GUI test of the vertical exaggeration (run_gui_test.py mode dem_exaggerated): a 9 km
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


def prepare(mode, out, env):
    here = os.path.dirname(os.path.abspath(__file__))
    if os.path.exists(out + ".picks"):
        os.remove(out + ".picks")
    write_geotiff(out)
    env["GEOSHAPING_HAPTICS_REPLAY"] = "mouse"
    env["GEOSHAPING_HAPTICS_SCRIPT"] = SCRIPT
    env["GEOSHAPING_GUI_SETUP"] = os.path.join(here, "gui_setup_dem.py")
    env["GEOSHAPING_GUI_SURFACE"] = out + ".tif"
    env["GEOSHAPING_GUI_EXAGGERATION"] = "%g" % EXAGGERATION


def drawn_picks(out):
    """VTK's picker's points (world, as drawn) of the hook's picks, and in data units."""
    scale = np.array([1.0, 1.0, EXAGGERATION])
    rows = [(line.split()[0], np.array([float(v) for v in line.split()[4:7]]))
            for line in open(out + ".picks")]
    return [(kind, p, p / scale) for kind, p in rows]


def check(mode, out):
    """Hover: the brush cursor where the hill is drawn under the mouse. Ctrl-drag: the
    stroke paints the vertices under its drawn path (in data units). Drag: the grasped
    vertex is the one drawn under the press and stays under the cursor. The dock's
    Vertical exaggeration sets the surface's Scale and its obstacle's."""
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
