#include "vtkGeoShapingSurfaceRepresentation.h"

#include "vtkDataArray.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPVView.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSparseArrayChanges.h"
#include "vtkSparseCompositeMapper.h"
#include "vtkSparsePointChanges.h"
#include "vtkSparseSurface.h"
#include "vtkSparseSurfaceMapper.h"

vtkStandardNewMacro(vtkGeoShapingSurfaceRepresentation);

vtkGeoShapingSurfaceRepresentation::vtkGeoShapingSurfaceRepresentation()
{
  // Replace the stock mapper, configured as the superclass configures it.
  this->Mapper->Delete();
  this->SparseMapper = vtkSparseCompositeMapper::New();
  this->SparseMapper->SetProcessIdArrayName("vtkProcessId");
  this->SparseMapper->SetCompositeIdArrayName("vtkCompositeIndex");
  this->Mapper = this->SparseMapper;
  this->SetArrayIdNames(nullptr, nullptr);
  this->SetupDefaults();
}

vtkGeoShapingSurfaceRepresentation::~vtkGeoShapingSurfaceRepresentation() = default;

int vtkGeoShapingSurfaceRepresentation::GetNumberOfSparseBuilds()
{
  return this->SparseMapper->GetSurfaceMapper()->GetNumberOfSparseBuilds();
}

int vtkGeoShapingSurfaceRepresentation::GetNumberOfFullBuilds()
{
  return this->SparseMapper->GetSurfaceMapper()->GetNumberOfFullBuilds();
}

int vtkGeoShapingSurfaceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = inputVector[0]->GetNumberOfInformationObjects() == 1
                         ? vtkPointSet::GetData(inputVector[0], 0)
                         : nullptr;
  if (input && this->FollowSparse(input))
  {
    ++this->NumberOfSparseUpdates;
    // Stamps the pipeline data time, so the view delivers (shares, in one process) again.
    return this->vtkPVDataRepresentation::RequestData(request, inputVector, outputVector);
  }
  const int ok = this->Superclass::RequestData(request, inputVector, outputVector);
  ++this->NumberOfFullUpdates;
  this->Adopt(input);
  return ok;
}

int vtkGeoShapingSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  const int result = this->Superclass::ProcessViewRequest(request, inInfo, outInfo);
  if (result && request == vtkPVView::REQUEST_RENDER() && !this->NoticedRemote &&
      this->NumberOfSparseUpdates + this->NumberOfFullUpdates == 0 &&
      vtkPVView::GetDeliveredPiece(inInfo, this))
  {
    // Drawn here, extracted elsewhere: every delivery is a new copy.
    vtkWarningMacro("GeoShaping Surface: this process renders geometry delivered from the "
                    "server, so each frame uploads the whole surface (stock path). Remote "
                    "rendering (the server renders) keeps frames in O(moved).");
    this->NoticedRemote = true;
  }
  return result;
}

bool vtkGeoShapingSurfaceRepresentation::FollowSparse(vtkPointSet* input)
{
  if (!this->Surface || !this->InputPoints || input->GetPoints() != this->InputPoints)
  {
    return false;
  }
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(this->MultiBlockMaker->GetOutputDataObject(0));
  if (!tree || tree->GetNumberOfBlocks() != 1 || tree->GetBlock(0) != this->Surface.GetPointer())
  {
    return false;
  }
  vtkIdTypeArray* changed = this->InputPoints->ChangesAfter(this->InputGeneration);
  if (!changed)
  {
    return false;
  }
  std::vector<std::uintptr_t> signature;
  vtkSparsePointChanges::AppendSignature(input, signature);
  if (signature != this->InputSignature)
  {
    return false;
  }
  if (!this->FollowArrays(input))
  {
    return false;
  }
  if (this->SharedCoordinates)
  {
    this->Surface->PointsChanged(nullptr); // the input's points already list the change
  }
  else if (!this->CopyChanged(input, changed))
  {
    return false;
  }
  this->InputGeneration = this->InputPoints->GetGeneration();
  return true;
}

bool vtkGeoShapingSurfaceRepresentation::FollowArrays(vtkPointSet* input)
{
  // Point arrays that record their changed values (a paint dab): copy those values to
  // the surface's own array, unless it shares the input's, and record them there.
  vtkPointData* fields = input->GetPointData();
  for (int i = 0; i < fields->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = fields->GetArray(i);
    const int generation = vtkSparseArrayChanges::GetGeneration(array);
    auto seen = this->ArrayGenerations.find(array);
    if (generation == 0 || (seen != this->ArrayGenerations.end() && seen->second == generation))
    {
      continue;
    }
    vtkIdTypeArray* changed = seen == this->ArrayGenerations.end()
                                ? nullptr
                                : vtkSparseArrayChanges::ChangesAfter(array, seen->second);
    if (!changed)
    {
      return false;
    }
    vtkDataArray* to =
      array->GetName() ? this->Surface->GetPointData()->GetArray(array->GetName()) : nullptr;
    if (to != array)
    {
      if (!to || to->GetNumberOfComponents() != array->GetNumberOfComponents())
      {
        return false;
      }
      this->SurfaceChanged->SetNumberOfTuples(0);
      for (vtkIdType j = 0; j < changed->GetNumberOfTuples(); ++j)
      {
        const vtkIdType v = changed->GetValue(j);
        const vtkIdType s = v >= 0 && v < vtkIdType(this->InputToSurface.size())
                              ? this->InputToSurface[std::size_t(v)]
                              : -1;
        if (s >= 0)
        {
          to->SetTuple(s, v, array);
          this->SurfaceChanged->InsertNextValue(s);
        }
      }
      vtkSparseArrayChanges::ValuesChanged(
        to, this->SurfaceChanged->GetPointer(0), this->SurfaceChanged->GetNumberOfTuples());
    }
    seen->second = generation;
  }
  return true;
}

