"""The hands of the Haptics dock on `mpiexec -n 2 pvserver` (docs/mpi.md, "The GUI client
on a distributed server"), with the harness of gui_pvserver.py:

- paint (run_gui_test.py pvserver_paint): a Ctrl+drag of the mouse paints a stroke on
  the horizon, whose MalleabilityPaint runs on each rank's piece (geodesic); the dock's
  Undo takes it off and Redo puts it back. After each step every rank's malleability,
  ghosts included, equals one process's from the same dabs, bit for bit.
  pvserver_paint_remote: the same with the Remote Render Threshold at 0 (the client
  holds no geometry: the pick asks the ranks, docs/mpi.md "Picking on several ranks").
- stylus (pvserver_stylus): a replayed stylus trace (deterministic input: every step
  the frames must see is held still for 3-4 s) touches the plateau, grasps it near the
  step and drags across the seam of the pieces;
  the release commits and the dock's Undo undoes. Every rank's points equal one
  process's; the force the stylus is asked to render while it holds the drag is finite
  and equal to a builtin (one-process) paraview's on the same trace and to
  k(m) (anchor - stylus) computed here; touching the plateau without a grasp is felt as
  in one process (the contact patch asked of the ranks, docs/haptics.md "The contact
  patch on a server").
- touch (pvserver_touch, pvserver_touch_remote): a replayed stylus comes down 2 mm into
  the lower plateau, rank 1's piece, without a button; the force the servo is asked for
  equals a builtin paraview's on the same trace within 1e-9 N (800 N/m x 2 mm along the
  normal), with the client rendering (the default threshold) or the server rendering
  (Remote Render Threshold 0, checked in the client's log), and the dock shows the
  patch's round trip; with the client rendering every patch is taken as late (a budget
  of 0 ms): every other frame keeps the last patch, the dock says so, the force is the
  same."""
import numpy as np

import gui_pvserver as harness
from gui_pvserver import RANKS, check_session, check_shape, gathered, prepare, read_figures
from gui_files import DEPTH, device_axes, write_trace
from gui_setup_camera import CAMERA

# A stroke across the fault step, where the ranks' pieces meet (x = 50: rank 0 the upper
# plateau, rank 1 the lower).
PAINT_STEPS = ("press 0.3 0.5 ctrl; move 0.35 0.5; move 0.4 0.5; move 0.45 0.5; move 0.5 0.5; "
               "move 0.55 0.5; move 0.6 0.5; release; wait; dump paint; undo; wait; dump undo; "
               "redo; wait; dump redo")


def one_process_paint(figures):
    """The paint of dump `figures` in this (one) process, on the whole horizon: {global id:
    malleability} painted and unpainted, the points numbered by coordinates as several
    processes number them."""
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from mpi_pipeline import COORDINATE_RANKS
    horizon = simple.FaultStepHorizon(PaintFigure5C=1)
    paint = simple.MalleabilityPaint(Input=horizon, **harness.PAINT)
    paint.Dabs = [float(v) for v in figures.get("Dabs", "").split()]
    paint.PointDabs = [float(v) for v in figures.get("PointDabs", "").split()]
    ids = simple.ProgrammableFilter(Input=paint, Script=COORDINATE_RANKS)
    ids.UpdatePipeline()
    data = ids.GetClientSideObject().GetOutputDataObject(0)
    gid = vtk_to_numpy(data.GetPointData().GetGlobalIds())
    painted = vtk_to_numpy(data.GetPointData().GetArray("Malleability")).astype(float)
    rest = horizon.GetClientSideObject().GetOutputDataObject(0).GetPointData()
    rest = vtk_to_numpy(rest.GetArray("Malleability")).astype(float)
    for proxy in (ids, paint, horizon):
        simple.Delete(proxy)
    return ({int(g): m for g, m in zip(gid, painted)}, {int(g): m for g, m in zip(gid, rest)})


