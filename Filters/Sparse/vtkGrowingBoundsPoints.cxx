#include "vtkGrowingBoundsPoints.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationInformationVectorKey.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkGrowingBoundsPoints);

void vtkGrowingBoundsPoints::Reset()
{
  this->Known = false;
  this->Data->Modified();
  this->Modified();
}

void vtkGrowingBoundsPoints::ComputeBounds()
{
  if (this->GetMTime() <= this->ComputeTime)
  {
    return; // current: computed, or grown by PointsChanged
  }
  // Modified some other way: an exact pass.
  this->Known = false;
  this->Superclass::ComputeBounds();
  double norm[2];
  this->Data->GetRange(norm, -1);
  bool finite = this->GetNumberOfPoints() > 0;
  for (int k = 0; k < 6; ++k)
    finite = finite && std::isfinite(this->Bounds[k]);
  if (!finite || !std::isfinite(norm[0]) || !std::isfinite(norm[1]))
  {
    return;
  }
  std::copy(this->Bounds, this->Bounds + 6, this->Box);
  std::copy(norm, norm + 2, this->Norm);
  this->Known = true;
  this->Publish();
}

vtkIdTypeArray* vtkGrowingBoundsPoints::ChangesAfter(int generation)
{
  return generation + 1 == this->Generation && this->GetMTime() == this->ChangedTime
           ? this->Changed.GetPointer()
           : nullptr;
}

void vtkGrowingBoundsPoints::PointsChanged(const vtkIdType* ids, vtkIdType k, bool exact)
{
  this->Data->Modified(); // drops the array's range caches
  this->Modified();
  this->ChangedTime = this->GetMTime();
  ++this->Generation;
  this->Changed->SetNumberOfTuples(k);
  std::copy(ids, ids + k, this->Changed->GetPointer(0));
  this->LastChangeExact = exact;
  if (exact)
  {
    this->Known = false;
  }
  if (!this->Known)
  {
    return;
  }
  for (vtkIdType i = 0; i < k; ++i)
  {
    double x[3];
    this->GetPoint(ids[i], x);
    const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (!std::isfinite(r))
    {
      this->Known = false;
      return;
    }
    for (int c = 0; c < 3; ++c)
    {
      this->Box[2 * c] = std::min(this->Box[2 * c], x[c]);
      this->Box[2 * c + 1] = std::max(this->Box[2 * c + 1], x[c]);
    }
    this->Norm[0] = std::min(this->Norm[0], r);
    this->Norm[1] = std::max(this->Norm[1], r);
  }
  this->Publish();
}

void vtkGrowingBoundsPoints::Publish()
{
  std::copy(this->Box, this->Box + 6, this->Bounds);
  this->ComputeTime.Modified();
  // The same caches vtkDataArray::GetRange/GetFiniteRange fill (every value is finite).
  vtkInformation* info = this->Data->GetInformation();
  for (vtkInformationInformationVectorKey* key :
    { vtkAbstractArray::PER_COMPONENT(), vtkAbstractArray::PER_FINITE_COMPONENT() })
  {
    vtkNew<vtkInformationVector> perComponent;
    perComponent->SetNumberOfInformationObjects(3);
    for (int c = 0; c < 3; ++c)
    {
      perComponent->GetInformationObject(c)->Set(
        vtkDataArray::COMPONENT_RANGE(), this->Box + 2 * c, 2);
    }
    info->Set(key, perComponent);
  }
  info->Set(vtkDataArray::L2_NORM_RANGE(), this->Norm, 2);
  info->Set(vtkDataArray::L2_NORM_FINITE_RANGE(), this->Norm, 2);
}
