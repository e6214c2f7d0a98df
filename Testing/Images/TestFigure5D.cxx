// Figure 5D: the painted horizon of Figure 5C after grasping the middle of the step and
// lifting it 10 units (FIFO Priority): the black step moves as a rigid body,
// the white borders bend abruptly, the red surface gradually.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkChainMailDeformationFilter.h"

using namespace geoshaping_image_testing;

int TestFigure5D(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(false);
  return CompareFaultStepFigure(argc, argv, LiftedStep(painted, 10.0));
}
