"""Marker Misfit through the plugin: markers from a CSV (CSV Reader -> Table To Points)
and from a GOCAD VSet, against a ChainMail output; the misfit follows a pull. ChainMail
Deformation's Markers and HonourMarkers: a pull next to honoured wells leaves them on the
surface."""
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
print("marker misfit: ok")
