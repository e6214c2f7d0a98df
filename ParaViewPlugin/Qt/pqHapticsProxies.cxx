#include "pqHapticsProxies.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServer.h>
#include <pqServerManagerModel.h>

#include "pqHapticsDisplay.h"
#include "pqHapticsUndo.h"
#include "undo_step.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGeoShapingContactPatch.h"
#include "vtkSMChainMailDeformationProxy.h"

#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMRenderViewProxy.h>
#include <vtkSMSessionProxyManager.h>
#include <vtkSMSourceProxy.h>
#include <vtkTransform.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

namespace
{
// Whether `a` is a rotation times a uniform scale (a similarity): distances keep their
// order through it. Within 1e-12 of its scale.
bool similarity(const Eigen::Matrix3d& a)
{
  const Eigen::Matrix3d g = a.transpose() * a;
  const double s = g.trace() / 3.0;
  return s > 0.0 && (g - s * Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-12 * s;
}

bool isA(pqPipelineSource* source, const char* xmlName)
{
  return source && source->getProxy() && source->getProxy()->GetXMLName() &&
         std::strcmp(source->getProxy()->GetXMLName(), xmlName) == 0;
}
}

pqPipelineSource* pqHapticsFindSource(const char* xmlName, pqView* view)
{
  auto* model = pqApplicationCore::instance()->getServerManagerModel();
  pqPipelineSource* first = nullptr;
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    if (!isA(source, xmlName))
    {
      continue;
    }
    if (!view)
    {
      return source;
    }
    first = first ? first : source;
    pqDataRepresentation* shown = source->getRepresentation(view);
    if (shown && shown->isVisible())
    {
      return source;
    }
  }
  return first;
}

namespace
{
// `proxy` and the proxies feeding it, following first inputs upstream.
std::vector<vtkSMProxy*> inputChain(vtkSMProxy* proxy)
{
  std::vector<vtkSMProxy*> chain;
  for (int depth = 0; proxy && depth < 64; ++depth)
  {
    chain.push_back(proxy);
    proxy =
      proxy->GetProperty("Input") ? vtkSMPropertyHelper(proxy, "Input").GetAsProxy(0) : nullptr;
  }
  return chain;
}

// The MalleabilityPaint feeding `source`, following first inputs upstream.
pqPipelineSource* paintUpstreamOf(pqPipelineSource* source)
{
  auto* model = pqApplicationCore::instance()->getServerManagerModel();
  for (vtkSMProxy* proxy : inputChain(source ? source->getProxy() : nullptr))
  {
    auto* item = model->findItem<pqPipelineSource*>(proxy);
    if (isA(item, "MalleabilityPaint"))
    {
      return item;
    }
  }
  return nullptr;
}
}

void pqHapticsProxies::refresh()
{
  this->InformationRead = false;
  auto& active = pqActiveObjects::instance();
  this->View = qobject_cast<pqRenderView*>(active.activeView());
  pqPipelineSource* deformation = active.activeSource();
  if (!isA(deformation, "ChainMailDeformation"))
  {
    deformation = pqHapticsFindSource("ChainMailDeformation", this->View);
  }
  if (deformation != this->Deformation)
  {
    this->Deformation = deformation;
    this->Paint = nullptr;
  }
  if (!this->Paint)
  {
    this->Paint = paintUpstreamOf(deformation);
    if (!this->Paint)
    {
      this->Paint = pqHapticsFindSource("MalleabilityPaint");
    }
    this->Dabs.clear();
    this->PointDabs.clear();
    if (this->Paint)
    {
      this->Dabs = vtkSMPropertyHelper(this->Paint->getProxy(), "Dabs").GetDoubleArray();
      if (this->Paint->getProxy()->GetProperty("PointDabs"))
      {
        this->PointDabs =
          vtkSMPropertyHelper(this->Paint->getProxy(), "PointDabs").GetDoubleArray();
      }
    }
  }
}

geoshaping::interactor::CameraPose pqHapticsProxies::camera() const
{
  geoshaping::interactor::CameraPose pose;
  auto* viewProxy = this->View ? this->View->getRenderViewProxy() : nullptr;
  vtkCamera* camera = viewProxy ? viewProxy->GetActiveCamera() : nullptr;
  if (camera)
  {
    pose.position = Eigen::Map<const Eigen::Vector3d>(camera->GetPosition());
    pose.focal_point = Eigen::Map<const Eigen::Vector3d>(camera->GetFocalPoint());
    pose.view_up = Eigen::Map<const Eigen::Vector3d>(camera->GetViewUp());
    pose.view_angle_deg = camera->GetViewAngle();
    pose.parallel = camera->GetParallelProjection() != 0;
    pose.parallel_scale = camera->GetParallelScale();
  }
  return pose;
}

