/**
 * @class   vtkChainMailDeformationFilter
 * @brief   Drag one vertex of a surface or volume mesh and let the displacement
 *          propagate by inhomogeneous Generalized ChainMail.
 *
 * Each update recomputes the shape from the input (rest) points: the grasped vertex
 * moves by `Displacement`, and the motion spreads through cell edges, each vertex
 * moving at most once into the valid region of the neighbour that sponsored it. The
 * valid region of a vertex follows from its malleability (0 rigid ... 1 soft, the
 * point array selected with SetInputArrayToProcess(0, ...), `Malleability` by default,
 * otherwise `DefaultMalleability`) through linear (or smooth, step, piecewise) transfer
 * curves for stretch, compression and shear. `CandidateQueue` selects the order in
 * which candidates are examined: FIFO, Priority, FIFO Priority (default; deformation
 * flows through stiff regions before soft ones, so rigid regions keep their shape) or
 * Max Violation. See docs/design.md (the deformation contract) and the core's chainmail_deformer.h.
 * `ValidRegionFrame` selects the shape of the valid region: Axes (default, the paper's
 * axis-aligned box) or Link (a cylinder aligned with the rest link: rotation invariant).
 *
 * An optional second array (SetInputArrayToProcess(1, ...)) marks pinned vertices
 * (non-zero = never moves; propagation stops at them). An optional third
 * (SetInputArrayToProcess(2, ...), `SlidingArray` in ParaView) marks vertices that lie on
 * an obstacle and slide on it (see Obstacles below).
 *
 * `RefinementIterations` (default 0, off) adds a pass after ChainMail that pulls the
 * result toward satisfying every link (the core's refine_links over the displaced region,
 * grasp and pins fixed; by default the Envelope solver, see RefinementSolver), so a user
 * can buy a lower E_link with time.
 * Its cost follows the displaced region (plus any rigid region it touches), never the
 * mesh; the per-vertex link data is rebuilt (O(points)) only when the geometry, the
 * malleability, the pins or the transfer curves change. `RelaxationIterations` (default
 * 0, off) then smooths the displaced soft region (facets, saw-tooth "teeth") within the
 * links: grasp, pins and rigid regions stay exact, satisfied links stay satisfied, the
 * link error never grows; its region widens by one ring per sweep (docs/deformer.md,
 * "Relaxation").
 *
 * Changing only the grasp, the displacement, the queue or the transfer curves reuses
 * the adjacency and rest state; the output points persist between updates and only the
 * vertices that moved in this or the previous update are rewritten, so a small grasp
 * costs the same on a mesh of millions of vertices as on a small one.
 *
 * Editing (docs/editing.md): CommitEdit() makes the shape of the last update the rest
 * shape for the next grasp; GraspPointId and Displacement are the client's and stay as
 * they are (the ParaView proxy's command releases the grasp). The edit's record
 * (GetLastEdit(), a lossless line of text) is appended to the edit list, which is also
 * the `EditHistory` property (AddEdit / RemoveAllEdits): the output is the input with
 * every listed edit applied, replayed once when the list or the geometry changes, with
 * the least work (only the edits that differ are undone or applied, each in time
 * proportional to the vertices it moved). UndoEdit, RedoEdit and ResetEdits edit that
 * list; undo restores the previous points bit-exactly.
 *
 * Input: any vtkPointSet (vtkPolyData, vtkUnstructuredGrid, ...). Output: the same
 * type, topology and attribute data passed, new points whose precision follows
 * `OutputPointsPrecision`. Bad input (non-finite points, grasp out of range, non-finite
 * displacement or grasp position, a displacement or result the output point type cannot
 * hold, a malleability or pin array with fewer or more values than points, a pin array
 * that is not numeric point data) gives an error and the input geometry unchanged; no
 * NaN or infinite coordinate leaves the filter. Quiet fall-backs warn once per cause: a
 * malleability array that is not one-component numeric point data (DefaultMalleability
 * is used), a pin array of several components (component 0 is the mask), an input with
 * no cell edges (only the grasped vertex moves).
 *
 * In parallel (more than one process, docs/mpi.md) the filter asks for one ghost level,
 * takes point identity from the point GlobalIds and ownership from vtkGhostType, and
 * propagates across processes in supersteps (the core's partitioned_chainmail.h): the
 * result equals the one-process result bit for bit. GraspPointId is then a global id,
 * as it is in one process whenever the input carries point GlobalIds. Refinement runs
 * there with RefinementSolver REFINEMENT_ENVELOPE with the AXES region (the core's
 * partitioned_envelope.h, the same bits as one process). Edits (commit, undo, redo,
 * EditHistory) and a grasp nearest to GraspPosition work there too. Not distributed
 * yet, refused with the same error on every process (output = input): the other
 * refinement solvers or the LINK region, relaxation, obstacles, honoured markers
 * (HonourMarkers with markers), the Priority and Max Violation queues.
 */
