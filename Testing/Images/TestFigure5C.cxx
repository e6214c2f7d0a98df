// Figure 5C: the fault-step horizon painted red, its step black, a white border around
// the step, shown with the black-body colour map.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"

using namespace geoshaping_image_testing;

int TestFigure5C(int argc, char* argv[])
{
  return CompareFaultStepFigure(argc, argv, PaintedFaultStep(false));
}
