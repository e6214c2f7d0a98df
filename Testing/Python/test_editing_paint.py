"""Painting during a drag lands on the vertices under the brush on the deformed surface
and the next frame follows the new malleability; pinned vertices never move through
grasps, commits and undo."""
import numpy as np

from geoshaping_testing import check, load, points, triangulated_plane
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy

load(ns=globals())
N = 31
surface = triangulated_plane(N - 1)
paint = MalleabilityPaint(Input=surface)  # noqa: F405
paint.InitialMalleability = 0.5
pins = MalleabilityPaint(Input=paint, PaintPins=1)  # noqa: F405
pins.Falloff = "Constant"
chain = ChainMailDeformation(Input=pins)  # noqa: F405
chain.MalleabilityArray = ["POINTS", "Malleability"]
rest = points(surface)


def array(proxy, name):
    data = sm.Fetch(proxy)
    a = data.GetPointData().GetArray(name)
    return a, vtk_to_numpy(a).astype(float)


def commit(chain):  # docs/editing.md: the proxy appends the record and releases
    before = len(chain.EditHistory)
    chain.InvokeCommand("CommitEdit")
    check(len(chain.EditHistory) == before + 1, "the commit is recorded once in EditHistory")
    check(chain.GraspPointId == -1 and list(chain.Displacement) == [0.0, 0.0, 0.0],
          "the proxy is released")


# --- painting during a drag ---------------------------------------------------------
grasp = 15 * N + 15
chain.GraspPointId = grasp
chain.Displacement = [0.0, 0.0, 4.0]
shown = points(chain)  # the deformed surface the user sees
centre, radius = shown[15 * N + 18], 1.5
under = np.flatnonzero(np.linalg.norm(shown - centre, axis=1) <= radius)
under_rest = np.flatnonzero(np.linalg.norm(rest - centre, axis=1) <= radius)
check(len(under) >= 5, "the brush covers %d vertices of the deformed surface" % len(under))
check(set(under) != set(under_rest), "the same sphere on the rest mesh would cover others")
# The client measures on what it shows and sends point dabs: rigid, full strength.
paint.PointDabs = [v for i in under for v in (float(i), 0.0, 1.0)]
_, m = array(chain, "Malleability")
check(set(np.flatnonzero(m == 0.0)) == set(under), "exactly the vertices under the brush are painted")
check(np.all(m[np.setdiff1d(np.arange(N * N), under)] == np.float32(0.5)), "the others keep 0.5")

after = points(chain)  # the next frame, same grasp
check(not np.array_equal(after, shown), "the next frame's shape differs")
u = after[under] - rest[under]
check(np.all(u == u[0]), "the painted (rigid) patch now translates as one, as malleability 0 says")
check(np.any(shown[under] - rest[under] != (shown[under] - rest[under])[0]),
      "it did not before the paint")
chain.GraspPointId = -1
paint.PointDabs = []

# --- pins ---------------------------------------------------------------------------
pins.Dabs = [20.0, 15.0, 0.0, 2.5, 1.0, 1.0]  # a pinned disc right of the grasp
arr, pinned = array(pins, "Pinned")
check(arr.GetDataTypeAsString() == "unsigned char", "the pin brush writes an unsigned char mask")
pinned_ids = np.flatnonzero(pinned)
expected = np.flatnonzero(np.linalg.norm(rest - [20.0, 15.0, 0.0], axis=1) <= 2.5)
check(set(pinned_ids) == set(expected), "the pin brush pins the %d vertices in its disc" % len(expected))
check(sm.Fetch(pins).GetPointData().GetScalars().GetName() == "Malleability",
      "the heat map's array stays the active scalars")
chain.PinnedArray = ["POINTS", "Pinned"]
for g, d in [(15 * N + 15, [0.0, 0.0, 5.0]), (15 * N + 23, [0.0, 0.0, -3.0]),
             (12 * N + 17, [2.0, 1.0, 2.0])]:
    chain.GraspPointId = g
    chain.Displacement = d
    x = points(chain)
    check(np.abs(x - rest).max() > 1.0, "grasp %d deforms" % g)
    check(np.array_equal(x[pinned_ids], rest[pinned_ids]), "pinned vertices unchanged while dragging")
    commit(chain)
    check(np.array_equal(points(chain)[pinned_ids], rest[pinned_ids]), "and after the commit")
chain.InvokeCommand("UndoEdit")
check(len(chain.EditHistory) == 2, "the undo dropped one record")
check(np.array_equal(points(chain)[pinned_ids], rest[pinned_ids]), "and after an undo")

# Pins shown apart from the heat map: exactly the pinned vertices, as cyan points.
import geoshaping_presets  # noqa: E402
shown_pins, pin_display = geoshaping_presets.show_pins(chain)
extracted = sm.Fetch(shown_pins)
got = vtk_to_numpy(extracted.GetPoints().GetData()).astype(float)
check(extracted.GetNumberOfPoints() == len(pinned_ids) and
      np.array_equal(np.sort(got, axis=0), np.sort(points(chain)[pinned_ids], axis=0)),
      "show_pins extracts exactly the %d pinned vertices" % len(pinned_ids))
check(pin_display.Representation == "Points" and list(pin_display.DiffuseColor) == [0.0, 1.0, 1.0]
      and pin_display.ColorArrayName[1] == "", "drawn as cyan points, not by the heat map")
