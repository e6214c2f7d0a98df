// The stages of vtkChainMailDeformationFilter::RequestData.
#include "vtkChainMailDeformationFilterInternals.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"

#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/mesh/huge_pages.h"
#include "geoshaping/parallel/coordinate_ids.h"

#include <algorithm>
#include <cmath>
#include <future>

using namespace vtkChainMailDeformationFilterDetail;

namespace
{
// out[v] = in[v] + offset(v) for every v of the lists that `skip(v)` does not exclude,
// through the arrays' own value types (no virtual call per vertex).
struct RewriteWorker
{
  template<class InArray, class OutArray, class Skip, class Offset>
  void operator()(InArray* inArray, OutArray* outArray, IdLists lists, const Skip& skip,
    const Offset& offset) const
  {
    const auto source = vtk::DataArrayTupleRange<3>(inArray);
    auto out = vtk::DataArrayTupleRange<3>(outArray);
    using Value = typename decltype(out)::ComponentType;
    for (const IdList* list : lists)
      for (geoshaping::index_t v : *list)
      {
        if (skip(v))
          continue;
        const Eigen::Vector3d u = offset(v);
        const auto from = source[v];
        auto to = out[v];
        for (int k = 0; k < 3; ++k)
          to[k] = static_cast<Value>(double(from[k]) + u[k]);
      }
  }
};

template<class Skip, class Offset>
void RewritePoints(vtkDataArray* inArray, vtkDataArray* outArray, IdLists lists, const Skip& skip,
  const Offset& offset)
{
  using Reals = vtkArrayDispatch::Reals;
  RewriteWorker worker;
  if (!vtkArrayDispatch::Dispatch2ByValueType<Reals, Reals>::Execute(
        inArray, outArray, worker, lists, skip, offset))
  {
    worker(inArray, outArray, lists, skip, offset); // any other array type, through vtkDataArray
  }
}
} // namespace

bool vtkChainMailDeformationFilter::UpdateGeometry(vtkPointSet* input)
{
  vtkInternals& state = *this->Internals;
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  // 1. Geometry and topology: rebuilt only when they change, on every process when they
  // changed on any (each rebuilds its piece and replays its edits, collectively). The
  // checks of the piece are agreed in the same gather, with whether it has GlobalIds.
  vtkDataArray* gids = vtkGeoShapingAdapter::PointGlobalIds(input);
  const bool several = bool(state.Processes);
  std::string problem;
  if (n > vtkIdType(std::numeric_limits<geoshaping::index_t>::max()))
    problem = std::to_string(n) + " points, more than the deformer's 2^31 - 1";
  else if (several)
    problem = vtkGeoShapingAdapter::PieceArraysProblem(input);
  if (!problem.empty())
    vtkErrorMacro(<< state.Where() << problem << "; output is the undeformed input.");
  const vtkMTimeType geometryTime = vtkGeoShapingAdapter::GeometryTime(input);
  const bool changed = !state.GeometryValid || several != bool(state.Partition) ||
                       state.GeometryPoints != inPoints || state.GeometrySize != n ||
                       state.GeometryTime != geometryTime ||
                       state.GeometryPrecision != this->OutputPointsPrecision;
  const auto pieces = vtkGeoShapingAdapter::AgreeOnPieces(
    state.Processes.get(), problem.empty(), changed, n, gids != nullptr);
  if (!pieces.Refusal.empty())
    vtkErrorMacro(<< pieces.Refusal << "; output is the undeformed input.");
  if (!pieces.Ok)
  {
    state.GeometryValid = false;
    state.Partition.reset();
    return false;
  }
  if (!pieces.AnyChanged)
  {
    return true;
  }

  state.Invalidate(vtkInternals::Stale::Geometry);
  std::vector<double> storage;
  vtkIdType bad = 0, firstBad = -1;
  const double* xyz =
    n == 0 ? nullptr : vtkGeoShapingAdapter::PointsView(inPoints, storage, bad, firstBad);
  if (bad > 0)
  {
    vtkErrorMacro(<< state.Where() << bad << " non-finite point coordinates (first at point "
                  << firstBad << "); output is the undeformed input.");
  }
  if (!state.AllAgree(bad == 0))
  {
    state.Partition.reset();
    return false;
  }
  state.GeometryPoints = inPoints;
  state.GeometrySize = n;
  state.GeometryTime = geometryTime;
  state.GeometryPrecision = this->OutputPointsPrecision;
  // Point GlobalIds decide the propagation order and name the grasp (docs/mpi.md), so
  // one process gives the same result as several. Without them the order comes from
  // the coordinates, as on several processes (coordinate_ids.h), and the grasp and the
  // edit records keep naming point indices: numbered on a second thread meanwhile (they
  // need neither the adjacency nor the deformer's layout).
  const bool pointIds =
    gids && gids->GetNumberOfTuples() == n && gids->GetNumberOfComponents() == 1;
  std::future<std::vector<std::int64_t>> coordinateIds;
  if (!several && !pointIds)
    coordinateIds = std::async(std::launch::async,
      [xyz, n] { return geoshaping::coordinate_ids(xyz, geoshaping::index_t(n)); });
  geoshaping::Adjacency adjacency = vtkGeoShapingAdapter::BuildAdjacency(
    this, input, state.Where(), "their edges do not propagate deformation.");
  if (n > 1 && adjacency.neighbors.empty())
  {
    vtkWarningMacro(<< state.Where() << "input has no cell edges (" << input->GetNumberOfCells()
                    << " cells, none with an edge): only the grasped vertex moves.");
  }
  if (n > 0)
  {
    this->BuildOutputCaches(input, xyz);
    ++this->NumberOfRebuilds;
  }
  state.Ids.clear();
  if (several)
  {
    return this->SetUpPiece(input, xyz, std::move(adjacency), pieces.WithIds);
  }
  state.Deformer.set_mesh(xyz, geoshaping::index_t(n), std::move(adjacency));
  if (pointIds)
  {
    std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
      gid[std::size_t(i)] = std::int64_t(gids->GetTuple1(i));
    state.Ids.set(gid.data(), geoshaping::index_t(n));
    state.Deformer.set_global_ids(gid.data());
  }
  else
  {
    state.Deformer.set_global_ids(coordinateIds.get().data());
  }
  state.GeometryValid = true;
  return true;
}

