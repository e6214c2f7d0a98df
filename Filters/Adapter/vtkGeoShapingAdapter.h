/**
 * @class   vtkGeoShapingAdapter
 * @brief   Converts VTK data into the plain data of the GeoShaping core.
 *
 * Shared by the GeoShaping filters so each converts its data one way: cell edges to a CSR
 * adjacency, points to doubles, and the modification times that tell a filter whether
 * its cached core state is still valid; and so each sets up a piece of distributed data
 * one way (its checks, the points it owns, its ids). Not wrapped.
 */
#ifndef vtkGeoShapingAdapter_h
#define vtkGeoShapingAdapter_h

#include "GeoShapingAdapterModule.h" // For export macro
#include "vtkSmartPointer.h"         // For vtkSmartPointer
#include "vtkType.h"

#include "geoshaping/mesh/adjacency.h"    // For Adjacency
#include "geoshaping/parallel/exchange.h" // For Exchange

#include <cstdint>
#include <string>
#include <vector>

class vtkCellArray;
class vtkDataArray;
class vtkDataSet;
class vtkInformationVector;
class vtkObject;
class vtkPointSet;
class vtkPoints;

class GEOSHAPINGADAPTER_EXPORT vtkGeoShapingAdapter
{
public:
  /// The core cell kind for a VTK cell type (`unsupported` for higher-order and
  /// polyhedral cells).
  static geoshaping::CellKind CellKindOf(int vtkCellType);

  /// Vertex adjacency from the edges of every cell. `skippedCells` counts cells whose
  /// type is unsupported or whose point ids are invalid.
  static geoshaping::Adjacency BuildAdjacency(vtkDataSet* input, vtkIdType& skippedCells);

  /// The polygons (triangles, quads, polygons) of a vtkPolyData as CSR faces for
  /// geoshaping::SparseNormals. False, and nothing built, when `input` is not polydata,
  /// has no polygons, has triangle strips, or a polygon holds an invalid point id.
  static bool BuildFaces(vtkPointSet* input, std::vector<std::int64_t>& offsets,
    std::vector<geoshaping::index_t>& vertices);

  /// Copies points into xyz (3 doubles each). Returns the number of non-finite
  /// coordinates; `firstBad` is the id of the first point holding one (or -1).
  static vtkIdType PointsAsDouble(vtkPoints* points, std::vector<double>& xyz, vtkIdType& firstBad);

  /// The points as 3 doubles each, read in place when they are doubles already (valid
  /// while `points` is), else copied into `storage` (as PointsAsDouble). `bad` receives
  /// the number of non-finite coordinates, `firstBad` as above.
  static const double* PointsView(
    vtkPoints* points, std::vector<double>& storage, vtkIdType& bad, vtkIdType& firstBad);

  /// Double-precision points from xyz (3 doubles each) and a cell array of cells of
  /// `cellSize` ids each, for the sample scenes of the core.
  static vtkSmartPointer<vtkPoints> MakePoints(const std::vector<double>& xyz);
  static vtkSmartPointer<vtkCellArray> MakeCells(
    const std::vector<geoshaping::index_t>& connectivity, int cellSize);

  /// Modification time of the geometry and connectivity (points and cells), ignoring
  /// point and cell data so that repainting an array does not rebuild adjacency.
  static vtkMTimeType GeometryTime(vtkPointSet* input);

  /// The point `GlobalIds` that name the points (docs/mpi.md, "Identity"): null when there
  /// are none, or when they are D3's own (`___D3___GlobalNodeIds`: numbered per partition,
  /// so different for each number of processes, and absent on one).
  static vtkDataArray* PointGlobalIds(vtkDataSet* input);

  // A distributed path's request (docs/mpi.md): at least one ghost level from the first
  // input (every neighbour of an owned point on this process), more if downstream asked.
  static void RequestGhostRing(
    vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  ///@{
  /// The distributed set-up of a piece (docs/mpi.md, "Ghosts" and "Identity"), one rule
  /// for ChainMailDeformation, MalleabilityPaint and vtkGeoShapingGhostRing.
  ///
  /// What is wrong with a piece's point GlobalIds or vtkGhostType array ("" when
  /// nothing): either must hold one value per point.
  static std::string PieceArraysProblem(vtkDataSet* input);

  /// Collective over `ex` (null: one process): every process's `ok` (its piece passed
  /// its checks), `changed` and whether its piece (of `n` points) has point GlobalIds,
  /// agreed. `Ok` when every piece passed and no pieces holding points differ in having
  /// GlobalIds (no numbering can join them); else `Refusal` says why, on a process whose
  /// own piece passed ("" on one that did not: it reports its own problem).
  struct PieceAgreement
  {
    bool Ok = true;
    bool AnyChanged = false;
    bool WithIds = false;
    std::string Refusal;
  };
  static PieceAgreement AgreeOnPieces(
    geoshaping::Exchange* ex, bool ok, bool changed, vtkIdType n, bool hasIds);

  /// The points this process owns: those vtkGhostType does not mark as duplicates (every
  /// point without the array: the one process holding points, vtkGeoShapingGhostRing).
  static std::vector<std::uint8_t> OwnedPoints(vtkDataSet* input);

  /// Collective over `ex`: the ids of the `n` points xyz of a piece of a mesh without
  /// point GlobalIds, numbered by coordinates, the same for any partition
  /// (geoshaping/parallel/coordinate_ids.h). `owned` holds the points this piece claims
  /// and receives those it owns (a seam point several pieces claim goes to the lowest).
  /// Empty, with `refusal` (the same text on every process), when a piece holds two
  /// points at one position (split nodes, which coordinates cannot keep apart).
  static std::vector<std::int64_t> CoordinateIds(const double* xyz, vtkIdType n,
    std::vector<std::uint8_t>& owned, geoshaping::Exchange& ex, std::string& refusal);

  /// Collective over `ex`: a piece's ids and the points it owns (OwnedPoints): its point
  /// GlobalIds when `globalIds` (decided alike on every process, AgreeOnPieces), else
  /// CoordinateIds of xyz. False, with `refusal`, as CoordinateIds.
  static bool IdentifyPiece(vtkDataSet* input, const double* xyz, bool globalIds,
    geoshaping::Exchange& ex, std::vector<std::int64_t>& ids, std::vector<std::uint8_t>& owned,
    std::string& refusal);

  /// BuildAdjacency, warning through `self` when cells were skipped: "<where><count>
  /// cells are of an unsupported type ... ; <consequence>".
  static geoshaping::Adjacency BuildAdjacency(
    vtkObject* self, vtkDataSet* input, const std::string& where, const char* consequence);
  ///@}
};

#endif
