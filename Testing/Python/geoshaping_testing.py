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
