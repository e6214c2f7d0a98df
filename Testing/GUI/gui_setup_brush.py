"""paraview --script for the GUI tests of the brush: the surface GEOSHAPING_GUI_SURFACE
(a GOCAD TSurf written by brush_checks.py) opened with the plugin's reader, through
MalleabilityPaint (Falloff GEOSHAPING_GUI_FALLOFF, else the default) into
ChainMailDeformation, coloured with the black-body map, seen from above (or, with
GEOSHAPING_GUI_CAMERA=oblique, from the south-west and above)."""
import os

from paraview.simple import *  # noqa: F401,F403

from gui_scene import scene_ready, show_deformable

surface = OpenDataFile(os.environ["GEOSHAPING_GUI_SURFACE"])  # noqa: F405
deformation, view = show_deformable(surface, os.environ.get("GEOSHAPING_GUI_FALLOFF"))
Render(view)  # noqa: F405 (paraview.simple resets the camera on the first render: set it after)
bounds = surface.GetDataInformation().GetBounds()
centre = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
view.CameraFocalPoint = centre
if os.environ.get("GEOSHAPING_GUI_CAMERA") == "oblique":
    view.CameraPosition = [centre[0] - 0.4, centre[1] - 1.0, centre[2] + 0.9]
    view.CameraViewUp = [0.0, 0.0, 1.0]
else:
    view.CameraPosition = [centre[0], centre[1], centre[2] + 1.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 0
view.ResetCamera()
scene_ready(deformation, view)
