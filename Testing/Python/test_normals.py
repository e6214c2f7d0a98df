"""Lighting follows the shape: the deformation's output normals are those of the
deformed surface. A 120 x 120 triangulated plane (with the plane source's Normals) lifted
by 40 at its centre: every output normal equals vtkPolyDataNormals' point normal of the
output shape (no splitting, no reorientation) to float precision. Before the fix the
input's normals passed through: 14,161 of the 14,400 vertices moved and carried a normal
more than 18 degrees off the deformed surface."""
import numpy as np

from geoshaping_testing import *  # noqa: F401,F403
from paraview import servermanager as sm
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

load(ns=globals())

n = 120
plane = triangulated_plane(n - 1)
chain = ChainMailDeformation(Input=plane)
chain.MalleabilityArray = ["POINTS", ""]
chain.DefaultMalleability = 0.5
chain.GraspPointId = (n // 2) * n + n // 2


def normals_and_reference():
    out = sm.Fetch(chain)
    check(out.GetPointData().GetNormals() is not None, "the output has point normals")
    normals = vtk_to_numpy(out.GetPointData().GetNormals()).astype(float)
    bare = vtkPolyData()
    bare.SetPoints(out.GetPoints())
    bare.SetPolys(out.GetPolys())
    reference = vtkPolyDataNormals()
    reference.SetInputData(bare)
    reference.SplittingOff()
    reference.ConsistencyOff()
    reference.AutoOrientNormalsOff()
    reference.Update()
    expected = vtk_to_numpy(reference.GetOutput().GetPointData().GetNormals()).astype(float)
    return normals, expected


def degrees_off(a, b):
    cos = np.clip(np.sum(a * b, axis=1) / np.linalg.norm(a, axis=1) / np.linalg.norm(b, axis=1),
                  -1.0, 1.0)
    return np.degrees(np.arccos(cos))


for lift in (40.0, 12.5, 0.0):  # lift, move again, release to rest
    chain.Displacement = [0.0, 0.0, lift]
    chain.UpdatePipeline()
    chain.UpdatePropertyInformation()
    moved = chain.GetPropertyValue("NumberOfDisplacedPoints") if lift else 0
    check(abs(points(chain)[:, 2].max() - lift) < 1e-9, "the plane is lifted by %g" % lift)
    normals, expected = normals_and_reference()
    off = degrees_off(normals, expected)
    check(len(normals) == n * n, "one normal per vertex")
    check(off.max() < 1e-3, "lift %g (%d moved): every normal is the deformed surface's "
          "(largest difference %.2e degrees)" % (lift, moved, off.max()))
    check(int((off > 18.0).sum()) == 0, "lift %g: no normal more than 18 degrees off" % lift)
