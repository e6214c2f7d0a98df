"""paraview --script for the GUI test of the markers' misfit in the dock
(markers_checks.py): the fault-step horizon through MalleabilityPaint into
ChainMailDeformation, with markers (a Programmable Source, not shown) 0.5 above every
seventh interior vertex of the rest surface (gui_setup_markers_rule.py) on its Markers
input (HonourMarkers off: the pull is the one without markers), seen from the fixed
oblique camera of gui_setup.py."""
from paraview.simple import *  # noqa: F401,F403

from gui_scene import scene_ready, show_deformable
from gui_setup_camera import set_camera

horizon = FaultStepHorizon()  # noqa: F405
deformation, view = show_deformable(horizon)
markers = ProgrammableSource(registrationName="Wells")  # noqa: F405
markers.OutputDataSetType = "vtkPolyData"
# The surface's rest points, read here on the client (a builtin session).
from paraview import servermanager as sm  # noqa: E402
from gui_setup_markers_rule import markers as chosen  # noqa: E402

surface = sm.Fetch(horizon)
rest = [surface.GetPoint(v) for v in range(surface.GetNumberOfPoints())]
coordinates = [m for _, m in chosen(rest)]
markers.Script = (
    "from vtkmodules.vtkCommonCore import vtkPoints\n"
    "points = vtkPoints()\n"
    "points.SetDataTypeToDouble()\n"
    "for p in %r:\n"
    "    points.InsertNextPoint(p)\n"
    "self.GetPolyDataOutput().SetPoints(points)\n" % (coordinates,))
deformation.Markers = [markers]
Render(view)  # noqa: F405 (paraview.simple resets the camera on the first render: set it after)
set_camera(view)
scene_ready(deformation, view)
