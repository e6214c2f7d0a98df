"""paraview --script for the GUI test of obstacles (obstacle_checks.py): the fault-step
horizon (z 0 ... 20) through MalleabilityPaint into ChainMailDeformation, and a plane
"Ceiling" at z = 25 over it, left out of the view (the test chooses it as the Obstacles
in the Properties panel), seen from the fixed oblique camera of gui_setup.py."""
from paraview.simple import *  # noqa: F401,F403

from gui_scene import scene_ready, show_deformable
from gui_setup_camera import set_camera

deformation, view = show_deformable(FaultStepHorizon())  # noqa: F405
Plane(registrationName="Ceiling", Origin=[-10.0, -10.0, 25.0],  # noqa: F405
      Point1=[110.0, -10.0, 25.0], Point2=[-10.0, 70.0, 25.0])
Render(view)  # noqa: F405 (paraview.simple resets the camera on the first render: set it after)
set_camera(view)
scene_ready(deformation, view)
