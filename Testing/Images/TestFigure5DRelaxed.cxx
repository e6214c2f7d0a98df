// Figure 5D with the relaxation pass (RelaxationIterations 100): the same lift of the
// rigid step, the displaced soft region smoothed within its links (docs/deformer.md,
// "Relaxation"); compare TestFigure5D.
#include "GeoShapingImageTesting.h"

#include "vtkAlgorithm.h"
#include "vtkChainMailDeformationFilter.h"

using namespace geoshaping_image_testing;

int TestFigure5DRelaxed(int argc, char* argv[])
{
  vtkSmartPointer<vtkAlgorithm> painted = PaintedFaultStep(false);
  vtkSmartPointer<vtkChainMailDeformationFilter> lifted = LiftedStep(painted, 10.0);
  lifted->SetRelaxationIterations(100);
  lifted->Update();
  std::cout << "relaxed " << lifted->GetNumberOfRelaxedPoints() << " vertices in "
            << lifted->GetNumberOfRelaxationSweeps() << " sweeps\n";
  return CompareFaultStepFigure(argc, argv, lifted);
}
