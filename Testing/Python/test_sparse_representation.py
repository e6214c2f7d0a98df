"""The GeoShaping Surface representation: a drag updates in O(moved) and draws exactly
what ParaView's stock Surface representation draws for the same output.

For a triangulated plane (vtkPolyData) and a tetrahedral block (vtkUnstructuredGrid):
the deformation's default representation is GeoShaping Surface; after a drag of several
frames its counters show sparse updates (surface and GPU buffers); its image equals the
stock Surface image of the same output (vtkImageDifference, the usual 0.05 threshold); a
frame that skips an update (two UpdatePipeline calls, one render) falls back to the full
path and still draws the current shape. Painting during a drag re-maps only the painted
colours. Display properties changed mid-drag (opacity, lighting, colour map, scalar bar,
solid colour) cost one full rebuild, then the drag is sparse again and the image still
equals the stock one. Run under xvfb-run pvbatch."""
import os

from geoshaping_testing import *  # noqa: F401,F403
from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkIOImage import vtkPNGReader

load(ns=globals())
TMP = os.environ.get("GEOSHAPING_TEST_TMP", ".")


def counters(display):
    display.SMProxy.UpdatePropertyInformation()
    return {name: display.SMProxy.GetProperty(name).GetElement(0)
            for name in ("NumberOfSparseUpdates", "NumberOfFullUpdates",
                         "NumberOfSparseBuilds", "NumberOfFullBuilds")}


def image_error(a, b):
    readers = []
    for path in (a, b):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    diff = vtkImageDifference()
    diff.SetInputConnection(readers[0].GetOutputPort())
    diff.SetImageConnection(readers[1].GetOutputPort())
    diff.Update()
    return diff.GetThresholdedError()


def show_coloured(chain, focal):
    """A 400 x 300 view of `chain` coloured by Malleability, seen from the south-west."""
    view = CreateRenderView(ViewSize=[400, 300])
    display = Show(chain, view)
    ColorBy(display, ("POINTS", "Malleability"))
    view.CameraPosition = [-30, -60, 45]
    view.CameraFocalPoint = focal
    view.CameraViewUp = [0, 0, 1]
    ResetCamera(view)
    return view, display


def compare_with_stock(name, display, view):
    """The view's image against the same output drawn by the stock Surface
    representation; the display is left as GeoShaping Surface."""
    fast = os.path.join(TMP, "sparse_%s_fast.png" % name)
    stock = os.path.join(TMP, "sparse_%s_stock.png" % name)
    SaveScreenshot(fast, view)
    display.Representation = "Surface"
    Render(view)
    SaveScreenshot(stock, view)
    display.Representation = "GeoShaping Surface"
    Render(view)
    error = image_error(fast, stock)
    check(error <= 0.05, "%s: the sparse image equals the stock Surface image (error %g)"
          % (name, error))


def drag_and_compare(name, source, grasp, direction, frames=6):
    calc = Calculator(Input=source, ResultArrayName="Malleability", ResultArrayType="Float",
                      Function="0.2 + 0.6 * abs(sin(coordsX / 5))")
    chain = ChainMailDeformation(Input=calc)
    chain.MalleabilityArray = ["POINTS", "Malleability"]
    chain.GraspPointId = grasp
    view, display = show_coloured(chain, [10, 10, 0])
    check(display.Representation == "GeoShaping Surface",
          "%s: the deformation is shown as GeoShaping Surface by default" % name)
    display.RescaleTransferFunctionToDataRange(True)
    Render(view)
    before = counters(display)
    for f in range(1, frames + 1):
        chain.Displacement = [direction[k] * f for k in range(3)]
        chain.UpdatePipeline()
        Render(view)
    after = counters(display)
    sparse_updates = after["NumberOfSparseUpdates"] - before["NumberOfSparseUpdates"]
    sparse_builds = after["NumberOfSparseBuilds"] - before["NumberOfSparseBuilds"]
    check(sparse_updates == frames, "%s: %d of %d drag frames updated the surface sparsely"
          % (name, sparse_updates, frames))
    check(sparse_builds == frames, "%s: %d of %d drag frames uploaded only the moved points"
          % (name, sparse_builds, frames))

    # One render after two updates: the representation cannot follow, and rebuilds.
    chain.Displacement = [direction[k] * (frames + 2) for k in range(3)]
    chain.UpdatePipeline()
    chain.Displacement = [direction[k] * (frames + 3) for k in range(3)]
    chain.UpdatePipeline()
    Render(view)
    skipped = counters(display)
    check(skipped["NumberOfFullUpdates"] == after["NumberOfFullUpdates"] + 1,
          "%s: a skipped update takes the full path" % name)
    chain.Displacement = [direction[k] * (frames + 4) for k in range(3)]
    chain.UpdatePipeline()
    Render(view)
    check(counters(display)["NumberOfSparseBuilds"] == skipped["NumberOfSparseBuilds"] + 1,
          "%s: the next frame is sparse again" % name)

    compare_with_stock(name, display, view)
    Delete(display)
    Delete(view)


