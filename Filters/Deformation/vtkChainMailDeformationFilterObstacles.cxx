// The obstacles of input port 1 (docs/obstacles.md): triangulated once per obstacle
// geometry and handed to the core (geoshaping/deform/obstacles.h), which holds the rule.
#include "vtkChainMailDeformationFilterInternals.h"

#include "geoshaping/deform/obstacle_loop.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkGarbageCollector.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>

int vtkChainMailDeformationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
    return this->Superclass::FillInputPortInformation(port, info);
  // Port 1 the obstacles, port 2 the markers (HonourMarkers: the points of any data set,
  // as ParaView's Pipeline Connection gives an empty polydata when nothing is chosen).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

namespace
{
// Whether `self` is `producer` or upstream of it (every input of every algorithm).
bool MadeFrom(vtkAlgorithm* producer, vtkAlgorithm* self)
{
  return geoshaping::made_from(producer, self,
    [](vtkAlgorithm* algorithm, auto add)
    {
      for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
        for (int c = 0; c < algorithm->GetNumberOfInputConnections(port); ++c)
          add(algorithm->GetInputAlgorithm(port, c));
    });
}
} // namespace

int vtkChainMailDeformationFilter::ComputePipelineMTime(vtkInformation* request,
  vtkInformationVector** inInfoVec, vtkInformationVector* outInfoVec, int requestFromOutputPort,
  vtkMTimeType* mtime)
{
  // VTK forwards every request to every input: through an obstacle (or markers) made from
  // this filter's output a request would come back here without end (the stack
  // overflowed). The executive reads ports 1 and 2's connections after this call, so
  // taking such an input off its port here keeps every request of this update off the loop.
  auto& held = this->Internals->HeldInputs;
  for (auto it = held.begin(); it != held.end();)
  {
    if (MadeFrom(it->Producer, this))
    {
      ++it;
      continue;
    }
    this->AddInputConnection(it->Port, it->Producer->GetOutputPort(it->Output)); // no loop
    it = held.erase(it);
  }
  for (int port : { 1, 2 })
    for (int j = this->GetNumberOfInputConnections(port) - 1; j >= 0; --j)
    {
      vtkAlgorithmOutput* input = this->GetInputConnection(port, j);
      if (input && MadeFrom(input->GetProducer(), this))
      {
        held.insert(held.begin(), { input->GetProducer(), input->GetIndex(), port });
        this->RemoveInputConnection(port, j);
      }
    }
  return this->Superclass::ComputePipelineMTime(
    request, inInfoVec, outInfoVec, requestFromOutputPort, mtime);
}

void vtkChainMailDeformationFilter::DropHeldInputs(int port)
{
  auto& held = this->Internals->HeldInputs;
  const auto end =
    std::remove_if(held.begin(), held.end(), [port](const auto& h) { return h.Port == port; });
  if (end != held.end())
  {
    held.erase(end, held.end());
    this->Modified(); // the refusal ends even when the port was already empty
  }
}

void vtkChainMailDeformationFilter::SetInputConnection(int port, vtkAlgorithmOutput* input)
{
  this->DropHeldInputs(port);
  this->Superclass::SetInputConnection(port, input);
}

void vtkChainMailDeformationFilter::RemoveAllInputConnections(int port)
{
  this->DropHeldInputs(port);
  this->Superclass::RemoveAllInputConnections(port);
}

void vtkChainMailDeformationFilter::ReportReferences(vtkGarbageCollector* collector)
{
  this->Superclass::ReportReferences(collector);
  for (auto& held : this->Internals->HeldInputs)
    vtkGarbageCollectorReport(collector, held.Producer, "HeldInput");
}

void vtkChainMailDeformationFilter::RefuseObstacleLoop(const char* what)
{
  const std::string refused = what ? what : "";
  if (refused != this->Internals->RefusedLoop)
  {
    this->Internals->RefusedLoop = refused;
    this->Modified();
  }
}

bool vtkChainMailDeformationFilter::RefuseHeldObstacles()
{
  const auto& state = *this->Internals;
  if (state.HeldInputs.empty() && state.RefusedLoop.empty())
    return false;
  // The proxy's words ("Obstacle Transform1"), else the held input's port and class.
  const std::string what =
    !state.HeldInputs.empty()
      ? std::string(state.HeldInputs.front().Port == 2 ? "Markers input " : "Obstacle ") +
          state.HeldInputs.front().Producer->GetClassName()
      : state.RefusedLoop;
  vtkErrorMacro(<< what
                << " is made from this filter's own output: a pipeline loop (the deformation would "
                   "feed its own input). It is not used, and the output is the undeformed input "
                   "until that input changes.");
  return true;
}

vtkIdType vtkChainMailDeformationFilterDetail::AppendObstacle(
  vtkDataObject* obstacle, std::vector<double>& xyz, std::vector<std::int64_t>& triangles)
{
  vtkDataSet* data = vtkDataSet::SafeDownCast(obstacle);
  if (!data)
    return -1;
  vtkSmartPointer<vtkPolyData> surface = vtkPolyData::SafeDownCast(data);
  if (!surface)
  {
    vtkNew<vtkDataSetSurfaceFilter> boundary;
    boundary->SetInputData(data);
    boundary->Update();
    surface = boundary->GetOutput();
  }
  vtkIdType bad = 0;
  double x[3];
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    surface->GetPoint(p, x);
    bad += !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]));
  }
  if (bad > 0)
    return bad;
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* tris = triangulate->GetOutput();
  const auto base = std::int64_t(xyz.size() / 3);
  for (vtkIdType p = 0; p < tris->GetNumberOfPoints(); ++p)
  {
    tris->GetPoint(p, x);
    xyz.insert(xyz.end(), { x[0], x[1], x[2] });
  }
  auto cells = vtk::TakeSmartPointer(tris->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    cells->GetCurrentCell(npts, pts);
    if (npts == 3)
      triangles.insert(triangles.end(), { base + pts[0], base + pts[1], base + pts[2] });
  }
  return 0;
}

