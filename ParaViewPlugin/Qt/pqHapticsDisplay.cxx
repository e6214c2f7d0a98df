#include "pqHapticsDisplay.h"

#include "pqHapticsProxies.h"
#include "undo_step.h"

#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServerManagerModel.h>
#include <pqUndoStack.h>

#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCollection.h>
#include <vtkNew.h>
#include <vtkPVRenderView.h>
#include <vtkRenderer.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMRenderViewProxy.h>
#include <vtkSMSessionProxyManager.h>
#include <vtkSMSourceProxy.h>
#include <vtkSmartPointer.h>

#include <chrono>

namespace interactor = geoshaping::interactor;

interactor::DisplayTransform pqHapticsDisplayTransform(vtkSMProxy* repr)
{
  if (!repr || !repr->GetProperty("Position") || !repr->GetProperty("Scale"))
  {
    return interactor::DisplayTransform();
  }
  double position[3], orientation[3], origin[3], scale[3];
  vtkSMPropertyHelper(repr, "Position").Get(position, 3);
  vtkSMPropertyHelper(repr, "Orientation").Get(orientation, 3);
  vtkSMPropertyHelper(repr, "Origin").Get(origin, 3);
  vtkSMPropertyHelper(repr, "Scale").Get(scale, 3);
  return interactor::DisplayTransform::of_prop(position, orientation, origin, scale);
}

namespace
{
Eigen::Vector3d displayToWorld(vtkRenderer* renderer, double x, double y, double depth)
{
  renderer->SetDisplayPoint(x, y, depth);
  renderer->DisplayToWorld();
  const double* w = renderer->GetWorldPoint();
  return Eigen::Vector3d(w[0], w[1], w[2]) / w[3];
}

// The geometry the client draws itself, picked by VTK (which applies each actor's
// matrix): on a distributed server no process may have met the ray with the selected cell
// (ParaView 5.11 then answers a zero normal for every process's cell but the first,
// docs/mpi.md); a server that renders remotely delivers no geometry: no point then.
bool clientPick(vtkRenderer* renderer, const int display[2], double p[3], double n[3])
{
  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0);
  if (!picker->Pick(display[0], display[1], 0.0, renderer))
  {
    return false;
  }
  picker->GetPickPosition(p);
  picker->GetPickNormal(n);
  return true;
}

// The ray nearEnd -> farEnd (data coordinates of `input`) met with every process's piece of
// `input` on the server, the nearest hit reduced across them (GeoShapingRayPick, the
// core's ray_pick.h): one push of the ray and one pull of the answer. False: no hit.
bool serverPick(vtkSMRenderViewProxy* view, vtkSMProxy* input, unsigned int port,
  const Eigen::Vector3d& nearEnd, const Eigen::Vector3d& farEnd, double p[3], double n[3])
{
  vtkSmartPointer<vtkSMSourceProxy> pick;
  pick.TakeReference(vtkSMSourceProxy::SafeDownCast(
    view->GetSessionProxyManager()->NewProxy("misc", "GeoShapingRayPick")));
  if (!pick || !input)
  {
    return false;
  }
  const Eigen::Vector3d direction = farEnd - nearEnd;
  vtkSMPropertyHelper(pick, "Input").Set(input, port);
  vtkSMPropertyHelper(pick, "RayOrigin").Set(nearEnd.data(), 3);
  vtkSMPropertyHelper(pick, "RayDirection").Set(direction.data(), 3);
  pick->UpdateVTKObjects();
  pick->UpdatePipeline();
  pick->UpdatePropertyInformation();
  if (vtkSMPropertyHelper(pick, "Hit").GetAsInt() == 0)
  {
    return false;
  }
  vtkSMPropertyHelper(pick, "HitPoint").Get(p, 3);
  vtkSMPropertyHelper(pick, "HitNormal").Get(n, 3);
  return true;
}

// True when the server draws the view's image (the client then holds no geometry).
bool rendersRemotely(vtkSMRenderViewProxy* view)
{
  auto* pv = vtkPVRenderView::SafeDownCast(view->GetClientSideObject());
  return pv && pv->GetUseDistributedRenderingForRender();
}
}

