// A tetrahedral slab of the fault-step horizon, painted as in Figure 5C and deformed by
// dragging its step up; its outer surface coloured by malleability.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkChainMailDeformationFilter.h"

using namespace geoshaping_image_testing;

int TestSlabDeformed(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(true);
  return CompareFaultStepFigure(argc, argv, LiftedStep(painted, 5.0));
}
