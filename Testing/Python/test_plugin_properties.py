"""The plugin loads in pvpython and exposes the public names of docs/design.md (Public names)."""
import numpy as np

from geoshaping_testing import check, load
from paraview.simple import *  # noqa: F401,F403

load(ns=globals())
src = Sphere()
chain = ChainMailDeformation(Input=src)  # noqa: F405 (defined by the plugin)
names = set(chain.ListProperties())
for name in ["MalleabilityArray", "DefaultMalleability", "GraspPointId", "Displacement",
             "CandidateQueue", "StretchRange", "CompressionRange", "ShearRange",
             "PinnedArray", "OutputPointsPrecision"]:
    check(name in names, "ChainMailDeformation has property %s" % name)
check(chain.CandidateQueue == "FIFO Priority", "default queue is FIFO Priority")
check(list(chain.StretchRange) == [1.0, 2.0], "default stretch range 1 -> 2")
check(list(chain.CompressionRange) == [1.0, 0.5], "default compression range 1 -> 0.5")
check(list(chain.ShearRange) == [0.0, 0.5], "default shear range 0 -> 0.5")
check(chain.DefaultMalleability == 0.5, "default malleability 0.5")
check(chain.NumberOfThreads == 0 and
      chain.SMProxy.GetProperty("NumberOfThreads").GetPanelVisibility() == "advanced",
      "threads automatic by default, an advanced property")
# The panel's default view: what a geologist shapes with (issue 37: at most 14).
shown = []
it = chain.SMProxy.NewPropertyIterator()
it.Begin()
while not it.IsAtEnd():
    prop = it.GetProperty()
    if not prop.GetInformationOnly() and prop.GetPanelVisibility() == "default":
        shown.append(it.GetKey())
    it.Next()
check(sorted(shown) == sorted(["Input", "Obstacles", "MalleabilityArray", "ValidRegionFrame",
                               "StretchRange", "CompressionRange", "ShearRange", "PinnedArray",
                               "Markers", "HonourMarkers",
                               "CommitEdit", "UndoEdit", "RedoEdit", "ResetEdits"]),
      "the panel's default view shows the 14 shaping properties (%s)" % sorted(shown))
check(all(chain.SMProxy.GetProperty(n).GetPanelVisibility() == "never"
          for n in ["StretchCurve", "CompressionCurve", "ShearCurve"]),
      "one way to give the transfer curve in the panel: the ranges (curves from Python)")
check("ExactRigidAtZero" not in names, "malleability 0 is always rigid: no switch")
# ParaView 5.11's properties panel draws no widget for an IdTypeVectorProperty.
check(chain.SMProxy.GetProperty("GraspPointId").IsA("vtkSMIntVectorProperty"),
      "GraspPointId is an IntVectorProperty, so the properties panel draws it")
for queue in ["FIFO", "Priority", "FIFO Priority", "Max Violation"]:
    chain.CandidateQueue = queue
    check(chain.CandidateQueue == queue, "queue %s accepted" % queue)
check(chain.ValidRegionFrame == "Axes", "default valid-region shape is Axes")
chain.ValidRegionFrame = "Link"
check(chain.ValidRegionFrame == "Link", "valid-region shape Link accepted")
chain.ValidRegionFrame = "Axes"
# The refinement's default solver is the one that satisfies every link (Axes region).
check(chain.RefinementSolver == "Envelope", "default refinement solver is Envelope")

# A script creates the filter before its input has run: ParaView knows no arrays yet, and
# the array domain would pick None (uniform 0.5). The default stays Malleability, and the
# filter reads the painted array once the pipeline runs.
from geoshaping_testing import points, triangulated_plane  # noqa: E402

plane = triangulated_plane(20)
paint = MalleabilityPaint(Input=plane, Falloff="Constant",  # noqa: F405
                          Dabs=[10.0, 10.0, 0.0, 4.0, 0.0, 1.0])
fresh = ChainMailDeformation(Input=paint)  # noqa: F405
check(list(fresh.MalleabilityArray) == ["POINTS", "Malleability"],
      "MalleabilityArray is Malleability when the filter is created before its input ran")
fresh.GraspPointId = 10 * 21 + 10  # the centre of the rigid (painted 0) disc
fresh.Displacement = [0.0, 0.0, 3.0]
moved = points(fresh) - points(plane)
disc = np.linalg.norm(points(plane)[:, :2] - [10.0, 10.0], axis=1) < 2.0
check(np.allclose(moved[disc], [0.0, 0.0, 3.0]),
      "the painted rigid disc moves as one: the painted array was used")