vtkSMProxy* pqHapticsProxies::representation(pqPipelineSource* source) const
{
  pqDataRepresentation* repr =
    source && this->View ? source->getRepresentation(this->View) : nullptr;
  return repr ? repr->getProxy() : nullptr;
}

Eigen::Matrix4d pqHapticsProxies::objectMatrix() const
{
  return pqHapticsDisplayTransform(this->representation(this->Deformation)).matrix();
}

void pqHapticsProxies::setObjectMatrix(const Eigen::Matrix4d& m)
{
  vtkSMProxy* repr = this->representation(this->Deformation);
  if (!repr || !repr->GetProperty("Position") || !m.allFinite())
  {
    return;
  }
  double origin[3], scale[3];
  vtkSMPropertyHelper(repr, "Origin").Get(origin, 3);
  vtkSMPropertyHelper(repr, "Scale").Get(scale, 3);
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  const Eigen::Vector3d o(origin[0], origin[1], origin[2]);
  // m x = R S (x - O) + O + P  =>  P = t + (R S) O - O.
  const Eigen::Vector3d position = m.topRightCorner<3, 1>() + linear * o - o;
  vtkNew<vtkTransform> rotation;
  vtkNew<vtkMatrix4x4> r;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r->SetElement(i, j, scale[j] != 0.0 ? linear(i, j) / scale[j] : 0.0);
    }
  }
  rotation->SetMatrix(r);
  double orientation[3];
  rotation->GetOrientation(orientation);
  vtkSMPropertyHelper(repr, "Position").Set(position.data(), 3);
  vtkSMPropertyHelper(repr, "Orientation").Set(orientation, 3);
  this->RepresentationModified = true;
}

void pqHapticsProxies::grasp(const Eigen::Vector3d& position)
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy)
  {
    return;
  }
  const double zero[3] = { 0.0, 0.0, 0.0 };
  vtkSMPropertyHelper(proxy, "Displacement").Set(zero, 3);
  vtkStaticPointLocator* locator = this->shownLocator();
  vtkIdType id = locator ? locator->FindClosestPoint(position.data()) : -1;
  const auto shown = pqHapticsDisplayTransform(this->representation(this->Deformation));
  if (id >= 0 && shown.stretch() > 1.0 + 1e-9)
  {
    // Exaggerated: the vertex drawn nearest, among those it can be (DisplayTransform.h).
    vtkPointSet* surface = this->shownSurface();
    Eigen::Vector3d nearest;
    surface->GetPoint(id, nearest.data());
    vtkNew<vtkIdList> ids;
    locator->FindPointsWithinRadius(
      shown.stretch() * (nearest - position).norm(), position.data(), ids);
    std::vector<Eigen::Vector3d> candidates(std::size_t(ids->GetNumberOfIds()));
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      surface->GetPoint(ids->GetId(i), candidates[std::size_t(i)].data());
    }
    if (!candidates.empty())
    {
      id = ids->GetId(vtkIdType(shown.nearest_drawn(position, candidates)));
    }
  }
  if (id >= 0)
  {
    // The vertex the user sees nearest (after committed edits it is not the nearest
    // input vertex the filter's own Nearest To Position mode would take).
    vtkSMPropertyHelper(proxy, "GraspMode").Set(0); // Point Id
    vtkSMPropertyHelper(proxy, "GraspPointId").Set(static_cast<vtkIdType>(id));
  }
  else
  {
    vtkSMPropertyHelper(proxy, "GraspMode").Set(1); // Nearest To Position
    vtkSMPropertyHelper(proxy, "GraspPosition").Set(position.data(), 3);
  }
  this->DeformationModified = true;
}

vtkPointSet* pqHapticsProxies::shownSurface() const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  auto* filter = proxy ? vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject()) : nullptr;
  auto* output = filter ? vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0)) : nullptr;
  return output && output->GetNumberOfPoints() > 0 ? output : nullptr;
}

