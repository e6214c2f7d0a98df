"""GUI test (run by pvpython): paraview under xvfb-run loads the GeoShaping plugin, the
Haptics dock appears, a replayed stylus trace (Data/Traces/grasp_drag.trace) deforms the
fault-step horizon through the dock's interactor, and the plugin's test hook writes a
screenshot and figures. Checked here: the dock was shown, the grasped vertex moved by the
trace's drag mapped through the camera (docs/design.md, Haptics contract), the deformation spread to
its neighbours, and the screenshot shows the red (malleability 0.4) surface."""
import math
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_files import (DEPTH, WORKSPACE_RADIUS, device_axes, read_results, read_trace,  # noqa: E402
                       write_trace)
from gui_setup_camera import CAMERA  # noqa: E402
from gui_pull_check import check_pull  # noqa: E402
import gui_undo_checks  # noqa: E402
# Mode "replay": GEOSHAPING_HAPTICS_REPLAY is the trace; mode "mouse": the plugin's test
# hook drags the mouse itself (GEOSHAPING_HAPTICS_REPLAY=mouse); mode "openhaptics": hand 1
# is OpenHaptics on the fake HD library, which the hook faults; mode "state": paraview
# loads a state file with one edit (File > Load State) and the dock is started.

def expected_drag(trace_path):
    """The trace's motion from press to release, device coordinates -> scene."""
    samples = read_trace(trace_path)
    held = [s for s in samples if s[2] & 1]
    press, last = held[0][1], held[-1][1]
    d = [b - a for a, b in zip(press, last)]
    x, y, z, scale = device_axes()
    return [scale * (d[0] * x[i] + d[1] * y[i] + d[2] * z[i]) for i in range(3)]


# The touch test: a point of the horizon's upper plateau (the fault-step horizon is
# z = throw = 20 for x < 47) and its normal, the scene's +z.
PLATEAU_POINT = [20.0, 30.0, 20.0]
# The GUI stalls (the hook blocks its thread) 7.1 s into the trace for 1 s, the stylus
# resting below the plateau since 6.5 s: longer than a scene stays valid (at most 0.5 s),
# shorter than the servo holds contact against the last patch (2 s, docs/haptics.md).
TOUCH_STALL = (7.1, 1.0)


def write_touch_trace(path):
    """The stylus starts 1 cm above the plateau (along the surface normal in the device
    frame); holds the second button there and moves onto swatch 3 (0.3) of the 3D palette
    (the layout of HapticsControl.h's StylusPalette: 2 cm up, 1 cm apart, the row kept
    inside the 8 cm workspace), lets go, comes back, goes 2 mm below the surface and
    rests there, the palette shown again (second button held) for the screenshot.
    Returns the device-frame normal."""
    x, y, z, scale = device_axes()
    rel = [(p - f) / scale for p, f in zip(PLATEAU_POINT, CAMERA["focal_point"])]
    point = [sum(a[i] * rel[i] for i in range(3)) for a in (x, y, z)]
    normal = [a[2] for a in (x, y, z)]  # A^T e_z
    above = [c + 0.01 * n for c, n in zip(point, normal)]
    room = WORKSPACE_RADIUS - 0.05
    swatch = [min(max(above[0], -room), room) + 0.01 * (3 - 5), above[1] + 0.02, above[2]]
    below = [c - DEPTH * n for c, n in zip(point, normal)]

    def lerp(a, b, f):
        return [u + (v - u) * min(1.0, max(0.0, f)) for u, v in zip(a, b)]

    # The button is held 2 s before the stylus moves, so the first frame that sees it lays
    # the row out from `above`; then 2 s on the swatch: frames see both even when a loaded
    # machine leaves 1.5 s between two frames (0.5 s was missed at 4.8 frames/s under two
    # busy loops: no frame came between 0.42 and 1.30 s).
    def sample(t):
        if t < 0.5:
            return above, 0
        if t < 2.5:
            return above, 2
        if t < 5.0:
            return lerp(above, swatch, (t - 2.5) / 0.5), 2
        if t < 5.5:
            return lerp(swatch, above, (t - 5.0) / 0.5), 0
        return lerp(above, below, t - 5.5), (2 if t >= 6.5 else 0)

    write_trace(path, "palette pick, then touch the plateau", 8.5, sample)
    return normal


