"""ParaView check of the GOCAD TSurf proxies: File > Open picks the reader by the .ts
extension, Save Data picks the writer, and the saved file reads back bit-exact.

Usage: pvpython tsurf_pvpython_check.py GeoShaping.so input.ts output.ts
"""
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, SaveData
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, source_file, saved_file = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())

vertices = triangles = 0
with open(source_file) as text:
    for line in text:
        keyword = line.split()[0] if line.split() else ""
        vertices += keyword in ("VRTX", "PVRTX")
        triangles += keyword == "TRGL"

source = OpenDataFile(source_file)
assert source.GetXMLName() == "GocadTSurfReader", source.GetXMLName()
original = servermanager.Fetch(source)
assert original.GetNumberOfPoints() == vertices, (original.GetNumberOfPoints(), vertices)
assert original.GetNumberOfPolys() == triangles, (original.GetNumberOfPolys(), triangles)

SaveData(saved_file, proxy=source)
copy_proxy = GOCADTSurfReader(FileName=saved_file)  # noqa: F821 (defined by LoadPlugin)
copy = servermanager.Fetch(copy_proxy)
a = vtk_to_numpy(original.GetPoints().GetData())
b = vtk_to_numpy(copy.GetPoints().GetData())
assert a.dtype.name == "float64" and (a == b).all(), "coordinates changed on the round trip"
print(f"ok: {vertices} points, {triangles} triangles, saved and read back bit-exact")
