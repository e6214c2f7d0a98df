/**
 * @class   vtkMalleabilityPaintFilter
 * @brief   Paint malleability (0 rigid ... 1 soft) on a surface or volume mesh with a
 *          list of brush dabs.
 *
 * The output is the input with a float point array (`Malleability` by default, see
 * MalleabilityArrayName) in [0, 1]: a copy of the input's array of that name when it
 * has one (values clamped to [0, 1], NaN read as 0, with a warning; a non-numeric or
 * multi-component one is replaced, with a warning), otherwise InitialMalleability
 * everywhere; the input's array is never modified. An array with fewer or more values
 * than points is refused: error, output = input. The array is
 * made the active scalars so that a mapper colours by it.
 *
 * Dabs (x y z radius value strength) are painted in order, stroke by stroke: a vertex
 * at distance d <= radius from a dab's centre moves toward `value`,
 *
 *   m += strength * falloff(d / radius) * (value - m),
 *
 * with Falloff CONSTANT, LINEAR, SMOOTH or GAUSSIAN (see geoshaping/paint/brush.h), and
 * consecutive dabs of one brush whose centres follow a path (each within one radius of
 * the previous, as the GUI's brush lays them) form a stroke that moves each vertex
 * once, with the weight of its nearest dab: where such dabs overlap their weights no
 * longer compound. Distance
 * is EUCLIDEAN (a sphere, found with a vtkStaticPointLocator) or GEODESIC (the path
 * along cell edges from the vertex nearest the centre, bounded by the radius), so a
 * brush on one side of a fault gap or a tight fold does not paint the other side. A
 * Euclidean stroke costs time in proportion to the vertices it covers, a geodesic dab to
 * the vertices under it; the vertex grid, locator and adjacency are built once per
 * geometry. The result is deterministic: the same input and dabs give a
 * bit-identical array, so a ParaView state file or a script reproduces the painting.
 *
 * Point dabs (id value weight) paint given vertices after the dabs:
 * m += weight * (value - m). A client painting on a deformed surface (the output of
 * ChainMailDeformation downstream, which this filter cannot read without a pipeline
 * cycle) finds the vertices under its brush there and sends them as point dabs, so the
 * paint lands on the vertices the user sees while the array stays on the rest mesh.
 *
 * With PaintPins on, the filter paints the unsigned-char pin mask PinnedArrayName
 * (default "Pinned", for ChainMailDeformation's PinnedArray) instead of malleability:
 * the same dabs are applied to 0/1 values (the input's mask, non-zero read as 1, or 0)
 * and a vertex is pinned where the result is >= 0.5 (a dab of value 1 pins, of value 0
 * unpins). The malleability array and the active scalars pass through untouched; a
 * PinnedArrayName equal to MalleabilityArrayName is refused (error, output = input).
 *
 * A bad dab (a non-finite number, a negative radius, value or strength outside [0, 1])
 * is skipped with an error naming it; the other dabs are applied as if it were absent.
 * In parallel (an MPI server or pvbatch with more than one process) each process paints
 * its own points and their ghost copies. Euclidean painting is exact. Geodesic painting
 * asks for one ghost level and takes point identity from the point GlobalIds (numbered
 * by coordinates, geoshaping/parallel/coordinate_ids.h, when the input has none; an input with
 * them on some processes and not on others is refused): the source of a dab is the
 * vertex nearest its centre over all processes (ties to the lowest global id, the rule
 * on one process too) and the distances are found by a distributed label-correcting run
 * (geoshaping/parallel/partitioned_geodesic.h), equal bit for bit to one process's. Updates there
 * always repaint every dab (never incrementally) and cannot be aborted midway (an abort on one
 * process would leave the others waiting).
 */
#ifndef vtkMalleabilityPaintFilter_h
#define vtkMalleabilityPaintFilter_h

#include "GeoShapingFiltersPaintModule.h" // For export macro
#include "vtkPointSetAlgorithm.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <memory> // For std::unique_ptr
#include <vector> // For std::vector

class vtkFloatArray;
class vtkPointSet;
namespace geoshaping
{
class Exchange;
struct PaintReport;
}