# The bimanual test: hand 2 paints (value 1) where hand 1's drag has lifted the surface,
# from 3.0 to 3.8 s while hand 1 holds still at the end of its drag (grasp_drag.trace).
PAINT_AT = [-0.03, 0.024, 0.022]  # device coordinates: grasp_drag's press + its drag
PLATEAU_Z = 20.0  # the rest surface under the grasp


def write_paint_trace(path):
    write_trace(path, "hand 2 paints on the lifted surface", 4.5,
                lambda t: (PAINT_AT, 1 if 3.0 <= t < 3.8 else 0))


def check_bimanual(results):
    """Hand 2's dabs landed on the surface the user saw (deformed by hand 1's drag), not
    on the rest surface: the brush is farther than its radius from the rest plateau, and
    yet vertices were painted, through PointDabs only."""
    x, y, z, scale = device_axes()
    f = CAMERA["focal_point"]
    height = f[2] + scale * sum(PAINT_AT[i] * (x, y, z)[i][2] for i in range(3)) - PLATEAU_Z
    radius = float(results["brush_radius"])
    print("hand 2 paints %.2f above the rest plateau (brush radius %.1f): %s painted, "
          "%s point-dab values, %s dab values" % (height, radius, results["painted_vertices"],
                                                  results["point_dab_values"],
                                                  results["dab_values"]))
    assert height > radius, (height, radius)
    assert int(results["painted_vertices"]) > 0, results
    assert float(results["smallest_paint_increase"]) > 0, results
    assert int(results["point_dab_values"]) > 0 and int(results["dab_values"]) == 0, results


# The hold-and-turn test: hand 1 presses, then moves by TURN_MOVE (device metres) while
# turning 30 degrees about the device's y axis (the screen's up), and releases.
TURN_PRESS = [-0.01, 0.0, 0.01]
TURN_MOVE = [0.01, 0.005, 0.0]
TURN_DEGREES = 30.0


def write_turn_trace(path):
    half = math.radians(TURN_DEGREES) / 2

    def sample(t):
        a = min(1.0, max(0.0, t - 1.5))  # still while pressed 1.0-1.5 s, then 1 s of motion
        p = [c + a * m for c, m in zip(TURN_PRESS, TURN_MOVE)]
        return p, (1 if 1.0 <= t < 3.5 else 0), (math.cos(a * half), 0.0, math.sin(a * half), 0.0)

    write_trace(path, "hold and turn the horizon", 4.0, sample)


