"""paraview --script for the GUI test of a DEM ready to shape (dem_checks.py, mode
dem_ready): only the render view. The test opens the GeoTIFF hill GEOSHAPING_GUI_SURFACE
with ParaView's GDAL reader and applies DEM Surface, Malleability Paint and ChainMail
Deformation through the GUI (the hook's `open` and `apply`: File > Open, the Filters
menu, Apply, as a user does), then pulls the hill with the mouse."""
import os

from paraview.simple import *  # noqa: F401,F403

view = GetActiveViewOrCreate("RenderView")  # noqa: F405
view.OrientationAxesVisibility = 0
Render(view)  # noqa: F405
os.environ["GEOSHAPING_GUI_SCENE_READY"] = "1"  # putenv: the hook reads it (gui_scene.py)
