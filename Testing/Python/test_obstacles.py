"""Obstacles through the plugin's proxy: `chain.Obstacles = [fault, lower]` takes any
number of surfaces on port 1, the pull stops above the lower one, the grasp reports it,
and removing the obstacles gives the free pull back."""
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
print("obstacles: ok")