void vtkChainMailDeformationFilter::BuildOutputCaches(vtkPointSet* input, const double* xyz)
{
  // The output's points (and normals) of a new geometry, kept between updates.
  vtkInternals& state = *this->Internals;
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  state.OutputPoints = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
  const int precision = this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION ? VTK_FLOAT
                        : this->OutputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION
                          ? VTK_DOUBLE
                          : inPoints->GetDataType();
  state.OutputPoints->SetDataType(precision);
  // Sized first, in fresh storage advised for huge pages, for the copy to fill (page
  // faults are most of a big copy's cost: geoshaping/mesh/huge_pages.h).
  state.OutputPoints->SetNumberOfPoints(n);
  geoshaping::advise_huge_pages(state.OutputPoints->GetVoidPointer(0),
    std::size_t(3 * n) * std::size_t(state.OutputPoints->GetData()->GetDataTypeSize()));
  state.OutputPoints->DeepCopy(inPoints);
  if (state.OutputPoints->GetDataType() != precision)
  {
    auto converted = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
    converted->SetDataType(precision);
    converted->SetNumberOfPoints(n);
    for (vtkIdType i = 0; i < n; ++i)
      converted->SetPoint(i, xyz + 3 * i);
    state.OutputPoints = converted;
  }
  std::vector<std::int64_t> faceOffsets;
  std::vector<geoshaping::index_t> faceVertices;
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  state.OutputNormals = nullptr;
  state.Normals = geoshaping::SparseNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n &&
      vtkGeoShapingAdapter::BuildFaces(input, faceOffsets, faceVertices))
  {
    state.Normals.set_mesh(std::move(faceOffsets), std::move(faceVertices), geoshaping::index_t(n));
    const double* rest = xyz;
    state.Normals.set_positions(
      [rest](geoshaping::index_t v) { return Eigen::Vector3d(rest + 3 * v); });
    state.OutputNormals = vtk::TakeSmartPointer(normals->NewInstance());
    state.OutputNormals->DeepCopy(normals);
  }
}

void vtkChainMailDeformationFilter::WarnOnce(const std::string& message)
{
  if (this->Internals->Warned.insert(message).second)
  {
    vtkWarningMacro(<< message);
  }
}

