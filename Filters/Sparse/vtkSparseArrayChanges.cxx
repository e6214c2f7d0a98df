#include "vtkSparseArrayChanges.h"

#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationInformationVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkInformationUnsignedLongKey.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSparseArrayChanges);

vtkInformationKeyMacro(vtkSparseArrayChanges, GENERATION, Integer);
vtkInformationKeyMacro(vtkSparseArrayChanges, CHANGED_TIME, UnsignedLong);
vtkInformationKeyMacro(vtkSparseArrayChanges, CHANGED, ObjectBase);

namespace
{
// A cached range: (key, component or -1 for the L2 norm), its two values.
struct CachedRange
{
  vtkInformationInformationVectorKey* perComponent; // nullptr for an L2 key
  vtkInformationDoubleVectorKey* key;
  int component;
  double range[2];
};

std::vector<CachedRange> TakeRanges(vtkDataArray* array)
{
  std::vector<CachedRange> ranges;
  vtkInformation* info = array->GetInformation();
  for (auto* perComponent :
    { vtkAbstractArray::PER_COMPONENT(), vtkAbstractArray::PER_FINITE_COMPONENT() })
  {
    vtkInformationVector* components = info->Get(perComponent);
    for (int c = 0; components && c < components->GetNumberOfInformationObjects() &&
                    c < array->GetNumberOfComponents();
         ++c)
    {
      vtkInformation* ci = components->GetInformationObject(c);
      if (ci->Has(vtkDataArray::COMPONENT_RANGE()))
      {
        CachedRange r{ perComponent, vtkDataArray::COMPONENT_RANGE(), c, { 0, 0 } };
        ci->Get(vtkDataArray::COMPONENT_RANGE(), r.range);
        ranges.push_back(r);
      }
    }
  }
  for (auto* key : { vtkDataArray::L2_NORM_RANGE(), vtkDataArray::L2_NORM_FINITE_RANGE() })
  {
    if (info->Has(key))
    {
      CachedRange r{ nullptr, key, -1, { 0, 0 } };
      info->Get(key, r.range);
      ranges.push_back(r);
    }
  }
  return ranges;
}
} // namespace

int vtkSparseArrayChanges::GetGeneration(vtkDataArray* array)
{
  vtkInformation* info = array ? array->GetInformation() : nullptr;
  return info && info->Has(GENERATION()) ? info->Get(GENERATION()) : 0;
}

vtkIdTypeArray* vtkSparseArrayChanges::ChangesAfter(vtkDataArray* array, int generation)
{
  if (!array || GetGeneration(array) != generation + 1)
  {
    return nullptr;
  }
  vtkInformation* info = array->GetInformation();
  if (static_cast<vtkMTimeType>(info->Get(CHANGED_TIME())) != array->GetMTime())
  {
    return nullptr;
  }
  return vtkIdTypeArray::SafeDownCast(info->Get(CHANGED()));
}

void vtkSparseArrayChanges::ValuesChanged(vtkDataArray* array, const vtkIdType* ids, vtkIdType k)
{
  std::vector<CachedRange> ranges = TakeRanges(array);
  array->Modified(); // drops the caches
  const int nc = array->GetNumberOfComponents();
  std::vector<double> tuple(std::size_t(std::max(nc, 1)));
  bool finite = true;
  for (vtkIdType i = 0; i < k && !ranges.empty(); ++i)
  {
    array->GetTuple(ids[i], tuple.data());
    double norm = 0.0;
    for (int c = 0; c < nc; ++c)
    {
      finite = finite && std::isfinite(tuple[std::size_t(c)]);
      norm += tuple[std::size_t(c)] * tuple[std::size_t(c)];
    }
    norm = std::sqrt(norm);
    for (CachedRange& r : ranges)
    {
      const double v = r.component < 0 ? norm : tuple[std::size_t(r.component)];
      r.range[0] = std::min(r.range[0], v);
      r.range[1] = std::max(r.range[1], v);
    }
  }
  vtkInformation* info = array->GetInformation();
  if (finite) // a NaN or infinity: leave the ranges to an exact pass
  {
    for (auto* perComponent :
      { vtkAbstractArray::PER_COMPONENT(), vtkAbstractArray::PER_FINITE_COMPONENT() })
    {
      vtkNew<vtkInformationVector> components;
      bool any = false;
      for (const CachedRange& r : ranges)
      {
        if (r.perComponent != perComponent)
          continue;
        if (components->GetNumberOfInformationObjects() < nc)
          components->SetNumberOfInformationObjects(nc);
        components->GetInformationObject(r.component)->Set(r.key, r.range, 2);
        any = true;
      }
      // vtkDataArray reads a per-component vector only when every component has a range.
      bool complete = any;
      for (int c = 0; complete && c < nc; ++c)
        complete = components->GetInformationObject(c)->Has(vtkDataArray::COMPONENT_RANGE());
      if (complete)
        info->Set(perComponent, components);
    }
    for (const CachedRange& r : ranges)
      if (!r.perComponent)
        info->Set(r.key, r.range, 2);
  }
  vtkNew<vtkIdTypeArray> changed;
  changed->SetNumberOfTuples(k);
  if (k > 0)
  {
    std::copy(ids, ids + k, changed->GetPointer(0));
  }
  info->Set(CHANGED(), changed);
  info->Set(GENERATION(), GetGeneration(array) + 1);
  info->Set(CHANGED_TIME(), static_cast<unsigned long>(array->GetMTime()));
}
