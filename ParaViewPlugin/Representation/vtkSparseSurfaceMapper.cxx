#include "vtkSparseSurfaceMapper.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkScalarsToColors.h"
#include "vtkSelection.h"
#include "vtkSparseArrayChanges.h"
#include "vtkSparsePointChanges.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstring>
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
    if (ids && this->Signature(poly, act) == this->BuiltFrom && this->UploadChanged(poly, ids) &&
        this->UploadChangedColors(poly))
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
  this->BuiltScalarsGeneration = vtkSparseArrayChanges::GetGeneration(this->ColorScalars(poly));
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

vtkDataArray* vtkSparseSurfaceMapper::ColorScalars(vtkPolyData* poly)
{
  int cellFlag = 0;
  vtkDataArray* scalars =
    poly && this->ScalarVisibility
      ? vtkDataArray::SafeDownCast(vtkAbstractMapper::GetAbstractScalars(
          poly, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag))
      : nullptr;
  return cellFlag == 0 ? scalars : nullptr;
}

bool vtkSparseSurfaceMapper::UploadChangedColors(vtkPolyData* poly)
{
  vtkDataArray* scalars = this->ColorScalars(poly);
  const int generation = vtkSparseArrayChanges::GetGeneration(scalars);
  if (generation == this->BuiltScalarsGeneration)
  {
    return true; // the colours did not change
  }
  vtkIdTypeArray* ids = vtkSparseArrayChanges::ChangesAfter(scalars, this->BuiltScalarsGeneration);
  vtkOpenGLVertexBufferObject* vbo = this->ColorCoordinates ? this->VBOs->GetVBO("tcoord")
                                     : this->Colors         ? this->VBOs->GetVBO("scalarColor")
                                                            : nullptr;
  const vtkIdType n = poly->GetNumberOfPoints();
  if (!ids || !vbo || vtkIdType(vbo->GetNumberOfTuples()) != n)
  {
    return false;
  }
  // The changed values, mapped by VTK's own MapScalars with this mapper's settings (the
  // lookup table's range, not the data's, so a subset maps as the whole does).
  const vtkIdType k = ids->GetNumberOfTuples();
  vtkNew<vtkPolyData> subset;
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(k);
  subset->SetPoints(points);
  auto values = vtk::TakeSmartPointer(scalars->NewInstance());
  values->SetName(scalars->GetName());
  values->SetNumberOfComponents(scalars->GetNumberOfComponents());
  values->SetNumberOfTuples(k);
  for (vtkIdType i = 0; i < k; ++i)
  {
    const vtkIdType v = ids->GetValue(i);
    if (v < 0 || v >= n)
    {
      return false;
    }
    values->SetTuple(i, v, scalars);
  }
  subset->GetPointData()->AddArray(values);
  if (scalars == poly->GetPointData()->GetScalars())
  {
    subset->GetPointData()->SetScalars(values);
  }
  this->ColorHelper->ShallowCopy(this);
  this->ColorHelper->SetInputArrayToProcess(0, this->GetInputArrayInformation(0));
  vtkUnsignedCharArray* colors = this->ColorHelper->MapScalars(subset, 1.0);
  vtkDataArray* mapped = this->ColorCoordinates
                           ? static_cast<vtkDataArray*>(this->ColorHelper->GetColorCoordinates())
                           : static_cast<vtkDataArray*>(colors);
  if (!mapped || mapped->GetNumberOfTuples() != k ||
      mapped->GetNumberOfComponents() != int(vbo->GetNumberOfComponents()))
  {
    return false;
  }
  // Write through the full-size array the next full build would upload, then upload.
  vtkDataArray* full = this->ColorCoordinates ? static_cast<vtkDataArray*>(this->ColorCoordinates)
                                              : static_cast<vtkDataArray*>(this->Colors);
  if (full->GetNumberOfTuples() != n)
  {
    return false;
  }
  for (vtkIdType i = 0; i < k; ++i)
  {
    full->SetTuple(ids->GetValue(i), i, mapped);
  }
  this->Sorted.assign(ids->GetPointer(0), ids->GetPointer(0) + k);
  std::sort(this->Sorted.begin(), this->Sorted.end());
  this->UploadRuns(vbo, full);
  this->BuiltScalarsGeneration = generation;
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
  // The buffer's layout: one tuple of `nc` floats (shifted and scaled for positions) or
  // unsigned chars per point, `stride` bytes apart.
  const int nc = int(vbo->GetNumberOfComponents());
  const vtkIdType stride = vbo->GetStride();
  const bool bytes = vbo->GetDataType() == VTK_UNSIGNED_CHAR;
  double shift[4] = { 0, 0, 0, 0 }, scale[4] = { 1, 1, 1, 1 };
  if (vbo->GetCoordShiftAndScaleEnabled())
  {
    const std::vector<double>& s = vbo->GetShift();
    const std::vector<double>& c = vbo->GetScale();
    for (int k = 0; k < nc && k < int(s.size()) && k < int(c.size()); ++k)
    {
      shift[k] = s[k];
      scale[k] = c[k];
    }
  }
  std::vector<float>& packed = vbo->GetPackedVBO();
  const bool keepPacked =
    vtkIdType(packed.size() * sizeof(float)) == values->GetNumberOfTuples() * stride;
  double x[4];
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
    this->Staging.assign(std::size_t((last - first + 1) * stride), 0);
    for (vtkIdType v = first; v <= last; ++v)
    {
      values->GetTuple(v, x);
      unsigned char* to = this->Staging.data() + (v - first) * stride;
      for (int k = 0; k < nc; ++k)
      {
        if (bytes)
        {
          to[k] = static_cast<unsigned char>(x[k]);
        }
        else
        {
          const float f = static_cast<float>((x[k] - shift[k]) * scale[k]);
          std::memcpy(to + k * sizeof(float), &f, sizeof(float));
        }
      }
    }
    glBufferSubData(GL_ARRAY_BUFFER, GLintptr(first * stride), GLsizeiptr(this->Staging.size()),
      this->Staging.data());
    if (keepPacked)
    {
      std::memcpy(reinterpret_cast<unsigned char*>(packed.data()) + first * stride,
        this->Staging.data(), this->Staging.size());
    }
  }
  vbo->Release();
}
