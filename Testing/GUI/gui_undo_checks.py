"""GUI test checks of ParaView's undo stack against the Haptics dock's edits
(docs/editing.md, "ParaView's undo stack"); the hook writes the values
(TestHook/pqHapticsUndoChecks.cxx), run_gui_test.py calls these."""
import math
import os

from gui_setup_camera import CAMERA

# The state file's edit: a pull of the upper plateau far above the surface, so that grown
# bounds would show (the horizon is 20 high there).
STATE_GRASP = [20.0, 30.0, 20.0]
STATE_PULL = [0.0, 0.0, 60.0]


def write_state(path):
    """A .pvsm holding the GUI test's scene with one committed edit (made here, in
    pvpython, the way a Python user commits: InvokeCommand)."""
    import paraview.simple as simple
    from paraview.simple import GetActiveViewOrCreate, Show, SaveState, SetActiveSource
    plugin_dir = os.environ["PV_PLUGIN_PATH"].split(":")[0]
    simple.LoadPlugin(os.path.join(plugin_dir, "GeoShaping.so"), remote=False)
    import geoshaping_presets
    horizon = simple.FaultStepHorizon(PaintFigure5C=1)
    paint = simple.MalleabilityPaint(Input=horizon)
    deformation = simple.ChainMailDeformation(Input=paint)
    deformation.MalleabilityArray = ["POINTS", "Malleability"]
    view = GetActiveViewOrCreate("RenderView")
    geoshaping_presets.show_malleability(Show(deformation, view))
    view.OrientationAxesVisibility = 0
    view.CameraPosition = CAMERA["position"]
    view.CameraFocalPoint = CAMERA["focal_point"]
    view.CameraViewUp = CAMERA["view_up"]
    view.CameraViewAngle = CAMERA["view_angle"]
    deformation.GraspMode = "Nearest To Position"
    deformation.GraspPosition = STATE_GRASP
    deformation.Displacement = STATE_PULL
    deformation.UpdatePipeline()
    deformation.SMProxy.InvokeCommand("CommitEdit")
    assert len(deformation.EditHistory) == 1, "the state must hold one edit"
    SetActiveSource(deformation)
    SaveState(path)


def _floats(text):
    return [float(v) for v in text.split()]


def check_settled(results, prefix, what):
    """After `what`: no grasp left, and the bounds the filter, the Information panel and
    Reset Camera see are the exact bounds of the points shown."""
    print("%s: grasp %s, displacement %s, bounds %s (exact %s), Information panel %s, "
          "Reset Camera off centre by %s of the diagonal" % (
              what, results[prefix + "_grasp_point_id"], results[prefix + "_displacement"],
              results[prefix + "_bounds"], results[prefix + "_expected_bounds"],
              results[prefix + "_information_bounds"], results[prefix + "_reset_camera_offset"]))
    assert results[prefix + "_grasp_point_id"] == "-1", what + " left a grasp"
    assert _floats(results[prefix + "_displacement"]) == [0.0, 0.0, 0.0], what
    assert results[prefix + "_bounds_exact"] == "1", what + ": the output's bounds stay grown"
    assert results[prefix + "_information_bounds_exact"] == "1", what + ": Information panel"
    assert float(results[prefix + "_reset_camera_offset"]) < 1e-9, what + ": Reset Camera"


def check_edit_menu(results):
    """A drag is one step of ParaView's undo stack ("Commit Edit", no drag frame on it);
    Edit > Undo gives the rest points exactly, with no grasp left, as the dock's Undo does;
    Edit > Redo gives the released points; the bounds shrink back each time."""
    assert results.get("edit_menu") == "1", "Edit > Undo / Redo actions not found"
    steps = results["undo_steps"].split(" | ")
    print("ParaView's undo steps, newest first:", steps, "- menu:", results["edit_menu_undo_text"])
    assert steps[0] == "Commit Edit", steps
    assert not any("ChainMailDeformation" in s for s in steps), "a drag frame is an undo step"
    check_settled(results, "released", "release")
    assert results["edit_menu_undo_equals_rest"] == "1", "Edit > Undo did not give the rest points"
    assert results["edit_menu_undo_edit_history"] == "0", results
    check_settled(results, "edit_menu_undo", "Edit > Undo")
    assert results["edit_menu_redo_equals_released"] == "1", "Edit > Redo"
    assert results["edit_menu_redo_edit_history"] == "1", results
    check_settled(results, "edit_menu_redo", "Edit > Redo")
    assert results["dock_undo_equals_edit_menu_undo"] == "1", "the dock's Undo differs"
    check_settled(results, "dock_undo", "the dock's Undo")
    assert results["dock_redo_equals_released"] == "1", "the dock's Redo"


def check_loaded_state(results):
    """Right after File > Load State and Start the dock counts the state's edit; its Undo
    then gives the rest points, and the bounds shrink back from the pull's."""
    print("after Load State + Start the dock says:", results["loaded_edits_label"],
          "- after its Undo:", results["loaded_undo_label"])
    assert results["loaded_edit_history"] == "1", results
    assert results["loaded_edits_label"] == "Edits: 1, redoable 0", results["loaded_edits_label"]
    top = _floats(results["loaded_bounds"])[5]
    assert top > STATE_PULL[2], "the state's pull is not shown: z max %g" % top
    assert results["loaded_undo_label"] == "Edits: 0, redoable 1", results["loaded_undo_label"]
    assert results["loaded_undo_equals_rest"] == "1", results
    check_settled(results, "loaded_undo", "Undo after Load State")
    assert math.isclose(_floats(results["loaded_undo_bounds"])[5], 20.0), results
