"""Through the plugin's proxies: pins are chosen, never guessed,
and lists whose length does not fit their records are reported, not cut silently."""
from geoshaping_testing import check, load
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

load(ns=globals())

# 6 x 6 points: a float Malleability, a float Elevation (sorted first) and an integer
# Labels array, non-zero everywhere but at the grasp (pinning by Labels would leave
# only the grasp to move).
plane = Plane(XResolution=5, YResolution=5)
scene = ProgrammableFilter(Input=Triangulate(Input=plane))
scene.Script = """
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIntArray
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
m = vtkFloatArray(); m.SetName("Malleability"); m.SetNumberOfTuples(36); m.Fill(1.0)
labels = vtkIntArray(); labels.SetName("Labels"); labels.SetNumberOfTuples(36); labels.Fill(7)
labels.SetValue(14, 0)
out.GetPointData().AddArray(m)
out.GetPointData().AddArray(labels)
e = vtkFloatArray(); e.SetName("Elevation"); e.SetNumberOfTuples(36); e.Fill(0.0)
out.GetPointData().AddArray(e)
"""
scene.UpdatePipeline()  # the array domains need the arrays
chain = ChainMailDeformation(Input=scene)  # noqa: F405
check(chain.PinnedArray[1] == "None",
      "PinnedArray stays None beside an integer array (got %s)" % list(chain.PinnedArray))
check(chain.MalleabilityArray[1] == "Malleability", "MalleabilityArray picks Malleability, not Elevation (got %s)" % list(chain.MalleabilityArray))
chain.GraspPointId = 14
chain.Displacement = [0.0, 0.0, 2.0]
chain.UpdatePipeline()
chain.UpdatePropertyInformation()
moved = chain.GetProperty("NumberOfDisplacedPoints").GetElement(0)
check(moved == 36, "all 36 vertices follow a 2-unit pull on a soft mesh (moved %d)" % moved)
chain.PinnedArray = ["POINTS", "Labels"]
chain.UpdatePipeline()
chain.UpdatePropertyInformation()
check(chain.GetProperty("NumberOfDisplacedPoints").GetElement(0) == 1,
      "a chosen pin array pins: only the grasp moves")

# Warnings go to the output window (builtin session: client and server are this process).
# An incomplete last entry is reported by the client proxy, which sees the whole list
# (ParaView drops the tail on its way to the filter); the panel keeps one column per value.
window = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(window)
chain.PinnedArray = ["POINTS", "None"]
chain.StretchCurve = [0.0, 1.0, 1.0, 3.0, 0.5]
chain.UpdatePipeline()
check("ChainMailDeformation.StretchCurve has 5 values, not a whole number of 2-value entries: "
      "the last 1 is ignored" in window.GetOutput(),
      "an odd-length StretchCurve is reported")

paint = MalleabilityPaint(Input=scene)  # noqa: F405
paint.Dabs = [0.5, 0.5, 0.0, 0.3, 0.0, 1.0, 0.1]
paint.UpdatePipeline()
check("MalleabilityPaint.Dabs has 7 values, not a whole number of 6-value entries: the last 1 "
      "is ignored" in window.GetOutput(),
      "an incomplete last dab is reported")
check(sm.Fetch(paint).GetPointData().GetArray("Malleability").GetRange()[0] == 0.0,
      "the complete dab is applied")