bool vtkChainMailDeformationFilterDetail::IsEmptyObstacle(vtkDataObject* obstacle)
{
  vtkDataSet* data = vtkDataSet::SafeDownCast(obstacle);
  return data && data->GetNumberOfPoints() == 0;
}

bool vtkChainMailDeformationFilterDetail::ObstacleSources(vtkChainMailDeformationFilter* self,
  geoshaping::ChainMailDeformer& deformer,
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>>& sources)
{
  if (!deformer.set_obstacle_clearance(self->GetObstacleClearance()))
  {
    vtkErrorWithObjectMacro(self, "ObstacleClearance "
                                    << self->GetObstacleClearance()
                                    << " is not a finite distance >= 0; output is the "
                                       "undeformed input.");
    return false;
  }
  sources.clear();
  for (int i = 0; i < self->GetNumberOfInputConnections(1); ++i)
  {
    vtkDataObject* data = self->GetInputDataObject(1, i);
    sources.emplace_back(data, data ? data->GetMTime() : 0);
  }
  return true;
}

bool vtkChainMailDeformationFilterDetail::SetObstacles(vtkChainMailDeformationFilter* self,
  geoshaping::ChainMailDeformer& deformer, const std::vector<double>& xyz,
  const std::vector<std::int64_t>& triangles)
{
  const std::string error =
    deformer.set_obstacles(xyz.data(), xyz.size() / 3, triangles.data(), triangles.size() / 3);
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(
      self, "Obstacles refused: " << error << "; output is the undeformed input.");
    return false;
  }
  return true;
}

bool vtkChainMailDeformationFilter::UpdateObstacles(vtkInformationVector** inputVector)
{
  vtkInternals& state = *this->Internals;
  const int count = inputVector[1]->GetNumberOfInformationObjects();
  if (count == 0)
  {
    state.Deformer.clear_obstacles();
    state.ObstacleSources.clear();
    return true;
  }
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> sources;
  if (!vtkChainMailDeformationFilterDetail::ObstacleSources(this, state.Deformer, sources))
    return false;
  if (sources == state.ObstacleSources && state.Deformer.obstacles())
    return true;
  state.ObstacleSources.clear();
  state.Deformer.clear_obstacles();

  std::vector<double> xyz;
  std::vector<std::int64_t> triangles;
  for (int i = 0; i < count; ++i)
  {
    vtkDataObject* data = sources[std::size_t(i)].first;
    if (vtkChainMailDeformationFilterDetail::IsEmptyObstacle(data))
      continue; // a connection with nothing chosen (docs/obstacles.md)
    const std::size_t before = triangles.size();
    const vtkIdType bad = vtkChainMailDeformationFilterDetail::AppendObstacle(data, xyz, triangles);
    if (bad < 0)
    {
      vtkErrorMacro("Obstacle " << i << " is not a vtkDataSet; output is the undeformed input.");
      return false;
    }
    if (bad > 0)
    {
      vtkErrorMacro("Obstacle " << i << " (" << data->GetClassName() << ") has " << bad
                                << " points with non-finite coordinates; output is the "
                                   "undeformed input.");
      return false;
    }
    if (triangles.size() == before)
    {
      vtkErrorMacro("Obstacle " << i << " (" << data->GetClassName() << ", "
                                << vtkDataSet::SafeDownCast(data)->GetNumberOfCells()
                                << " cells) has no triangles or polygons; output is the "
                                   "undeformed input.");
      return false;
    }
  }
  if (!triangles.empty() &&
      !vtkChainMailDeformationFilterDetail::SetObstacles(this, state.Deformer, xyz, triangles))
    return false;
  state.ObstacleSources = std::move(sources);
  return true;
}

bool vtkChainMailDeformationFilter::UpdateSliding(vtkPointSet* input)
{
  vtkInternals& state = *this->Internals;
  bool valid = true;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* sliding = this->PointMask(2, "Sliding", input, valid);
  if (!valid)
  {
    return false;
  }
  if (sliding && !state.Deformer.obstacles())
  {
    this->WarnOnce(std::string("Sliding array '") + sliding->GetName() +
                   "' without obstacles on port 1: there is nothing to slide on.");
  }
  if (sliding != state.SlidingSource || (sliding && sliding->GetMTime() != state.SlidingTime))
  {
    if (sliding)
    {
      std::vector<std::uint8_t> mask(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        mask[std::size_t(i)] = sliding->GetComponent(i, 0) != 0.0;
      state.Deformer.set_sliding(mask.data());
      state.SlidingTime = sliding->GetMTime();
    }
    else
    {
      state.Deformer.set_sliding(nullptr);
    }
    state.SlidingSource = sliding;
  }
  return true;
}
