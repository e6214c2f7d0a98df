"""What the GUI tests' paraview --script setups share: a surface painted through
MalleabilityPaint into ChainMailDeformation, shown with the black-body map, and the
marker that tells the test hook (TestHook/pqHapticsTestHook) the scene is complete."""
import os

from paraview.simple import *  # noqa: F401,F403

import geoshaping_presets  # ParaViewPlugin/Python, on PYTHONPATH


def show_deformable(surface, falloff=None):
    """surface -> MalleabilityPaint -> ChainMailDeformation, shown in the active render
    view (orientation axes off); returns (deformation, view)."""
    paint = MalleabilityPaint(Input=surface)  # noqa: F405 (defined by the plugin)
    if falloff:
        paint.Falloff = falloff
    deformation = ChainMailDeformation(Input=paint)  # noqa: F405
    deformation.MalleabilityArray = ["POINTS", "Malleability"]
    view = GetActiveViewOrCreate("RenderView")  # noqa: F405
    geoshaping_presets.show_malleability(Show(deformation, view))  # noqa: F405
    view.OrientationAxesVisibility = 0
    return deformation, view


def scene_ready(deformation, view):
    """The last step of every setup: the hook starts the dock once this is set (a render
    inside the script processes events, so the hook's timer runs mid-script; waiting a
    fixed time for the camera was not enough under load)."""
    SetActiveSource(deformation)  # noqa: F405
    Render(view)  # noqa: F405
    os.environ["GEOSHAPING_GUI_SCENE_READY"] = "1"  # putenv: the hook reads it
