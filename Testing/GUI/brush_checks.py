"""The GUI tests of the brush and of the keyed pull (run_gui_test.py modes brush_* and
pull_keys): a 1,000 km square surface in metres (a GOCAD TSurf with AXIS_UNIT m, opened
with the plugin's reader), painted or pulled with the mouse through the plugin's test hook
(GEOSHAPING_HAPTICS_SCRIPT, see TestHook/pqHapticsTestScript.h); checked from the
hook's snapshots."""
import math
import os

import numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

from gui_files import read_results

SIDE = 1.0e6  # m
N = 51  # vertices per side: 20 km apart
RELIEF = 2000.0  # m
ORIGIN = (400000.0, 4000000.0)  # a UTM-like corner
SPACING_FRACTION = 0.25  # geoshaping::BrushStroke's default
INITIAL = 0.5  # MalleabilityPaint's InitialMalleability

SCRIPTS = {
    # The default radius paints on Ctrl+drag, and its cursor shows; then a 5 m brush: its
    # dab reaches no vertex, is not stored, the dock says why, the cursor still shows.
    "brush_default": "press 0.45 0.5 ctrl; move 0.5 0.5; move 0.55 0.5; snapshot held; "
                     "release; wait; snapshot stroke; radius 5; press 0.41 0.43 ctrl; "
                     "snapshot tinyheld; release; wait; snapshot tiny",
    # Two frames far apart (about 450 km, ten radii): the stroke fills the way.
    "brush_fast": "swatch 10; press 0.4 0.4 ctrl; move 0.6 0.6; release; wait; snapshot stroke",
    # A pull, then a black stroke on the pulled surface; the dock's Undo takes the stroke
    # off first, then the pull; Redo puts them back in order; Edit > Undo (Ctrl+Z) takes
    # the stroke off as the dock's Undo does, Edit > Redo puts it back.
    "brush_undo": "press 0.5 0.55; move 0.5 0.57; move 0.5 0.6; release; wait; swatch 0; "
                  "press 0.42 0.45 ctrl; move 0.47 0.45; move 0.52 0.46; release; wait; "
                  "snapshot stroke; undo; snapshot undo1; undo; snapshot undo2; redo; "
                  "snapshot redo1; redo; snapshot redo2; editundo; snapshot editundo; "
                  "editredo; snapshot editredo",
    # Hovering with Ctrl held (the next press would paint): the brush cursor shows where a
    # dab would land; not without Ctrl, off the surface, once Ctrl is released (with the
    # keyboard focus on the dock, before the mouse moves) or once the mouse left the view.
    "brush_hover": "hover 0.45 0.5 ctrl; snapshot hover; hover 0.55 0.42 ctrl; snapshot hover2; "
                   "hover 0.45 0.5; snapshot noctrl; hover 0.02 0.02 ctrl; snapshot off; "
                   "hover 0.5 0.5 ctrl; snapshot back; ctrlup; snapshot ctrlup; "
                   "hover 0.5 0.5 ctrl; leave; snapshot left",
    # A free pull, then Z typed mid-drag (through Qt, as a user's key): vertical from there
    # on; Z again frees it; Z once more, then the release: the next drag is free again (a
    # key lasts one drag); seen from the south-west, so the vertical is not end-on.
    "pull_keys": "press 0.5 0.5; move 0.53 0.51; move 0.56 0.52; snapshot free; key Z; "
                 "snapshot switched; move 0.58 0.58; move 0.6 0.65; snapshot vertical; key Z; "
                 "snapshot freed; move 0.55 0.7; snapshot free2; key Z; snapshot vertical2; "
                 "release; wait; snapshot released; press 0.45 0.45; move 0.5 0.47; "
                 "snapshot next; release; wait",
}