bool pqHapticsPickSurface(vtkSMRenderViewProxy* view, const int display[2], Eigen::Vector3d& world,
  Eigen::Vector3d& normal, double* serverMilliseconds)
{
  vtkRenderer* renderer = view ? view->GetRenderer() : nullptr;
  if (!renderer)
  {
    return false;
  }
  // The pick makes ParaView's selection proxies, whose changes are no undo step.
  const geoshaping::undo::Exclude pick;
  int region[4] = { display[0], display[1], display[0], display[1] };
  vtkNew<vtkCollection> representations;
  vtkNew<vtkCollection> sources;
  if (!view->SelectSurfaceCells(region, representations, sources, false) ||
      representations->GetNumberOfItems() == 0 || sources->GetNumberOfItems() == 0)
  {
    return false;
  }
  auto* repr = vtkSMProxy::SafeDownCast(representations->GetItemAsObject(0));
  auto* selection = vtkSMSourceProxy::SafeDownCast(sources->GetItemAsObject(0));
  const interactor::DisplayTransform shown = pqHapticsDisplayTransform(repr);
  if (!repr || !selection || !shown.invertible())
  {
    return false;
  }
  const Eigen::Vector3d nearEnd =
    shown.to_data(displayToWorld(renderer, display[0], display[1], 0.0));
  const Eigen::Vector3d farEnd =
    shown.to_data(displayToWorld(renderer, display[0], display[1], 1.0));
  double towardViewer[3];
  renderer->GetActiveCamera()->GetViewPlaneNormal(towardViewer);
  const Eigen::Vector3d toward(towardViewer[0], towardViewer[1], towardViewer[2]);
  vtkSMPropertyHelper input(repr, "Input");
  double p[3], n[3];
  if (rendersRemotely(view))
  {
    // The client holds no geometry: every process meets the ray with its piece.
    const auto start = std::chrono::steady_clock::now();
    const bool hit =
      serverPick(view, input.GetAsProxy(0), input.GetOutputPort(0), nearEnd, farEnd, p, n);
    if (serverMilliseconds)
    {
      *serverMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    if (!hit)
    {
      return false;
    }
  }
  else
  {
    vtkSmartPointer<vtkSMProxy> helper;
    helper.TakeReference(view->GetSessionProxyManager()->NewProxy("misc", "PickingHelper"));
    if (!helper)
    {
      return false;
    }
    vtkSMPropertyHelper(helper, "Input").Set(input.GetAsProxy(0));
    vtkSMPropertyHelper(helper, "Selection").Set(selection);
    vtkSMPropertyHelper(helper, "PointA").Set(nearEnd.data(), 3);
    vtkSMPropertyHelper(helper, "PointB").Set(farEnd.data(), 3);
    vtkSMPropertyHelper(helper, "SnapOnMeshPoint").Set(0);
    helper->UpdateVTKObjects();
    helper->UpdateProperty("Update", 1);
    vtkSMPropertyHelper(helper, "Intersection").UpdateValueFromServer();
    vtkSMPropertyHelper(helper, "Intersection").Get(p, 3);
    vtkSMPropertyHelper(helper, "IntersectionNormal").UpdateValueFromServer();
    vtkSMPropertyHelper(helper, "IntersectionNormal").Get(n, 3);
  }
  if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
  {
    if (!clientPick(renderer, display, p, n))
    {
      return false;
    }
    world = Eigen::Vector3d(p[0], p[1], p[2]);
    normal = Eigen::Vector3d(n[0], n[1], n[2]);
    normal = normal.dot(toward) < 0.0 ? Eigen::Vector3d(-normal) : normal;
  }
  else
  {
    world = shown.to_world(Eigen::Vector3d(p[0], p[1], p[2]));
    normal = shown.normal_to_world(Eigen::Vector3d(n[0], n[1], n[2]), toward);
  }
  return world.allFinite();
}

std::vector<pqOutputPort*> pqHapticsProxies::obstaclePorts() const
{
  std::vector<pqOutputPort*> ports;
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy || !proxy->GetProperty("Obstacles"))
  {
    return ports;
  }
  auto* model = pqApplicationCore::instance()->getServerManagerModel();
  vtkSMPropertyHelper obstacles(proxy, "Obstacles");
  for (unsigned int i = 0; i < obstacles.GetNumberOfElements(); ++i)
  {
    // A source connected directly (Python, older states) or chosen in the panel's
    // Pipeline Connection, whose own Input is the source.
    vtkSMProxy* connected = obstacles.GetAsProxy(i);
    unsigned int output = obstacles.GetOutputPort(i);
    if (connected && !model->findItem<pqPipelineSource*>(connected) &&
        connected->GetProperty("Input"))
    {
      vtkSMPropertyHelper input(connected, "Input");
      output = input.GetNumberOfElements() > 0 ? input.GetOutputPort(0) : 0;
      connected = input.GetNumberOfElements() > 0 ? input.GetAsProxy(0) : nullptr;
    }
    auto* source = model->findItem<pqPipelineSource*>(connected);
    if (pqOutputPort* port = source ? source->getOutputPort(int(output)) : nullptr)
    {
      ports.push_back(port);
    }
  }
  return ports;
}

std::vector<vtkSMProxy*> pqHapticsProxies::shapedRepresentations() const
{
  std::vector<vtkSMProxy*> shaped;
  if (vtkSMProxy* repr = this->representation(this->Deformation))
  {
    shaped.push_back(repr);
  }
  for (pqOutputPort* port : this->View ? this->obstaclePorts() : std::vector<pqOutputPort*>())
  {
    if (pqDataRepresentation* repr = port->getRepresentation(this->View))
    {
      shaped.push_back(repr->getProxy());
    }
  }
  return shaped;
}

double pqHapticsProxies::verticalExaggeration() const
{
  vtkSMProxy* repr = this->representation(this->Deformation);
  double scale[3] = { 1.0, 1.0, 1.0 };
  if (repr && repr->GetProperty("Scale"))
  {
    vtkSMPropertyHelper(repr, "Scale").Get(scale, 3);
  }
  return interactor::exaggeration_of(scale);
}

void pqHapticsProxies::setVerticalExaggeration(double s)
{
  const Eigen::Vector3d scale = interactor::exaggeration_scale(s);
  BEGIN_UNDO_SET(QString("Vertical Exaggeration"));
  for (vtkSMProxy* repr : this->shapedRepresentations())
  {
    if (repr->GetProperty("Scale"))
    {
      vtkSMPropertyHelper(repr, "Scale").Set(scale.data(), 3);
      repr->UpdateVTKObjects();
    }
  }
  END_UNDO_SET();
  if (this->View)
  {
    this->View->render();
  }
}
