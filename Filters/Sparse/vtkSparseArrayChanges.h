/**
 * @class   vtkSparseArrayChanges
 * @brief   Modified() for a data array whose values changed at a few tuples: the
 *          cached value ranges follow in O(changed), and consumers learn which tuples.
 *
 * vtkDataArray::Modified() drops the array's cached component and L2-norm ranges, so
 * the next GetRange() (ParaView's data information asks after every update) passes over
 * all n tuples. ValuesChanged(array, ids) instead keeps each cached range R that was
 * present, grown over the new values: R' = R ∪ [min, max] of the listed tuples, which
 * contains every value (unlisted tuples did not change). Ranges only grow until the next
 * full pass (an array nobody asked a range of gets none: the next query is exact).
 *
 * It also records the change on the array's information, which travels with the array
 * through shallow copies: GetGeneration() counts the calls, ChangesAfter(array, g)
 * returns the listed tuples when that call directly followed call g and nothing else
 * modified the array since; otherwise nullptr (the consumer rebuilds, always correct).
 */
#ifndef vtkSparseArrayChanges_h
#define vtkSparseArrayChanges_h

#include "GeoShapingFiltersSparseModule.h" // For export macro
#include "vtkObject.h"

class vtkDataArray;
class vtkIdTypeArray;
class vtkInformationIntegerKey;
class vtkInformationObjectBaseKey;
class vtkInformationUnsignedLongKey;

class GEOSHAPINGFILTERSSPARSE_EXPORT vtkSparseArrayChanges : public vtkObject
{
public:
  static vtkSparseArrayChanges* New();
  vtkTypeMacro(vtkSparseArrayChanges, vtkObject);

  /// The values of the k tuples `ids` of `array` changed (O(k) plus the components).
  /// A producer calls it with k = 0 on a new array to start recording.
  static void ValuesChanged(vtkDataArray* array, const vtkIdType* ids, vtkIdType k);

  /// The number of ValuesChanged() calls on `array` (0 before any).
  static int GetGeneration(vtkDataArray* array);

  /// The tuples of the last ValuesChanged() if it directly followed call `generation` and
  /// nothing else modified the array since; nullptr otherwise.
  static vtkIdTypeArray* ChangesAfter(vtkDataArray* array, int generation);

  ///@{
  /// The keys on the array's information: the call count, the array's modification time
  /// right after the last call, and that call's tuple ids (a vtkIdTypeArray).
  static vtkInformationIntegerKey* GENERATION();
  static vtkInformationUnsignedLongKey* CHANGED_TIME();
  static vtkInformationObjectBaseKey* CHANGED();
  ///@}

protected:
  vtkSparseArrayChanges() = default;
  ~vtkSparseArrayChanges() override = default;

private:
  vtkSparseArrayChanges(const vtkSparseArrayChanges&) = delete;
  void operator=(const vtkSparseArrayChanges&) = delete;
};

#endif
