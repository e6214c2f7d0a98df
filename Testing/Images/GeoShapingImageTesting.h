#pragma once
// Scenes and colours shared by the GeoShaping image-regression tests.
#include "vtkSmartPointer.h"

class vtkActor;
class vtkAlgorithm;
class vtkChainMailDeformationFilter;
class vtkColorTransferFunction;
class vtkRenderWindow;
class vtkRenderer;
class vtkScalarsToColors;

namespace geoshaping_image_testing
{

// The "Malleability (black-body)" colour map, read from the ParaView preset file that
// the plugin ships (one definition for ParaView and for these tests). Range 0-1.
vtkSmartPointer<vtkColorTransferFunction> MalleabilityColors();

// The Figure 5 horizon (default size, spacing 1) painted as in Figure 5C by
// vtkMalleabilityPaintFilter from the core's dab list; `slab` gives the tetrahedral one.
vtkSmartPointer<vtkAlgorithm> PaintedFaultStep(bool slab);

// A renderer showing `source`'s output surface coloured by the point array `array`
// through `colors` (scalar range fixed by the colour map), flat-lit, on a grey background.
vtkSmartPointer<vtkRenderer> SurfaceRenderer(
  vtkAlgorithm* source, const char* array, vtkColorTransferFunction* colors);

// `source`'s output coloured by height through `heights` (its table range spanning
// z = 0 ... top), as the Figure 8 panels show a pull.
vtkSmartPointer<vtkActor> ElevationActor(
  vtkAlgorithm* source, double top, vtkScalarsToColors* heights);

// Figure 8's scene: an n x n sheet of unit triangulated cells at z = 0, pulled at the
// vertex nearest its centre by `lift` at malleability 0.5 with `queue` (not updated).
vtkSmartPointer<vtkChainMailDeformationFilter> Figure8Pull(int n, double lift, int queue);

// The oblique camera used for the fault-step figures.
void FaultStepCamera(vtkRenderer* renderer);

// An off-screen-sized window for one test image.
vtkSmartPointer<vtkRenderWindow> TestWindow(int width, int height);

// VTK's regression test (-V baseline, -T temporary directory), then a stricter colour
// check against the same baseline: vtkImageDifference's default threshold (105 per
// pixel, 68 when averaged) lets a red turn orange unnoticed, so pixels are compared
// again with a threshold of 30 (shifts of two pixels still allowed). Returns 0 when
// both pass, as the test driver expects.
int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window);

// The painted fault step with the middle of its step (the vertex nearest (50, 30, 10))
// lifted by `lift` under FIFO Priority, updated; prints how many vertices moved.
vtkSmartPointer<vtkChainMailDeformationFilter> LiftedStep(vtkAlgorithm* painted, double lift);

// `source` coloured by Malleability through the fault-step camera in a 480 x 360 window,
// compared with the test's baseline (CompareWithBaseline).
int CompareFaultStepFigure(int argc, char* argv[], vtkAlgorithm* source);

} // namespace geoshaping_image_testing