vtkStaticCellLocator* pqHapticsProxies::cellLocator(vtkDataSet* data)
{
  this->CellLocators.erase(std::remove_if(this->CellLocators.begin(), this->CellLocators.end(),
                             [](const CellLocatorEntry& e) { return !e.data; }),
    this->CellLocators.end());
  auto* pointSet = vtkPointSet::SafeDownCast(data);
  const vtkMTimeType time =
    pointSet ? vtkGeoShapingAdapter::GeometryTime(pointSet) : data->GetMTime();
  auto entry = std::find_if(this->CellLocators.begin(), this->CellLocators.end(),
    [data](const CellLocatorEntry& e) { return e.data == data; });
  if (entry == this->CellLocators.end())
  {
    entry = this->CellLocators.insert(this->CellLocators.end(), CellLocatorEntry());
    entry->data = data;
  }
  if (!entry->locator || entry->time != time)
  {
    entry->locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    entry->locator->SetDataSet(data);
    entry->locator->BuildLocator();
    entry->time = time;
  }
  return entry->locator;
}

void pqHapticsProxies::contactTriangles(const Eigen::Vector3d& world, double radius, bool withShown,
  std::size_t nearest, std::vector<Eigen::Vector3d>& out)
{
  this->PatchFigures = ServerPatchFigures();
  if (!this->View || !world.allFinite() || !(radius > 0.0))
  {
    return;
  }
  const bool remote = this->View->getServer() && this->View->getServer()->isRemote();
  // The deformation's upstream: the same surface before the deformation (the
  // deformation itself is left out or not by `withShown`).
  std::vector<vtkSMProxy*> upstream =
    inputChain(this->Deformation ? this->Deformation->getProxy() : nullptr);
  if (!upstream.empty())
  {
    upstream.erase(upstream.begin());
  }
  std::vector<double> xyz;
  for (pqRepresentation* item : this->View->getRepresentations())
  {
    auto* repr = qobject_cast<pqDataRepresentation*>(item);
    pqPipelineSource* source = repr ? repr->getInput() : nullptr;
    if (!repr || !repr->isVisible() || !source ||
        std::find(upstream.begin(), upstream.end(), source->getProxy()) != upstream.end() ||
        (!withShown && source == this->Deformation))
    {
      continue;
    }
    auto* algorithm = vtkAlgorithm::SafeDownCast(source->getProxy()->GetClientSideObject());
    const int port = repr->getOutputPortFromInput()->getPortNumber();
    auto* data = algorithm && port < algorithm->GetNumberOfOutputPorts()
                   ? vtkDataSet::SafeDownCast(algorithm->GetOutputDataObject(port))
                   : nullptr;
    const bool held = data && data->GetNumberOfCells() > 0;
    if (!held && !remote)
    {
      continue;
    }
    const Eigen::Matrix4d m = pqHapticsDisplayTransform(repr->getProxy()).matrix();
    const Eigen::Matrix4d inverse = m.inverse();
    if (!inverse.allFinite())
    {
      continue;
    }
    const Eigen::Vector3d centre = (inverse * world.homogeneous()).hnormalized();
    // The Frobenius norm bounds the inverse's largest stretch: a box that holds the ball.
    const double local = radius * inverse.topLeftCorner<3, 3>().norm();
    xyz.clear();
    if (held)
    {
      vtkGeoShapingContactPatch::AppendTrianglesNear(
        data, this->cellLocator(data), centre.data(), local, xyz);
    }
    else if (!this->serverPatch(source->getProxy(), port, centre.data(), local,
               similarity(m.topLeftCorner<3, 3>()) ? nearest : 0, xyz))
    {
      continue;
    }
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    {
      out.push_back((m * Eigen::Vector4d(xyz[i], xyz[i + 1], xyz[i + 2], 1.0)).hnormalized());
    }
  }
}

