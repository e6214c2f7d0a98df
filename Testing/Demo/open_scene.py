"""Opens the demo scene in the ParaView GUI with the GeoShaping plugin loaded:
the Jacksboro DEM and the fault-step horizon painted from the stored dabs, each with a
ChainMailDeformation ready to grasp (use the Haptics dock or the filter's properties).

    Testing/Demo/open-in-paraview.sh        (runs: paraview --script=<this file>)
"""
import json
import os
import sys

# paraview --script runs this file without __file__: open-in-paraview.sh passes the root.
ROOT = os.environ["GEOSHAPING_SOURCE_DIR"]
HERE = os.path.join(ROOT, "Testing", "Demo")
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "ParaViewPlugin", "Python"))

from paraview.simple import *  # noqa: E402,F401,F403

import geoshaping_demo as demo  # noqa: E402
import geoshaping_presets  # noqa: E402

LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], remote=False, ns=globals())
LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], remote=False, ns=vars(demo))  # its proxies too
config = json.load(open(os.path.join(ROOT, "Data", "Demo", "demo_scene.json")))
view = GetActiveViewOrCreate("RenderView")


def shown(source, cfg, to_xyz, name):
    chain = demo.painted_scene(source, cfg, to_xyz, name)[1]
    display = Show(chain, view)
    display.Scale = [1.0, 1.0, cfg["z_exaggeration"]]
    geoshaping_presets.show_malleability(display)
    return chain


dem = JacksboroFaultDEM(registrationName="Jacksboro DEM",  # noqa: F405 (the plugin's source)
                        FileName=demo.jacksboro.find_dem())
data = demo.output_of(dem)
dem_chain = shown(dem, config["jacksboro"], demo.jacksboro_xyz(data), "Jacksboro")
step = FaultStepHorizon(registrationName="Fault step", **config["fault_step"]["source"])  # noqa: F405
step_chain = shown(step, config["fault_step"], tuple, "Fault step")
Hide(step_chain, view)  # both scenes are in the pipeline browser; the DEM is shown
# The deformation of what is shown is active: the Haptics dock and the properties panel
# act on the surface the user sees.
SetActiveSource(dem_chain)
ResetCamera(view)
Render(view)
