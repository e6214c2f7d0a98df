#include "GeoShapingImageTesting.h"

#include "vtkChainMailDeformationFilter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkElevationFilter.h"
#include "vtkFaultStepHorizonSource.h"
#include "vtkImageDifference.h"
#include "vtkMalleabilityPaintFilter.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTriangleFilter.h"
#include "vtkWindowToImageFilter.h"

#include "geoshaping/paint/malleability_preset.h"
#include "geoshaping/scenes/sample_scenes.h"

#include <iostream>
#include <string>

namespace geoshaping_image_testing
{

vtkSmartPointer<vtkColorTransferFunction> MalleabilityColors()
{
  auto colors = vtkSmartPointer<vtkColorTransferFunction>::New();
  colors->SetColorSpaceToRGB();
  const double* p = geoshaping::malleability_rgb_points;
  for (int i = 0; i < geoshaping::malleability_rgb_point_count; ++i, p += 4)
    colors->AddRGBPoint(p[0], p[1], p[2], p[3]);
  colors->SetNanColor(0.0, 0.5, 1.0);
  return colors;
}

vtkSmartPointer<vtkAlgorithm> PaintedFaultStep(bool slab)
{
  vtkNew<vtkFaultStepHorizonSource> scene;
  scene->SetOutputMeshType(
    slab ? vtkFaultStepHorizonSource::SLAB : vtkFaultStepHorizonSource::SURFACE);
  auto paint = vtkSmartPointer<vtkMalleabilityPaintFilter>::New();
  paint->SetInputConnection(scene->GetOutputPort());
  paint->SetInitialMalleability(geoshaping::fault_step_red);
  paint->SetFalloff(vtkMalleabilityPaintFilter::CONSTANT);
  paint->SetDistanceMode(vtkMalleabilityPaintFilter::EUCLIDEAN);
  for (const geoshaping::Dab& d : geoshaping::fault_step_painting(geoshaping::FaultStepParams{}))
    paint->AddDab(d.center.x(), d.center.y(), d.center.z(), d.radius, d.value, d.strength);
  return paint;
}

vtkSmartPointer<vtkRenderer> SurfaceRenderer(
  vtkAlgorithm* source, const char* array, vtkColorTransferFunction* colors)
{
  vtkNew<vtkDataSetSurfaceFilter> surface; // a no-op pass for polygonal data
  surface->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(surface->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(array);
  mapper->SetLookupTable(colors);
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.35);
  actor->GetProperty()->SetDiffuse(0.65);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->AddActor(actor);
  renderer->SetBackground(0.55, 0.6, 0.68);
  return renderer;
}

void FaultStepCamera(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(50.0, 30.0, 5.0);
  camera->SetPosition(135.0, -75.0, 85.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkActor> ElevationActor(
  vtkAlgorithm* source, double top, vtkScalarsToColors* heights)
{
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(source->GetOutputPort());
  elevation->SetLowPoint(0.0, 0.0, 0.0);
  elevation->SetHighPoint(0.0, 0.0, top);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  mapper->SetLookupTable(heights);
  mapper->UseLookupTableScalarRangeOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkChainMailDeformationFilter> Figure8Pull(int n, double lift, int queue)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(n, 0.0, 0.0);
  plane->SetPoint2(0.0, n, 0.0);
  plane->SetResolution(n, n);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  auto pull = vtkSmartPointer<vtkChainMailDeformationFilter>::New();
  pull->SetInputConnection(triangles->GetOutputPort());
  pull->SetDefaultMalleability(0.5);
  pull->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  pull->SetGraspPosition(n / 2.0, n / 2.0, 0.0);
  pull->SetDisplacement(0.0, 0.0, lift);
  pull->SetCandidateQueue(queue);
  return pull;
}

vtkSmartPointer<vtkRenderWindow> TestWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  return window;
}

int CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window)
{
  if (vtkRegressionTestImage(window) == vtkTesting::FAILED)
    return 1;
  vtkNew<vtkTesting> testing;
  testing->AddArguments(argc, argv);
  const std::string baseline = testing->GetValidImageFileName();
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline.c_str());
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkImageDifference> difference;
  difference->SetInputConnection(capture->GetOutputPort());
  difference->SetImageConnection(reader->GetOutputPort());
  difference->SetThreshold(30);
  difference->AveragingOff();
  difference->Update();
  const double error = difference->GetThresholdedError();
  std::cout << "Colour check against " << baseline << ": thresholded error " << error
            << " (limit 1)\n";
  return error > 1.0 ? 1 : 0;
}

vtkSmartPointer<vtkChainMailDeformationFilter> LiftedStep(vtkAlgorithm* painted, double lift)
{
  auto drag = vtkSmartPointer<vtkChainMailDeformationFilter>::New();
  drag->SetInputConnection(painted->GetOutputPort());
  drag->SetGraspMode(vtkChainMailDeformationFilter::GRASP_NEAREST_TO_POSITION);
  drag->SetGraspPosition(50.0, 30.0, 10.0);
  drag->SetDisplacement(0.0, 0.0, lift);
  drag->SetCandidateQueue(vtkChainMailDeformationFilter::FIFO_PRIORITY);
  drag->Update();
  std::cout << "displaced " << drag->GetNumberOfDisplacedPoints() << " vertices\n";
  return drag;
}

int CompareFaultStepFigure(int argc, char* argv[], vtkAlgorithm* source)
{
  vtkSmartPointer<vtkRenderer> renderer =
    SurfaceRenderer(source, "Malleability", MalleabilityColors());
  FaultStepCamera(renderer);
  vtkSmartPointer<vtkRenderWindow> window = TestWindow(480, 360);
  window->AddRenderer(renderer);
  window->Render();
  return CompareWithBaseline(argc, argv, window);
}

} // namespace geoshaping_image_testing