def write_surface(path):
    """A gently rolling N x N grid, two triangles per cell, in metres."""
    with open(path, "w") as f:
        f.write("GOCAD TSurf 1\nHEADER {\nname:square_1000km\n}\n"
                "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME Default\nAXIS_NAME \"X\" \"Y\" \"Z\"\n"
                "AXIS_UNIT \"m\" \"m\" \"m\"\nZPOSITIVE Elevation\n"
                "END_ORIGINAL_COORDINATE_SYSTEM\nTFACE\n")
        for j in range(N):
            for i in range(N):
                x, y = SIDE * i / (N - 1), SIDE * j / (N - 1)
                z = RELIEF * math.sin(2 * math.pi * x / SIDE) * math.cos(math.pi * y / SIDE)
                f.write("VRTX %d %.6f %.6f %.6f\n" % (j * N + i + 1, ORIGIN[0] + x, ORIGIN[1] + y, z))
        for j in range(N - 1):
            for i in range(N - 1):
                a = j * N + i + 1
                f.write("TRGL %d %d %d\nTRGL %d %d %d\n" % (a, a + 1, a + N + 1, a, a + N + 1, a + N))
        f.write("END\n")


def prepare(mode, out, env):
    here = os.path.dirname(os.path.abspath(__file__))
    for suffix in (".picks",):
        if os.path.exists(out + suffix):
            os.remove(out + suffix)
    write_surface(out + ".ts")
    env["GEOSHAPING_HAPTICS_REPLAY"] = "mouse"
    env["GEOSHAPING_HAPTICS_SCRIPT"] = SCRIPTS[mode]
    env["GEOSHAPING_GUI_SETUP"] = os.path.join(here, "gui_setup_brush.py")
    env["GEOSHAPING_GUI_SURFACE"] = out + ".ts"
    if mode == "pull_keys":
        env["GEOSHAPING_GUI_CAMERA"] = "oblique"
    if mode in ("brush_fast", "brush_undo"):
        env["GEOSHAPING_GUI_FALLOFF"] = "Constant"  # every vertex under a dab gets its share


def snapshot(out, name):
    """(key = value texts, per-point array: x y z sx sy sz m)"""
    assert os.path.exists(out + "-%s.csv" % name), "no snapshot " + name
    return read_results(out + "-%s.txt" % name), np.loadtxt(out + "-%s.csv" % name, skiprows=1)


def picks(out):
    return [(l.split()[0], np.array([float(v) for v in l.split()[1:4]])) for l in open(out + ".picks")]


def image(png):
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    data = reader.GetOutput()
    return vtk_to_numpy(data.GetPointData().GetScalars()).astype(int)[:, :3]


def changed_pixels(a, b):
    pa, pb = image(a), image(b)
    assert pa.shape == pb.shape, (pa.shape, pb.shape)
    return int((np.abs(pa - pb).max(axis=1) > 24).sum())


def distance_to_segment(points, a, b):
    ab = b - a
    t = np.clip((points - a) @ ab / (ab @ ab), 0.0, 1.0)
    return np.linalg.norm(points - (a + t[:, None] * ab), axis=1)


def stroke_cover(points, path, radius):
    """The points every stroke along the polyline `path` must reach with its whole
    weight: within 0.98 radius of the path, the last spacing before its end left out (the
    last dab is within a spacing of the end; a Constant brush reaches every point within
    radius sqrt(1 - s^2/4) = 0.992 radius of the dabs' path)."""
    end = path[-1] - SPACING_FRACTION * radius * (path[-1] - path[-2]) / np.linalg.norm(path[-1] - path[-2])
    path = path[:-1] + [end]
    d = np.min([distance_to_segment(points, a, b) for a, b in zip(path, path[1:])], axis=0)
    return d <= 0.98 * radius