# vtkPolyData: a triangulated 41 x 41 plane, grasped in its middle, lifted.
drag_and_compare("polydata", triangulated_plane(40), 20 * 41 + 20, [0.0, 0.0, 1.5])

# vtkUnstructuredGrid: a tetrahedral block, grasped at a top vertex, lifted: the surface
# is extracted once and later frames copy only its moved points.
block = Tetrahedralize(Input=Wavelet(WholeExtent=[0, 20, 0, 20, 0, 4]))
grasp = 4 * 21 * 21 + 10 * 21 + 10  # (10, 10, 4): the middle of the top face
drag_and_compare("tetrahedra", block, grasp, [0.0, 0.0, 1.0])


# Painting while dragging (two hands): each frame moves the grasp and appends a dab.
# The paint filter paints only the new dab onto its array (bit for bit what a full
# update gives), and the representation re-maps only the painted colours.
plane = triangulated_plane(40)
paint = MalleabilityPaint(Input=plane)
paint.InitialMalleability = 0.5
paint.Falloff = "Smooth"
chain = ChainMailDeformation(Input=paint)
chain.MalleabilityArray = ["POINTS", "Malleability"]
chain.GraspPointId = 20 * 41 + 20
view, display = show_coloured(chain, [20, 20, 0])
lut = GetColorTransferFunction("Malleability")
lut.RescaleTransferFunction(0.0, 1.0)
Render(view)
before = counters(display)
paint.UpdatePropertyInformation()
incremental_before = paint.GetPropertyValue("NumberOfIncrementalUpdates")
dabs = []
frames = 6
for f in range(1, frames + 1):
    dabs += [6.0 * f, 8.0, 0.0, 4.0, 0.05 if f % 2 else 0.95, 0.8]
    paint.Dabs = dabs
    chain.Displacement = [0.0, 0.0, 1.5 * f]
    chain.UpdatePipeline()
    Render(view)
after = counters(display)
paint.UpdatePropertyInformation()
check(paint.GetPropertyValue("NumberOfIncrementalUpdates") - incremental_before == frames,
      "paint during drag: every dab painted incrementally")
check(after["NumberOfSparseUpdates"] - before["NumberOfSparseUpdates"] == frames,
      "paint during drag: every frame followed sparsely (positions and malleability)")
check(after["NumberOfSparseBuilds"] - before["NumberOfSparseBuilds"] == frames,
      "paint during drag: every frame uploaded only moved points and painted colours")
fresh = MalleabilityPaint(Input=plane)
fresh.InitialMalleability = 0.5
fresh.Falloff = "Smooth"
fresh.Dabs = dabs
incremental = sm.Fetch(paint).GetPointData().GetArray("Malleability")
full = sm.Fetch(fresh).GetPointData().GetArray("Malleability")
check(all(incremental.GetValue(i) == full.GetValue(i) for i in range(full.GetNumberOfTuples())),
      "paint during drag: the incremental array equals a full paint bit for bit")
compare_with_stock("paint", display, view)


# The usual display properties keep working on the fast path: mid-drag the user turns
# down the opacity, changes the lighting and the colour map, shows the scalar bar, then
# switches to a solid colour; the drag goes on and each image equals the stock Surface's.
Delete(display)
Delete(view)
calc = Calculator(Input=triangulated_plane(40), ResultArrayName="Malleability",
                  ResultArrayType="Float", Function="0.2 + 0.6 * abs(sin(coordsX / 5))")
chain = ChainMailDeformation(Input=calc)
chain.MalleabilityArray = ["POINTS", "Malleability"]
chain.GraspPointId = 20 * 41 + 20
view, display = show_coloured(chain, [20, 20, 0])
Render(view)
lift = [1.5]


def drag(frames):
    start = counters(display)
    for _ in range(frames):
        lift[0] += 1.5
        chain.Displacement = [0.0, 0.0, lift[0]]
        chain.UpdatePipeline()
        Render(view)
    end = counters(display)
    return {k: end[k] - start[k] for k in end}


drag(2)
display.Opacity = 0.6
display.Specular = 0.5
display.Interpolation = "Flat"
lut = GetColorTransferFunction("Malleability")
lut.ApplyPreset("Viridis (matplotlib)", True)
lut.RescaleTransferFunction(0.2, 0.8)
display.SetScalarBarVisibility(view, True)
moved = drag(4)
check(moved["NumberOfSparseUpdates"] == 4 and moved["NumberOfSparseBuilds"] >= 3,
      "restyled: the drag stays sparse after a one-off rebuild (%s)" % moved)
compare_with_stock("restyled", display, view)
ColorBy(display, None)
display.DiffuseColor = [0.8, 0.5, 0.2]
moved = drag(3)
check(moved["NumberOfSparseUpdates"] == 3 and moved["NumberOfSparseBuilds"] >= 2,
      "solid colour: the drag stays sparse after a one-off rebuild (%s)" % moved)
compare_with_stock("solid", display, view)
