"""open-in-paraview.sh's scene opens ready to drag: the active source is the
ChainMailDeformation of the surface that is shown, so the Haptics dock and the properties
panel act on what the user sees. Runs open_scene.py in pvbatch, as paraview --script does."""
import os
import runpy
import sys

from paraview.simple import GetActiveSource, GetActiveView, GetDisplayProperties

runpy.run_path(os.path.join(os.environ["GEOSHAPING_SOURCE_DIR"], "Testing", "Demo",
                            "open_scene.py"))


def check(condition, message):
    print(("ok: " if condition else "FAILED: ") + message)
    if not condition:
        sys.exit(1)


active = GetActiveSource()
check(active is not None and active.GetXMLName() == "ChainMailDeformation",
      "the active source is a ChainMailDeformation (%s)" % (active and active.GetXMLName()))
check(GetDisplayProperties(active, GetActiveView()).Visibility == 1,
      "and it is the one shown in the view")