def check_default(out):
    held, _ = snapshot(out, "held")
    results, rows = snapshot(out, "stroke")
    rest = rows[:, :3]
    diagonal = np.linalg.norm(rest.max(axis=0) - rest.min(axis=0))
    radius = float(results["brush_radius"])
    painted = int((rows[:, 6] != INITIAL).sum())
    print("1,000 km surface: diagonal %.1f m, default radius %.1f m (%.2f %%), %s; %d vertices "
          "painted, %s dab values; dock: %r / %r" % (
              diagonal, radius, 100 * radius / diagonal, results["label_BrushRadius"], painted,
              results["dab_values"], results["label_BrushRadiusAbout"], results["label_BrushNote"]))
    assert abs(radius - 0.03 * diagonal) <= 1e-9 * diagonal, (radius, diagonal)
    assert float(results["BrushRadius"]) == 0.0, "the default is not written to the state"
    assert results["label_BrushRadius"].endswith(" m"), results["label_BrushRadius"]
    assert "42.4 km" in results["label_BrushRadiusAbout"], results["label_BrushRadiusAbout"]
    assert painted >= 10, painted
    assert int(results["dab_values"]) >= 6 and results["label_BrushNote"].startswith("Last stroke: "), results
    cursor = changed_pixels(out + "-held.png", out + "-stroke.png")
    print("the cursor while painting: %d pixels differ from the view after the release" % cursor)
    assert cursor > 100, cursor

    tiny, tiny_rows = snapshot(out, "tiny")
    print("5 m brush: %s dab values, BrushRadius %s, note %r" % (
        tiny["dab_values"], tiny["BrushRadius"], tiny["label_BrushNote"]))
    assert float(tiny["brush_radius"]) == 5.0 and float(tiny["BrushRadius"]) == 5.0, tiny
    assert tiny["dab_values"] == results["dab_values"], "a dab that reaches nothing was stored"
    assert np.array_equal(tiny_rows[:, 6], rows[:, 6]), "the 5 m dab painted"
    note = tiny["label_BrushNote"]
    assert "reached no vertex" in note and "not stored" in note and "(5 m)" in note, note
    assert tiny["label_BrushRadius"].endswith(" m") and "set for this surface" in tiny["label_BrushRadiusAbout"], tiny
    cursor = changed_pixels(out + "-tinyheld.png", out + "-tiny.png")
    print("the 5 m brush's cursor: %d pixels differ" % cursor)
    assert cursor >= 20, cursor


def check_fast(out):
    results, rows = snapshot(out, "stroke")
    radius = float(results["brush_radius"])
    path = [p for kind, p in picks(out)]
    assert len(path) == 2, path
    length = np.linalg.norm(path[1] - path[0])
    cover = stroke_cover(rows[:, :3], path, radius)
    beyond = np.min([distance_to_segment(rows[:, :3], path[0], path[1])], axis=0) > radius * (1 + 1e-9)
    m = rows[:, 6]
    assert cover.sum() >= 50, "%d vertices within 0.98 radius (%.1f m) of the path" % (cover.sum(), radius)
    print("fast stroke: %.1f km between two frames (%.1f radii), radius %.1f m; %d vertices "
          "within 0.98 radius of the path: %d painted 1 exactly, smallest %.9g; %d vertices "
          "changed beyond the radius" % (length / 1e3, length / radius, radius, cover.sum(),
                                          (m[cover] == 1.0).sum(), m[cover].min(),
                                          (m[beyond] != INITIAL).sum()))
    assert length > 8 * radius, (length, radius)
    assert np.all(m[cover] == 1.0), "gaps or a weaker value along the stroke"
    assert np.all(m[beyond] == INITIAL), "painted beyond the brush"


