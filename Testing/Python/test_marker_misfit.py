"""Marker Misfit through the plugin: markers from a CSV (CSV Reader -> Table To Points)
and from a GOCAD VSet, against a ChainMail output; the misfit follows a pull. ChainMail
Deformation's Markers and HonourMarkers: a pull next to honoured wells leaves them on the
surface. The misfit figures of every frame (MarkerVerticalMisfitRMS / Max,
NumberOfMarkersInside, the output's field data) against Marker Misfit's VerticalMisfit;
SnapToMarkers as one edit, undone and redone."""
import os

from geoshaping_testing import check, load
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403

load(ns=globals())
tmp = os.environ["GEOSHAPING_TEST_TMP"]

# A horizon z = 0 over [0, 20]^2 and three wells: 2 above, on it, 1 below.
horizon = Triangulate(Input=Plane(Origin=[0, 0, 0], Point1=[20, 0, 0], Point2=[0, 20, 0],
                                  XResolution=20, YResolution=20))
csv = os.path.join(tmp, "markers.csv")
with open(csv, "w") as f:
    f.write("x,y,z,well\n10.5,10.25,2,1\n3.5,4.5,0,2\n15.25,6.5,-1,3\n")
table = CSVReader(FileName=[csv])
markers = TableToPoints(Input=table, XColumn="x", YColumn="y", ZColumn="z")
chain = ChainMailDeformation(Input=horizon)  # noqa: F405
misfit = MarkerMisfit(Input=chain, Markers=markers)  # noqa: F405
out = sm.Fetch(misfit)
vertical = out.GetPointData().GetArray("VerticalMisfit")
values = [vertical.GetValue(i) for i in range(3)]
check(values == [-2.0, 0.0, 1.0], "VerticalMisfit is surface minus marker (%r)" % values)
check(out.GetPointData().GetArray("well") is not None, "the CSV's columns are kept")
rms = out.GetFieldData().GetArray("MisfitRMS").GetValue(0)
check(abs(rms - (5.0 / 3.0) ** 0.5) < 1e-12, "MisfitRMS over the three (%r)" % rms)

# Pull the vertex under the first well up by 2: the surface reaches it.
chain.GraspPointId = 10 * 21 + 10
chain.Displacement = [0.0, 0.0, 2.0]
out = sm.Fetch(misfit)
first = out.GetPointData().GetArray("VerticalMisfit").GetValue(0)
check(-2.0 < first <= 0.0, "after the pull the first well is nearer (%r)" % first)

# The same markers as a GOCAD VSet file.
vs = os.path.join(tmp, "markers.vs")
with open(vs, "w") as f:
    f.write("GOCAD VSet 1\nHEADER {\nname:tops\n}\nVRTX 1 10.5 10.25 2\nVRTX 2 3.5 4.5 0\n"
            "VRTX 3 15.25 6.5 -1\nEND\n")
vset = GOCADTSurfReader(FileName=vs)  # noqa: F405
again = MarkerMisfit(Input=horizon, Markers=vset)  # noqa: F405
out = sm.Fetch(again)
values = [out.GetPointData().GetArray("VerticalMisfit").GetValue(i) for i in range(3)]
check(values == [-2.0, 0.0, 1.0], "a VSet's markers read the same (%r)" % values)

# Honoured while shaping: three wells on the horizon, a pull next to them. With
# HonourMarkers they stay on it (Marker Misfit on the output reads 0); without, not.
on_csv = os.path.join(tmp, "on.csv")
with open(on_csv, "w") as f:
    f.write("x,y,z\n3.5,4.5,0\n6.25,4.75,0\n4.5,6.5,0\n")
wells = TableToPoints(Input=CSVReader(FileName=[on_csv]), XColumn="x", YColumn="y",
                      ZColumn="z")
shaped = {}
for honour in (0, 1):
    pull = ChainMailDeformation(Input=horizon, Markers=[wells], HonourMarkers=honour)  # noqa: F405
    pull.GraspPointId = 5 * 21 + 5
    pull.Displacement = [0.0, 0.0, 4.0]
    out = sm.Fetch(MarkerMisfit(Input=pull, Markers=wells))  # noqa: F405
    vertical = out.GetPointData().GetArray("VerticalMisfit")
    shaped[honour] = [vertical.GetValue(i) for i in range(3)]
    pull.UpdatePropertyInformation()
    if honour:
        honoured = pull.GetProperty("NumberOfHonouredMarkers").GetData()
        check(honoured == 3, "three wells honoured (%r)" % honoured)
