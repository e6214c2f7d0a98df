"""An obstacle made from the deformation's own output (a Transform of it, chosen in
Python or through the panel's Pipeline Connection), or markers made from it, is a
pipeline loop: taken off the Obstacles (Markers) with an error naming it, the output the undeformed input, no crash and no hang
(the test's ctest TIMEOUT fails it if it hangs; before, UpdatePipeline overflowed the
stack); with the Obstacles set again the filter deforms again."""
import numpy as np
from geoshaping_testing import check, load, points
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

load(ns=globals())



def update(proxy):
    """Updates `proxy` and returns what went to the output window meanwhile (pvpython's
    own window, which also prints this test's lines, is put back after)."""
    shown = vtkOutputWindow.GetInstance()
    window = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(window)
    proxy.UpdatePipeline()
    vtkOutputWindow.SetInstance(shown)
    return window.GetOutput()


horizon = FaultStepHorizon()  # noqa: F405
paint = MalleabilityPaint(Input=horizon)  # noqa: F405
chain = ChainMailDeformation(Input=paint)  # noqa: F405
chain.OutputPointsPrecision = "Double"
chain.GraspPointId = 0
chain.Displacement = [0.0, 0.0, 5.0]
rest = points(paint)
free = points(chain)
check(np.abs(free - rest).max() >= 5.0 - 1e-9,
      "without obstacles the pull moves the surface (%r)" % np.abs(free - rest).max())

lifted = Transform(Input=chain)  # noqa: F405
lifted.Transform.Translate = [0.0, 0.0, 1.0]
for how in ("Python", "Pipeline Connection"):
    if how == "Python":
        chain.Obstacles = [lifted]
        check(len(chain.Obstacles) == 1 and chain.Obstacles[0].GetXMLName() ==
              "PipelineConnection", "Python: the Transform is taken off the Obstacles (%r)"
              % (chain.Obstacles,))
    else:
        # As in the panel: the filter's Pipeline Connection, its Input picked.
        connection = sm._getPyProxy(chain.GetProperty("Obstacles").FindDomain(
            "vtkSMProxyListDomain").GetProxy(0))
        chain.Obstacles = [connection]
        connection.Input = lifted
        check(connection.Input is None, "Pipeline Connection: its Input goes back to (none)")
    chain.Displacement = [0.0, 0.0, 6.0]
    text = update(chain)
    x = points(chain)
    check(np.array_equal(x, rest), "%s: the loop leaves the output the input's shape "
          "(%r from it)" % (how, np.abs(x - rest).max()))
    check("is made from this filter's own output: a pipeline loop" in text,
          "%s: the error names the loop (%r)" % (how, text[-300:]))
    update(lifted)  # downstream of the loop: no hang, the undeformed input + 1
    z = points(lifted)[:, 2]
    check(np.array_equal(z, rest[:, 2] + 1.0), "%s: the Transform updates" % how)

    chain.Obstacles = []
    chain.Displacement = [0.0, 0.0, 5.0]
    chain.UpdatePipeline()
    check(np.array_equal(points(chain), free), "%s: without the loop the pull is back" % how)
# The same loop through the Markers (port 2): taken off with an error, the output the
# input's shape, the Transform downstream updates, the pull back once it is gone.
chain.Markers = [lifted]
check(len(chain.Markers) == 1 and chain.Markers[0].GetXMLName() == "PipelineConnection",
      "Markers: the Transform is taken off the Markers (%r)" % (chain.Markers,))
chain.Displacement = [0.0, 0.0, 6.0]
text = update(chain)
check(np.array_equal(points(chain), rest) and "Markers input Transform1 is made from this "
      "filter's own output: a pipeline loop" in text,
      "Markers: refused, the output the input's shape (%r)" % text[-300:])
update(lifted)
check(np.array_equal(points(lifted)[:, 2], rest[:, 2] + 1.0), "Markers: the Transform updates")
chain.Markers = []
chain.Displacement = [0.0, 0.0, 5.0]
chain.UpdatePipeline()
check(np.array_equal(points(chain), free), "Markers: without the loop the pull is back")
# A loop closed upstream: an obstacle that was a Transform of a plane gets the
# deformation as its Input (Change Input...).
plane = Plane(Origin=[-50, -50, 100], Point1=[150, -50, 100], Point2=[-50, 150, 100])  # noqa: F405
moved = Transform(Input=plane)  # noqa: F405
chain.Obstacles = [moved]
chain.Displacement = [0.0, 0.0, 6.0]
check(update(chain) == "" and np.abs(points(chain) - rest).max() >= 6.0 - 1e-9,
      "a plane far above is an obstacle that holds nothing back")
moved.Input = chain
check(len(chain.Obstacles) == 1 and chain.Obstacles[0].GetXMLName() == "PipelineConnection",
      "Change Input: the Transform is taken off the Obstacles (%r)" % (chain.Obstacles,))
text = update(chain)
check(np.array_equal(points(chain), rest) and "Transform2" in text and "pipeline loop" in text,
      "Change Input: refused, the output the input's shape (%r)" % text[-200:])
chain.Obstacles = [plane]
check(update(chain) == "" and np.abs(points(chain) - rest).max() >= 6.0 - 1e-9,
      "another obstacle set: the filter deforms again")
print("obstacle loop: ok")
