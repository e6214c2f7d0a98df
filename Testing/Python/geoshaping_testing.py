"""Helpers shared by the pvpython tests: load the plugin, build small scenes, compare."""
import os
import sys

from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403  (tests use the simple API)
from vtkmodules.util.numpy_support import vtk_to_numpy

PLUGIN = os.environ["GEOSHAPING_PLUGIN"]


def load(remote=False, ns=None):
    LoadPlugin(PLUGIN, remote=remote, ns=ns if ns is not None else globals())


def points(proxy):
    data = sm.Fetch(proxy)
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float)


def triangulated_plane(resolution=40):
    plane = Plane(XResolution=resolution, YResolution=resolution)
    plane.Origin = [0.0, 0.0, 0.0]
    plane.Point1 = [float(resolution), 0.0, 0.0]
    plane.Point2 = [0.0, float(resolution), 0.0]
    return Triangulate(Input=plane)


def check(condition, message):
    if not condition:
        print("FAILED:", message)
        sys.exit(1)
    print("ok:", message)


def check_same_dem_surface(ours, ref, label, ref_name):
    """Checks that the DEM surface `ours` (vtkPolyData) has `ref`'s points within 1e-6 m, in
    double precision, its triangles, and its Elevation equal to z; returns the points."""
    import numpy as np
    p = vtk_to_numpy(ours.GetPoints().GetData())
    q = vtk_to_numpy(ref.GetPoints().GetData())
    check(ours.GetPoints().GetDataType() == 11, "%s: double-precision points" % label)
    check(p.shape == q.shape, "%s: %d points, as the %s" % (label, len(q), ref_name))
    diff = float(np.abs(p - q).max())
    check(diff < 1e-6, "%s: every point within 1e-6 m of the %s (%.2g m)" % (label, ref_name, diff))
    a = vtk_to_numpy(ours.GetPolys().GetConnectivityArray())
    b = vtk_to_numpy(ref.GetPolys().GetConnectivityArray())
    check(np.array_equal(a, b), "%s: the same %d triangles" % (label, len(b) // 3))
    e = vtk_to_numpy(ours.GetPointData().GetArray("Elevation"))
    check(np.array_equal(e, p[:, 2]), "%s: Elevation is z" % label)
    return p
