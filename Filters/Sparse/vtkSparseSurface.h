/**
 * @class   vtkSparseSurface
 * @brief   The surface a renderer draws, followed in O(changed) when a few points move.
 *
 * A vtkPolyData whose points are a vtkGrowingBoundsPoints. PointsChanged(ids) grows the
 * point bounds over the listed points (vtkGrowingBoundsPoints), stores the same box as
 * the cells' bounds (what vtkCompositePolyDataMapper2 and ParaView's representations
 * ask for, otherwise a pass over every cell); the points keep the change, which a
 * mapper that drew the previous update follows with a partial upload.
 */
#ifndef vtkSparseSurface_h
#define vtkSparseSurface_h

#include "GeoShapingFiltersSparseModule.h" // For export macro
#include "vtkNew.h"                        // For vtkNew
#include "vtkPolyData.h"

class vtkGrowingBoundsPoints;
class vtkIdTypeArray;

class GEOSHAPINGFILTERSSPARSE_EXPORT vtkSparseSurface : public vtkPolyData
{
public:
  static vtkSparseSurface* New();
  vtkTypeMacro(vtkSparseSurface, vtkPolyData);

  /// Share `from`'s topology and arrays. The points: `shared` when given (a producer's
  /// vtkGrowingBoundsPoints over the same coordinates, which lists its own changes),
  /// else a new vtkGrowingBoundsPoints over `from`'s coordinate array.
  void Adopt(vtkPolyData* from, vtkGrowingBoundsPoints* shared = nullptr);

  /// The coordinates of the listed points changed (O(k)); nullptr: the shared points'
  /// producer already listed them. `exact`: the bounds are computed again at the next
  /// query instead of grown (vtkGrowingBoundsPoints::PointsChanged).
  void PointsChanged(vtkIdTypeArray* ids, bool exact = false);

  /// A shallow copy of a vtkSparseSurface keeps its cached cell bounds (same points,
  /// same cells), so a renderer's copy does not pass over every cell again.
  void ShallowCopy(vtkDataObject* src) override;

protected:
  vtkSparseSurface() = default;
  ~vtkSparseSurface() override = default;

private:
  vtkSparseSurface(const vtkSparseSurface&) = delete;
  void operator=(const vtkSparseSurface&) = delete;
};

#endif
