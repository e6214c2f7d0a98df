// The stages of vtkChainMailDeformationFilter::RequestData.
#include "vtkChainMailDeformationFilterInternals.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"

#include "geoshaping/parallel/coordinate_ids.h"

#include <cmath>

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
  // 1. Geometry and topology: rebuilt only when they change.
  const vtkMTimeType geometryTime = vtkGeoShapingAdapter::GeometryTime(input);
  if (!state.GeometryValid || state.GeometryPoints != inPoints || state.GeometrySize != n ||
      state.GeometryTime != geometryTime || state.GeometryPrecision != this->OutputPointsPrecision)
  {
    state.Invalidate(vtkInternals::Stale::Geometry);
    state.GeometryPoints = inPoints;
    state.GeometrySize = n;
    state.GeometryTime = geometryTime;
    state.GeometryPrecision = this->OutputPointsPrecision;

    std::vector<double> xyz;
    vtkIdType firstBad;
    const vtkIdType bad = vtkGeoShapingAdapter::PointsAsDouble(inPoints, xyz, firstBad);
    if (bad > 0)
    {
      vtkErrorMacro("Input has " << bad << " non-finite point coordinates (first at point "
                                 << firstBad << "); output is the undeformed input.");
      return false;
    }
    vtkIdType skipped = 0;
    geoshaping::Adjacency adjacency = vtkGeoShapingAdapter::BuildAdjacency(input, skipped);
    if (skipped > 0)
    {
      vtkWarningMacro(<< skipped
                      << " cells are of an unsupported type (higher-order or polyhedral) or "
                         "have invalid point ids; their edges do not propagate deformation.");
    }
    if (n > 1 && adjacency.neighbors.empty())
    {
      vtkWarningMacro("Input has no cell edges (" << input->GetNumberOfCells()
                                                  << " cells, none with an edge): only the "
                                                     "grasped vertex moves.");
    }
    state.Deformer.set_mesh(xyz.data(), geoshaping::index_t(n), std::move(adjacency));
    // Point GlobalIds decide the propagation order and name the grasp (docs/mpi.md), so
    // one process gives the same result as several. Without them the order comes from
    // the coordinates, as on several processes (coordinate_ids.h), and the grasp and the
    // edit records keep naming point indices.
    state.Ids.clear();
    vtkDataArray* gids = vtkGeoShapingAdapter::PointGlobalIds(input);
    if (gids && gids->GetNumberOfTuples() == n && gids->GetNumberOfComponents() == 1)
    {
      std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        gid[std::size_t(i)] = std::int64_t(gids->GetTuple1(i));
      state.Ids.set(gid.data(), geoshaping::index_t(n));
      state.Deformer.set_global_ids(gid.data());
    }
    else
    {
      state.Deformer.set_global_ids(
        geoshaping::coordinate_ids(xyz.data(), geoshaping::index_t(n)).data());
    }

    this->BuildOutputCaches(input, xyz);
    state.GeometryValid = true;
    ++this->NumberOfRebuilds;
  }

  return state.GeometryValid;
}

