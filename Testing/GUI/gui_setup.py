"""paraview --script for the GUI test: the fault-step horizon, painted as in Figure 5C,
through MalleabilityPaint into ChainMailDeformation, coloured with the black-body map,
seen from a fixed oblique camera (run_gui_test.py computes the expected drag from it)."""
from paraview.simple import *  # noqa: F401,F403

from gui_scene import scene_ready, show_deformable
from gui_setup_camera import set_camera

deformation, view = show_deformable(FaultStepHorizon(PaintFigure5C=1))  # noqa: F405
Render(view)  # noqa: F405 (paraview.simple resets the camera on the first render: set it after)
set_camera(view)
scene_ready(deformation, view)