bool pqHapticsProxies::serverPatch(vtkSMProxy* input, int port, const double centre[3],
  double radius, std::size_t nearest, std::vector<double>& xyz)
{
  // A question to the server each frame: none of its pushes is an undo step.
  const geoshaping::undo::Exclude asking;
  this->ServerPatches.erase(std::remove_if(this->ServerPatches.begin(), this->ServerPatches.end(),
                              [](const ServerPatchEntry& e) { return !e.input; }),
    this->ServerPatches.end());
  auto entry = std::find_if(this->ServerPatches.begin(), this->ServerPatches.end(),
    [&](const ServerPatchEntry& e) { return e.input == input && e.port == port; });
  if (entry == this->ServerPatches.end())
  {
    vtkSmartPointer<vtkSMSourceProxy> patch;
    patch.TakeReference(vtkSMSourceProxy::SafeDownCast(
      input->GetSessionProxyManager()->NewProxy("misc", "GeoShapingContactPatch")));
    if (!patch)
    {
      this->PatchFigures.message = "no contact patch from the server: it has no "
                                   "GeoShapingContactPatch (load the plugin on the server too)";
      return false;
    }
    vtkSMPropertyHelper(patch, "Input").Set(input, static_cast<unsigned int>(port));
    entry = this->ServerPatches.insert(this->ServerPatches.end(), ServerPatchEntry());
    entry->input = input;
    entry->port = port;
    entry->patch = patch;
  }
  if (entry->late)
  {
    // The last round trip came late: this frame feels the last patch, the next asks again.
    entry->late = false;
    xyz.insert(xyz.end(), entry->last.begin(), entry->last.end());
    this->PatchFigures.message = "the contact patch from the server came late: the last "
                                 "patch kept every other frame";
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  vtkSMSourceProxy* patch = entry->patch;
  vtkSMPropertyHelper(patch, "Center").Set(centre, 3);
  vtkSMPropertyHelper(patch, "Radius").Set(radius);
  vtkSMPropertyHelper(patch, "MaxTriangles").Set(int(std::min<std::size_t>(nearest, VTK_INT_MAX)));
  patch->UpdateVTKObjects();
  patch->UpdatePipeline();
  patch->UpdatePropertyInformation();
  vtkSMPropertyHelper triangles(patch, "Triangles");
  const unsigned int n = triangles.GetNumberOfElements() / 9 * 9;
  entry->last.resize(n);
  if (n > 0)
  {
    triangles.Get(entry->last.data(), n);
  }
  const double ms =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  entry->late = ms > this->PatchBudget;
  xyz.insert(xyz.end(), entry->last.begin(), entry->last.end());
  ServerPatchFigures& f = this->PatchFigures;
  if (entry->late)
  {
    f.message = "the contact patch from the server came late (" + std::to_string(int(ms)) +
                " ms): the next frame keeps it";
  }
  f.milliseconds = std::max(f.milliseconds, 0.0) + ms;
  f.bytes += 8 * (long long)n;
  f.triangles += (long long)(n / 9);
  return true;
}

vtkStaticPointLocator* pqHapticsProxies::shownLocator()
{
  vtkPointSet* shown = this->shownSurface();
  if (!shown || !shown->GetPoints())
  {
    this->Locator = nullptr;
    this->LocatorData = nullptr;
    return nullptr;
  }
  return upToDate(shown, this->Locator, this->LocatorData, this->LocatorTime);
}

vtkStaticPointLocator* pqHapticsProxies::upToDate(vtkPointSet* data,
  vtkSmartPointer<vtkStaticPointLocator>& locator, vtkPointSet*& of, vtkMTimeType& time)
{
  const vtkMTimeType now = std::max(data->GetMTime(), data->GetPoints()->GetMTime());
  if (!locator || of != data || time != now)
  {
    // A static locator over ~10^4 points builds in well under a millisecond; the points
    // change every frame of a drag, so it is rebuilt only when a dab or grasp needs it.
    locator = vtkSmartPointer<vtkStaticPointLocator>::New();
    locator->SetDataSet(data);
    locator->BuildLocator();
    of = data;
    time = now;
  }
  return locator;
}

void pqHapticsProxies::setDisplacement(const Eigen::Vector3d& d)
{
  if (vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr)
  {
    vtkSMPropertyHelper(proxy, "Displacement").Set(d.data(), 3);
    this->DeformationModified = true;
  }
}

geoshaping::interactor::StrokeOutcome pqHapticsProxies::appendDabs(
  const std::vector<std::array<double, 6>>& dabs, bool onShown)
{
  geoshaping::interactor::StrokeOutcome outcome;
  vtkSMProxy* proxy = this->Paint ? this->Paint->getProxy() : nullptr;
  if (!proxy || dabs.empty())
  {
    return outcome;
  }
  vtkStaticPointLocator* locator =
    onShown && proxy->GetProperty("PointDabs") ? this->shownLocator() : nullptr;
  if (locator)
  {
    vtkPointSet* shown = this->shownSurface();
    // MalleabilityPaint's Falloff entries are the core's enum, value for value
    // (Filters.Enumerations.XmlEntriesMatchTheCore).
    const auto falloff = static_cast<geoshaping::Falloff>(
      std::clamp(vtkSMPropertyHelper(proxy, "Falloff").GetAsInt(), 0, 3));
    vtkNew<vtkIdList> found;
    std::vector<long long> ids;
    std::vector<double> distances;
    for (const auto& dab : dabs)
    {
      const double centre[3] = { dab[0], dab[1], dab[2] };
      locator->FindPointsWithinRadius(dab[3], centre, found);
      if (found->GetNumberOfIds() == 0)
      {
        double nearest[3];
        const vtkIdType id = locator->FindClosestPoint(centre);
        shown->GetPoint(id >= 0 ? id : 0, nearest);
        outcome.add_unreached(
          id >= 0 ? std::sqrt(vtkMath::Distance2BetweenPoints(nearest, centre)) : -1.0);
        continue;
      }
      ++outcome.stored;
      ids.clear();
      distances.clear();
      for (vtkIdType k = 0; k < found->GetNumberOfIds(); ++k)
      {
        const vtkIdType id = found->GetId(k);
        double p[3];
        shown->GetPoint(id, p);
        ids.push_back(id);
        distances.push_back(std::sqrt(vtkMath::Distance2BetweenPoints(p, centre)));
      }
      geoshaping::interactor::append_point_dabs(
        ids, distances, dab[3], dab[4], dab[5], falloff, this->PointDabs);
    }
    vtkSMPropertyHelper(proxy, "PointDabs")
      .Set(this->PointDabs.data(), static_cast<unsigned int>(this->PointDabs.size()));
  }
  else
  {
    for (const auto& dab : dabs)
    {
      double nearest = -1.0;
      if (!this->reachesInput(dab.data(), dab[3], nearest))
      {
        outcome.add_unreached(nearest);
        continue;
      }
      ++outcome.stored;
      this->Dabs.insert(this->Dabs.end(), dab.begin(), dab.end());
    }
    vtkSMPropertyHelper(proxy, "Dabs")
      .Set(this->Dabs.data(), static_cast<unsigned int>(this->Dabs.size()));
  }
  this->PaintModified = this->PaintModified || outcome.stored > 0;
  return outcome;
}

geoshaping::interactor::EditResult pqHapticsProxies::runEdit(
  geoshaping::interactor::EditCommand command)
{
  geoshaping::interactor::EditResult result;
  auto* proxy = vtkSMChainMailDeformationProxy::SafeDownCast(
    this->Deformation ? this->Deformation->getProxy() : nullptr);
  if (!proxy)
  {
    result.message = "no ChainMailDeformation";
    return result;
  }
  // CommitEdit commits the shape of the filter's last update: the one rendered last
  // frame, which is what the user saw at the release. The proxy keeps EditHistory in step
  // (the same path as the panel's buttons and Python).
  // Undo and redo step ParaView's undo stack when its next step is this proxy's edit.
  if (!pqHapticsUndo::stepThroughStack(proxy, command))
  {
    proxy->InvokeCommand(geoshaping::interactor::command_property(command));
  }
  this->InformationRead = false;
  result.changed = proxy->GetLastEditChanged();
  result.edits = static_cast<std::size_t>(this->numberOfEdits());
  result.redoable = proxy->GetLastEditRedoable();
  result.message = proxy->GetLastEditMessage();
  return result;
}

int pqHapticsProxies::numberOfEdits() const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  return proxy && proxy->GetProperty("EditHistory")
           ? static_cast<int>(vtkSMPropertyHelper(proxy, "EditHistory").GetNumberOfElements())
           : 0;
}