# The properties panel: groups, ranges with domains, labelled table columns.
sm_chain = fresh.SMProxy
groups = {}
for i in range(sm_chain.GetNumberOfPropertyGroups()):
    group = sm_chain.GetPropertyGroup(i)
    groups[group.GetXMLLabel()] = [sm_chain.GetPropertyName(group.GetProperty(k))
                                   for k in range(group.GetNumberOfProperties())]
check(list(groups) == ["Malleability", "Grasp", "How the pull spreads", "Pins", "Refinement",
                       "Obstacles", "Markers", "Editing", "Diagnostics"],
      "ChainMailDeformation's groups: %s" % list(groups))
check(groups["Obstacles"] == ["Obstacles", "ObstacleClearance", "SlidingArray"],
      "the obstacles group holds the surfaces, the clearance and the sliding mask")
check(groups["Markers"] == ["Markers", "HonourMarkers"],
      "the markers group holds the wells and the switch that honours them")
check(groups["Grasp"] == ["GraspMode", "GraspPointId", "GraspPosition", "Displacement"] and
      groups["Editing"] == ["CommitEdit", "UndoEdit", "RedoEdit", "ResetEdits"],
      "the grasp and edit groups hold their properties")
check(groups["Refinement"] == ["RefinementIterations", "RefinementTolerance",
                               "RefinementSolver", "RelaxationIterations"],
      "the refinement group holds the iteration cap, the tolerance, the solver and the relaxation")
check(groups["How the pull spreads"][:2] == ["CandidateQueue", "ValidRegionFrame"],
      "ValidRegionFrame is in the group of how the pull spreads, after CandidateQueue")
grouped = [name for names in groups.values() for name in names]
panel = [name for name in fresh.ListProperties()
         if sm_chain.GetProperty(name).GetPanelVisibility() != "never"
         and not sm_chain.GetProperty(name).GetInformationOnly() and name != "Input"]
check(sorted(grouped) == sorted(panel), "every panel property is in exactly one group")
for name, low, high in [("StretchRange", 1.0, None), ("CompressionRange", 0.0, 1.0),
                        ("ShearRange", 0.0, None)]:
    domain = sm_chain.GetProperty(name).GetDomain("range")
    check(domain is not None and all(domain.GetMinimum(k) == low for k in (0, 1)) and
          (high is None or all(domain.GetMaximum(k) == high for k in (0, 1))),
          "%s has a range domain from %s" % (name, low))


def column_labels(proxy, name):
    hints = proxy.SMProxy.GetProperty(name).GetHints()
    element = hints.FindNestedElementByName("ShowComponentLabels") if hints else None
    return [element.GetNestedElement(k).GetAttribute("label")
            for k in range(element.GetNumberOfNestedElements())] if element else []


check(column_labels(fresh, "StretchCurve") == ["Malleability", "Stretch"] and
      column_labels(fresh, "ShearCurve") == ["Malleability", "Shear"],
      "the curve tables have column labels")
check(column_labels(paint, "Dabs") == ["x", "y", "z", "Radius", "Value", "Strength"] and
      column_labels(paint, "PointDabs") == ["Point Id", "Value", "Weight"],
      "the dab tables have column labels")

# The Haptics dock's brush radius lives on the paint proxy, so a state file keeps it
# (0, the default: 3 % of the data's diagonal, docs/interactor.md).
import os  # noqa: E402

check(paint.BrushRadius == 0.0, "BrushRadius is 0 (fitted to the data) by default")
check(paint.SMProxy.GetProperty("BrushRadius").GetPanelVisibility() == "never",
      "BrushRadius is the dock's, not on the properties panel")
paint.BrushRadius = 40000.0
state = os.path.join(os.environ["GEOSHAPING_TEST_TMP"], "brush-radius.pvsm")
SaveState(state)  # noqa: F405
ResetSession()  # noqa: F405
load(ns=globals())
LoadState(state)  # noqa: F405
loaded = [s for s in GetSources().values() if s.GetXMLName() == "MalleabilityPaint"]  # noqa: F405
check(len(loaded) == 1 and loaded[0].BrushRadius == 40000.0, "LoadState gives BrushRadius back")

# Sources > GeoShaping lists the plugin's sources and filters (the Jacksboro sample too),
# as ParaView builds its menus from the proxies' ShowInMenu hints.
manager = servermanager.ProxyManager()  # noqa: F405
for group, name in (("sources", "FaultStepHorizon"), ("sources", "LayeredFaultScene"),
                    ("sources", "JacksboroFaultDEM"), ("filters", "DEMSurface"),
                    ("filters", "MalleabilityPaint"), ("filters", "ChainMailDeformation")):
    hints = manager.GetPrototypeProxy(group, name).GetHints()
    menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
    check(menu is not None and menu.GetAttribute("category") == "GeoShaping",
          "%s is under %s > GeoShaping" % (name, "Sources" if group == "sources" else "Filters"))