void vtkChainMailDeformationFilter::BuildOutputCaches(
  vtkPointSet* input, const std::vector<double>& xyz)
{
  // The output's points (and normals) of a new geometry, kept between updates; the
  // distributed path calls this alone (its deformer is set up by set_piece).
  vtkInternals& state = *this->Internals;
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  state.OutputPoints = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
  const int precision = this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION ? VTK_FLOAT
                        : this->OutputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION
                          ? VTK_DOUBLE
                          : inPoints->GetDataType();
  state.OutputPoints->SetDataType(precision);
  state.OutputPoints->DeepCopy(inPoints);
  if (state.OutputPoints->GetDataType() != precision)
  {
    auto converted = vtkSmartPointer<vtkGrowingBoundsPoints>::New();
    converted->SetDataType(precision);
    converted->SetNumberOfPoints(n);
    for (vtkIdType i = 0; i < n; ++i)
      converted->SetPoint(i, xyz.data() + 3 * i);
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
    const double* rest = xyz.data();
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
  if (pins != state.PinSource || (pins && pins->GetMTime() != state.PinTime))
  {
    if (pins)
    {
      std::vector<std::uint8_t> mask(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        mask[i] = pins->GetComponent(i, 0) != 0.0;
      state.Deformer.set_pinned(mask.data());
      state.PinTime = pins->GetMTime();
    }
    else
    {
      state.Deformer.set_pinned(nullptr);
    }
    state.PinSource = pins;
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
  IdList touched = state.Edits.take_touched();
  if (!touched.empty())
  {
    state.Invalidate(vtkInternals::Stale::Links); // built from the old rest shape
  }

  return touched;
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
  }
  else
  {
    state.Deformer.set_transfer_function(tf);
    state.Deformer.set_queue(static_cast<geoshaping::QueueKind>(this->CandidateQueue));
    state.Deformer.set_valid_region_frame(
      static_cast<geoshaping::ValidRegionFrame>(this->ValidRegionFrame));

    // 5. Grasp and deform.
    vtkIdType grasp = this->GraspPointId;
    if (this->GraspMode == GRASP_NEAREST_TO_POSITION)
    {
      if (!(std::isfinite(this->GraspPosition[0]) && std::isfinite(this->GraspPosition[1]) &&
            std::isfinite(this->GraspPosition[2])))
      {
        vtkErrorMacro("No deformation: GraspPosition (" << this->GraspPosition[0] << ", "
                                                        << this->GraspPosition[1] << ", "
                                                        << this->GraspPosition[2]
                                                        << ") is not finite; output is the "
                                                           "undeformed input.");
        state.Deformer.reset();
        return;
      }
      if (!state.Locator)
      {
        state.Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
        state.Locator->SetDataSet(input);
        state.Locator->BuildLocator();
      }
      double dist2;
      grasp = NearestPoint(
        state.Locator, input->GetPoints(), this->GraspPosition,
        [&state](vtkIdType v) { return state.Deformer.global_id(geoshaping::index_t(v)); }, dist2);
    }
    if (grasp >= 0 && this->GraspMode == GRASP_POINT_ID && !state.Ids.empty())
    {
      const geoshaping::index_t local = state.Ids.find(grasp); // GraspPointId is a global id
      grasp = local < 0 ? n : vtkIdType(local);
    }
    if (grasp < 0 && this->GraspMode == GRASP_POINT_ID)
    {
      state.Deformer.reset(); // no grasp: the rest shape
    }
    else if (grasp >= n)
    {
      // Checked here: the core's 32-bit ids would wrap a 64-bit id into range.
      vtkErrorMacro("No deformation: grasp vertex " << grasp << " is outside [0, " << n
                                                    << "); output is the undeformed input.");
      state.Deformer.reset();
    }
    else
    {
      const auto start = std::chrono::steady_clock::now();
      const geoshaping::FrameResult r = state.Deformer.deform(geoshaping::index_t(grasp),
        Eigen::Vector3d(this->Displacement[0], this->Displacement[1], this->Displacement[2]));
      this->Statistics.LastDeformationMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (!r.ok)
      {
        vtkErrorMacro("No deformation: " << r.message << "; output is the undeformed input.");
      }
      this->Statistics.NumberOfDisplacedPoints = vtkIdType(r.moved);
      this->Statistics.NumberOfExaminedCandidates = vtkIdType(r.examined);
      this->Statistics.NumberOfObstacleBlockedPoints = vtkIdType(r.blocked);
      this->Statistics.LastGraspObstacleFraction =
        r.ok ? r.grasp_fraction : std::numeric_limits<double>::quiet_NaN();
      this->Statistics.LastGraspPointId = r.ok ? grasp : -1;
      this->Statistics.LastGraspMalleability = r.ok ? double(state.Deformer.malleability(grasp))
                                                    : std::numeric_limits<double>::quiet_NaN();
      state.FrameRecipe =
        Recipe(this, state.Ids.empty() ? std::int64_t(grasp)
                                       : state.Deformer.global_id(geoshaping::index_t(grasp)));
      if (r.ok && this->RefinementIterations > 0)
      {
        this->Refine(grasp);
      }
      if (r.ok && this->RelaxationIterations > 0)
      {
        this->Relax(grasp);
      }
      if (r.ok && !this->OutputFits())
      {
        this->DropFrame(stale);
      }
    }
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
    // The sponsor's global id where points have ids (point GlobalIds, or several
    // processes: the same for any partition; -1 on a ghost copy, whose owner examined it),
    // else its point index.
    const bool byId = state.Partition || !state.Ids.empty();
    for (geoshaping::index_t v : state.Deformer.moved())
    {
      const geoshaping::index_t s = state.Deformer.sponsor(v);
      sponsor->SetValue(v, s < 0 ? -1 : byId ? state.Deformer.global_id(s) : s);
    }
    for (const IdList* write : IdLists{ &state.Deformer.moved(), &state.PassesWritten })
      for (geoshaping::index_t v : *write)
      {
        displacement->SetTuple(v, state.FinalDisplacement(v).data());
      }
    output->GetPointData()->AddArray(displacement);
    output->GetPointData()->AddArray(sponsor);
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
