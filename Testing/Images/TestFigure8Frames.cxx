// Figure 8's grasp (a triangulated sheet of equal malleability pulled up at its centre,
// FIFO Priority) seen from above, with the paper's axis-aligned valid region (left) and
// the link-aligned one (right, ValidRegionFrame Link), coloured by elevation in bands of
// one unit. With the box a link along a grid diagonal may slide h (|o_x| + |o_y|), sqrt(2)
// times its share per unit length, so the bands are a diamond with corners on the axes.
// With the cylinder every link slides h |o|, the same per unit of its length whatever its
// direction, so the pull falls off with the length of the edge paths: on this
// triangulation (axis edges and one family of diagonals) a hexagon, reaching as far along
// the diagonal that has edges as along the axes and less along the other diagonal
// (sqrt(2) h per unit there, two axis edges per diagonal step). Not round: the remaining
// anisotropy is the mesh's edge graph, not the valid region.
#include "GeoShapingImageTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkElevationFilter.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <iostream>

int TestFigure8Frames(int argc, char* argv[])
{
  const int n = 60; // cells per side
  const double lift = 7.0;
  // Bands of one unit of height, hue from blue (rest) to red (the grasp).
  const int bands = 8;
  vtkNew<vtkLookupTable> heights;
  heights->SetNumberOfTableValues(bands);
  heights->SetHueRange(0.667, 0.0);
  heights->SetTableRange(0.0, 1.0);
  heights->Build();
  heights->SetTableValue(0, 0.75, 0.75, 0.75); // at rest: grey

  vtkSmartPointer<vtkRenderWindow> window = geoshaping_image_testing::TestWindow(600, 300);
  const int frames[2] = { vtkChainMailDeformationFilter::AXES,
    vtkChainMailDeformationFilter::LINK };
  const double viewports[2][4] = { { 0.0, 0.0, 0.5, 1.0 }, { 0.5, 0.0, 1.0, 1.0 } };
  for (int panel = 0; panel < 2; ++panel)
  {
    auto pull =
      geoshaping_image_testing::Figure8Pull(n, lift, vtkChainMailDeformationFilter::FIFO_PRIORITY);
    pull->SetValidRegionFrame(frames[panel]);
    pull->Update();
    std::cout << (panel ? "Link" : "Axes") << ": " << pull->GetNumberOfDisplacedPoints()
              << " displaced\n";
    vtkNew<vtkElevationFilter> elevation;
    elevation->SetInputConnection(pull->GetOutputPort());
    elevation->SetLowPoint(0.0, 0.0, 0.0);
    elevation->SetHighPoint(0.0, 0.0, bands);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(elevation->GetOutputPort());
    mapper->SetLookupTable(heights);
    mapper->UseLookupTableScalarRangeOn();
    mapper->InterpolateScalarsBeforeMappingOn();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.55, 0.6, 0.68);
    renderer->SetViewport(viewports[panel]);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(n / 2.0, n / 2.0, 0.0);
    camera->SetPosition(n / 2.0, n / 2.0, 3.0 * n);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.52 * n);
    renderer->ResetCameraClippingRange();
    window->AddRenderer(renderer);
  }
  window->Render();
  return geoshaping_image_testing::CompareWithBaseline(argc, argv, window);
}
