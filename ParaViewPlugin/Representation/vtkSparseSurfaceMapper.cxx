#include "vtkSparseSurfaceMapper.h"

#include "vtkActor.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkScalarsToColors.h"
#include "vtkSelection.h"
#include "vtkSparsePointChanges.h"
#include "vtkTexture.h"
#include "vtk_glew.h"

#include <algorithm>
#include <functional>
#include <string>

vtkStandardNewMacro(vtkSparseSurfaceMapper);

std::vector<std::uintptr_t> vtkSparseSurfaceMapper::Signature(vtkPolyData* poly, vtkActor* act)
{
  std::vector<std::uintptr_t> s;
  vtkSparsePointChanges::AppendSignature(poly, s);
  const std::vector<std::uintptr_t> settings = Settings(this);
  s.insert(s.end(), settings.begin(), settings.end());
  for (vtkObject* o : { static_cast<vtkObject*>(this->Selection),
         static_cast<vtkObject*>(act->GetProperty()), static_cast<vtkObject*>(act->GetTexture()) })
    vtkSparsePointChanges::AppendObject(o, s);
  return s;
}

std::vector<std::uintptr_t> vtkSparseSurfaceMapper::Settings(vtkPolyDataMapper* m)
{
  const auto hash = [](const char* text) { return std::hash<std::string>()(text ? text : ""); };
  std::vector<std::uintptr_t> s{ std::uintptr_t(m->GetScalarVisibility()),
    std::uintptr_t(m->GetScalarMode()), std::uintptr_t(m->GetColorMode()),
    std::uintptr_t(m->GetArrayAccessMode()), std::uintptr_t(m->GetArrayId()),
    std::uintptr_t(m->GetArrayComponent()), hash(m->GetArrayName()),
    std::uintptr_t(m->GetInterpolateScalarsBeforeMapping()),
    std::uintptr_t(m->GetUseLookupTableScalarRange()), std::uintptr_t(m->GetFieldDataTupleId()),
    std::uintptr_t(m->GetSeamlessU()), std::uintptr_t(m->GetSeamlessV()),
    std::uintptr_t(m->GetStatic()), std::hash<double>()(m->GetScalarRange()[0]),
    std::hash<double>()(m->GetScalarRange()[1]) };
  vtkSparsePointChanges::AppendObject(m->GetLookupTable(), s);
  vtkSparsePointChanges::AppendObject(m->GetClippingPlanes(), s);
  if (vtkInformation* array = m->GetInputArrayInformation(0))
  {
    s.push_back(hash(array->Get(vtkDataObject::FIELD_NAME())));
    s.push_back(std::uintptr_t(array->Get(vtkDataObject::FIELD_ASSOCIATION())));
  }
  return s;
}

void vtkSparseSurfaceMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* poly = this->CurrentInput;
  if (poly && this->NumberOfFullBuilds > 0)
  {
    auto* points = vtkGrowingBoundsPoints::SafeDownCast(poly->GetPoints());
    vtkIdTypeArray* ids =
      points && points == this->BuiltPoints ? points->ChangesAfter(this->BuiltGeneration) : nullptr;
    if (ids && this->Signature(poly, act) == this->BuiltFrom && this->UploadChanged(poly, ids))
    {
      this->BuiltGeneration = points->GetGeneration();
      this->VBOBuildTime.Modified();
      ++this->NumberOfSparseBuilds;
      this->LastSparsePoints = ids->GetNumberOfTuples();
      return;
    }
  }
  this->Superclass::BuildBufferObjects(ren, act);
  ++this->NumberOfFullBuilds;
  this->BuiltFrom = poly ? this->Signature(poly, act) : std::vector<std::uintptr_t>();
  auto* points = vtkGrowingBoundsPoints::SafeDownCast(poly ? poly->GetPoints() : nullptr);
  this->BuiltPoints = points;
  this->BuiltGeneration = points ? points->GetGeneration() : -1;
}

bool vtkSparseSurfaceMapper::UploadChanged(vtkPolyData* poly, vtkIdTypeArray* ids)
{
  const vtkIdType n = poly->GetNumberOfPoints();
  this->Sorted.assign(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfTuples());
  std::sort(this->Sorted.begin(), this->Sorted.end());
  if (!this->Sorted.empty() && (this->Sorted.front() < 0 || this->Sorted.back() >= n))
  {
    return false;
  }
  // Positions always; normals when the mapper drew them (the producer lists both).
  vtkOpenGLVertexBufferObject* normals = this->VBOs->GetVBO("normalMC");
  vtkDataArray* pointNormals = poly->GetPointData()->GetNormals();
  if (normals && (!pointNormals || !this->Writable(normals, n)))
  {
    return false;
  }
  vtkOpenGLVertexBufferObject* positions = this->VBOs->GetVBO("vertexMC");
  if (!positions || !this->Writable(positions, n))
  {
    return false;
  }
  this->UploadRuns(positions, poly->GetPoints()->GetData());
  if (normals)
  {
    this->UploadRuns(normals, pointNormals);
  }
  return true;
}

bool vtkSparseSurfaceMapper::Writable(vtkOpenGLVertexBufferObject* vbo, vtkIdType n)
{
  // One float triple per point, as vtkOpenGLVertexBufferObject packs a 3-component array.
  return vbo->GetDataType() == VTK_FLOAT && vbo->GetNumberOfComponents() == 3 &&
         vtkIdType(vbo->GetNumberOfTuples()) == n && vbo->GetStride() % sizeof(float) == 0 &&
         vbo->GetStride() >= 3 * sizeof(float);
}

void vtkSparseSurfaceMapper::UploadRuns(vtkOpenGLVertexBufferObject* vbo, vtkDataArray* values)
{
  const vtkIdType block = vbo->GetStride() / sizeof(float);
  double shift[3] = { 0, 0, 0 }, scale[3] = { 1, 1, 1 };
  if (vbo->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& s = vbo->GetShift();
    const std::vector<double>& c = vbo->GetScale();
    for (int k = 0; k < 3 && k < int(s.size()) && k < int(c.size()); ++k)
    {
      shift[k] = s[k];
      scale[k] = c[k];
    }
  }
  std::vector<float>& packed = vbo->GetPackedVBO();
  const bool keepPacked = vtkIdType(packed.size()) == values->GetNumberOfTuples() * block;
  vbo->Bind();
  for (std::size_t i = 0; i < this->Sorted.size();)
  {
    // One run: ids closer than MergeGap, the values between them rewritten as they are.
    const vtkIdType first = this->Sorted[i];
    vtkIdType last = first;
    while (i < this->Sorted.size() && this->Sorted[i] - last <= this->MergeGap)
    {
      last = this->Sorted[i++];
    }
    this->Staging.assign(std::size_t((last - first + 1) * block), 0.0f);
    for (vtkIdType v = first; v <= last; ++v)
    {
      double x[3];
      values->GetTuple(v, x);
      float* to = this->Staging.data() + (v - first) * block;
      for (int k = 0; k < 3; ++k)
      {
        to[k] = static_cast<float>((x[k] - shift[k]) * scale[k]);
      }
    }
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(first * vbo->GetStride()),
      GLsizeiptr(this->Staging.size() * sizeof(float)), this->Staging.data());
    if (keepPacked)
    {
      std::copy(this->Staging.begin(), this->Staging.end(), packed.begin() + first * block);
    }
  }
  vbo->Release();
}
