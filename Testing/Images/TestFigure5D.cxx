// Figure 5D: the painted horizon of Figure 5C after grasping the middle of the step and
// lifting it 10 units (FIFO Priority): the black step moves as a rigid body,
// the white borders bend abruptly, the red surface gradually.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

using namespace geoshaping_image_testing;

int TestFigure5D(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(false);
  vtkNew<vtkChainMailDeformationFilter> drag;
  drag->SetInputConnection(painted->GetOutputPort());
  drag->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  drag->SetGraspPosition(50.0, 30.0, 10.0);
  drag->SetDisplacement(0.0, 0.0, 10.0);
  drag->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO_PRIORITY);
  drag->Update();
  std::cout << "displaced " << drag->GetNumberOfDisplacedPoints() << " vertices\n";

  vtkSmartPointer<vtkRenderer> renderer = SurfaceRenderer(drag, "Malleability", MalleabilityColors());
  FaultStepCamera(renderer);
  vtkSmartPointer<vtkRenderWindow> window = TestWindow(480, 360);
  window->AddRenderer(renderer);
  window->Render();
  return CompareWithBaseline(argc, argv, window);
}
