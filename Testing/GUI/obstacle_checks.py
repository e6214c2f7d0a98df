"""The GUI test of obstacles you can see (run_gui_test.py mode obstacle_panel): the plane
"Ceiling" (z = 25) is chosen as the ChainMailDeformation's Obstacles in the Properties
panel (its Pipeline Connection, then Apply); the mouse, through the Haptics dock, drags
the fault-step horizon's plateau (z = 20) up into it. Checked from the hook's snapshots
(TestHook/pqHapticsTestScript.h): the Pipeline Browser shows each filter once, no vertex
crosses the plane (computed here), the dock shows the count held back, the grasp marker
sits on the grasped vertex with a line to the cursor, and the release clears both."""

import numpy as np

from brush_checks import mouse_script, snapshot, vector

CEILING = 25.0
SCRIPT = ("obstacle Ceiling; wait; snapshot chosen; press 0.4 0.6; move 0.4 0.65; "
          "move 0.4 0.7; move 0.4 0.75; move 0.4 0.8; wait; snapshot held; release; wait; "
          "snapshot released")


def prepare(mode, out, env):
    mouse_script(env, SCRIPT, "gui_setup_obstacle.py")


def check(mode, out):
    chosen, _ = snapshot(out, "chosen")
    rows = chosen["pipeline"].split(",")
    print("Pipeline Browser:", rows)
    assert "ChainMailDeformation1" in rows and "Ceiling" in rows, rows
    assert len(rows) == len(set(rows)), "a filter shown more than once: %s" % rows

    held, points = snapshot(out, "held")
    grasp = int(held["GraspPointId"])
    rest, shown = points[:, :3], points[:, 3:6]
    wanted = rest[grasp, 2] + vector(held, "Displacement")[2]
    blocked = int(held["NumberOfObstacleBlockedPoints"])
    figures = held["label_Figures"]
    print("held: grasp %d at z %.4f (the cursor asks %.2f), highest vertex z %.6f, %d held "
          "back; dock: %r" % (grasp, shown[grasp, 2], wanted, shown[:, 2].max(), blocked,
                              figures))
    assert rest[:, 2].max() < CEILING and wanted > CEILING + 1.0, "the pull never met the plane"
    assert shown[:, 2].max() <= CEILING, "a vertex crossed the obstacle"
    assert shown[grasp, 2] > CEILING - 0.5, "the grasp stopped short of the plane"
    assert blocked > 0 and ("held back by obstacles: %d" % blocked) in figures, (blocked, figures)

    # The marker on the grasped vertex as drawn (no display transform here), the line from
    # it to the cursor, which went on above the plane.
    assert held["cursors"] == "1" and held["tethers"] == "1", held
    marker = vector(held, "cursor_0")[:3]
    tether = vector(held, "tether_0")
    off = np.linalg.norm(marker - shown[grasp])
    print("marker %.3g from the grasped vertex; line to the cursor %s, %.2f long" % (
        off, tether[3:], np.linalg.norm(tether[3:] - tether[:3])))
    assert off <= 1e-9 * np.abs(shown).max(), off
    assert np.allclose(tether[:3], marker, rtol=0, atol=1e-9 * np.abs(shown).max()), tether
    assert tether[5] > CEILING + 1.0, "the line does not reach the cursor above the plane"

    released, _ = snapshot(out, "released")
    print("released: edits %s, tethers %s, dock %r" % (
        released["edit_history"], released["tethers"], released["label_Figures"]))
    assert released["edit_history"] == "1" and released["tethers"] == "0", released
    assert "held back by obstacles" not in released["label_Figures"], released
