/**
 * @class   vtkGrowingBoundsPoints
 * @brief   vtkPoints whose bounds and coordinate ranges follow a sparse rewrite in
 *          O(changed) instead of a pass over every point.
 *
 * vtkPoints recomputes its bounds, and its vtkDataArray its component and L2-norm
 * ranges (what ParaView's data information, the render view and the mappers ask for),
 * with a pass over all n points whenever the coordinates are modified. A producer that
 * rewrote k points calls PointsChanged(ids) instead of Modified(). With B the cached
 * box and N the cached norm range, the caches become
 *
 *     B' = B ∪ bbox{ x_i : i in ids },    N' = N ∪ [min |x_i|, max |x_i|]
 *
 * in O(k). B' contains every point: a point is either unchanged (inside B) or listed.
 * The caches are exact after Reset() (the next query passes over all points) and grow
 * conservatively after that: a point that moves inward does not shrink them until the
 * next Reset() or exact change. A non-finite listed point drops the caches (the next
 * query is exact). A producer whose change settles the shape (a drag released, an edit
 * undone) lists it with `exact` = true: the caches become exact again and bounds shrink
 * back; the change is still listed for consumers, which pass the flag on
 * (GetLastChangeExact()).
 *
 * The exact caches after a settling change cost O(moved), not O(n): the points keep the
 * exact box and norm range of the last exact state (E), for each of its 8 extremes one
 * point that attains it (its witness), and the set M of points listed since. A point
 * outside M has not moved since E, so while a side's witness is outside M (or in M but
 * still at or beyond E's extreme) the unmoved points are within E's extreme on that side
 * and one point of E ∪ M attains it; the exact caches are then
 *
 *     B = E ∪ bbox{ x_i : i in M },    N = N_E ∪ [min |x_i|, max |x_i|] over M,
 *
 * O(|M|), and they become the new exact state (a witness that M beats is replaced). When
 * a witness moved inward (e.g. a pull that made a new maximum, undone) the side may
 * shrink to any point: the caches are dropped and the next query passes over every point
 * (O(n), once; GetNumberOfFullPasses() counts those passes).
 *
 * The points also say what changed, for consumers that keep a copy (an extracted
 * surface, a GPU buffer): each PointsChanged() is update number GetGeneration() and
 * keeps its ids; ChangesAfter(g) returns them when that update directly follows update
 * g and nothing else modified the points since. The points object travels through
 * shallow copies, so a consumer downstream of any pass-through filter sees it. The
 * contract with a producer: between two updates only the listed points' coordinates
 * (and active point normals, when it maintains them) changed.
 * A consumer that gets nullptr (first sight, a skipped update, another modification)
 * must rebuild, which is always correct.
 */
#ifndef vtkGrowingBoundsPoints_h
#define vtkGrowingBoundsPoints_h

#include "GeoShapingFiltersSparseModule.h" // For export macro
#include "vtkIdTypeArray.h"                // For vtkNew<vtkIdTypeArray>
#include "vtkNew.h"                        // For vtkNew
#include "vtkPoints.h"

#include <vector> // For the points moved since the last exact state

class GEOSHAPINGFILTERSSPARSE_EXPORT vtkGrowingBoundsPoints : public vtkPoints
{
public:
  static vtkGrowingBoundsPoints* New();
  vtkTypeMacro(vtkGrowingBoundsPoints, vtkPoints);

  /// The coordinates of the k points `ids` changed: bump the modification time and grow
  /// the cached bounds and ranges over them, O(k); with `exact`, drop them instead (the
  /// next query passes over every point).
  void PointsChanged(const vtkIdType* ids, vtkIdType k, bool exact = false);

  /// Whether the last PointsChanged() asked for exact caches.
  bool GetLastChangeExact() const { return this->LastChangeExact; }

  /// Forget the caches: the next query computes them exactly, O(n).
  void Reset();

  /// True while the caches are those grown by PointsChanged (not recomputed).
  bool HasGrownBounds() const { return this->Known; }

  void ComputeBounds() override;

  /// The number of the last PointsChanged() (0 before any).
  vtkGetMacro(Generation, int);

  /// Passes over every point made for the caches (first query, another modification, a
  /// settling change that moved an extreme point).
  vtkGetMacro(NumberOfFullPasses, int);

  /// The ids of the last PointsChanged() if it was update `generation` + 1 and nothing
  /// else modified the points since; nullptr otherwise.
  vtkIdTypeArray* ChangesAfter(int generation);

protected:
  vtkGrowingBoundsPoints() = default;
  ~vtkGrowingBoundsPoints() override = default;

private:
  vtkGrowingBoundsPoints(const vtkGrowingBoundsPoints&) = delete;
  void operator=(const vtkGrowingBoundsPoints&) = delete;

  // Write Box and Norm into vtkPoints::Bounds and the array's range caches.
  void Publish();
  // The exact caches from E and the points moved since, O(|M|); false when a witness moved.
  bool Settle();
  // Forget E and M.
  void ForgetExact();

  double Box[6] = { 0, 0, 0, 0, 0, 0 };
  double Norm[2] = { 0, 0 };
  bool Known = false;
  // The last exact state E: its caches, witnesses (x min, x max, y..., z..., |x| min, max),
  // and the points listed since (Moved, flagged in IsMoved).
  bool ExactKnown = false;
  double ExactBox[6] = { 0, 0, 0, 0, 0, 0 };
  double ExactNorm[2] = { 0, 0 };
  vtkIdType Witness[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  std::vector<char> IsMoved;
  std::vector<vtkIdType> Moved;
  int NumberOfFullPasses = 0;
  bool LastChangeExact = false;
  int Generation = 0;
  vtkMTimeType ChangedTime = 0;
  vtkNew<vtkIdTypeArray> Changed;
};

#endif