class GEOSHAPINGFILTERSPAINT_EXPORT vtkMalleabilityPaintFilter : public vtkPointSetAlgorithm
{
public:
  static vtkMalleabilityPaintFilter* New();
  vtkTypeMacro(vtkMalleabilityPaintFilter, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Falloffs
  {
    CONSTANT = 0,
    LINEAR = 1,
    SMOOTH = 2,
    GAUSSIAN = 3
  };
  enum DistanceModes
  {
    EUCLIDEAN = 0,
    GEODESIC = 1
  };

  ///@{
  /// Name of the output point array. Default "Malleability".
  vtkSetStringMacro(MalleabilityArrayName);
  vtkGetStringMacro(MalleabilityArrayName);
  ///@}

  ///@{
  /// Value of the array when the input has none. Default 0.5.
  vtkSetClampMacro(InitialMalleability, double, 0.0, 1.0);
  vtkGetMacro(InitialMalleability, double);
  ///@}

  ///@{
  /// The dabs, applied in the order they were added.
  void AddDab(double x, double y, double z, double radius, double value, double strength);
  void RemoveAllDabs();
  int GetNumberOfDabs();
  /// Six doubles: x y z radius value strength. False when `i` is out of range.
  bool GetDab(int i, double dab[6]);
  ///@}

  ///@{
  /// Point dabs, applied after the dabs in the order added: vertex id, value, weight,
  /// each in [0, 1] but the id; a bad one is skipped with an error.
  void AddPointDab(double id, double value, double weight);
  void RemoveAllPointDabs();
  ///@}

  ///@{
  /// Paint the pin mask instead of malleability. Off by default.
  vtkSetMacro(PaintPins, bool);
  vtkGetMacro(PaintPins, bool);
  vtkBooleanMacro(PaintPins, bool);
  vtkSetStringMacro(PinnedArrayName);
  vtkGetStringMacro(PinnedArrayName);
  ///@}

  ///@{
  /// Weight across the brush: CONSTANT, LINEAR, SMOOTH (default) or GAUSSIAN.
  vtkSetClampMacro(Falloff, int, CONSTANT, GAUSSIAN);
  vtkGetMacro(Falloff, int);
  ///@}

  ///@{
  /// EUCLIDEAN (default) or GEODESIC distance from the dab centre.
  vtkSetClampMacro(DistanceMode, int, EUCLIDEAN, GEODESIC);
  vtkGetMacro(DistanceMode, int);
  ///@}

  ///@{
  /// Figures of the last update: dabs applied and skipped, vertex values written
  /// (a vertex under two strokes counts twice, under two dabs of one stroke once), and the painting
  /// time in milliseconds (dabs only, not the array copy).
  vtkGetMacro(NumberOfAppliedDabs, int);
  vtkGetMacro(NumberOfRejectedDabs, int);
  vtkGetMacro(NumberOfPaintedValues, vtkIdType);
  vtkGetMacro(LastPaintMilliseconds, double);
  ///@}

  /// Number of times the point locator and adjacency were (re)built: stays 1 while
  /// only the dabs or the array change.
  vtkGetMacro(NumberOfRebuilds, int);

  /// Updates that painted only the dabs appended since the previous update onto its
  /// array (O(their reach)) instead of copying the input's array and painting every dab
  /// (O(points)). Such an update keeps the array object, records the painted tuples
  /// (vtkSparseArrayChanges) and gives bit for bit the result of a full update.
  vtkGetMacro(NumberOfIncrementalUpdates, int);

protected:
  vtkMalleabilityPaintFilter();
  ~vtkMalleabilityPaintFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ComputeInputUpdateExtent(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* MalleabilityArrayName = nullptr;
  double InitialMalleability = 0.5;
  int Falloff = SMOOTH;
  int DistanceMode = EUCLIDEAN;
  bool PaintPins = false;
  char* PinnedArrayName = nullptr;

  int NumberOfAppliedDabs = 0;
  int NumberOfRejectedDabs = 0;
  vtkIdType NumberOfPaintedValues = 0;
  double LastPaintMilliseconds = 0.0;
  int NumberOfRebuilds = 0;
  int NumberOfIncrementalUpdates = 0;

private:
  vtkMalleabilityPaintFilter(const vtkMalleabilityPaintFilter&) = delete;
  void operator=(const vtkMalleabilityPaintFilter&) = delete;

  // The stages of RequestData, each collective on several processes (Distributed):
  // SelectInput: the input (with the ghost ring when needed), the output its copy, the
  // figures reset; the array's name, or null (an error given) when nothing is painted.
  const char* SelectInput(vtkPointSet*& input, vtkPointSet* output);
  // False (an error given, on every process alike) when the data cannot be painted.
  bool CheckData(vtkPointSet* input, const char* name);
  // The array to paint: a clamped float copy of the input's, or InitialMalleability.
  vtkSmartPointer<vtkFloatArray> StartingArray(vtkPointSet* input, const char* name);
  // Apply the dabs from `first` on (point dabs: from triplet `first` on) to m; append
  // the vertices they reach to `touched` when given. ApplyDabs reports progress and
  // returns false when the pipeline asked to abort (CheckAbort) before the last dab.
  bool ApplyDabs(
    vtkPointSet* input, float* m, std::size_t first = 0, std::vector<vtkIdType>* touched = nullptr);
  void ApplyPointDabs(
    vtkIdType n, float* m, std::size_t first = 0, std::vector<vtkIdType>* touched = nullptr);
  // The painted array (or its pin mask) into the output, kept for appended dabs.
  void WriteOutput(vtkPointSet* input, vtkPointSet* output, vtkFloatArray* painted);
  // After an abort: the output shown before stays.
  void KeepShownOutput(vtkPointSet* input, vtkPointSet* output);
  // The figures of the dabs from `first` on, and an error naming the skipped ones.
  void ReportPainting(const geoshaping::PaintReport& report, std::size_t first, double ms);

  // Geodesic dabs on data split across processes (collective); returns as ApplyDabs.
  bool ApplyDabsDistributed(
    vtkPointSet* input, float* m, std::size_t first, std::vector<vtkIdType>* touched);
  // Its stages: the pieces' checks agreed and, when a piece changed, each piece set up
  // again (SetUpPiece: ids, owned points, adjacency); false when refused on every process.
  bool SetUpPieces(vtkPointSet* input, geoshaping::Exchange& ex);
  bool SetUpPiece(vtkPointSet* input, bool globalIds, geoshaping::Exchange& ex);
  geoshaping::PaintReport PaintPieces(vtkPointSet* input, float* m, std::size_t first,
    std::vector<vtkIdType>* touched, geoshaping::Exchange& ex);
  // True when painting needs the processes together: geodesic with several processes.
  bool Distributed() const;
  // The update when only dabs were appended since the last one; false otherwise.
  bool PaintIncrementally(vtkPointSet* input, vtkPointSet* output, const char* name);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
