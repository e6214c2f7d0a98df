"""The GUI test's fixed camera: gui_setup.py sets it, run_gui_test.py maps the trace with it."""
CAMERA = dict(position=[50.0, -90.0, 170.0], focal_point=[50.0, 30.0, 10.0],
              view_up=[0.0, 0.8, 0.6], view_angle=30.0)


def set_camera(view):
    """The fixed camera on `view` (after its first render: paraview.simple resets the
    camera on the first render)."""
    view.CameraPosition = CAMERA["position"]
    view.CameraFocalPoint = CAMERA["focal_point"]
    view.CameraViewUp = CAMERA["view_up"]
    view.CameraViewAngle = CAMERA["view_angle"]
    view.CameraParallelProjection = 0
