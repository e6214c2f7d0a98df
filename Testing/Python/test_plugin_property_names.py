"""Every property name the plugin's own code uses exists on the proxy it is used on.

vtkSMPropertyHelper on a name a proxy does not declare only warns and reads 0, and
GetProperty returns None: a typo or an undeclared property (LastGraspPointId once) goes
unnoticed. This scans the plugin's C++ and Python (ParaViewPlugin/) for the names passed
to vtkSMPropertyHelper(proxy, "Name") and GetProperty("Name") and checks each on the
proxies they are used on: a display (`repr`, `display`) -> the ChainMailDeformation's
representation in a render view; ParaView's picking helper (`helper`, the mouse's pick:
pqHapticsDisplay.cxx) -> a PickingHelper; a `viewProxy` -> the render view (the DEM
Surface's view, pqDEMSurfaceBehavior.cxx); any other proxy -> one of the plugin's own
proxies (the filters, the GeoShapingRayPick of the remote pick and the
GeoShapingContactPatch of the remote contact patch)."""
import glob
import os
import re

from geoshaping_testing import check, load, triangulated_plane
from paraview.simple import *  # noqa: F401,F403

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ParaViewPlugin")
HELPER = re.compile(r'vtkSMPropertyHelper\(\s*([^,()]+(?:\([^()]*\))?[^,()]*),\s*"(\w+)"')
GET = re.compile(r'(\w[\w\->().]*?)\s*(?:->|\.)\s*GetProperty\(\s*"(\w+)"')

uses = []  # (file:line, proxy expression, name)
files = sorted(glob.glob(os.path.join(ROOT, "**", "*.cxx"), recursive=True) +
               glob.glob(os.path.join(ROOT, "**", "*.py"), recursive=True))
for path in files:
    with open(path) as f:
        for number, line in enumerate(f, 1):
            for pattern in (HELPER, GET):
                for m in pattern.finditer(line):
                    where = "%s:%d" % (os.path.relpath(path, ROOT), number)
                    uses.append((where, m.group(1).strip(), m.group(2)))
check(len(uses) >= 40, "found %d property uses in the plugin's code" % len(uses))

load(ns=globals())
plane = triangulated_plane(8)
paint = MalleabilityPaint(Input=plane)  # noqa: F405 (defined by the plugin)
chain = ChainMailDeformation(Input=paint)  # noqa: F405
pins = MalleabilityPaint(Input=plane, PaintPins=1)  # noqa: F405
view = CreateRenderView()
display = Show(chain, view)
ray_pick = servermanager.ProxyManager().NewProxy("misc", "GeoShapingRayPick")  # noqa: F405
patch = servermanager.ProxyManager().NewProxy("misc", "GeoShapingContactPatch")  # noqa: F405
filters = [chain, paint, pins, ray_pick, patch]
picking = servermanager.ProxyManager().NewProxy("misc", "PickingHelper")  # noqa: F405


def declared(proxies, name):
    return any(getattr(p, "SMProxy", p).GetProperty(name) is not None for p in proxies)


for where, expression, name in uses:
    on_display = re.search(r"\b(repr|display)\b", expression) is not None
    on_helper = re.search(r"\bhelper\b", expression) is not None
    on_view = re.search(r"\bviewProxy\b", expression) is not None
    proxies = [display] if on_display else [picking] if on_helper else [view] if on_view \
        else filters
    on = "the display" if on_display else "the PickingHelper" if on_helper else \
        "the render view" if on_view else "a GeoShaping proxy"
    check(declared(proxies, name), "%s: %s on %s is declared" % (where, name, on))

# The one that was missing, and what it reads: -1 until the filter has grasped.
chain.UpdatePropertyInformation()
check(chain.SMProxy.GetProperty("LastGraspPointId").GetElement(0) == -1,
      "LastGraspPointId is -1 before any grasp")
chain.GraspPointId = 40
chain.Displacement = [0.0, 0.0, 1.0]
chain.UpdatePipeline()
chain.UpdatePropertyInformation()
check(chain.SMProxy.GetProperty("LastGraspPointId").GetElement(0) == 40,
      "LastGraspPointId is the grasped vertex after an update")
