// Figure 5C: the fault-step horizon painted red, its step black, a white border around
// the step, shown with the black-body colour map.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkColorTransferFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

using namespace geoshaping_image_testing;

int TestFigure5C(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(false);
  vtkSmartPointer<vtkRenderer> renderer =
    SurfaceRenderer(painted, "Malleability", MalleabilityColors());
  FaultStepCamera(renderer);
  vtkSmartPointer<vtkRenderWindow> window = TestWindow(480, 360);
  window->AddRenderer(renderer);
  window->Render();
  return CompareWithBaseline(argc, argv, window);
}