vtkDataArray* vtkChainMailDeformationFilter::PointMask(
  int index, const char* what, vtkPointSet* input, bool& valid)
{
  const vtkIdType n = input->GetNumberOfPoints();
  // Optional: asked for only when one was named.
  vtkInformationVector* arrays = this->GetInformation()->Get(INPUT_ARRAYS_TO_PROCESS());
  int association = -1;
  vtkAbstractArray* named =
    arrays && arrays->GetNumberOfInformationObjects() > index &&
        arrays->GetInformationObject(index)->Get(vtkDataObject::FIELD_NAME())
      ? this->GetInputAbstractArrayToProcess(index, input, association)
      : nullptr;
  vtkDataArray* mask = vtkDataArray::SafeDownCast(named);
  valid = !named || (mask && association == vtkDataObject::FIELD_ASSOCIATION_POINTS &&
                      mask->GetNumberOfTuples() == n);
  if (!valid)
  {
    vtkErrorMacro(<< what << " array '" << named->GetName()
                  << "' must be numeric point data with one value per point (it is "
                  << named->GetClassName() << " with " << named->GetNumberOfTuples()
                  << " tuples for " << n << " points); output is the undeformed input.");
    return nullptr;
  }
  if (mask && mask->GetNumberOfComponents() != 1)
  {
    this->WarnOnce(std::string(what) + " array '" + mask->GetName() + "' has " +
                   std::to_string(mask->GetNumberOfComponents()) +
                   " components; component 0 is the mask.");
  }
  return mask;
}

