"""ChainMailDeformation through paraview.simple gives the analytic results."""
import numpy as np

from geoshaping_testing import check, load, points, triangulated_plane
from paraview.simple import *  # noqa: F401,F403

load(ns=globals())
n = 21
surface = triangulated_plane(n - 1)
rest = points(surface)

chain = ChainMailDeformation(Input=surface)  # noqa: F405
chain.MalleabilityArray = ["POINTS", "None"]
chain.DefaultMalleability = 0.0
chain.GraspPointId = 10 * n + 10
chain.Displacement = [0.5, -1.0, 3.0]
moved = points(chain)
check(np.array_equal(moved - rest, np.tile([0.5, -1.0, 3.0], (n * n, 1))),
      "malleability 0: every vertex translates by exactly the displacement")

# Soft, shear 0.25 on unit spacing: vertical motion decreases by 0.25 per edge hop
# (see the core's QuadGridPulledAtCentreFollowsShearCone for the derivation); on a
# triangulated grid the hop count is the triangulated graph distance, so check the ends.
chain.DefaultMalleability = 1.0
chain.ShearRange = [0.0, 0.25]
chain.Displacement = [0.0, 0.0, 2.0]
soft = points(chain) - rest
check(soft[10 * n + 10, 2] == 2.0, "the grasped vertex moves by the displacement")
check(abs(soft[10 * n + 11, 2] - 1.75) < 1e-12, "its neighbour absorbs one shear step")
check(np.all(soft[:, :2] == 0.0), "no horizontal motion for a vertical pull")
check(soft[0, 2] == 0.0, "the far corner stays at rest")

chain.GraspPointId = -1
check(np.array_equal(points(chain), rest), "grasp -1 gives the rest shape back")
