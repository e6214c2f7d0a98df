"""Obstacles through the plugin's proxy: `chain.Obstacles = [fault, lower]` takes any
number of surfaces on port 1, the pull stops above the lower one, the grasp reports it,
removing the obstacles gives the free pull back, and `chain.SlidingArray` keeps a
horizon's cut-off line on its fault while it moves along it."""
from geoshaping_testing import check, load
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403

load(ns=globals())

# A 21 x 21 horizon at z = 0 over [0, 20]^2, grasped at its centre (point 220).
horizon = Triangulate(Input=Plane(Origin=[0, 0, 0], Point1=[20, 0, 0], Point2=[0, 20, 0],
                                  XResolution=20, YResolution=20))
# Lower horizon at z = -3 and a vertical fault x = 30, away from the pull.
lower = Plane(Origin=[-5, -5, -3], Point1=[25, -5, -3], Point2=[-5, 25, -3],
              XResolution=10, YResolution=10)
fault = Plane(Origin=[30, -5, -10], Point1=[30, 25, -10], Point2=[30, -5, 10])
chain = ChainMailDeformation(Input=horizon)  # noqa: F405
# Double output: the stand-off (1e-9 of the obstacles' diagonal) is below float32's
# resolution, so float points could round a stopped vertex onto the plane.
chain.OutputPointsPrecision = "Double"
chain.GraspPointId = 220
chain.Displacement = [0.0, 0.0, -10.0]
chain.Obstacles = [fault, lower]
check(len(chain.Obstacles) == 2, "two obstacles connected (%d)" % len(chain.Obstacles))
chain.UpdatePipeline()
chain.UpdatePropertyInformation()
fraction = chain.GetProperty("LastGraspObstacleFraction").GetElement(0)
blocked = chain.GetProperty("LastGraspBlocked").GetElement(0)
check(abs(fraction - 0.3) < 1e-6 and fraction < 0.3,
      "the grasp stops just above z = -3 (fraction %r)" % fraction)
check(blocked == 1, "LastGraspBlocked is 1 (%r)" % blocked)
z = sm.Fetch(chain).GetBounds()[4]
check(-3.0 < z < -3.0 + 1e-6, "nothing goes below the lower horizon (lowest z %r)" % z)

chain.Obstacles = []
chain.UpdatePipeline()
chain.UpdatePropertyInformation()
z = sm.Fetch(chain).GetBounds()[4]
check(z == -10.0, "without obstacles the pull goes through (lowest z %r)" % z)
check(chain.GetProperty("LastGraspObstacleFraction").GetElement(0) == 1.0,
      "and the grasp is free")

# Sliding: a horizon x in [0, 10] cut off by the fault x = 10 - 0.5 z, its last column
# flagged OnFault; pulled down, that column slides down the fault and stays on it.
import numpy as np  # noqa: E402
from geoshaping_testing import points  # noqa: E402

cut = Triangulate(Input=Plane(Origin=[0, 0, 0], Point1=[10, 0, 0], Point2=[0, 20, 0],
                              XResolution=10, YResolution=20))
flagged = Calculator(Input=cut, ResultArrayName="OnFault", Function="coordsX >= 9.5",
                     ResultArrayType="Int")
dipping = Plane(Origin=[15, -5, -10], Point1=[15, 25, -10], Point2=[5, -5, 10])
slide = ChainMailDeformation(Input=flagged)  # noqa: F405
slide.OutputPointsPrecision = "Double"
slide.StretchRange = [1.5, 1.5]
slide.CompressionRange = [0.75, 0.75]
slide.ShearRange = [0.05, 0.05]
slide.GraspPointId = 10 * 11 + 5
slide.Displacement = [0.0, 0.0, -4.0]
slide.Obstacles = [dipping]
check(slide.SlidingArray[1] == "None", "SlidingArray is None by default")
slide.SlidingArray = ["POINTS", "OnFault"]
x = points(slide)
on = np.arange(len(x)) % 11 == 10
off_fault = np.abs(x[:, 0] + 0.5 * x[:, 2] - 10.0) / np.sqrt(1.25)
check(off_fault[on].max() <= 1e-9, "the cut-off line stays on the fault (%r)" % off_fault[on].max())
check(x[on, 2].max() < -0.25 and x[10 * 11 + 10, 2] < -2.0,
      "and slides down it (z %r ... %r)" % (x[on, 2].min(), x[on, 2].max()))
print("obstacles: ok")

# A state written before the Obstacles were chosen through a Pipeline Connection
# (data/obstacles_before_issue40.pvsm: the fault-step horizon pulled up by 30 under the
# plane "Ceiling" at z = 25, connected directly): it loads with Ceiling as the Input of
# the filter's Pipeline Connection (what the panel shows), the pull still held under it,
# and still after another property is pushed.
import os  # noqa: E402

for source in list(GetSources().values()):  # noqa: F405
    Delete(source)  # noqa: F405
LoadState(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data",  # noqa: F405
                       "obstacles_before_issue40.pvsm"))
old = FindSource("ChainMailDeformation1")  # noqa: F405
connection = old.Obstacles[0] if len(old.Obstacles) == 1 else None
check(connection is not None and connection.GetXMLName() == "PipelineConnection" and
      connection.Input is not None and connection.Input.GetXMLName() == "PlaneSource",
      "the old state's obstacle is the Input of the Pipeline Connection (%r)" % (old.Obstacles,))
for step in ("loaded", "after a push"):
    old.UpdatePipeline()
    top = old.GetDataInformation().GetBounds()[5]
    check(20.0 < top < 25.0, "%s: the pull stops under the plane at z = 25 (top %r)" % (step, top))
    old.Displacement = [0.0, 0.0, 40.0]
print("obstacles: old state ok")