void pqHapticsProxies::update()
{
  this->push();
  if (auto* source =
        vtkSMSourceProxy::SafeDownCast(this->Deformation ? this->Deformation->getProxy() : nullptr))
  {
    source->UpdatePipeline();
  }
  this->InformationRead = false; // the filter may have updated
}

bool pqHapticsProxies::graspedVertexNow(const Eigen::Vector3d& rest, Eigen::Vector3d& at) const
{
  Eigen::Vector3d landed;
  if (this->shownGraspedVertex(at))
  {
    return at.allFinite();
  }
  if (!this->lastGraspDisplacement(landed))
  {
    return false;
  }
  at = rest + landed;
  return true;
}

long long pqHapticsProxies::numberOfObstacleBlockedPoints() const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy || !proxy->GetProperty("NumberOfObstacleBlockedPoints"))
  {
    return 0;
  }
  this->readInformation(proxy);
  return vtkSMPropertyHelper(proxy, "NumberOfObstacleBlockedPoints").GetAsIdType();
}

void pqHapticsProxies::render()
{
  this->push();
  if (this->View)
  {
    this->View->getViewProxy()->StillRender();
  }
  this->InformationRead = false; // the filter may have updated
}

void pqHapticsProxies::push()
{
  // Per-frame pushes are never steps of ParaView's undo stack (pqHapticsUndo.h).
  geoshaping::undo::Exclude frame;
  if (this->PaintModified && this->Paint)
  {
    this->Paint->getProxy()->UpdateVTKObjects();
  }
  if (this->DeformationModified && this->Deformation)
  {
    this->Deformation->getProxy()->UpdateVTKObjects();
  }
  if (this->RepresentationModified && this->Deformation)
  {
    if (vtkSMProxy* repr = this->representation(this->Deformation))
    {
      repr->UpdateVTKObjects();
    }
  }
  this->PaintModified = this->DeformationModified = this->RepresentationModified = false;
}