bool vtkChainMailDeformationFilter::UpdateMalleabilityAndPins(vtkPointSet* input)
{
  vtkInternals& state = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  // 2. Malleability and pins: copied only when their array changes. An array is read
  // only as numeric point data with one value per point.
  int association = -1;
  vtkAbstractArray* named = this->GetInputAbstractArrayToProcess(0, input, association);
  vtkDataArray* malleability = vtkDataArray::SafeDownCast(named);
  if (named && (!malleability || association != vtkDataObject::FIELD_ASSOCIATION_POINTS ||
                 malleability->GetNumberOfComponents() != 1))
  {
    this->WarnOnce(std::string("Malleability array '") + named->GetName() + "' is " +
                   (!malleability ? std::string("not numeric (") + named->GetClassName() + ")"
                     : association != vtkDataObject::FIELD_ASSOCIATION_POINTS
                       ? std::string("not point data")
                       : std::to_string(malleability->GetNumberOfComponents()) + "-component") +
                   "; DefaultMalleability is used everywhere.");
    malleability = nullptr;
  }
  vtkInformation* request = this->GetInputArrayInformation(0);
  const char* wanted = request ? request->Get(vtkDataObject::FIELD_NAME()) : nullptr;
  if (!named && wanted && *wanted && std::string(wanted) != "None")
  {
    this->WarnOnce(std::string("The input has no point array '") + wanted +
                   "' (MalleabilityArray); DefaultMalleability is used everywhere.");
  }
  if (malleability && malleability->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("Malleability array '" << malleability->GetName() << "' has "
                                         << malleability->GetNumberOfTuples() << " values for " << n
                                         << " points; output is the undeformed input.");
    return false;
  }
  bool valid = true;
  vtkDataArray* pins = this->PointMask(1, "Pinned", input, valid);
  if (!valid)
  {
    return false;
  }

  if (malleability != state.MalleabilitySource ||
      (malleability && malleability->GetMTime() != state.MalleabilityTime) ||
      (!malleability && state.MalleabilityDefault != this->DefaultMalleability))
  {
    if (malleability)
    {
      std::vector<double> m(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        m[i] = malleability->GetComponent(i, 0);
      const std::size_t bad = state.Deformer.set_malleability(m.data());
      if (bad > 0)
      {
        vtkWarningMacro(<< bad
                        << " malleability values are outside [0, 1] or NaN; they were "
                           "clamped (NaN counts as 0, rigid).");
      }
      state.MalleabilityTime = malleability->GetMTime();
    }
    else
    {
      state.Deformer.set_uniform_malleability(this->DefaultMalleability);
    }
    state.MalleabilitySource = malleability;
    state.MalleabilityDefault = this->DefaultMalleability;
    state.Invalidate(vtkInternals::Stale::Links);
  }
  // The pins: the PinnedArray's joined to those under the honoured markers.
  const std::vector<geoshaping::index_t>& underMarkers = state.Markers.vertices;
  if (pins != state.PinSource || (pins && pins->GetMTime() != state.PinTime) ||
      state.MarkersChanged)
  {
    if (pins || !underMarkers.empty())
    {
      std::vector<std::uint8_t> mask(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; pins && i < n; ++i)
        mask[i] = pins->GetComponent(i, 0) != 0.0;
      for (geoshaping::index_t v : underMarkers)
        mask[std::size_t(v)] = 1;
      state.Deformer.set_pinned(mask.data());
      state.PinTime = pins ? pins->GetMTime() : 0;
    }
    else
    {
      state.Deformer.set_pinned(nullptr);
    }
    state.PinSource = pins;
    state.MarkersChanged = false;
    state.Invalidate(vtkInternals::Stale::Links);
  }
  return true;
}

std::vector<int> vtkChainMailDeformationFilter::UpdateEdits(std::vector<int>& stale)
{
  vtkInternals& state = *this->Internals;
  // 3. Committed edits: replayed when the list or the geometry changed.
  if (state.Edits.pending())
  {
    stale = state.Deformer.moved();
    std::string error;
    Eigen::Vector3d x;
    const auto fits = [&state, &x](geoshaping::index_t v)
    { return state.Fits(v, state.Deformer.committed_offset(v), x); };
    if (!state.Edits.synchronize(state.Deformer, error, fits, state.Placement()))
    {
      vtkErrorMacro("EditHistory: " << error << "; the edits before it are applied.");
    }
  }
  stale.insert(stale.end(), state.SnapStale.begin(), state.SnapStale.end());
  state.SnapStale.clear();
  IdList touched = state.Edits.take_touched();
  if (!touched.empty())
  {
    state.Invalidate(vtkInternals::Stale::Links); // built from the old rest shape
  }

  return touched;
}

std::int64_t vtkChainMailDeformationFilter::ResolveGrasp(vtkPointSet* input)
{
  vtkInternals& state = *this->Internals;
  if (this->GraspMode != GRASP_NEAREST_TO_POSITION)
  {
    return this->GraspPointId;
  }
  const double* p = this->GraspPosition;
  if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
  {
    vtkErrorMacro("No deformation: GraspPosition (" << p[0] << ", " << p[1] << ", " << p[2]
                                                    << ") is not finite; output is the "
                                                       "undeformed input.");
    return -1;
  }
  // Each process's nearest point, then the smallest (squared distance, name) over the
  // processes: a ghost has its owner's coordinates and name, so the grasp is the same
  // point for any partition.
  std::int64_t mine[3] = { 0, 0, 0 }; // found, squared distance's bits, name
  if (input->GetNumberOfPoints() > 0)
  {
    if (!state.Locator)
    {
      state.Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
      state.Locator->SetDataSet(input);
      state.Locator->BuildLocator();
      // Kept until Invalidate drops it (the geometry changed): the input's MTime moves
      // on every frame, and a query would otherwise rebuild it, O(points) a frame.
      state.Locator->UseExistingSearchStructureOn();
    }
    double dist2 = 0.0;
    const vtkIdType v = NearestPoint(
      state.Locator, input->GetPoints(), p,
      [&state](vtkIdType w) { return state.Deformer.global_id(geoshaping::index_t(w)); }, dist2);
    if (v >= 0)
    {
      mine[0] = 1;
      mine[1] = geoshaping::bit_cast<std::int64_t>(dist2);
      mine[2] = state.PointName(geoshaping::index_t(v));
    }
  }
  std::int64_t grasp = -1;
  double best = 0.0;
  for (const auto& o : state.AllGather({ mine[0], mine[1], mine[2] }))
  {
    const double d2 = geoshaping::bit_cast<double>(o[1]);
    if (o[0] && (grasp < 0 || d2 < best || (d2 == best && o[2] < grasp)))
      grasp = o[2], best = d2;
  }
  return grasp;
}

void vtkChainMailDeformationFilter::Deform(vtkPointSet* input, std::vector<int>& stale)
{
  vtkInternals& state = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  // 4. Transfer function, queue and frame, cheap to set every time.
  const geoshaping::TransferFunction tf =
    Transfer(this, state.StretchCurve, state.CompressionCurve, state.ShearCurve);
  if (*tf.validate())
  {
    vtkErrorMacro("Invalid transfer function: " << tf.validate() << ".");
    state.Deformer.reset();
    return;
  }
  state.Deformer.set_transfer_function(tf);
  state.Deformer.set_queue(static_cast<geoshaping::QueueKind>(this->CandidateQueue));
  state.Deformer.set_valid_region_frame(
    static_cast<geoshaping::ValidRegionFrame>(this->ValidRegionFrame));

  // 5. Grasp and deform.
  const std::int64_t grasp = this->ResolveGrasp(input);
  if (grasp < 0)
  {
    state.Deformer.reset(); // no grasp: the rest shape
    return;
  }
  const Eigen::Vector3d d(this->Displacement[0], this->Displacement[1], this->Displacement[2]);
  const auto start = std::chrono::steady_clock::now();
  geoshaping::FrameResult r;
  if (state.Partition)
  {
    r = state.Partition->deform(grasp, d, *state.Processes);
  }
  else
  {
    const geoshaping::index_t v = state.Vertex(grasp); // checked: 32-bit ids would wrap
    if (v < 0)
    {
      vtkErrorMacro("No deformation: GraspPointId "
                    << grasp
                    << (state.Ids.empty() ? " is outside [0, " + std::to_string(n) + ")"
                                          : std::string(" is no point's GlobalIds value"))
                    << "; output is the undeformed input.");
      state.Deformer.reset();
      return;
    }
    state.Deformer.set_threads(this->NumberOfThreads,
      this->ThreadsEvenWhenBusy ? geoshaping::ChainMailDeformer::ThreadUse::always
                                : geoshaping::ChainMailDeformer::ThreadUse::when_cores_free);
    state.Deformer.set_threaded_threshold(std::size_t(this->ThreadedSuperstepThreshold));
    r = state.Deformer.deform(v, d);
    if (!r.ok && state.Deformer.pinned(v) &&
        std::binary_search(state.Markers.vertices.begin(), state.Markers.vertices.end(), v))
      r.message += " under an honoured marker (HonourMarkers): grasp a vertex off the markers' "
                   "triangles";
    this->Statistics.LastFrameThreads = r.threaded_supersteps > 0 ? state.Deformer.threads() : 1;
    this->Statistics.LastFrameSupersteps = vtkIdType(r.supersteps);
    this->Statistics.LastFrameThreadedSupersteps = vtkIdType(r.threaded_supersteps);
  }
  this->Statistics.LastDeformationMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!r.ok)
  {
    vtkErrorMacro("No deformation: " << r.message << "; output is the undeformed input.");
  }
  state.FrameRecipe = Recipe(this, grasp);
  if (r.ok && this->RefinementIterations > 0)
  {
    this->Refine(grasp);
  }
  if (r.ok && this->RelaxationIterations > 0)
  {
    this->Relax(grasp);
  }
  this->RecordFrame(r, grasp);
  if (r.ok && !state.AllAgree(n == 0 || this->OutputFits()))
  {
    this->DropFrame(stale);
  }
}

