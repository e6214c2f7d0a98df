// A tetrahedral slab of the fault-step horizon, painted as in Figure 5C and deformed by
// dragging its step up; its outer surface coloured by malleability.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

using namespace geoshaping_image_testing;

int TestSlabDeformed(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(true);
  vtkNew<vtkChainMailDeformationFilter> drag;
  drag->SetInputConnection(painted->GetOutputPort());
  drag->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  drag->SetGraspPosition(50.0, 30.0, 10.0);
  drag->SetDisplacement(0.0, 0.0, 5.0);
  drag->Update();
  std::cout << "displaced " << drag->GetNumberOfDisplacedPoints() << " vertices\n";

  vtkSmartPointer<vtkRenderer> renderer = SurfaceRenderer(drag, "Malleability", MalleabilityColors());
  FaultStepCamera(renderer);
  vtkSmartPointer<vtkRenderWindow> window = TestWindow(480, 360);
  window->AddRenderer(renderer);
  window->Render();
  return CompareWithBaseline(argc, argv, window);
}