#ifndef vtkChainMailDeformationFilter_h
#define vtkChainMailDeformationFilter_h

#include "GeoShapingFiltersDeformationModule.h" // For export macro
#include "vtkPointSetAlgorithm.h"

#include <limits> // For quiet_NaN

#include <functional> // For std::function
#include <memory>     // For std::unique_ptr
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkAlgorithmOutput;
class vtkIdTypeArray;
class vtkPiecewiseFunction;
namespace geoshaping
{
struct Adjacency;
class Exchange;
struct FrameResult;
}

class GEOSHAPINGFILTERSDEFORMATION_EXPORT vtkChainMailDeformationFilter
  : public vtkPointSetAlgorithm
{
public:
  static vtkChainMailDeformationFilter* New();
  vtkTypeMacro(vtkChainMailDeformationFilter, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum QueueTypes
  {
    FIFO = 0,
    PRIORITY = 1,
    FIFO_PRIORITY = 2,
    MAX_VIOLATION = 3
  };
  enum ValidRegionFrames
  {
    AXES = 0,
    LINK = 1
  };
  enum CurveShapes
  {
    LINEAR = 0,
    SMOOTH = 1,
    STEP = 2
  };
  enum RefinementSolvers
  {
    REFINEMENT_ADMM = 0,
    REFINEMENT_DYKSTRA = 1,
    REFINEMENT_ENVELOPE = 2
  };
  enum GraspModes
  {
    GRASP_POINT_ID = 0,
    GRASP_NEAREST_TO_POSITION = 1
  };
  enum
  {
    MAX_REFINEMENT_ITERATIONS = 64,
    MAX_RELAXATION_ITERATIONS = 200
  };

  ///@{
  /// The grasped vertex (GRASP_POINT_ID mode). -1 (default): no grasp, output = input.
  vtkSetMacro(GraspPointId, vtkIdType);
  vtkGetMacro(GraspPointId, vtkIdType);
  ///@}

  ///@{
  /// In GRASP_NEAREST_TO_POSITION mode the grasped vertex is the one nearest to
  /// GraspPosition (found with a vtkStaticPointLocator built once per mesh).
  vtkSetClampMacro(GraspMode, int, GRASP_POINT_ID, GRASP_NEAREST_TO_POSITION);
  vtkGetMacro(GraspMode, int);
  vtkSetVector3Macro(GraspPosition, double);
  vtkGetVector3Macro(GraspPosition, double);
  ///@}

  ///@{
  /// Displacement of the grasped vertex from its rest position (world units).
  vtkSetVector3Macro(Displacement, double);
  vtkGetVector3Macro(Displacement, double);
  ///@}

  ///@{
  /// Malleability used when the selected array is absent. Default 0.5.
  vtkSetClampMacro(DefaultMalleability, double, 0.0, 1.0);
  vtkGetMacro(DefaultMalleability, double);
  ///@}

  ///@{
  /// Candidate structure: FIFO, PRIORITY, FIFO_PRIORITY (default), MAX_VIOLATION.
  vtkSetClampMacro(CandidateQueue, int, FIFO, MAX_VIOLATION);
  vtkGetMacro(CandidateQueue, int);
  ///@}

  ///@{
  /// Threads a large superstep runs on in one process (geoshaping/deform/chainmail_deformer.h,
  /// "Threads"): 0 (the default) every core, 1 one thread, n > 1 n threads. A frame runs on
  /// one thread while other programs hold the cores its threads need, and for a while after
  /// a stall, so threads never make it slower; ThreadsEvenWhenBusy (off by default; for
  /// tests and measurements) uses them whatever the load. A superstep of the FIFO or FIFO
  /// Priority queue with at least ThreadedSuperstepThreshold entries runs on the threads
  /// (not with obstacles, not on MPI pieces); the result is the same bit for bit either way
  /// (docs/benchmarks.md, "Threaded frame").
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  vtkSetMacro(ThreadsEvenWhenBusy, bool);
  vtkGetMacro(ThreadsEvenWhenBusy, bool);
  vtkBooleanMacro(ThreadsEvenWhenBusy, bool);
  vtkSetClampMacro(ThreadedSuperstepThreshold, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(ThreadedSuperstepThreshold, vtkIdType);
  ///@}

  ///@{
  /// Shape of each vertex's valid region (geoshaping/deform/valid_region.h): AXES (default), the
  /// paper's box aligned with the coordinate axes; LINK, a cylinder aligned with the rest
  /// link (stretch and compression along it, shear across it), so rotating the mesh and
  /// the displacement rotates the result. Rigid regions translate exactly in both.
  vtkSetClampMacro(ValidRegionFrame, int, AXES, LINK);
  vtkGetMacro(ValidRegionFrame, int);
  ///@}

  ///@{
  /// Transfer curves: value at malleability 0 and at malleability 1.
  /// Defaults: stretch (1, 2), compression (1, 0.5), shear (0, 0.5).
  vtkSetVector2Macro(StretchRange, double);
  vtkGetVector2Macro(StretchRange, double);
  vtkSetVector2Macro(CompressionRange, double);
  vtkGetVector2Macro(CompressionRange, double);
  vtkSetVector2Macro(ShearRange, double);
  vtkGetVector2Macro(ShearRange, double);
  ///@}

  ///@{
  /// Shape of the three curves between their ends: LINEAR (default), SMOOTH
  /// (smoothstep) or STEP at StepThreshold.
  vtkSetClampMacro(TransferCurveShape, int, LINEAR, STEP);
  vtkGetMacro(TransferCurveShape, int);
  vtkSetClampMacro(StepThreshold, double, 0.0, 1.0);
  vtkGetMacro(StepThreshold, double);
  ///@}

  ///@{
  /// Arbitrary piecewise-linear curves (malleability, value) pairs; when a curve has
  /// points it replaces the range/shape of that parameter. In C++ a
  /// vtkPiecewiseFunction can be given directly.
  void AddStretchCurvePoint(double m, double value);
  void AddCompressionCurvePoint(double m, double value);
  void AddShearCurvePoint(double m, double value);
  void RemoveAllStretchCurvePoints();
  void RemoveAllCompressionCurvePoints();
  void RemoveAllShearCurvePoints();
  void SetStretchFunction(vtkPiecewiseFunction* f);
  void SetCompressionFunction(vtkPiecewiseFunction* f);
  void SetShearFunction(vtkPiecewiseFunction* f);
  ///@}

  ///@{
  /// Sweeps of the refinement pass after ChainMail (0, the default: none, the plain
  /// ChainMail result), at most MAX_REFINEMENT_ITERATIONS (64, the plugin's range; larger
  /// values are clamped); the pass runs the RefinementSolver (Envelope by default: one
  /// exact pass with the Axes region) over the displaced region (the core's refine_links)
  /// and stops earlier once converged to RefinementTolerance, or when the pipeline asks
  /// the filter to abort (checked after every sweep).
  vtkSetClampMacro(RefinementIterations, int, 0, MAX_REFINEMENT_ITERATIONS);
  vtkGetMacro(RefinementIterations, int);
  ///@}

  ///@{
  /// When the refinement pass stops before RefinementIterations: once the largest link
  /// violation (E_link) and the last sweep's largest move are both at most this many
  /// mean edge lengths. Default 1e-6; clamped to [1e-12, 1].
  vtkSetClampMacro(RefinementTolerance, double, 1e-12, 1.0);
  vtkGetMacro(RefinementTolerance, double);
  ///@}

  ///@{
  /// The refinement's solver (the core's ProjectionSolver, link_projection.h).
  /// REFINEMENT_ENVELOPE (the default): with the Axes region one exact pass (every link
  /// satisfied, grasp and pins fixed, rigid sets moved as one; not the nearest such shape),
  /// with the Link region (which has no envelope) Dykstra. REFINEMENT_DYKSTRA:
  /// RefinementIterations sweeps of Dykstra's projection, each lowering the link error
  /// without reaching zero in general. REFINEMENT_ADMM: ADMM on the region's link graph (a sparse
  /// factorisation per region), the report's reference solver. The pass runs only when
  /// RefinementIterations > 0.
  vtkSetClampMacro(RefinementSolver, int, REFINEMENT_ADMM, REFINEMENT_ENVELOPE);
  vtkGetMacro(RefinementSolver, int);
  /// Sweeps of the relaxation pass after ChainMail and the refinement (0, the default:
  /// none), at most MAX_RELAXATION_ITERATIONS (200, the plugin's range; larger values
  /// are clamped). Each sweep moves every displaced soft vertex toward the mean of its
  /// neighbours (over-relaxed Gauss-Seidel on the Dirichlet energy of the displacement
  /// with a weak tether to rest, the core's relaxation.h) as far as its links allow, and
  /// adds the resting soft neighbours of the vertices that moved for the next sweep:
  /// grasp, pins and rigid vertices stay exactly, a link that holds keeps holding, the
  /// link error never grows. The pass stops early once nothing moves, or when the
  /// pipeline asks the filter to abort.
  vtkSetClampMacro(RelaxationIterations, int, 0, MAX_RELAXATION_ITERATIONS);
  vtkGetMacro(RelaxationIterations, int);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION, DOUBLE_PRECISION or DEFAULT_PRECISION (same as
  /// the input, the default).
  vtkSetMacro(OutputPointsPrecision, int);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /// When on, adds point arrays "ChainMailDisplacement" (vector) and
  /// "ChainMailSponsor" (-1 where not moved). Off by default: it costs O(points).
  vtkSetMacro(GenerateDiagnostics, bool);
  vtkGetMacro(GenerateDiagnostics, bool);
  vtkBooleanMacro(GenerateDiagnostics, bool);
  ///@}

  ///@{
  /// Figures of the last update: displaced vertices, candidates examined, the
  /// deformation time in milliseconds (core only), the grasped vertex and the
  /// malleability the deformation used there (NaN without a grasp; a NaN or missing
  /// value reads as the deformer took it: NaN counts as rigid, 0). A haptic client reads
  /// the last one for the grasp's coupling stiffness, also against a remote server.
  vtkIdType GetNumberOfDisplacedPoints() { return this->Statistics.NumberOfDisplacedPoints; }
  vtkIdType GetNumberOfExaminedCandidates() { return this->Statistics.NumberOfExaminedCandidates; }
  double GetLastDeformationMilliseconds() { return this->Statistics.LastDeformationMilliseconds; }
  vtkIdType GetLastGraspPointId() { return this->Statistics.LastGraspPointId; }
  /// Threads the last frame ran on (1 unless a superstep ran threaded, see NumberOfThreads).
  int GetLastFrameThreads() { return this->Statistics.LastFrameThreads; }
  /// In one process, the last frame's supersteps (FIFO, FIFO Priority; 0 for the other
  /// queues) and how many of them ran on threads: with their sizes, what the frame's
  /// time on more cores follows (docs/benchmarks.md, "Threaded frame").
  vtkIdType GetLastFrameSupersteps() { return this->Statistics.LastFrameSupersteps; }
  vtkIdType GetLastFrameThreadedSupersteps()
  {
    return this->Statistics.LastFrameThreadedSupersteps;
  }
  double GetLastGraspMalleability() { return this->Statistics.LastGraspMalleability; }
  ///@}

  ///@{
  /// Figures of the last update on data split across processes (docs/mpi.md; 0 in one
  /// process): bytes of moved frontier sent between processes (all processes' sum),
  /// supersteps run, and rounds: the synchronisations between processes they took (a
  /// process alone with the lowest key runs ahead while it has nothing to send).
  vtkIdType GetNumberOfBytesExchanged() { return this->Statistics.NumberOfBytesExchanged; }
  vtkIdType GetNumberOfSupersteps() { return this->Statistics.NumberOfSupersteps; }
  vtkIdType GetNumberOfRounds() { return this->Statistics.NumberOfRounds; }
  ///@}

  ///@{
  /// Figures of the last refinement pass: sweeps run, vertices it moved off the
  /// ChainMail result, and its time in milliseconds (all 0 without refinement).
  int GetNumberOfRefinementSweeps() { return this->Statistics.NumberOfRefinementSweeps; }
  vtkIdType GetNumberOfRefinedPoints() { return this->Statistics.NumberOfRefinedPoints; }
  double GetLastRefinementMilliseconds() { return this->Statistics.LastRefinementMilliseconds; }
  ///@}

  ///@{
  /// Figures of the last relaxation pass: sweeps run and vertices it moved (both 0
  /// without relaxation).
  int GetNumberOfRelaxationSweeps() { return this->Statistics.NumberOfRelaxationSweeps; }
  vtkIdType GetNumberOfRelaxedPoints() { return this->Statistics.NumberOfRelaxedPoints; }
  ///@}

  ///@{
  /// The applied edits as records (see geoshaping/edit/edit_history.h), in order; the
  /// EditHistory property. A bad record is refused with an error and ends the replay.
  void AddEdit(const char* record);
  void RemoveAllEdits();
  int GetNumberOfEdits();
  const char* GetEdit(int i);
  ///@}

  ///@{
  /// Commands (geoshaping::EditSession). CommitEdit: the last update's shape becomes the
  /// rest shape (an edit is appended, the redo tail dropped); GraspPointId and
  /// Displacement are left as the client set them: release the grasp (GraspPointId -1),
  /// or the next update applies it again to the new rest shape. UndoEdit / RedoEdit:
  /// drop the last edit / re-append the next undone one. ResetEdits: drop every edit
  /// (all stay redoable). Each takes effect at the next update.
  void CommitEdit();
  void UndoEdit();
  void RedoEdit();
  void ResetEdits();
  ///@}

  /// The record of the edit last committed or redone ("" before any): a client copies it
  /// into its EditHistory property so a saved state holds it.
  const char* GetLastEdit();
  /// Undone edits that RedoEdit can re-append.
  int GetNumberOfRedoableEdits();

  ///@{
  /// Obstacles (docs/obstacles.md): surfaces on input port 1, optional, any number of
  /// connections (polygons of polydata, or the boundary surface of any other dataset,
  /// triangulated), open or closed. No vertex's straight path from its rest position to
  /// its deformed position crosses an obstacle triangle, and a vertex that started at
  /// least ObstacleClearance away ends at least that far: a vertex (the grasp included)
  /// stops at the last admissible point of its path and its neighbours follow from there;
  /// rigid regions stop as one; pins stay. Sliding contact: a vertex flagged non-zero in
  /// the sliding mask (input array 2) lands on the obstacle point nearest its target,
  /// so it stays on the obstacle while it moves along it. The triangles' tree is built
  /// once per obstacle geometry. On several processes every process's piece of the
  /// obstacles is gathered to every process (same bits as one process). Refused with an
  /// error (output = input): an obstacle made from this filter's own output (a pipeline
  /// loop: taken off port 1 before any request reaches it, put back once the loop is
  /// gone), an obstacle with non-finite points or no triangle, a sliding
  /// mask that is not numeric point data with one value per point, and on several
  /// processes a rigid region owned by several of them or the refinement with obstacles.
  void AddObstacleConnection(vtkAlgorithmOutput* output) { this->AddInputConnection(1, output); }
  void AddObstacleData(vtkDataObject* data) { this->AddInputDataObject(1, data); }
  void RemoveAllObstacleConnections() { this->SetInputConnection(1, nullptr); }
  /// An obstacle or markers input that ParaView's proxy took off because it is made from
  /// this filter's output (a pipeline loop, named by `what`, e.g. "Obstacle Transform1"):
  /// until this is called with an empty name (the proxy does when the Obstacles or the
  /// Markers change) RequestData refuses, naming it, with the input as output. The
  /// proxy's way to refuse a loop that never reached the filter.
  void RefuseObstacleLoop(const char* what);
  int GetNumberOfObstacleConnections() { return this->GetNumberOfInputConnections(1); }
  vtkSetClampMacro(ObstacleClearance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ObstacleClearance, double);
  ///@}

  ///@{
  /// Obstacle figures of the last update: the part of Displacement the grasp moved (1
  /// when nothing stopped it or without obstacles, NaN without a grasp), whether an
  /// obstacle stopped it (the stopped grasp is at rest + fraction * Displacement: where a
  /// haptic coupling should pull), the vertices an obstacle held back: by the frame and
  /// by the refinement and relaxation passes' gate (a vertex held back by the frame and
  /// again by a pass, or by both passes, counts each time), and the passes' part of it.
  /// With a connection on port 1 the output's field data also holds the held-back count
  /// as the one-value vtkIdTypeArray "ObstacleBlockedPoints" (the Information panel's).
  /// A connection whose data set has no points is no obstacle (nothing chosen in the
  /// panel's Pipeline Connection); any other obstacle without polygons is refused.
  double GetLastGraspObstacleFraction() { return this->Statistics.LastGraspObstacleFraction; }
  bool GetLastGraspBlocked() { return this->Statistics.LastGraspObstacleFraction < 1.0; }
  vtkIdType GetNumberOfObstacleBlockedPoints()
  {
    return this->Statistics.NumberOfObstacleBlockedPoints;
  }
  /// Where the grasp landed in the last update: its output position minus its rest
  /// position (NaN without a grasp). Displacement bit for bit for a free grasp; fraction
  /// x Displacement for a grasp an obstacle stopped; the landed point on the obstacle
  /// for a sliding grasp (even at fraction 1): where a haptic coupling should pull.
  double* GetLastGraspDisplacement() VTK_SIZEHINT(3)
  {
    return this->Statistics.LastGraspDisplacement;
  }
  vtkIdType GetNumberOfPassObstacleBlockedPoints()
  {
    return this->Statistics.NumberOfPassObstacleBlockedPoints;
  }
  ///@}

  ///@{
  /// Well markers (docs/markers.md, "Honoured while shaping"): the points of the data
  /// sets on input port 2, optional, any number of connections (a vtkPointSet: ParaView's
  /// CSV Reader then Table To Points, a GOCAD VSet). With HonourMarkers on (default off) each
  /// marker whose vertical line crosses the surface (Marker Misfit's Inside) keeps its vertical
  /// misfit in every frame and after a commit: the three corners of the triangle under it
  /// (geoshaping/metrics/marker_pins.h) are pinned, joined to the PinnedArray's pins, so
  /// a marker on the surface stays on it and a pull near a well bends around it. The map
  /// from markers to pins is made from the committed shape (input + committed edits)
  /// once per input geometry and markers and again when a commit, undo or redo changes
  /// that shape, never per frame. Not refused, with one warning each (counts below):
  /// markers with a NaN or infinite coordinate (skipped), markers outside the surface's
  /// footprint (not honoured), markers off the surface by more than 1e-6 of its size
  /// (their misfit kept as it is). Grasping a vertex under a marker is refused as
  /// grasping a pinned vertex is. With HonourMarkers off, or no markers, the output's
  /// points are as without this input, bit for bit (connected markers add the misfit
  /// figures below to its field data).
  void AddMarkersConnection(vtkAlgorithmOutput* output) { this->AddInputConnection(2, output); }
  void SetMarkersData(vtkDataObject* data) { this->SetInputDataObject(2, data); }
  void RemoveAllMarkersConnections() { this->SetInputConnection(2, nullptr); }
  vtkSetMacro(HonourMarkers, bool);
  vtkGetMacro(HonourMarkers, bool);
  vtkBooleanMacro(HonourMarkers, bool);
  /// Figures of the markers the filter honours (all 0 with HonourMarkers off): markers
  /// honoured, markers outside the footprint, markers skipped for a non-finite
  /// coordinate, honoured markers off the surface by more than 1e-6 of its size, and
  /// the vertices pinned under them.
  vtkIdType GetNumberOfHonouredMarkers();
  vtkIdType GetNumberOfMarkersOutside();
  vtkIdType GetNumberOfNonFiniteMarkers();
  vtkIdType GetNumberOfMarkersOffSurface();
  vtkIdType GetNumberOfMarkerPinnedPoints();
  /// How far this update's output is from the markers (any HonourMarkers; one process):
  /// the RMS and the max |.| of the vertical misfit (Marker Misfit's VerticalMisfit,
  /// surface minus marker, data units) over the NumberOfMarkersInside markers whose
  /// vertical line crosses the committed shape, each read on the triangles it crossed
  /// there (geoshaping::mapped_vertical_misfit: O(markers) a frame, no locator; exact
  /// while a frame's vertices stay over their markers, always for honoured ones). Also
  /// in the output's field data as MarkerVerticalMisfitRMS, MarkerVerticalMisfitMax and
  /// MarkersInside when markers are connected. All 0 without markers, on several
  /// processes, or when none is inside.
  double GetMarkerVerticalMisfitRMS() { return this->Statistics.MarkerVerticalMisfitRMS; }
  double GetMarkerVerticalMisfitMax() { return this->Statistics.MarkerVerticalMisfitMax; }
  vtkIdType GetNumberOfMarkersInside() { return this->Statistics.NumberOfMarkersInside; }
  ///@}

  ///@{
  /// Snap to markers (docs/markers.md, "Snap to markers"; the rule is the core's
  /// geoshaping/edit/marker_snap.h): an edit command, as CommitEdit is. For each marker
  /// inside the footprint, in order, the vertex of its crossed triangle nearest to its
  /// vertical crossing is grasped and moved onto it by one ChainMail frame, the markers
  /// already snapped pinned (and the PinnedArray's pins; not the honoured markers'), and
  /// the whole is committed as ONE edit (one record, one UndoEdit). Each snapped marker is
  /// then the position of a vertex (within a few ulps). Refused with an error, nothing
  /// changed: on several processes, before an update, without a marker inside. The last
  /// snap's counts: markers snapped and skipped (corners pinned, an obstacle in the way).
  void SnapToMarkers();
  vtkGetMacro(LastSnappedMarkers, vtkIdType);
  vtkGetMacro(LastSkippedMarkers, vtkIdType);
  ///@}

  /// Number of times the adjacency and rest state were (re)built: stays 1 while only
  /// the grasp, displacement, queue or curves change.
  vtkGetMacro(NumberOfRebuilds, int);

protected:
  vtkChainMailDeformationFilter();
  ~vtkChainMailDeformationFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int ComputeInputUpdateExtent(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  // The first call of every update, before the executive forwards a request to the
  // inputs: an obstacle or markers made from this filter's output (a loop) is taken off
  // port 1 or 2 here, so no request goes round the loop (docs/obstacles.md); RequestData
  // then refuses.
  int ComputePipelineMTime(vtkInformation* request, vtkInformationVector** inInfoVec,
    vtkInformationVector* outInfoVec, int requestFromOutputPort, vtkMTimeType* mtime) override;
  void ReportReferences(vtkGarbageCollector*) override; // the held obstacles

public:
  using Superclass::SetInputConnection;
  // Setting or clearing port 1 or 2 drops its inputs held back for a loop.
  void SetInputConnection(int port, vtkAlgorithmOutput* input) override;
  void RemoveAllInputConnections(int port) override;

protected:
  vtkIdType GraspPointId = -1;
  int GraspMode = GRASP_POINT_ID;
  double GraspPosition[3] = { 0.0, 0.0, 0.0 };
  double Displacement[3] = { 0.0, 0.0, 0.0 };
  double DefaultMalleability = 0.5;
  int CandidateQueue = FIFO_PRIORITY;
  int ValidRegionFrame = AXES;
  int NumberOfThreads = 0;
  bool ThreadsEvenWhenBusy = false;
  vtkIdType ThreadedSuperstepThreshold; // the core's default (constructor)
  double StretchRange[2] = { 1.0, 2.0 };
  double CompressionRange[2] = { 1.0, 0.5 };
  double ShearRange[2] = { 0.0, 0.5 };
  int TransferCurveShape = LINEAR;
  double StepThreshold = 0.5;
  int OutputPointsPrecision = vtkAlgorithm::DEFAULT_PRECISION;
  bool GenerateDiagnostics = false;
  int RefinementIterations = 0;
  double RefinementTolerance = 1e-6;
  int RefinementSolver = REFINEMENT_ENVELOPE;
  int RelaxationIterations = 0;
  double ObstacleClearance = 0.0;
  bool HonourMarkers = false;
  vtkIdType LastSnappedMarkers = 0;
  vtkIdType LastSkippedMarkers = 0;

  // What the last update did (the information properties above), in one place: every
  // RequestData starts from FrameStatistics{} and each stage fills its part.
  struct FrameStatistics
  {
    vtkIdType NumberOfDisplacedPoints = 0;
    vtkIdType NumberOfExaminedCandidates = 0;
    double LastDeformationMilliseconds = 0.0;
    int LastFrameThreads = 1;
    vtkIdType LastFrameSupersteps = 0;
    vtkIdType LastFrameThreadedSupersteps = 0;
    vtkIdType LastGraspPointId = -1;
    double LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
    int NumberOfRefinementSweeps = 0;
    vtkIdType NumberOfRefinedPoints = 0;
    double LastRefinementMilliseconds = 0.0;
    int NumberOfRelaxationSweeps = 0;
    vtkIdType NumberOfRelaxedPoints = 0;
    vtkIdType NumberOfBytesExchanged = 0;
    vtkIdType NumberOfSupersteps = 0;
    vtkIdType NumberOfRounds = 0;
    double LastGraspObstacleFraction = std::numeric_limits<double>::quiet_NaN();
    vtkIdType NumberOfObstacleBlockedPoints = 0;
    vtkIdType NumberOfPassObstacleBlockedPoints = 0;
    double MarkerVerticalMisfitRMS = 0.0;
    double MarkerVerticalMisfitMax = 0.0;
    vtkIdType NumberOfMarkersInside = 0;
    double LastGraspDisplacement[3] = { std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN() };
  };
  FrameStatistics Statistics;
  int NumberOfRebuilds = 0;

private:
  vtkChainMailDeformationFilter(const vtkChainMailDeformationFilter&) = delete;
  void operator=(const vtkChainMailDeformationFilter&) = delete;

  // The refinement pass after a successful frame grasping the point named `grasp` (a
  // global id where points have ids, else a point index); on several processes the
  // partitioned envelope (collective).
  void Refine(std::int64_t grasp);
  // The relaxation pass after it (or after the frame when there is no refinement); one
  // process only.
  void Relax(std::int64_t grasp);
  // A pass's progress and abort check, asked after every sweep; what an abort keeps.
  std::function<bool()> SweepMonitor(int total, int& sweeps, bool& aborted);
  void KeepAbortedPass(const char* pass, int done, int total);
  // The stages of RequestData (vtkChainMailDeformationFilterUpdate.cxx), the same on one
  // process and on several; each returns false (after an error, the same on every
  // process) when the output is the input. The data worked on: the input, or on several
  // processes the input with the ghost ring the filter made (output = that ring), after
  // the refusals of what is not distributed (vtkChainMailDeformationFilterParallel.cxx).
  bool SelectInput(vtkPointSet*& input, vtkPointSet* output);
  // Geometry and topology into the deformer, when they changed (on any process).
  bool UpdateGeometry(vtkPointSet* input);
  // The deformer over this process's piece of a new geometry, its points numbered by
  // their GlobalIds (`globalIds`) or, when no process has any, by coordinates
  // (vtkGeoShapingAdapter::IdentifyPiece).
  bool SetUpPiece(
    vtkPointSet* input, const double* xyz, geoshaping::Adjacency adjacency, bool globalIds);
  void BuildOutputCaches(vtkPointSet* input, const double* xyz);
  // The grasped point's name (GraspPointId's naming), -1 for none: GraspPointId, or the
  // point nearest GraspPosition over every process.
  std::int64_t ResolveGrasp(vtkPointSet* input);
  // The frame's statistics (totals over the processes; the grasp's from its owner).
  void RecordFrame(const geoshaping::FrameResult& r, std::int64_t grasp);
  // The arrays are read from `input`, the data the filter works on (on several processes
  // the input with the ghost ring the filter made, vtkGeoShapingGhostRing).
  bool UpdateMalleabilityAndPins(vtkPointSet* input);
  // The optional point mask named as input array `index` (pins 1, sliding 2), null when
  // none is named; `valid` false (after an error naming `what`) when it is not numeric
  // point data with one value per point.
  vtkDataArray* PointMask(int index, const char* what, vtkPointSet* input, bool& valid);
  // The obstacles of port 1 into the deformer (vtkChainMailDeformationFilterObstacles.cxx);
  // false (after an error) when they are refused.
  bool UpdateObstacles(vtkInformationVector** inputVector);
  // An input held back for a loop (ComputePipelineMTime): one error naming it, true.
  bool RefuseHeldObstacles();
  // Forgets the inputs of `port` held back for a loop (SetInputConnection and
  // RemoveAllInputConnections on it).
  void DropHeldInputs(int port);
  // On several processes (vtkChainMailDeformationFilterParallelObstacles.cxx, collective):
  // every process's piece of the obstacles gathered to every process, the same triangles
  // everywhere, and the sliding mask of `input`; false (after an error, on every process)
  // when refused.
  bool UpdateObstaclesParallel(vtkPointSet* input, geoshaping::Exchange& exchange);
  // The markers of port 2 to the vertices pinned under them in the committed shape
  // (vtkChainMailDeformationFilterMarkers.cxx), made again when the geometry, the markers
  // or HonourMarkers changed, or with `force` (the committed shape changed); true when
  // the pinned vertices changed.
  bool UpdateMarkers(vtkPointSet* input, bool force);
  // The frame's misfit figures from `output`'s points and the markers' map.
  void UpdateMarkerMisfit(vtkPointSet* output);
  // The sliding mask (input array 2 of `input`, the data worked on) into the deformer;
  // false (after an error) when it is refused.
  bool UpdateSliding(vtkPointSet* input);
  std::vector<int> UpdateEdits(std::vector<int>& stale);
  void Deform(vtkPointSet* input, std::vector<int>& stale);
  bool OutputFits();
  // A frame whose output does not fit is dropped, on one process or several alike: the
  // last frame's vertices join `stale` (restored to rest), the statistics say no frame.
  void DropFrame(std::vector<int>& stale);
  // A quiet fall-back is reported once per distinct message, not on every drag frame.
  void WarnOnce(const std::string& message);
  void UpdateNormals(vtkIdTypeArray* changed);
  void UpdateElevation(vtkPointSet* input, vtkPointSet* output, vtkIdTypeArray* changed);
  void WriteOutput(vtkPointSet* input, vtkPointSet* output, const std::vector<int>& stale,
    const std::vector<int>& touched);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