void vtkChainMailDeformationFilter::RecordFrame(
  const geoshaping::FrameResult& r, std::int64_t grasp)
{
  vtkInternals& state = *this->Internals;
  // Totals over the processes (each point counted by its owner; the bytes include the
  // refinement's), and the grasp's figures from the process that owns it.
  // Malleability, obstacle fraction, where the grasp landed (bits).
  std::int64_t owner[5] = { -1, -1, -1, -1, -1 };
  std::vector<geoshaping::index_t> holding;
  state.Holders(grasp, holding);
  for (geoshaping::index_t v : holding)
    if (r.ok && state.Deformer.owned(v))
    {
      owner[0] = geoshaping::bit_cast<std::int64_t>(double(state.Deformer.malleability(v)));
      owner[1] = geoshaping::bit_cast<std::int64_t>(r.grasp_fraction);
      for (int k = 0; k < 3; ++k)
        owner[2 + k] = geoshaping::bit_cast<std::int64_t>(state.Deformer.displacement(v)[k]);
    }
  const std::int64_t bytes = state.Processes ? std::int64_t(state.Processes->bytes_sent()) : 0;
  // Everything an obstacle held back: the frame's vertices and the refinement's and
  // relaxation's (their gate, each pass counted).
  std::int64_t total[5] = { 0, 0, 0, 0, 0 };
  for (const auto& v : state.AllGather({ std::int64_t(r.moved), std::int64_t(r.examined),
         std::int64_t(r.blocked), bytes, std::int64_t(state.Passes.held_back()), owner[0], owner[1],
         owner[2], owner[3], owner[4] }))
  {
    for (int k = 0; k < 5; ++k)
      total[k] += v[std::size_t(k)];
    if (v[5] != -1)
    {
      this->Statistics.LastGraspMalleability = geoshaping::bit_cast<double>(v[5]);
      this->Statistics.LastGraspObstacleFraction = geoshaping::bit_cast<double>(v[6]);
      for (int k = 0; k < 3; ++k)
        this->Statistics.LastGraspDisplacement[k] = geoshaping::bit_cast<double>(v[7 + k]);
    }
  }
  this->Statistics.NumberOfDisplacedPoints = vtkIdType(total[0]);
  this->Statistics.NumberOfExaminedCandidates = vtkIdType(total[1]);
  this->Statistics.NumberOfPassObstacleBlockedPoints = vtkIdType(total[4]);
  this->Statistics.NumberOfObstacleBlockedPoints = vtkIdType(total[2] + total[4]);
  this->Statistics.NumberOfBytesExchanged = vtkIdType(total[3]);
  this->Statistics.LastGraspPointId = r.ok ? grasp : -1;
  if (state.Partition) // the refinement's supersteps are counted by Refine
  {
    this->Statistics.NumberOfSupersteps += vtkIdType(state.Partition->supersteps());
    this->Statistics.NumberOfRounds += vtkIdType(state.Partition->rounds());
  }
}