bool vtkGeoShapingSurfaceRepresentation::CopyChanged(vtkPointSet* input, vtkIdTypeArray* changed)
{
  vtkDataArray* from = input->GetPoints()->GetData();
  vtkDataArray* to = this->Surface->GetPoints()->GetData();
  vtkDataArray* fromNormals = input->GetPointData()->GetNormals();
  vtkDataArray* toNormals = this->Surface->GetPointData()->GetNormals();
  if (fromNormals == toNormals || !fromNormals || !toNormals)
  {
    fromNormals = toNormals = nullptr; // shared, or none to follow
  }
  const vtkIdType n = vtkIdType(this->InputToSurface.size());
  this->SurfaceChanged->SetNumberOfTuples(0);
  for (vtkIdType i = 0; i < changed->GetNumberOfTuples(); ++i)
  {
    const vtkIdType v = changed->GetValue(i);
    if (v < 0 || v >= n)
    {
      return false;
    }
    const vtkIdType s = this->InputToSurface[v];
    if (s >= 0) // else an interior point of a volume mesh
    {
      to->SetTuple(s, v, from);
      if (toNormals)
      {
        toNormals->SetTuple(s, v, fromNormals);
      }
      this->SurfaceChanged->InsertNextValue(s);
    }
  }
  if (toNormals)
  {
    toNormals->Modified();
  }
  // A settled shape (released, undone) gets exact bounds here too: Reset Camera frames it.
  this->Surface->PointsChanged(this->SurfaceChanged, this->InputPoints->GetLastChangeExact());
  return true;
}

void vtkGeoShapingSurfaceRepresentation::Adopt(vtkPointSet* input)
{
  this->Surface = nullptr;
  this->InputPoints = nullptr;
  this->InputGeneration = -1;
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(this->MultiBlockMaker->GetOutputDataObject(0));
  auto* surface =
    tree && tree->GetNumberOfBlocks() == 1 ? vtkPolyData::SafeDownCast(tree->GetBlock(0)) : nullptr;
  auto* points = vtkGrowingBoundsPoints::SafeDownCast(input ? input->GetPoints() : nullptr);
  if (!points || !surface || !surface->GetPoints())
  {
    return; // only inputs whose points list their changes are followed
  }
  // The surface-to-input point map: vtkPVGeometryFilter's original ids, else identity.
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType m = surface->GetNumberOfPoints();
  auto* original =
    vtkIdTypeArray::SafeDownCast(surface->GetPointData()->GetArray("vtkOriginalPointIds"));
  this->InputToSurface.assign(std::size_t(n), -1);
  if (original && original->GetNumberOfTuples() == m)
  {
    for (vtkIdType s = 0; s < m; ++s)
    {
      const vtkIdType v = original->GetValue(s);
      if (v < 0 || v >= n)
      {
        return;
      }
      this->InputToSurface[v] = s;
    }
  }
  else if (m == n)
  {
    for (vtkIdType s = 0; s < m; ++s)
      this->InputToSurface[s] = s;
  }
  else
  {
    return;
  }
  this->SharedCoordinates = surface->GetPoints()->GetData() == input->GetPoints()->GetData();
  if (auto* adopted = vtkSparseSurface::SafeDownCast(surface))
  {
    this->Surface = adopted; // the geometry filter did not run again
  }
  else
  {
    this->Surface = vtkSmartPointer<vtkSparseSurface>::New();
    this->Surface->Adopt(surface, this->SharedCoordinates ? points : nullptr);
    tree->SetBlock(0, this->Surface);
  }
  this->InputPoints = points;
  this->InputGeneration = points->GetGeneration();
  this->InputSignature.clear();
  vtkSparsePointChanges::AppendSignature(input, this->InputSignature);
  this->ArrayGenerations.clear();
  vtkPointData* fields = input->GetPointData();
  for (int i = 0; i < fields->GetNumberOfArrays(); ++i)
  {
    if (const int generation = vtkSparseArrayChanges::GetGeneration(fields->GetArray(i)))
    {
      this->ArrayGenerations[fields->GetArray(i)] = generation;
    }
  }
}
