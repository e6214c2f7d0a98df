"""paraview --script for the GUI test of the vertical exaggeration: the GeoTIFF hill
GEOSHAPING_GUI_SURFACE (written by dem_checks.py) opened with ParaView's GDAL reader,
through DEM Surface, MalleabilityPaint and ChainMailDeformation (with a small square
under the hill's foot as its Obstacles), both shown with the display Scale (1, 1,
GEOSHAPING_GUI_EXAGGERATION) set as a user sets it in Properties > Transforming, seen
from the south-west and above."""
import os

from paraview.simple import *  # noqa: F401,F403

from gui_scene import scene_ready, show_deformable

raster = GDALRasterReader(FileName=os.environ["GEOSHAPING_GUI_SURFACE"])  # noqa: F405
dem = DEMSurface(Input=raster)  # noqa: F405
deformation, view = show_deformable(dem)
dem.UpdatePipeline()
bounds = dem.GetDataInformation().GetBounds()
# An obstacle the pulls never reach: a 2 km square at z = 200 m, under the hill's foot.
x, y = bounds[0] + 1000.0, bounds[2] + 1000.0
floor = Plane(Origin=[x, y, 200.0], Point1=[x + 2000.0, y, 200.0],  # noqa: F405
              Point2=[x, y + 2000.0, 200.0])
deformation.Obstacles = [floor]
s = float(os.environ["GEOSHAPING_GUI_EXAGGERATION"])
for shown in (deformation, floor):
    Show(shown, view).Scale = [1.0, 1.0, s]  # noqa: F405
view.InteractionMode = "3D"
Render(view)  # noqa: F405 (paraview.simple resets the camera on the first render: set it after)
centre = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), s * bounds[5]]
size = bounds[1] - bounds[0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0] - 0.5 * size, centre[1] - 1.2 * size, centre[2] + 0.9 * size]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelProjection = 0
view.ResetCamera()
scene_ready(deformation, view)