def check_undo(out):
    results, stroke = snapshot(out, "stroke")
    radius = float(results["brush_radius"])
    path = [p for kind, p in picks(out)][-3:]  # the stroke's press and moves (after the pull's)
    cover = stroke_cover(stroke[:, 3:6], path, radius)  # painted where it is shown
    rest, pulled = stroke[:, :3], stroke[:, 3:6]
    assert cover.sum() >= 20, "%d vertices within 0.98 radius (%.1f m) of the path" % (cover.sum(), radius)
    print("after a pull and a black stroke: edits %s, %d vertices moved; %d vertices within "
          "0.98 radius of the stroke, %d of them exactly 0, largest %.9g; %s point-dab values" % (
              results["edit_history"], (np.abs(pulled - rest).max(axis=1) > 0).sum(), cover.sum(),
              (stroke[cover, 6] == 0.0).sum(), stroke[cover, 6].max(), results["point_dab_values"]))
    assert results["edit_history"] == "1" and np.any(pulled != rest), "the pull was not committed"
    assert np.all(stroke[cover, 6] == 0.0), "the black swatch did not paint 0"
    black = (image(out + "-stroke.png").max(axis=1) < 16).mean()
    print("black pixels in the view: %.2f %%" % (100 * black))
    assert black > 0.002, black
    steps = {name: snapshot(out, name)
             for name in ("undo1", "undo2", "redo1", "redo2", "editundo", "editredo")}
    for name, (texts, rows) in steps.items():
        print("%s: edits %s, %d vertices painted, shape %s; dock %r" % (
            name, texts["edit_history"], (rows[:, 6] != INITIAL).sum(),
            "pulled" if np.array_equal(rows[:, 3:6], pulled) else
            "rest" if np.array_equal(rows[:, 3:6], rest) else "other", texts["label_Edits"]))
    # The dock counts what its Redo will restore: the stroke, then the pull too.
    for name, redoable in (("undo1", 1), ("undo2", 2), ("redo1", 1), ("redo2", 0)):
        label = steps[name][0]["label_Edits"]
        assert ("redoable %d" % redoable) in label, (name, label)
    t, rows = steps["undo1"]
    assert np.all(rows[:, 6] == INITIAL), "the first Undo did not take the stroke off"
    assert np.array_equal(rows[:, 3:6], pulled) and t["edit_history"] == "1", "the first Undo undid the pull"
    t, rows = steps["undo2"]
    assert np.array_equal(rows[:, 3:6], rest) and t["edit_history"] == "0", "the second Undo left the pull"
    assert np.all(rows[:, 6] == INITIAL), rows[:, 6]
    t, rows = steps["redo1"]
    assert np.array_equal(rows[:, 3:6], pulled) and np.all(rows[:, 6] == INITIAL), "Redo: the pull first"
    t, rows = steps["redo2"]
    assert np.array_equal(rows[:, 6], stroke[:, 6]), "the second Redo did not put the stroke back"
    t, rows = steps["editundo"]
    assert np.all(rows[:, 6] == INITIAL) and np.array_equal(rows[:, 3:6], pulled), \
        "Edit > Undo did not take the stroke off (alone)"
    t, rows = steps["editredo"]
    assert np.array_equal(rows[:, 6], stroke[:, 6]), "Edit > Redo did not put the stroke back"


def check_hover(out):
    """The brush cursor while hovering: at the surface point under the mouse, the brush's
    radius in world units, a cage; hidden without Ctrl, off the surface, out of the view.
    Hovering paints nothing."""
    steps = {name: snapshot(out, name)[0]
             for name in ("hover", "hover2", "noctrl", "off", "back", "ctrlup", "left")}
    kinds = [kind for kind, p in picks(out)]
    at = [p for kind, p in picks(out)]
    # Picks on the surface: hover, hover2, noctrl, back, and before leaving (the corner of
    # the view is off it).
    assert kinds == ["hover"] * 5, kinds
    for name, texts in steps.items():
        print("%-7s cursors %s %s" % (name, texts["cursors"], texts.get("cursor_0", "")))
    radius = float(steps["hover"]["brush_radius"])
    for name, pick in (("hover", at[0]), ("hover2", at[1]), ("back", at[3])):
        texts = steps[name]
        assert texts["cursors"] == "1", (name, texts)
        c = [float(v) for v in texts["cursor_0"].split()]
        print("%s: cursor %.3f m from the pick, radius %.3f m (brush %.3f m), representation %d"
              % (name, np.linalg.norm(np.array(c[:3]) - pick), c[3], radius, c[4]))
        assert np.linalg.norm(np.array(c[:3]) - pick) <= 1e-6 * radius, (name, c, pick)
        assert abs(c[3] - radius) <= 1e-9 * radius and c[4] == 1, (name, c, radius)
    for name in ("noctrl", "off", "ctrlup", "left"):
        assert steps[name]["cursors"] == "0", (name, steps[name])
    assert all(t["dab_values"] == "0" and t["point_dab_values"] == "0" for t in steps.values())
    cage = changed_pixels(out + "-hover.png", out + "-noctrl.png")
    print("the hovering cursor: %d pixels differ from the view without it" % cage)
    assert cage > 100, cage