def check_turn(results):
    """The horizon's representation matrix is the stylus's motion since the press, in the
    scene: rotation A R_y(30) A^T about the stylus tip at the press, plus the drag."""
    x, y, z, scale = device_axes()
    f = CAMERA["focal_point"]
    A = [[x[i], y[i], z[i]] for i in range(3)]  # columns: the screen axes in the scene
    c, s = math.cos(math.radians(TURN_DEGREES)), math.sin(math.radians(TURN_DEGREES))
    Ry = [[c, 0, s], [0, 1, 0], [-s, 0, c]]

    def mul(P, Q):
        return [[sum(P[i][k] * Q[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    At = [[A[j][i] for j in range(3)] for i in range(3)]
    R = mul(mul(A, Ry), At)
    pivot = [f[i] + scale * sum(A[i][k] * TURN_PRESS[k] for k in range(3)) for i in range(3)]
    move = [scale * sum(A[i][k] * TURN_MOVE[k] for k in range(3)) for i in range(3)]
    t = [pivot[i] + move[i] - sum(R[i][k] * pivot[k] for k in range(3)) for i in range(3)]
    got = [float(v) for v in results["object_matrix"].split()]
    expected = [R[0][0], R[0][1], R[0][2], t[0], R[1][0], R[1][1], R[1][2], t[1],
                R[2][0], R[2][1], R[2][2], t[2], 0, 0, 0, 1]
    print("object matrix", got, "expected", expected)
    assert all(abs(a - b) < 1e-6 * (1 + abs(b)) for a, b in zip(got, expected)), (got, expected)
    assert int(results["moved_points"]) == 0, "holding and turning must not deform"


def check_touch(results, normal):
    """At rest 2 mm into the plateau, the force asked of the servo loop is the penalty
    contact k_c d = 800 N/m * 2 mm = 1.6 N along the surface's normal (device coordinates)."""
    force = [float(v) for v in results["force_from_last_scene"].split()]
    expected = [800.0 * DEPTH * n for n in normal]
    print("touch force", force, "expected", expected, "triangles sent (max)",
          results["max_contact_triangles"])
    assert results["force_status"] == "ok" and results["in_contact_last_scene"] == "1", results
    assert all(abs(a - b) < 1e-3 for a, b in zip(force, expected)), (force, expected)
    assert 0 < int(results["max_contact_triangles"]) <= 256, results
    # And the servo loop itself rendered it: its snapshots, taken by the interactor once a
    # frame, reported contact (the scene stays valid for three frames, at most 0.5 s).
    # The contact survived the GUI's stall (TOUCH_STALL) with the stylus under the plateau:
    # the servo kept its proxy (before, it started afresh under the surface, no contact).
    assert float(results["gui_stall_seconds"]) >= TOUCH_STALL[1], results
    assert int(results["contact_ticks"]) > 0, results
    assert int(results["moved_points"]) == 0, "touching must not deform"
    assert abs(float(results["brush_value"]) - 0.3) < 1e-12, "the 3D palette pick: " + results["brush_value"]


def red_fraction(png):
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)
    r, g, b = pixels[:, 0], pixels[:, 1], pixels[:, 2]
    return float(((r > 90) & (g < 0.45 * r) & (b < 0.45 * r)).mean()), image.GetDimensions()


def screen_axes():
    pos, foc, up = CAMERA["position"], CAMERA["focal_point"], CAMERA["view_up"]
    z = [p - f for p, f in zip(pos, foc)]
    n = math.sqrt(sum(c * c for c in z))
    return [c / n for c in z], up


def check_mouse(results):
    """The mouse dragged 60 px up on the surface: the grasped vertex moved up the screen,
    and the camera did not turn (the interactor style never saw the drag)."""
    toward_viewer, screen_up = screen_axes()
    d = [float(v) for v in results["last_displacement"].split()]
    length = math.sqrt(sum(c * c for c in d))
    up = sum(a * b for a, b in zip(d, screen_up))
    print("mouse drag", d, "screen-up part", up)
    assert length > 1.0 and up > 0.99 * length, d
    camera = [float(v) for v in results["camera_position"].split()]
    assert all(abs(a - b) < 1e-6 for a, b in zip(camera, CAMERA["position"])), camera
    assert int(results["moved_points"]) > 1, results
    # The dock says the mouse has no servo (not "servo 0 Hz"), how to grasp and paint, and
    # its messages wrap instead of widening the dock.
    figures = results["label_Figures"]
    assert "hand 1: mouse, no force feedback" in figures and "servo" not in figures, figures
    assert "Ctrl" in results["label_Help"] and "left-drag" in results["label_Help"], results
    for name in ("Figures", "Help", "Edits"):
        assert results["label_%s_wraps" % name] == "1", name


def check_recording(results, out, expected):
    """The dock recorded hand 1 to <out>.recorded.trace (the hook sets "Record traces
    to"): a trace that reads back, in time order, whose press-to-release motion maps to
    `expected` (the drag the test checks) — replaying it repeats the edit."""
    path = out + ".recorded.trace"
    samples = read_trace(path)
    print("recorded", len(samples), "samples to", path)
    assert len(samples) == int(results["recorded_samples"]) and len(samples) >= 5, results
    assert all(a[0] < b[0] for a, b in zip(samples, samples[1:])), "times must increase"
    if expected is not None:
        got = expected_drag(path)
        scale = math.sqrt(sum(c * c for c in expected))
        assert all(abs(a - b) <= 1e-6 * scale for a, b in zip(got, expected)), (got, expected)


def check_edits(results):
    """Releasing the Deform tool committed the edit (docs/editing.md): one record in
    EditHistory, the proxy released (GraspPointId -1), the points stay deformed; the
    dock's Undo gives back the rest points exactly (==), Redo the released ones."""
    print("edits:", {k: v for k, v in results.items() if "edit" in k or "release" in k or "equal" in k})
    assert results.get("edit_buttons") == "1", results
    assert results["edit_history"] == "1" and results["release_commits"] == "1", results
    assert results["grasp_point_id_after_release"] == "-1", results
    assert results["released_differs_from_rest"] == "1", results
    assert results["edit_history_after_undo"] == "0", results
    assert results["undo_equals_rest"] == "1", "after Undo the points are not the rest points"
    assert results["edit_history_after_redo"] == "1", results
    assert results["redo_equals_released"] == "1", "after Redo the points are not the released ones"


def check_sparse_frames(results):
    """The dock's drag was drawn by the GeoShaping Surface representation (the default for
    ChainMailDeformation, docs/rendering.md) and its frames followed the moved points:
    after the first full draw, drag frames updated and uploaded only what changed."""
    print("representation:", {k: v for k, v in results.items() if k.startswith(("repr", "Number"))})
    assert results.get("representation") == "GeoShaping Surface", results
    sparse, full = int(results["NumberOfSparseUpdates"]), int(results["NumberOfFullUpdates"])
    assert sparse >= 3 and full < sparse, results
    assert int(results["NumberOfSparseBuilds"]) >= 3, results


def check_openhaptics_fault(results):
    """Hand 1 ran OpenHaptics on the fake HD library (the dock offered it because
    GEOSHAPING_LIBHD names that file); after the injected HD_DEVICE_FAULT the dock's
    figures say so for hand 1, the device was last sent exactly zero force, and paraview
    carried on (the hook wrote its results and quit normally)."""
    figures = results["label_Figures"]
    print("figures:", figures, "fake force:", results.get("fake_last_force"))
    assert "hand 1: OpenHaptics: HD_DEVICE_FAULT (0x0300" in figures, figures
    assert "force output stopped" in figures, figures
    assert results.get("fake_last_force") == "0 0 0", results


def main():
    mode = sys.argv[1] if len(sys.argv) > 1 else "replay"
    out = os.path.join(os.environ["GEOSHAPING_TEST_TMP"], "gui_" + mode)
    for suffix in (".txt", ".png", "-view.png", ".recorded.trace", ".pvsm"):
        if os.path.exists(out + suffix):
            os.remove(out + suffix)
    if mode == "pvserver":
        import gui_pvserver
        gui_pvserver.run(out, read_results)
        return
    if mode in ("pvserver_pull_rank1", "pvserver_remote_pull_rank1"):
        import gui_pvserver
        gui_pvserver.run_pull_rank1(out, read_results, remote_render=mode.startswith(
            "pvserver_remote"))
        return
    if mode in ("pvserver_paint", "pvserver_paint_remote", "pvserver_stylus", "pvserver_touch",
                "pvserver_touch_remote"):
        import gui_pvserver_hands
        hands = gui_pvserver_hands
        if mode == "pvserver_stylus":
            hands.run_stylus(out, read_results)
        elif mode.startswith("pvserver_touch"):
            hands.run_touch(out, read_results, remote_render=mode == "pvserver_touch_remote")
        else:
            hands.run_paint(out, read_results, remote_render=mode == "pvserver_paint_remote")
        return
    env = dict(os.environ, GEOSHAPING_HAPTICS_TEST_OUTPUT=out)
    scripted = None  # a module with the mode's script: prepare(), check()
    if mode.startswith("dem_"):
        import dem_checks as scripted
    elif mode.startswith("obstacle_"):
        import obstacle_checks as scripted
    elif mode.startswith("brush_") or mode == "pull_keys":  # brush_checks.SCRIPTS
        import brush_checks as scripted
    if scripted:
        scripted.prepare(mode, out, env)
    if mode == "touch":
        env["GEOSHAPING_HAPTICS_REPLAY"] = out + ".trace"
        env["GEOSHAPING_HAPTICS_STALL"] = "%g,%g" % TOUCH_STALL
        normal = write_touch_trace(out + ".trace")
    if mode == "turn":
        env["GEOSHAPING_HAPTICS_REPLAY"] = out + ".trace"
        env["GEOSHAPING_HAPTICS_TOOL1"] = "hold_and_turn"
        write_turn_trace(out + ".trace")
    setup = env["GEOSHAPING_GUI_SETUP"]
    if mode == "pull":
        setup = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gui_setup_pull.py")
    if mode == "bimanual":
        env["GEOSHAPING_HAPTICS_REPLAY2"] = out + ".hand2.trace"
        write_paint_trace(out + ".hand2.trace")
    script = ["--script=" + setup]
    if mode == "state":
        env["GEOSHAPING_HAPTICS_REPLAY"] = "state"
        env["GEOSHAPING_GUI_STATE"] = out + ".pvsm"
        gui_undo_checks.write_state(out + ".pvsm")
        script = []  # the state is the scene
    command = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24 -noreset", os.environ["PARAVIEW"],
               "--dr"] + script
    run = subprocess.run(command, env=env, timeout=90, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    print(run.stdout[-4000:])
    assert os.path.exists(out + ".txt"), "paraview wrote no results (exit code %d)" % run.returncode
    results = read_results(out + ".txt")
    print("results:", results)
    assert results["started"] == "1" and results["timed_out"] == "0", results
    assert results["dock_visible"] == "1" and results["dock_title"] == "Haptics", results
    assert int(results["frames"]) >= 5, "too few interactor frames"
    if scripted:
        scripted.check(mode, out)
        print("GUI %s test passed; screenshots:" % mode, out + "-*.png")
        return
    if mode == "openhaptics":
        check_openhaptics_fault(results)
        check_recording(results, out, None)
        print("GUI OpenHaptics fault test passed")
        return
    if mode == "pull":
        check_pull(results)
        print("GUI pull test passed; screenshots:", out + "-*.png")
        return
    if mode == "turn":
        check_turn(results)
        check_recording(results, out, None)
        print("GUI hold-and-turn test passed")
        return
    if mode == "state":
        gui_undo_checks.check_loaded_state(results)
        print("GUI Load State test passed; screenshot:", out + "-view.png")
        return
    if mode == "touch":
        check_touch(results, normal)
        check_recording(results, out, None)
        print("GUI touch test passed")
        return
    check_sparse_frames(results)
    check_edits(results)
    if mode in ("replay", "mouse"):
        gui_undo_checks.check_edit_menu(results)
    if mode == "mouse":
        check_mouse(results)
        check_recording(results, out, [float(v) for v in results["last_displacement"].split()])
        print("GUI mouse test passed; screenshot:", out + "-view.png")
        return

    expected = expected_drag(os.environ["GEOSHAPING_HAPTICS_REPLAY"])
    sent = [float(v) for v in results["last_displacement"].split()]
    moved = [float(v) for v in results["max_displacement"].split()]
    tolerance = 1e-3 * math.sqrt(sum(c * c for c in expected))
    print("expected drag", expected, "sent", sent, "largest output motion", moved)
    assert all(abs(a - b) <= tolerance for a, b in zip(sent, expected)), (sent, expected)
    check_recording(results, out, expected)
    assert all(abs(a - b) <= 1e-4 + tolerance for a, b in zip(moved, expected)), (moved, expected)
    assert 1 < int(results["moved_points"]) < int(results["output_points"]), results
    # The figure is read at the release, before the commit (after it the filter shows
    # the committed shape with no grasp, and reports 0 displaced points).
    assert int(results["displaced_at_release"]) == int(results["moved_points"]), results

    fraction, size = red_fraction(out + "-view.png")
    print("view screenshot %s: %.1f %% red pixels" % (size, 100 * fraction))
    assert size[0] >= 200 and size[1] >= 200 and fraction > 0.05, (size, fraction)
    window_size = red_fraction(out + ".png")[1]
    assert window_size[0] > size[0], "the window screenshot should show the dock beside the view"
    if mode == "bimanual":
        check_bimanual(results)
    print("GUI test passed; screenshots:", out + ".png", out + "-view.png")


if __name__ == "__main__":
    main()