void vtkChainMailDeformationFilter::DropFrame(std::vector<int>& stale)
{
  vtkInternals& state = *this->Internals;
  // The last frame's vertices are still shown: restore them with the stale ones.
  const IdList& shown = state.Deformer.previously_moved();
  stale.insert(stale.end(), shown.begin(), shown.end());
  state.Deformer.reset();
  state.Passes.begin_frame();
  this->Statistics.NumberOfDisplacedPoints = 0;
  this->Statistics.LastGraspPointId = -1;
  this->Statistics.LastGraspMalleability = std::numeric_limits<double>::quiet_NaN();
}

bool vtkChainMailDeformationFilter::OutputFits()
{
  vtkInternals& state = *this->Internals;
  const IdLists written{ &state.Deformer.moved(), &state.Passes.beyond() };
  // Enough, and O(moved) without a virtual point read: every input coordinate is within
  // the input's bounds, so |x0 + u| <= max |bound| + max |u| <= what the type holds.
  double reach = 0.0;
  bool finite = true;
  for (const IdList* list : written)
    for (geoshaping::index_t v : *list)
    {
      const double u =
        (state.Deformer.committed_offset(v) + state.FinalDisplacement(v)).cwiseAbs().maxCoeff();
      finite = finite && std::isfinite(u);
      reach = std::max(reach, u);
    }
  const double* bounds = state.GeometryPoints->GetBounds(); // cached while the points stay
  double extent = 0.0;
  for (int i = 0; i < 6; ++i)
    extent = std::max(extent, std::abs(bounds[i]));
  if (finite && extent + reach <= state.OutputPoints->GetData()->GetDataTypeMax())
  {
    return true;
  }
  for (const IdList* list : written)
    for (geoshaping::index_t v : *list)
    {
      Eigen::Vector3d x;
      if (!state.Fits(v, state.Deformer.committed_offset(v) + state.FinalDisplacement(v), x))
      {
        vtkErrorMacro("No deformation: Displacement ("
                      << this->Displacement[0] << ", " << this->Displacement[1] << ", "
                      << this->Displacement[2] << ") moves point " << v << " to (" << x[0] << ", "
                      << x[1] << ", " << x[2] << "), beyond what the output's "
                      << state.OutputPoints->GetData()->GetDataTypeAsString()
                      << " points hold; output is the undeformed input.");
        return false;
      }
    }
  return true;
}