def vector(results, key):
    return np.array([float(v) for v in results[key].split()])


def check_pull_keys(out):
    """Z mid-drag: the displacement does not jump at the key, the dock's Pull row shows
    Vertical only, and from then on x and y stay (dx = dy = 0) while z follows the cursor;
    Z again: free, without a jump, and x, y move again. The grasped vertex shows where the
    Displacement puts it."""
    steps = {name: snapshot(out, name)
             for name in ("free", "switched", "vertical", "freed", "free2", "released")}
    d = {name: vector(texts, "Displacement") for name, (texts, _) in steps.items()}
    for name, (texts, _) in steps.items():
        print("%-8s Pull row %s, grasp %s, Displacement %s" % (
            name, texts.get("pull_constraint"), texts["GraspPointId"], d[name]))
    free, switched, vertical = d["free"], d["switched"], d["vertical"]
    size = np.linalg.norm(free)
    assert size > 1e3 and abs(free[0]) > 1e-3 * size, "the free pull did not move: %s" % free
    assert steps["free"][0]["pull_constraint"] == "0", steps["free"][0]
    assert steps["switched"][0]["pull_constraint"] == "1", "Z did not switch to Vertical only"
    assert np.linalg.norm(switched - free) <= 1e-9 * size, ("a jump at the key", free, switched)
    assert vertical[0] == switched[0] and vertical[1] == switched[1], (switched, vertical)
    assert vertical[2] - switched[2] > 1e-2 * size, ("the vertical pull did not rise", vertical)
    assert steps["freed"][0]["pull_constraint"] == "0", "Z again did not free the pull"
    assert np.linalg.norm(d["freed"] - vertical) <= 1e-9 * size, ("a jump at the second key",)
    assert np.linalg.norm((d["free2"] - d["freed"])[:2]) > 1e-3 * size, d["free2"]
    for name in ("free", "vertical", "free2"):
        texts, rows = steps[name]
        grasp = int(texts["GraspPointId"])
        moved = rows[grasp, 3:6] - rows[grasp, :3]
        print("%s: the grasped vertex moved %s" % (name, moved))
        assert np.linalg.norm(moved - d[name]) <= 1e-6 * np.linalg.norm(d[name]), (name, moved)
    released, _ = steps["released"]
    assert released["edit_history"] == "1" and released["GraspPointId"] == "-1", released
    # The key's vertical lasted its drag: the dock shows the chosen mode again, and the next
    # drag follows the cursor (x and y move).
    keyed, _ = snapshot(out, "vertical2")
    nxt, _ = snapshot(out, "next")
    print("Z before the release: Pull row %s, %r; after it: %s, %r; next drag %s" % (
        keyed["pull_constraint"], keyed["label_PullMode"], released["pull_constraint"],
        released["label_PullMode"], vector(nxt, "Displacement")))
    assert keyed["pull_constraint"] == "1" and keyed["label_PullMode"].startswith("This drag"), keyed
    assert released["pull_constraint"] == "0", "the key's mode outlived its drag"
    assert released["label_PullMode"].startswith("Every pull: follow the cursor"), released
    assert np.linalg.norm(vector(nxt, "Displacement")[:2]) > 1e-3 * size, "the next drag is not free"
    print("keyed pull: dz %.1f m after Z, dx = dy = 0; at the keys |jump| = %g and %g m" % (
        vertical[2] - switched[2], np.linalg.norm(switched - free),
        np.linalg.norm(d["freed"] - vertical)))


def check(mode, out):
    {"brush_default": check_default, "brush_fast": check_fast, "brush_undo": check_undo,
     "brush_hover": check_hover, "pull_keys": check_pull_keys}[mode](out)
