"""paraview --script for the GUI pull test: the fault-step horizon at two data scales, each
through ChainMailDeformation: "Pull unit" (scaled to a 1 x 0.6 x 0.2 box at the origin) and
"Pull 1000 km" (1,000 km x 600 km, throw 200 km, at UTM-like coordinates). The test hook
(TestHook/pqPullTestDriver) shows one at a time and sets the cameras."""
from paraview.simple import *

import geoshaping_presets  # ParaViewPlugin/Python, on PYTHONPATH
from gui_scene import scene_ready

view = GetActiveViewOrCreate("RenderView")
view.OrientationAxesVisibility = 0
for name, scale, offset in (("Pull unit", 0.01, [0.0, 0.0, 0.0]),
                            ("Pull 1000 km", 1.0e4, [5.0e5, 4.1e6, -2.0e3])):
    horizon = FaultStepHorizon(PaintFigure5C=1)
    scaled = Transform(Input=horizon)
    scaled.Transform.Scale = [scale] * 3
    scaled.Transform.Translate = offset
    deformation = ChainMailDeformation(Input=scaled, registrationName=name)
    deformation.MalleabilityArray = ["POINTS", "Malleability"]
    geoshaping_presets.show_malleability(Show(deformation, view))
scene_ready(deformation, view)