void vtkChainMailDeformationFilter::WriteOutput(vtkPointSet* input, vtkPointSet* output,
  const std::vector<int>& stale, const std::vector<int>& touched)
{
  vtkInternals& state = *this->Internals;
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  // 6. Rewrite only the vertices that moved now or last time (the moved and the refined)
  // and those an edit changed, as input + offset so unedited vertices stay the input's.
  vtkGrowingBoundsPoints* outPoints = state.OutputPoints;
  // A vertex moved last time and again now is written once, by the second pass.
  const auto& deformer = state.Deformer;
  const IdList previouslyWritten = std::move(state.PassesWritten);
  RewritePoints(
    inPoints->GetData(), outPoints->GetData(),
    IdLists{ &deformer.previously_moved(), &previouslyWritten, &stale, &touched },
    [&deformer](geoshaping::index_t v) { return deformer.moved_this_frame(v); },
    [&deformer](geoshaping::index_t v) { return deformer.committed_offset(v); });
  state.PassesWritten = state.Passes.beyond(); // the passes' region may reach beyond the frame's
  RewritePoints(
    inPoints->GetData(), outPoints->GetData(), IdLists{ &deformer.moved(), &state.PassesWritten },
    [](geoshaping::index_t) { return false; },
    [&state](geoshaping::index_t v) -> Eigen::Vector3d
    { return state.Deformer.committed_offset(v) + state.FinalDisplacement(v); });
  // What changed since the last update: everything either pass wrote.
  vtkIdTypeArray* changed = state.Changed;
  changed->SetNumberOfTuples(0);
  for (const IdList* written : IdLists{ &deformer.previously_moved(), &previouslyWritten, &stale,
         &touched, &deformer.moved(), &state.PassesWritten })
    for (geoshaping::index_t v : *written)
      changed->InsertNextValue(v);
  if (state.OutputNormals)
  {
    this->UpdateNormals(changed);
    output->GetPointData()->SetNormals(state.OutputNormals);
  }
  // During a drag the bounds grow over the moved points (O(moved) a frame); a frame that
  // writes points but moves none shows the rest shape (released, undone, redone, reset)
  // and makes them exact again, once, so they shrink back (the Information panel, Reset
  // Camera).
  const bool settled =
    deformer.moved().empty() && state.PassesWritten.empty() && changed->GetNumberOfTuples() > 0;
  outPoints->PointsChanged(changed->GetPointer(0), changed->GetNumberOfTuples(), settled);
  output->SetPoints(outPoints);
  this->UpdateElevation(input, output, changed);

  if (this->GenerateDiagnostics)
  {
    vtkNew<vtkDoubleArray> displacement;
    displacement->SetName("ChainMailDisplacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(n);
    displacement->Fill(0.0);
    vtkNew<vtkIdTypeArray> sponsor;
    sponsor->SetName("ChainMailSponsor");
    sponsor->SetNumberOfTuples(n);
    sponsor->Fill(-1);
    // The sponsor's name (its global id where points have ids: on several processes the
    // same for any partition, -1 on a ghost copy, whose owner examined it).
    for (geoshaping::index_t v : state.Deformer.moved())
    {
      const geoshaping::index_t s = state.Deformer.sponsor(v);
      sponsor->SetValue(v, s < 0 ? -1 : state.PointName(s));
    }
    for (const IdList* write : IdLists{ &state.Deformer.moved(), &state.PassesWritten })
      for (geoshaping::index_t v : *write)
      {
        displacement->SetTuple(v, state.FinalDisplacement(v).data());
      }
    output->GetPointData()->AddArray(displacement);
    output->GetPointData()->AddArray(sponsor);
  }
  if (state.GeneratedIds) // several processes, numbered by coordinates
  {
    output->GetPointData()->SetGlobalIds(state.GeneratedIds);
  }
}

void vtkChainMailDeformationFilter::UpdateElevation(
  vtkPointSet* input, vtkPointSet* output, vtkIdTypeArray* changed)
{
  vtkInternals& state = *this->Internals;
  vtkPointData* pd = output->GetPointData();
  vtkDataArray* rest = input->GetPointData()->GetArray("Elevation");
  const vtkIdType n = input->GetNumberOfPoints();
  if (!rest || rest->GetNumberOfComponents() != 1 || rest->GetNumberOfTuples() != n)
  {
    state.OutputElevation = nullptr;
    state.ElevationSource = nullptr;
    return;
  }
  vtkPoints* in = input->GetPoints();
  vtkPoints* out = output->GetPoints();
  const auto write = [rest, in, out, &state](vtkIdType v)
  {
    // z plus the rest elevation's offset from the rest z: z itself for a DEM's surface.
    state.OutputElevation->SetValue(
      v, out->GetPoint(v)[2] + (rest->GetComponent(v, 0) - in->GetPoint(v)[2]));
  };
  const vtkMTimeType time = std::max(rest->GetMTime(), in->GetMTime());
  if (!state.OutputElevation || state.ElevationSource != rest || state.ElevationTime != time)
  {
    state.OutputElevation = vtkSmartPointer<vtkDoubleArray>::New();
    state.OutputElevation->SetName("Elevation");
    state.OutputElevation->SetNumberOfTuples(n);
    for (vtkIdType v = 0; v < n; ++v)
      write(v);
    state.ElevationSource = rest;
    state.ElevationTime = time;
  }
  else
  {
    for (vtkIdType i = 0; i < changed->GetNumberOfTuples(); ++i)
      write(changed->GetValue(i));
    state.OutputElevation->Modified();
  }
  auto restElevation = vtk::TakeSmartPointer(rest->NewInstance());
  restElevation->ShallowCopy(rest);
  restElevation->SetName("RestElevation");
  const bool active = pd->GetScalars() == rest;
  pd->RemoveArray("Elevation");
  pd->AddArray(state.OutputElevation);
  pd->AddArray(restElevation);
  if (active)
  {
    pd->SetActiveScalars("Elevation");
  }
}

void vtkChainMailDeformationFilter::UpdateNormals(vtkIdTypeArray* changed)
{
  // Recompute the normals the changed points affect; they join the changed list.
  vtkInternals& state = *this->Internals;
  std::vector<geoshaping::index_t>& moved = state.NormalsMoved;
  moved.assign(changed->GetPointer(0), changed->GetPointer(0) + changed->GetNumberOfTuples());
  state.Affected.clear();
  vtkFloatArray* floatNormals = vtkFloatArray::FastDownCast(state.OutputNormals);
  const auto update = [&state, &moved, floatNormals](const auto& position)
  {
    state.Normals.moved(moved.data(), moved.size(), position, state.Affected);
    if (floatNormals) // the usual type: written in place, no virtual call per vertex
    {
      float* out = floatNormals->GetPointer(0);
      for (geoshaping::index_t v : state.Affected)
      {
        const Eigen::Vector3d normal = state.Normals.normal(v);
        for (int k = 0; k < 3; ++k)
          out[3 * std::size_t(v) + k] = static_cast<float>(normal[k]);
      }
      return;
    }
    for (geoshaping::index_t v : state.Affected)
    {
      const Eigen::Vector3d normal = state.Normals.normal(v);
      state.OutputNormals->SetTuple(v, normal.data());
    }
  };
  vtkDataArray* points = state.OutputPoints->GetData();
  if (auto* floats = vtkFloatArray::FastDownCast(points))
  {
    const float* x = floats->GetPointer(0);
    update(
      [x](geoshaping::index_t v) { return Eigen::Vector3d(x[3 * v], x[3 * v + 1], x[3 * v + 2]); });
  }
  else if (auto* doubles = vtkDoubleArray::FastDownCast(points))
  {
    const double* x = doubles->GetPointer(0);
    update([x](geoshaping::index_t v) { return Eigen::Vector3d(x + 3 * v); });
  }
  else
  {
    update(
      [points](geoshaping::index_t v)
      {
        Eigen::Vector3d x;
        points->GetTuple(v, x.data());
        return x;
      });
  }
  changed->SetNumberOfTuples(vtkIdType(state.Affected.size()));
  std::copy(state.Affected.begin(), state.Affected.end(), changed->GetPointer(0));
  vtkSparseArrayChanges::ValuesChanged(
    state.OutputNormals, changed->GetPointer(0), changed->GetNumberOfTuples());
}