check(max(abs(v) for v in shaped[1]) <= 1e-6 * 20 * 2 ** 0.5,
      "honoured wells stay on the surface (%r)" % shaped[1])
check(max(abs(v) for v in shaped[0]) > 0.1, "unhonoured wells do not (%r)" % shaped[0])

# The frame's figures, HonourMarkers off: the three wells of markers.csv and one outside,
# against Marker Misfit's VerticalMisfit on the output, at rest and through a vertical pull
# under the first well.
far = os.path.join(tmp, "far.csv")
with open(far, "w") as f:
    f.write("x,y,z\n10.5,10.25,2\n3.5,4.5,0\n15.25,6.5,-1\n40,40,0\n")
four = TableToPoints(Input=CSVReader(FileName=[far]), XColumn="x", YColumn="y", ZColumn="z")
figured = ChainMailDeformation(Input=horizon, Markers=[four])  # noqa: F405
for grasp, dz in ((-1, 0.0), (10 * 21 + 10, 1.5), (10 * 21 + 10, 3.0)):
    figured.GraspPointId = grasp
    figured.Displacement = [0.0, 0.0, dz]
    measured = sm.Fetch(MarkerMisfit(Input=figured, Markers=four))  # noqa: F405
    vertical = measured.GetPointData().GetArray("VerticalMisfit")
    inside = measured.GetPointData().GetArray("Inside")
    values = [vertical.GetValue(i) for i in range(4) if inside.GetValue(i)]
    want = ((sum(v * v for v in values) / len(values)) ** 0.5, max(abs(v) for v in values))
    figured.UpdatePropertyInformation()
    got = (figured.GetProperty("MarkerVerticalMisfitRMS").GetData(),
           figured.GetProperty("MarkerVerticalMisfitMax").GetData())
    count = figured.GetProperty("NumberOfMarkersInside").GetData()
    check(count == 3 and len(values) == 3, "three wells inside (%r)" % count)
    check(abs(got[0] - want[0]) <= 1e-12 and abs(got[1] - want[1]) <= 1e-12,
          "the figures at dz %g are Marker Misfit's (%r, %r)" % (dz, got, want))
    fields = sm.Fetch(figured).GetFieldData()
    check(fields.GetArray("MarkerVerticalMisfitRMS").GetValue(0) == got[0]
          and fields.GetArray("MarkersInside").GetValue(0) == 3, "and in the field data")
    if dz == 0.0:
        check(abs(got[0] - (5.0 / 3.0) ** 0.5) < 1e-12 and got[1] == 2.0,
              "at rest: the wells' offsets 2, 0, 1 (%r)" % (got,))
check(got[0] < (5.0 / 3.0) ** 0.5, "the pull brought the surface nearer (%r)" % (got,))

# Snap to markers, a command property as CommitEdit is: one edit (EditHistory one longer),
# after which the three wells are on the surface; UndoEdit gives the shape before it bit
# for bit, RedoEdit the snapped one.
figured.GraspPointId = -1
figured.Displacement = [0.0, 0.0, 0.0]
points = sm.Fetch(figured).GetPoints()
before = [points.GetPoint(i) for i in range(points.GetNumberOfPoints())]
figured.SMProxy.InvokeCommand("SnapToMarkers")
check(len(figured.EditHistory) == 1, "the snap is one edit (%d)" % len(figured.EditHistory))
measured = sm.Fetch(MarkerMisfit(Input=figured, Markers=four))  # noqa: F405
vertical = measured.GetPointData().GetArray("VerticalMisfit")
snapped_misfit = [vertical.GetValue(i) for i in range(3)]
check(max(abs(v) for v in snapped_misfit) <= 1e-6 * 20 * 2 ** 0.5,
      "snapped: the wells are on the surface (%r)" % snapped_misfit)
points = sm.Fetch(figured).GetPoints()
snapped = [points.GetPoint(i) for i in range(points.GetNumberOfPoints())]
figured.UpdatePropertyInformation()
check(figured.GetProperty("LastSnappedMarkers").GetData() == 3, "three wells snapped")
figured.SMProxy.InvokeCommand("UndoEdit")
points = sm.Fetch(figured).GetPoints()
check([points.GetPoint(i) for i in range(points.GetNumberOfPoints())] == before,
      "undo gives the shape before the snap bit for bit")
figured.SMProxy.InvokeCommand("RedoEdit")
points = sm.Fetch(figured).GetPoints()
check([points.GetPoint(i) for i in range(points.GetNumberOfPoints())] == snapped,
      "redo gives the snap again")
print("marker misfit: ok")
