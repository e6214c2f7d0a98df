"""pvpython: FaultStepHorizon -> MalleabilityPaint -> ChainMailDeformation, checked by
numbers; and the black-body preset imported and applied with the range fixed to 0-1."""
import os
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.environ["GEOSHAPING_PYTHON"])
import geoshaping_presets  # noqa: E402

LoadPlugin(os.environ["GEOSHAPING_PLUGIN"], remote=False, ns=globals())


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)
    print("ok:", message)


horizon = FaultStepHorizon(Length=40.0, Width=20.0, Throw=8.0, StepRun=2.0, Spacing=0.5)
paint = MalleabilityPaint(Input=horizon)
paint.InitialMalleability = 0.4
paint.Falloff = "Constant"
paint.DistanceMode = "Geodesic"
# Black over the step (x 19..21), then a half-strength white dab on the upper side.
dabs = []
for y in np.arange(0.0, 20.01, 1.0):
    for x, z in ((19.5, 7.0), (20.0, 4.0), (20.5, 1.0)):
        dabs += [x, y, z, 2.0, 0.0, 1.0]
dabs += [8.0, 10.0, 8.0, 3.0, 1.0, 0.5]
paint.Dabs = dabs
paint.UpdatePipeline()
painted = sm.Fetch(paint)
m = vtk_to_numpy(painted.GetPointData().GetArray("Malleability"))
xyz = vtk_to_numpy(painted.GetPoints().GetData())
check(m.dtype == np.float32 and m.min() >= 0.0 and m.max() <= 1.0, "float array in [0, 1]")
on_step = (xyz[:, 0] > 19.2) & (xyz[:, 0] < 20.8)
check(np.all(m[on_step] == 0.0), "the step is black (%d vertices)" % on_step.sum())
centre = np.argmin(np.linalg.norm(xyz - [8.0, 10.0, 8.0], axis=1))
check(abs(m[centre] - 0.7) < 1e-6, "a half-strength white dab takes 0.4 half way to 1 (%.6f)" % m[centre])
check(np.all(m[xyz[:, 0] > 30.0] == np.float32(0.4)), "far side keeps InitialMalleability")

deform = ChainMailDeformation(Input=paint)
deform.MalleabilityArray = ["POINTS", "Malleability"]
deform.GraspMode = "Nearest To Position"
deform.GraspPosition = [20.0, 10.0, 4.0]
deform.Displacement = [0.0, 0.0, 3.0]
deform.UpdatePipeline()
moved = vtk_to_numpy(sm.Fetch(deform).GetPoints().GetData())
d = moved - xyz
check(np.allclose(d[on_step], [0.0, 0.0, 3.0], atol=1e-9), "black step translates rigidly by the grasp")
far = xyz[:, 0] < 2.0
check(np.all(np.abs(d[far]) < 3.0), "deformation decays away from the step")
check(np.abs(d).max() <= 3.0 + 1e-9, "nothing moves farther than the grasp")

# Repainting with the same dabs reproduces the array bit for bit.
paint.Dabs = []
paint.UpdatePipeline()
paint.Dabs = dabs
paint.UpdatePipeline()
check(np.array_equal(vtk_to_numpy(sm.Fetch(paint).GetPointData().GetArray("Malleability")), m),
      "same dabs, bit-identical array")

display = Show(paint)
lut = geoshaping_presets.show_malleability(display)
rgb = list(lut.RGBPoints)
check(rgb[:4] == [0.0, 0.0, 0.0, 0.0] and rgb[-4:] == [1.0, 1.0, 1.0, 1.0],
      "preset applied: black at 0, white at 1")
check(lut.AutomaticRescaleRangeMode == "Never", "range fixed to 0-1")
