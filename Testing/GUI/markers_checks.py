"""The GUI test of the markers' misfit in the dock (run_gui_test.py mode markers_dock):
markers 0.5 above every seventh interior vertex of the fault-step horizon on the
ChainMailDeformation's Markers (gui_setup_markers.py); the mouse, through the Haptics
dock, drags the plateau up, vertically (key Z). Checked from the hook's snapshots
(TestHook/pqHapticsTestScript.h): while dragging the dock says "markers: vertical misfit
RMS r, max m (n inside)" with r, m and n those computed here from the shown surface (a
marker over a vertex reads it where the vertex is: a vertical pull keeps x and y), and
different from the rest's 0.5; the release clears the line. Then the dock's "Snap to
markers": one more edit, after which a vertex of the shown surface lies at each marker
(within 1e-6 of the surface's size); its Undo gives the released shape bit for bit, its
Redo the snapped one. Before the snap, the dock's "Show markers" draws them: a Marker
Misfit filter shown as Point Gaussian spheres coloured by Misfit on a range symmetric
about 0."""
import re

import numpy as np

from brush_checks import mouse_script, snapshot

SCRIPT = ("wait; press 0.4 0.6; key Z; move 0.4 0.65; move 0.4 0.7; move 0.4 0.75; wait; "
          "snapshot held; release; wait; snapshot released; showmarkers; wait; wait; "
          "snapshot shown; snap; wait; snapshot snapped; "
          "undo; wait; snapshot undone; redo; wait; snapshot redone")
LINE = re.compile(r"markers: vertical misfit RMS (\S+), max (\S+) \((\d+) inside\)")


def prepare(mode, out, env):
    mouse_script(env, SCRIPT, "gui_setup_markers.py")


def expected_figures(rest, shown):
    """gui_setup_markers.py's markers read against the shown surface, independently of the
    filter: each marker's crossing is the shown z, nearest to the marker, of the vertices
    at its (x, y) (a vertical wall puts two there)."""
    from gui_setup_markers_rule import markers

    misfits = []
    for v, marker in markers(rest):
        same = np.flatnonzero(np.all(rest[:, :2] == rest[v, :2], axis=1))
        z = shown[same, 2][np.argmin(np.abs(shown[same, 2] - marker[2]))]
        misfits.append(z - marker[2])
    misfits = np.array(misfits)
    return np.sqrt(np.mean(misfits ** 2)), np.abs(misfits).max(), len(misfits)


def check(mode, out):
    held, points = snapshot(out, "held")
    rest, shown = points[:, :3], points[:, 3:6]
    figures = held["label_Figures"]
    print("held: grasp %s, Displacement %s; dock: %r" % (
        held["GraspPointId"], held["Displacement"], figures))
    found = LINE.search(figures)
    assert found, "no markers line in the dock while dragging: %r" % figures
    rms, top, inside = float(found.group(1)), float(found.group(2)), int(found.group(3))
    want = expected_figures(rest, shown)
    print("dock: RMS %g, max %g, %d inside; computed here: RMS %g, max %g, %d" % (
        (rms, top, inside) + want))
    assert np.abs(shown[:, 2] - rest[:, 2]).max() > 1.0, "the drag moved nothing"
    assert np.allclose(shown[:, :2], rest[:, :2], rtol=0, atol=1e-9), "the pull was not vertical"
    assert inside == want[2], (inside, want)
    assert abs(rms - want[0]) <= 1e-3 * want[0] and abs(top - want[1]) <= 1e-3 * want[1], (
        rms, top, want)
    assert abs(rms - 0.5) > 1e-3, "the drag did not change the misfit"

    released, _ = snapshot(out, "released")
    print("released: edits %s, dock %r" % (released["edit_history"], released["label_Figures"]))
    assert released["edit_history"] == "1", released
    assert "markers:" not in released["label_Figures"], released

    from gui_setup_markers_rule import markers

    shown_markers, _ = snapshot(out, "shown")
    print("shown: %s as %s coloured by %s, range %s, visible %s" % (
        shown_markers.get("marker_misfit_points"),
        shown_markers.get("marker_misfit_representation"),
        shown_markers.get("marker_misfit_color"), shown_markers.get("marker_misfit_range"),
        shown_markers.get("marker_misfit_visible")))
    assert "MarkerMisfit1" in shown_markers["pipeline"].split(","), shown_markers["pipeline"]
    assert shown_markers["marker_misfit_representation"] == "Point Gaussian", shown_markers
    assert shown_markers["marker_misfit_color"] == "Misfit", shown_markers
    assert shown_markers["marker_misfit_visible"] == "1", shown_markers
    assert int(shown_markers["marker_misfit_points"]) == len(markers(rest)), shown_markers
    low, high = [float(v) for v in shown_markers["marker_misfit_range"].split()]
    assert low == -high and high > 1.0, (low, high)

    snapped, snapped_points = snapshot(out, "snapped")
    shape = snapped_points[:, 3:6]
    size = np.linalg.norm(shape.max(axis=0) - shape.min(axis=0))
    gaps = [np.linalg.norm(shape - np.array(m), axis=1).min() for _, m in markers(rest)]
    print("snapped: edits %s, dock %r; farthest marker from a vertex %.3g (size %.4g)" % (
        snapped["edit_history"], snapped["label_Edits"], max(gaps), size))
    assert snapped["edit_history"] == "2", snapped
    assert max(gaps) <= 1e-6 * size, max(gaps)
    _, before = snapshot(out, "released")
    _, undone = snapshot(out, "undone")
    _, redone = snapshot(out, "redone")
    assert np.array_equal(undone[:, 3:6], before[:, 3:6]), "the dock's Undo is not bit for bit"
    assert np.array_equal(redone[:, 3:6], shape), "the dock's Redo is not the snap"