bool pqHapticsProxies::graspedVertex(Eigen::Vector3d& position, double& malleability) const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy)
  {
    return false;
  }
  malleability = vtkSMPropertyHelper(proxy, "DefaultMalleability").GetAsDouble();
  auto* filter = vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject());
  auto* input = filter ? vtkPointSet::SafeDownCast(filter->GetInputDataObject(0, 0)) : nullptr;
  vtkIdType id = -1;
  if (vtkSMPropertyHelper(proxy, "GraspMode").GetAsInt() == 0)
  {
    id = vtkSMPropertyHelper(proxy, "GraspPointId").GetAsIdType();
  }
  else if (input)
  {
    id = input->FindPoint(position.data());
  }
  if (!input || id < 0 || id >= input->GetNumberOfPoints())
  {
    return false;
  }
  input->GetPoint(id, position.data());
  const char* name = vtkSMPropertyHelper(proxy, "MalleabilityArray").GetAsString(4);
  vtkDataArray* array = name ? input->GetPointData()->GetArray(name) : nullptr;
  if (array)
  {
    malleability = array->GetComponent(id, 0);
  }
  return true;
}

bool pqHapticsProxies::shownGraspedVertex(Eigen::Vector3d& position) const
{
  vtkPointSet* shown = this->shownSurface();
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!shown || !proxy || vtkSMPropertyHelper(proxy, "GraspMode").GetAsInt() != 0)
  {
    return false;
  }
  const vtkIdType id = vtkSMPropertyHelper(proxy, "GraspPointId").GetAsIdType();
  if (id < 0 || id >= shown->GetNumberOfPoints())
  {
    return false;
  }
  shown->GetPoint(id, position.data());
  return true;
}

bool pqHapticsProxies::lastGraspFigure(const char* name, double& value) const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy || !proxy->GetProperty(name))
  {
    return false;
  }
  this->readInformation(proxy);
  if (vtkSMPropertyHelper(proxy, "LastGraspPointId").GetAsIdType() < 0)
  {
    return false;
  }
  value = vtkSMPropertyHelper(proxy, name).GetAsDouble();
  return true;
}

bool pqHapticsProxies::lastGraspMalleability(double& malleability) const
{
  return this->lastGraspFigure("LastGraspMalleability", malleability);
}

bool pqHapticsProxies::lastGraspObstacleFraction(double& fraction) const
{
  return this->lastGraspFigure("LastGraspObstacleFraction", fraction);
}

bool pqHapticsProxies::lastGraspDisplacement(Eigen::Vector3d& landed) const
{
  double x = 0.0;
  if (!this->lastGraspFigure("LastGraspDisplacement", x))
  {
    return false;
  }
  vtkSMPropertyHelper helper(this->Deformation->getProxy(), "LastGraspDisplacement");
  for (int k = 0; k < 3; ++k)
  {
    landed[k] = helper.GetAsDouble(k);
  }
  return landed.allFinite();
}

double pqHapticsProxies::lastDeformationMilliseconds() const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  if (!proxy)
  {
    return 0.0;
  }
  this->readInformation(proxy);
  return vtkSMPropertyHelper(proxy, "LastDeformationMilliseconds").GetAsDouble();
}

void pqHapticsProxies::readInformation(vtkSMProxy* proxy) const
{
  if (!this->InformationRead)
  {
    proxy->UpdatePropertyInformation();
    this->InformationRead = true;
  }
}

long long pqHapticsProxies::numberOfDisplacedPoints() const
{
  vtkSMProxy* proxy = this->Deformation ? this->Deformation->getProxy() : nullptr;
  return proxy ? vtkSMPropertyHelper(proxy, "NumberOfDisplacedPoints").GetAsIdType() : 0;
}
