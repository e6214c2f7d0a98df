// A horizon pulled up into the fault that overhangs it (docs/obstacles.md): left, the
// pull without obstacles goes through the fault; right, the fault is an obstacle and
// the horizon stops under it, flattened against its plane. The horizon is coloured by
// elevation, the fault drawn as its edges, seen slightly oblique along the fault's strike.
#include "GeoShapingImageTesting.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkChainMailDeformationFilter.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTriangleFilter.h"

#include <iostream>

int TestHorizonStoppedAtFault(int argc, char* argv[])
{
  // Horizon x in [0, 48], y in [0, 50] at z = 0; fault x = 50 - 0.6 z, z in [-4, 16].
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(48.0, 0.0, 0.0);
  plane->SetPoint2(0.0, 50.0, 0.0);
  plane->SetResolution(48, 50);
  vtkNew<vtkTriangleFilter> horizon;
  horizon->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkPlaneSource> faultPlane;
  faultPlane->SetOrigin(50.0 + 0.6 * 4.0, -2.0, -4.0);
  faultPlane->SetPoint1(50.0 + 0.6 * 4.0, 52.0, -4.0);
  faultPlane->SetPoint2(50.0 - 0.6 * 16.0, -2.0, 16.0);
  faultPlane->SetResolution(10, 5);
  vtkNew<vtkTriangleFilter> fault;
  fault->SetInputConnection(faultPlane->GetOutputPort());

  const double lift = 14.0;
  vtkNew<vtkLookupTable> heights;
  heights->SetHueRange(0.667, 0.0);
  heights->SetTableRange(0.0, 1.0);
  heights->Build();
  vtkSmartPointer<vtkRenderWindow> window = geoshaping_image_testing::TestWindow(640, 320);
  for (int panel = 0; panel < 2; ++panel)
  {
    vtkNew<vtkChainMailDeformationFilter> pull;
    pull->SetInputConnection(horizon->GetOutputPort());
    if (panel == 1)
      pull->AddObstacleConnection(fault->GetOutputPort());
    pull->SetDefaultMalleability(1.0); // shear 0.5: a bump of radius ~28
    pull->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
    pull->SetGraspPosition(43.0, 25.0, 0.0);
    pull->SetDisplacement(0.0, 0.0, lift);
    pull->Update();
    std::cout << (panel ? "with" : "without") << " the fault: displaced "
              << pull->GetNumberOfDisplacedPoints() << ", blocked "
              << pull->GetNumberOfObstacleBlockedPoints() << ", grasp fraction "
              << pull->GetLastGraspObstacleFraction() << "\n";
    vtkSmartPointer<vtkActor> actor = geoshaping_image_testing::ElevationActor(pull, lift, heights);
    vtkNew<vtkPolyDataMapper> faultMapper;
    faultMapper->SetInputConnection(faultPlane->GetOutputPort());
    faultMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> faultActor;
    faultActor->SetMapper(faultMapper);
    faultActor->GetProperty()->SetRepresentationToWireframe();
    faultActor->GetProperty()->SetColor(0.15, 0.15, 0.15);
    faultActor->GetProperty()->SetLineWidth(2.0);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->AddActor(faultActor);
    renderer->SetBackground(0.55, 0.6, 0.68);
    renderer->SetViewport(0.5 * panel, 0.0, 0.5 * (panel + 1), 1.0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(34.0, 25.0, 3.0);
    camera->SetPosition(8.0, -40.0, 34.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(44.0);
    renderer->ResetCameraClippingRange();
    window->AddRenderer(renderer);
  }
  window->Render();
  return geoshaping_image_testing::CompareWithBaseline(argc, argv, window);
}
