"""paraview --script for the GUI test: the fault-step horizon, painted as in Figure 5C,
through MalleabilityPaint into ChainMailDeformation, coloured with the black-body map,
seen from a fixed oblique camera (run_gui_test.py computes the expected drag from it)."""
from paraview.simple import *

import geoshaping_presets  # ParaViewPlugin/Python, on PYTHONPATH
from gui_setup_camera import CAMERA  # noqa: E402


horizon = FaultStepHorizon(PaintFigure5C=1)
paint = MalleabilityPaint(Input=horizon)
deformation = ChainMailDeformation(Input=paint)
deformation.MalleabilityArray = ["POINTS", "Malleability"]
view = GetActiveViewOrCreate("RenderView")
display = Show(deformation, view)
geoshaping_presets.show_malleability(display)
view.OrientationAxesVisibility = 0
Render(view)  # paraview.simple resets the camera on the first render: set it after
view.CameraPosition = CAMERA["position"]
view.CameraFocalPoint = CAMERA["focal_point"]
view.CameraViewUp = CAMERA["view_up"]
view.CameraViewAngle = CAMERA["view_angle"]
view.CameraParallelProjection = 0
SetActiveSource(deformation)
Render(view)
