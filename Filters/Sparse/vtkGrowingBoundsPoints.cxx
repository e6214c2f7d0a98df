#include "vtkGrowingBoundsPoints.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
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
  this->ForgetExact();
  this->Data->Modified();
  this->Modified();
}

void vtkGrowingBoundsPoints::ForgetExact()
{
  this->ExactKnown = false;
  this->Moved.clear();
  this->IsMoved.clear();
}

namespace
{
double L2Norm(const double x[3])
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

// One pass over the points: the box, the norm range, and a point attaining each extreme;
// or, started from a known box, range and witnesses, those grown by more points.
struct Extremes
{
  double box[6] = { 0, 0, 0, 0, 0, 0 };
  double norm[2] = { 0, 0 };
  vtkIdType witness[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  bool finite = true;

  Extremes() = default;
  Extremes(const double b[6], const double n[2], const vtkIdType w[8])
  {
    std::copy(b, b + 6, box);
    std::copy(n, n + 2, norm);
    std::copy(w, w + 8, witness);
  }
  void first(const double x[3], vtkIdType i)
  {
    const double r = L2Norm(x);
    for (int c = 0; c < 3; ++c)
      box[2 * c] = box[2 * c + 1] = x[c];
    norm[0] = norm[1] = r;
    std::fill(witness, witness + 8, i);
    finite = std::isfinite(r);
  }
  void add(const double x[3], vtkIdType i)
  {
    const double r = L2Norm(x);
    finite = finite && std::isfinite(r);
    for (int c = 0; c < 3; ++c)
    {
      if (x[c] < box[2 * c])
      {
        box[2 * c] = x[c];
        witness[2 * c] = i;
      }
      if (x[c] > box[2 * c + 1])
      {
        box[2 * c + 1] = x[c];
        witness[2 * c + 1] = i;
      }
    }
    if (r < norm[0])
    {
      norm[0] = r;
      witness[6] = i;
    }
    if (r > norm[1])
    {
      norm[1] = r;
      witness[7] = i;
    }
  }
};

template<typename T>
void Scan(const T* xyz, vtkIdType n, Extremes& e)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double x[3] = { double(xyz[3 * i]), double(xyz[3 * i + 1]), double(xyz[3 * i + 2]) };
    i == 0 ? e.first(x, i) : e.add(x, i);
  }
}
} // namespace

void vtkGrowingBoundsPoints::ComputeBounds()
{
  if (this->GetMTime() <= this->ComputeTime)
  {
    return; // current: computed, or grown by PointsChanged
  }
  // Modified some other way: an exact pass, which also finds the witnesses.
  this->Known = false;
  this->ForgetExact();
  ++this->NumberOfFullPasses;
  const vtkIdType n = this->GetNumberOfPoints();
  Extremes e;
  if (auto* f = vtkFloatArray::FastDownCast(this->Data))
  {
    Scan(f->GetPointer(0), n, e);
  }
  else if (auto* d = vtkDoubleArray::FastDownCast(this->Data))
  {
    Scan(d->GetPointer(0), n, e);
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      this->GetPoint(i, x);
      i == 0 ? e.first(x, i) : e.add(x, i);
    }
  }
  if (n == 0 || !e.finite)
  {
    this->Superclass::ComputeBounds(); // VTK's own handling of the empty and non-finite
    return;
  }
  std::copy(e.box, e.box + 6, this->Box);
  std::copy(e.norm, e.norm + 2, this->Norm);
  std::copy(e.box, e.box + 6, this->ExactBox);
  std::copy(e.norm, e.norm + 2, this->ExactNorm);
  std::copy(e.witness, e.witness + 8, this->Witness);
  this->IsMoved.assign(std::size_t(n), 0);
  this->ExactKnown = true;
  this->Known = true;
  this->Publish();
}

bool vtkGrowingBoundsPoints::Settle()
{
  if (!this->ExactKnown)
  {
    return false;
  }
  for (int side = 0; side < 8; ++side)
  {
    const vtkIdType w = this->Witness[side];
    if (!this->IsMoved[std::size_t(w)])
    {
      continue;
    }
    // A moved witness still at or beyond E's extreme keeps the side exact (the unmoved
    // points are within E); one that moved inward may leave it to any point.
    double x[3];
    this->GetPoint(w, x);
    const double r = L2Norm(x);
    const bool beyond = side < 6 ? (side % 2 == 0 ? x[side / 2] <= this->ExactBox[side]
                                                  : x[side / 2] >= this->ExactBox[side])
                                 : (side == 6 ? r <= this->ExactNorm[0] : r >= this->ExactNorm[1]);
    if (!beyond)
    {
      return false;
    }
  }
  Extremes e(this->ExactBox, this->ExactNorm, this->Witness);
  for (vtkIdType i : this->Moved)
  {
    double x[3];
    this->GetPoint(i, x);
    e.add(x, i);
    this->IsMoved[std::size_t(i)] = 0;
  }
  this->Moved.clear();
  if (!e.finite)
  {
    return false;
  }
  std::copy(e.box, e.box + 6, this->Box);
  std::copy(e.norm, e.norm + 2, this->Norm);
  std::copy(e.box, e.box + 6, this->ExactBox);
  std::copy(e.norm, e.norm + 2, this->ExactNorm);
  std::copy(e.witness, e.witness + 8, this->Witness);
  this->Known = true;
  this->Publish();
  return true;
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
  for (vtkIdType i = 0; this->ExactKnown && i < k; ++i)
  {
    const vtkIdType v = ids[i];
    if (v < 0 || std::size_t(v) >= this->IsMoved.size())
    {
      this->ForgetExact();
    }
    else if (!this->IsMoved[std::size_t(v)])
    {
      this->IsMoved[std::size_t(v)] = 1;
      this->Moved.push_back(v);
    }
  }
  if (exact)
  {
    if (!this->Known || !this->Settle())
    {
      this->Known = false; // the next query passes over every point
      this->ForgetExact();
    }
    return;
  }
  if (!this->Known)
  {
    return;
  }
  // The box and range grown by the changed points (its witnesses are not kept: the
  // exact state's are, above).
  Extremes e(this->Box, this->Norm, this->Witness);
  for (vtkIdType i = 0; i < k; ++i)
  {
    double x[3];
    this->GetPoint(ids[i], x);
    e.add(x, ids[i]);
  }
  if (!e.finite)
  {
    this->Known = false;
    this->ForgetExact();
    return;
  }
  std::copy(e.box, e.box + 6, this->Box);
  std::copy(e.norm, e.norm + 2, this->Norm);
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
