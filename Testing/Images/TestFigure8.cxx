// Figure 8 (clockwise from the top left): a triangulated sheet of equal malleability at
// rest, then pulled up at its centre with the FIFO, FIFO Priority and Priority queues,
// coloured by elevation. FIFO and FIFO Priority agree (one malleability value, one
// bucket) and give a smooth pyramid; Priority's heap order among equal values gives the
// vein-like ridges of the paper.
#include "GeoShapingImageTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestFigure8(int argc, char* argv[])
{
  const int n = 60; // cells per side
  const double lift = 7.0;
  vtkNew<vtkLookupTable> heights;
  heights->SetHueRange(0.667, 0.0);
  heights->SetTableRange(0.0, 1.0);
  heights->Build();

  vtkSmartPointer<vtkRenderWindow> window = geoshaping_image_testing::TestWindow(600, 600);
  // Panels clockwise from the top left, as in the paper: rest, FIFO, FIFO Priority, Priority.
  const int queues[4] = { -1, vtkChainMailDeformationFilter::FIFO,
    vtkChainMailDeformationFilter::FIFO_PRIORITY, vtkChainMailDeformationFilter::PRIORITY };
  const double viewports[4][4] = { { 0.0, 0.5, 0.5, 1.0 }, { 0.5, 0.5, 1.0, 1.0 },
    { 0.5, 0.0, 1.0, 0.5 }, { 0.0, 0.0, 0.5, 0.5 } };
  for (int panel = 0; panel < 4; ++panel)
  {
    auto pull = geoshaping_image_testing::Figure8Pull(
      n, queues[panel] < 0 ? 0.0 : lift, queues[panel] < 0 ? 0 : queues[panel]);
    vtkSmartPointer<vtkActor> actor = geoshaping_image_testing::ElevationActor(pull, lift, heights);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.55, 0.6, 0.68);
    renderer->SetViewport(viewports[panel]);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(n / 2.0, n / 2.0, lift / 3.0);
    camera->SetPosition(n / 2.0, -0.3 * n, 1.05 * n);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(38.0);
    renderer->ResetCameraClippingRange();
    window->AddRenderer(renderer);
  }
  window->Render();
  return geoshaping_image_testing::CompareWithBaseline(argc, argv, window);
}