def run_paint(out, read_results, remote_render=False):
    """`remote_render`: the server renders and the client holds no geometry (the pick
    asks the ranks; harness.session)."""
    prepare(out)
    harness.write_state(out + "-scene.pvsm", out, paint_pieces=True)
    prefix = harness.session(out, "paint", PAINT_STEPS, out + "-scene.pvsm",
                             remote_render=remote_render)
    results = read_results(prefix + ".txt")
    check_session(results, "Edits: 0, redoable 0 (paint stroke redone)")
    # The dock shows the round trip of the ranks' pick when the view renders remotely.
    print("dock:", results["label_Figures"])
    assert ("last pick on the server: " in results["label_Figures"]) == remote_render, results
    painted = {}
    for name in ("paint", "undo", "redo"):
        figures = read_figures("%s-%s.txt" % (prefix, name))
        painted[name], pieces = gathered(out, name, "m")
        expected, rest = one_process_paint(figures)
        dabs = len(figures.get("Dabs", "").split()) // 6
        for r, (gid, m, mine) in enumerate(pieces):
            # Each rank's malleability, ghosts too, against one process's, bit for bit.
            same = all(np.array_equal(expected[int(g)], v) for g, v in zip(gid, m))
            here = sum(expected[int(g)] != rest[int(g)] for g in gid[mine])
            print("  %s rank %d: %d points (%d owned, %d of them painted), equal to one "
                  "process: %s" % (name, r, len(gid), mine.sum(), here, same))
            assert same, "%s: rank %d's malleability differs from one process" % (name, r)
            if name != "undo":
                assert here > 0, "%s: the stroke painted no point of rank %d" % (name, r)
        changed = sum(painted[name][g] != rest[g] for g in rest)
        print("%s: %d dabs, %d point dabs, %d points painted" % (
            name, dabs, len(figures.get("PointDabs", "").split()) // 3, changed))
        assert painted[name].keys() == expected.keys(), name
        assert len(figures.get("PointDabs", "").split()) == 0, "no edit: dabs are positional"
        if name == "undo":
            assert dabs == 0 and changed == 0, "undo left paint"
        else:
            assert dabs >= 4 and changed > 20, figures
            # The stroke follows the mouse down the step onto the lower plateau (z = 0,
            # x > 53: rank 1's piece), where its last move is.
            xyz = np.array([float(v) for v in figures["Dabs"].split()]).reshape(-1, 6)[:, :3]
            print("  dabs from %s to %s" % (xyz[0], xyz[-1]))
            assert xyz[-1][0] > 53.0 and abs(xyz[-1][2]) < 1e-6, "the stroke stops at the seam"
    assert all(np.array_equal(painted["redo"][g], painted["paint"][g]) for g in painted["paint"])
    print("GUI paint test on a %d-rank pvserver passed" % RANKS)


# The stylus: a point of the upper plateau near the step (the horizon is z = 20 for
# x < 47), so that the drag reaches the lower plateau's piece (rank 1, x > 50); the drag
# (device coordinates) small enough that the coupling stays below the device's 3.3 N (a
# saturated force would hide the grasp's stiffness).
STYLUS_POINT = [44.0, 30.0, 20.0]
DRAG = np.array([0.0, 0.004, 0.002])
# Each dump in the middle of a still stretch of the trace (`until T`: T s of the trace's
# clock), 2 s before it ends: the frame the dump follows saw the stylus there at 1 frame/s.
STYLUS_STEPS = ("until 5; dump touch; until 15; dump drag; until 19; dump commit; undo; wait; "
                "dump undo")


def write_stylus_trace(path):
    """Above STYLUS_POINT 1 cm (0-2 s), 2 mm into it (3-7 s, no button), back to 0.5 mm
    above it (8 s), the button pressed there at 9 s and held still 3 s, the drag in 1 s,
    held still 4 s, released at 17 s and still to the end (21 s). Returns (the stylus at
    the press, at the drag's end, the surface normal), device coordinates."""
    x, y, z, scale = device_axes()
    rel = [(p - f) / scale for p, f in zip(STYLUS_POINT, CAMERA["focal_point"])]
    point = np.array([sum(a[i] * rel[i] for i in range(3)) for a in (x, y, z)])
    normal = np.array([a[2] for a in (x, y, z)])
    above, below, press = point + 0.01 * normal, point - DEPTH * normal, point + 0.0005 * normal
    hold = press + DRAG
    path_points = [(0, above), (2, above), (3, below), (7, below), (8, press), (12, press),
                   (13, hold), (21, hold)]

    def sample(t):
        for (t0, a), (t1, b) in zip(path_points, path_points[1:]):
            if t <= t1:
                f = (t - t0) / (t1 - t0)
                return list(a + f * (b - a)), (1 if 9 <= t < 17 else 0)
        return list(hold), 0

    write_trace(path, "touch, grasp and drag the plateau", 21.0, sample)
    return press, hold, normal


def force(figures):
    return np.array([float(v) for v in figures["force_from_last_scene"].split()])


def run_stylus(out, read_results):
    prepare(out)
    harness.write_state(out + "-scene.pvsm", out)
    press, hold, normal = write_stylus_trace(out + ".trace")
    ranks = harness.session(out, "ranks", STYLUS_STEPS, out + "-scene.pvsm", hand=out + ".trace")
    one = harness.session(out, "one", STYLUS_STEPS.replace("dump ", "dump one_"),
                          out + "-scene.pvsm", hand=out + ".trace", ranks=0)
    check_session(read_results(ranks + ".txt"), "Edits: 0, redoable 1")
    check_session(read_results(one + ".txt"), "Edits: 0, redoable 1", ranks=0)
    # The drag: the Displacement sent is the trace's press-to-hold motion through the
    # camera (the frames saw both ends), the same with one process; each rank's points
    # equal one process's after the drag, the commit and the undo.
    x, y, z, scale = device_axes()
    expected = scale * (DRAG[0] * np.array(x) + DRAG[1] * np.array(y) + DRAG[2] * np.array(z))
    shape, figures, moved, m, by_rank = check_shape(out, ranks, "drag")
    alone = read_figures(one + "-one_drag.txt")
    sent = np.array([float(v) for v in figures["Displacement"].split()])
    print("drag: sent", sent, "expected", expected, "one process sent", alone["Displacement"])
    assert np.allclose(sent, expected, rtol=0, atol=1e-9 * np.linalg.norm(expected)), sent
    assert figures["Displacement"] == alone["Displacement"], (figures, alone)
    assert figures["last_grasp_malleability"] == alone["last_grasp_malleability"]
    assert moved > 20 and min(by_rank) > 0, "the drag must move points of both ranks"
    _, committed, _, _, _ = check_shape(out, ranks, "commit")
    assert committed["edit_history"] == "1", committed
    _, undone, moved_after_undo, _, _ = check_shape(out, ranks, "undo")
    assert moved_after_undo == 0 and undone["edit_history"] == "0", undone
    # The force while the drag is held: the coupling k(m) (anchor - stylus), the anchor
    # the stylus at the press, k(m) = k_max (0.8 (1 - m) + 0.15 m) of the grasped point's
    # malleability (the default DeviceLimits and ForceParams, docs/haptics.md).
    k = 1000.0 * (0.8 * (1.0 - m) + 0.15 * m)
    pull = k * (press - hold)
    felt, felt_alone = force(figures), force(alone)
    print("drag force: %s ranks %s, one process %s, k(%g) (anchor - stylus) = %s"
          % (RANKS, felt, felt_alone, m, pull))
    assert np.isfinite(felt).all() and figures["force_status"] == "ok", figures
    assert np.array_equal(felt, felt_alone), (felt, felt_alone)
    assert np.allclose(felt, pull, rtol=0, atol=1e-9), (felt, pull)
    assert np.linalg.norm(felt) < 3.3, "saturated: the stiffness would not show"
    # Touching the plateau without a grasp: the servo gets the triangles near the stylus
    # (800 N/m x 2 mm along the normal), on the server from the ranks' pieces.
    check_touch(read_figures(ranks + "-touch.txt"), read_figures(one + "-one_touch.txt"), normal)
    print("GUI stylus test on a %d-rank pvserver passed" % RANKS)


def check_touch(touch, touch_alone, normal):
    """The force at rest of a touch without a grasp on the server (`touch`) equals one
    process's (`touch_alone`) within 1e-9 N, and is the penalty contact k_c d along the
    surface's normal; the dock shows the server patch's round trip."""
    print("touch force: %d ranks %s, one process %s" % (RANKS, force(touch), force(touch_alone)))
    print("  dock: %s" % touch.get("label_Figures"))
    for figures in (touch, touch_alone):
        assert figures["in_contact_last_scene"] == "1" and figures["force_status"] == "ok", figures
    assert np.allclose(force(touch_alone), 800.0 * DEPTH * normal, rtol=0, atol=1e-3)
    assert np.allclose(force(touch), force(touch_alone), rtol=0, atol=1e-9), (touch, touch_alone)
    # The round trip ("contact patch from the server: ms, bytes"), or in a frame that kept
    # the last patch, why ("the contact patch from the server came late").
    assert "contact patch from the server" in touch["label_Figures"], touch["label_Figures"]
    assert "contact patch from the server" not in touch_alone["label_Figures"], touch_alone


# A point of the lower plateau (z = 0 for x > 53), rank 1's piece, far enough from the
# seam (x = 50) that the patch (13.4 scene units each way: ContactReachMetres) is all
# rank 1's.
TOUCH_POINT = [70.0, 30.0, 0.0]
TOUCH_STEPS = "until 7; dump touch"


def run_touch(out, read_results, remote_render=False):
    """A stylus 1 cm above TOUCH_POINT (0-2 s), 2 mm into it at 3 s and still to 9 s, no
    button; the dump in the middle of the still stretch, on the 2-rank server (the view
    rendering remotely with `remote_render`) and in a builtin session."""
    prepare(out)
    harness.write_state(out + "-scene.pvsm", out)
    x, y, z, scale = device_axes()
    rel = [(p - f) / scale for p, f in zip(TOUCH_POINT, CAMERA["focal_point"])]
    point = np.array([sum(a[i] * rel[i] for i in range(3)) for a in (x, y, z)])
    normal = np.array([a[2] for a in (x, y, z)])
    above, below = point + 0.01 * normal, point - DEPTH * normal

    def sample(t):
        f = min(1.0, max(0.0, t - 2.0))
        return list(above + f * (below - above)), 0

    write_trace(out + ".trace", "touch the lower plateau", 9.0, sample)
    # Remote rendering: the test hook sets the view's threshold to 0 after the state. Local
    # rendering: every patch counts as late (a budget of 0 ms), so every other frame
    # keeps the last one, which must change nothing but the dock's message.
    late = {} if remote_render else {"GEOSHAPING_HAPTICS_PATCH_BUDGET_MS": "0"}
    ranks = harness.session(out, "ranks", TOUCH_STEPS, out + "-scene.pvsm", hand=out + ".trace",
                            remote_render=remote_render, env=late)
    one = harness.session(out, "one", TOUCH_STEPS.replace("dump ", "dump one_"),
                          out + "-scene.pvsm", hand=out + ".trace", ranks=0)
    check_session(read_results(ranks + ".txt"), "Edits: 0, redoable 0")
    check_session(read_results(one + ".txt"), "Edits: 0, redoable 0", ranks=0)
    touch = read_figures(ranks + "-touch.txt")
    _, _, moved, _, by_rank = check_shape(out, ranks, "touch")
    assert moved == 0, "touching must not deform"
    check_touch(touch, read_figures(one + "-one_touch.txt"), normal)
    if not remote_render:  # every patch late (whether one is late otherwise is the machine's)
        assert "came late" in touch["label_Figures"], touch["label_Figures"]
    print("GUI touch test (rank 1's piece, %s rendering) on a %d-rank pvserver passed"
          % ("remote" if remote_render else "local", RANKS))
