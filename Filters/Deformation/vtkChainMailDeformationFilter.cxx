#include "vtkChainMailDeformationFilter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkInformationStringKey.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include "geoshaping/chainmail_deformer.h"
#include "geoshaping/edit_history.h"
#include "geoshaping/link_projection.h"

#include <chrono>
#include <initializer_list>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkChainMailDeformationFilter);

struct vtkChainMailDeformationFilter::vtkInternals
{
  geoshaping::ChainMailDeformer Deformer;
  geoshaping::Curve StretchCurve, CompressionCurve, ShearCurve; // only .points used

  // What the cached core state was built from.
  vtkPoints* GeometryPoints = nullptr;
  vtkIdType GeometrySize = -1;
  vtkMTimeType GeometryTime = 0;
  int GeometryPrecision = -1;
  bool GeometryValid = false;
  vtkDataArray* MalleabilitySource = nullptr;
  vtkMTimeType MalleabilityTime = 0;
  double MalleabilityDefault = -1.0;
  vtkDataArray* PinSource = nullptr;
  vtkMTimeType PinTime = 0;

  // The refinement pass: per-vertex link data (rebuilt when the geometry, malleability,
  // pins or curves change), the projector's scratch, and the vertices the last pass
  // moved off the ChainMail result (restored to rest next update, with the moved ones).
  geoshaping::LinkMesh Links;
  std::unique_ptr<geoshaping::LinkProjector> Projector;
  geoshaping::TransferFunction LinksTransfer;
  std::vector<geoshaping::index_t> Refined;
  bool Refining = false; // the last update wrote the projector's result

  // Editing: the applied edits' records (the EditHistory property), the history that
  // applies them (with the undone tail kept for redo), and the last frame's recipe.
  std::vector<std::string> EditRecords;
  bool EditsDirty = false;
  geoshaping::EditHistory History;
  geoshaping::EditRecipe FrameRecipe;
  std::string LastEdit;

  // Displacement of v from its rest position in the last frame (refined or not).
  const Eigen::Vector3d& FinalDisplacement(geoshaping::index_t v) const
  {
    return this->Refining ? this->Projector->displacement(v) : this->Deformer.displacement(v);
  }

  vtkSmartPointer<vtkPoints> OutputPoints;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  bool WarnedParallel = false;
};

namespace
{
void SetCurvePoints(geoshaping::Curve& curve, vtkPiecewiseFunction* f)
{
  curve.points.clear();
  if (!f)
    return;
  double node[4];
  for (int i = 0; i < f->GetSize(); ++i)
  {
    f->GetNodeValue(i, node);
    curve.points.emplace_back(node[0], node[1]);
  }
}

using IdList = std::vector<geoshaping::index_t>;
using IdLists = std::initializer_list<const IdList*>;

bool SameCurve(const geoshaping::Curve& a, const geoshaping::Curve& b)
{
  return a.at_rigid == b.at_rigid && a.at_soft == b.at_soft && a.shape == b.shape &&
    a.threshold == b.threshold && a.points == b.points;
}

bool SameTransfer(const geoshaping::TransferFunction& a, const geoshaping::TransferFunction& b)
{
  return SameCurve(a.stretch, b.stretch) && SameCurve(a.compression, b.compression) &&
    SameCurve(a.shear, b.shear) && a.exact_rigid_at_zero == b.exact_rigid_at_zero;
}

geoshaping::EditRecipe Recipe(vtkChainMailDeformationFilter* self, vtkIdType grasp)
{
  geoshaping::EditRecipe r;
  r.grasp = geoshaping::index_t(grasp);
  r.displacement = Eigen::Vector3d(self->GetDisplacement());
  r.queue = self->GetCandidateQueue();
  self->GetStretchRange(r.stretch);
  self->GetCompressionRange(r.compression);
  self->GetShearRange(r.shear);
  r.curve_shape = self->GetTransferCurveShape();
  r.step_threshold = self->GetStepThreshold();
  r.refinement_iterations = self->GetRefinementIterations();
  return r;
}

geoshaping::Curve MakeCurve(const double range[2], int shape, double threshold,
  const geoshaping::Curve& userPoints)
{
  geoshaping::Curve c;
  c.at_rigid = range[0];
  c.at_soft = range[1];
  c.threshold = threshold;
  c.shape = shape == vtkChainMailDeformationFilter::SMOOTH ? geoshaping::CurveShape::smooth
    : shape == vtkChainMailDeformationFilter::STEP         ? geoshaping::CurveShape::step
                                                           : geoshaping::CurveShape::linear;
  if (!userPoints.points.empty())
  {
    c.shape = geoshaping::CurveShape::piecewise;
    c.points = userPoints.points;
  }
  return c;
}
} // namespace

vtkChainMailDeformationFilter::vtkChainMailDeformationFilter()
  : Internals(new vtkInternals)
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Malleability");
}

vtkChainMailDeformationFilter::~vtkChainMailDeformationFilter() = default;

void vtkChainMailDeformationFilter::AddStretchCurvePoint(double m, double v)
{
  this->Internals->StretchCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::AddCompressionCurvePoint(double m, double v)
{
  this->Internals->CompressionCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::AddShearCurvePoint(double m, double v)
{
  this->Internals->ShearCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllStretchCurvePoints()
{
  this->Internals->StretchCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllCompressionCurvePoints()
{
  this->Internals->CompressionCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllShearCurvePoints()
{
  this->Internals->ShearCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::SetStretchFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->StretchCurve, f);
  this->Modified();
}

void vtkChainMailDeformationFilter::SetCompressionFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->CompressionCurve, f);
  this->Modified();
}

void vtkChainMailDeformationFilter::SetShearFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->ShearCurve, f);
  this->Modified();
}

int vtkChainMailDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("Input and output must be vtkPointSet.");
    return 0;
  }
  output->ShallowCopy(input);
  this->NumberOfDisplacedPoints = 0;
  this->NumberOfExaminedCandidates = 0;
  this->LastDeformationMilliseconds = 0.0;
  this->LastGraspPointId = -1;
  this->NumberOfRefinementSweeps = 0;
  this->NumberOfRefinedPoints = 0;
  this->LastRefinementMilliseconds = 0.0;
  vtkInternals& in = *this->Internals;
  in.Refining = false;

  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    if (!in.WarnedParallel)
    {
      vtkErrorMacro("ChainMailDeformation propagates through the whole connected mesh and "
                    "cannot run on data split across "
                    << controller->GetNumberOfProcesses()
                    << " processes; the output is the undeformed input. Run pvserver with "
                       "one rank (or the filter in pvpython/the builtin server).");
      in.WarnedParallel = true;
    }
    return 1;
  }

  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType n = input->GetNumberOfPoints();
  if (!inPoints || n == 0)
  {
    return 1;
  }
  if (n > vtkIdType(std::numeric_limits<geoshaping::index_t>::max()))
  {
    vtkErrorMacro("Input has " << n << " points; the deformer supports at most 2^31 - 1.");
    return 1;
  }

  // 1. Geometry and topology: rebuilt only when they change.
  const vtkMTimeType geometryTime = vtkGeoShapingAdapter::GeometryTime(input);
  if (!in.GeometryValid || in.GeometryPoints != inPoints || in.GeometrySize != n ||
    in.GeometryTime != geometryTime || in.GeometryPrecision != this->OutputPointsPrecision)
  {
    in.GeometryValid = false;
    in.GeometryPoints = inPoints;
    in.GeometrySize = n;
    in.GeometryTime = geometryTime;
    in.GeometryPrecision = this->OutputPointsPrecision;
    in.MalleabilitySource = nullptr;
    in.PinSource = nullptr;
    in.MalleabilityDefault = -1.0;
    in.Locator = nullptr;
    in.Projector.reset();
    in.Refined.clear();
    in.Refining = false;
    in.History.clear();
    in.EditsDirty = true;

    std::vector<double> xyz;
    vtkIdType firstBad;
    const vtkIdType bad = vtkGeoShapingAdapter::PointsAsDouble(inPoints, xyz, firstBad);
    if (bad > 0)
    {
      vtkErrorMacro("Input has " << bad << " non-finite point coordinates (first at point "
                                 << firstBad << "); output is the undeformed input.");
      return 1;
    }
    vtkIdType skipped = 0;
    geoshaping::Adjacency adjacency = vtkGeoShapingAdapter::BuildAdjacency(input, skipped);
    if (skipped > 0)
    {
      vtkWarningMacro(<< skipped
                      << " cells are of an unsupported type (higher-order or polyhedral) or "
                         "have invalid point ids; their edges do not propagate deformation.");
    }
    in.Deformer.set_mesh(xyz.data(), geoshaping::index_t(n), std::move(adjacency));

    in.OutputPoints = vtkSmartPointer<vtkPoints>::New();
    const int precision = this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION
      ? VTK_FLOAT
      : this->OutputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION ? VTK_DOUBLE
                                                                      : inPoints->GetDataType();
    in.OutputPoints->SetDataType(precision);
    in.OutputPoints->DeepCopy(inPoints);
    if (in.OutputPoints->GetDataType() != precision)
    {
      vtkNew<vtkPoints> converted;
      converted->SetDataType(precision);
      converted->SetNumberOfPoints(n);
      for (vtkIdType i = 0; i < n; ++i)
        converted->SetPoint(i, xyz.data() + 3 * i);
      in.OutputPoints = converted;
    }
    in.GeometryValid = true;
    ++this->NumberOfRebuilds;
  }
  if (!in.GeometryValid)
  {
    return 1;
  }

  // 2. Malleability and pins: copied only when their array changes.
  vtkDataArray* malleability = this->GetInputArrayToProcess(0, inputVector);
  if (malleability && malleability->GetNumberOfComponents() != 1)
  {
    vtkWarningMacro("Malleability array '" << malleability->GetName()
                                           << "' must have one component; using DefaultMalleability.");
    malleability = nullptr;
  }
  if (malleability != in.MalleabilitySource ||
    (malleability && malleability->GetMTime() != in.MalleabilityTime) ||
    (!malleability && in.MalleabilityDefault != this->DefaultMalleability))
  {
    if (malleability)
    {
      std::vector<double> m(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        m[i] = malleability->GetComponent(i, 0);
      const std::size_t bad = in.Deformer.set_malleability(m.data());
      if (bad > 0)
      {
        vtkWarningMacro(<< bad << " malleability values are outside [0, 1] or NaN; they were "
                                  "clamped (NaN counts as 0, rigid).");
      }
      in.MalleabilityTime = malleability->GetMTime();
    }
    else
    {
      in.Deformer.set_uniform_malleability(this->DefaultMalleability);
    }
    in.MalleabilitySource = malleability;
    in.MalleabilityDefault = this->DefaultMalleability;
    in.Projector.reset();
  }
  // The pin array is optional: ask for it only when one was named.
  vtkInformationVector* arrays = this->GetInformation()->Get(INPUT_ARRAYS_TO_PROCESS());
  vtkDataArray* pins = arrays && arrays->GetNumberOfInformationObjects() > 1 &&
      arrays->GetInformationObject(1)->Get(vtkDataObject::FIELD_NAME())
    ? this->GetInputArrayToProcess(1, inputVector)
    : nullptr;
  if (pins != in.PinSource || (pins && pins->GetMTime() != in.PinTime))
  {
    if (pins)
    {
      std::vector<std::uint8_t> mask(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
        mask[i] = pins->GetComponent(i, 0) != 0.0;
      in.Deformer.set_pinned(mask.data());
      in.PinTime = pins->GetMTime();
    }
    else
    {
      in.Deformer.set_pinned(nullptr);
    }
    in.PinSource = pins;
    in.Projector.reset();
  }

  // 3. Committed edits: replayed when the list or the geometry changed.
  IdList stale; // the last frame, shown until rewritten
  if (in.EditsDirty)
  {
    stale = in.Deformer.moved();
    std::string error;
    if (!in.History.synchronize(in.Deformer, in.EditRecords, error))
    {
      vtkErrorMacro("EditHistory: " << error << "; the edits before it are applied.");
    }
    in.EditsDirty = false;
  }
  const IdList touched = in.History.take_touched();
  if (!touched.empty())
  {
    in.Projector.reset(); // its links were built from the old rest shape
  }

  // 4. Transfer function and queue, cheap to set every time.
  geoshaping::TransferFunction tf;
  tf.stretch = MakeCurve(this->StretchRange, this->TransferCurveShape, this->StepThreshold,
    in.StretchCurve);
  tf.compression = MakeCurve(this->CompressionRange, this->TransferCurveShape,
    this->StepThreshold, in.CompressionCurve);
  tf.shear =
    MakeCurve(this->ShearRange, this->TransferCurveShape, this->StepThreshold, in.ShearCurve);
  tf.exact_rigid_at_zero = this->ExactRigidAtZero;
  if (*tf.validate())
  {
    vtkErrorMacro("Invalid transfer function: " << tf.validate() << ".");
    in.Deformer.reset();
  }
  else
  {
    in.Deformer.set_transfer_function(tf);
    in.Deformer.set_queue(static_cast<geoshaping::QueueKind>(this->CandidateQueue));

    // 5. Grasp and deform.
    vtkIdType grasp = this->GraspPointId;
    if (this->GraspMode == GRASP_NEAREST_TO_POSITION)
    {
      if (!in.Locator)
      {
        in.Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
        in.Locator->SetDataSet(input);
        in.Locator->BuildLocator();
      }
      grasp = in.Locator->FindClosestPoint(this->GraspPosition);
    }
    if (grasp < 0 && this->GraspMode == GRASP_POINT_ID)
    {
      in.Deformer.reset(); // no grasp: the rest shape
    }
    else if (grasp >= n)
    {
      // Checked here: the core's 32-bit ids would wrap a 64-bit id into range.
      vtkErrorMacro("No deformation: grasp vertex " << grasp << " is outside [0, " << n
                                                    << "); output is the undeformed input.");
      in.Deformer.reset();
    }
    else
    {
      const auto start = std::chrono::steady_clock::now();
      const geoshaping::FrameResult r = in.Deformer.deform(geoshaping::index_t(grasp),
        Eigen::Vector3d(this->Displacement[0], this->Displacement[1], this->Displacement[2]));
      this->LastDeformationMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
          .count();
      if (!r.ok)
      {
        vtkErrorMacro("No deformation: " << r.message << "; output is the undeformed input.");
      }
      this->NumberOfDisplacedPoints = vtkIdType(r.moved);
      this->NumberOfExaminedCandidates = vtkIdType(r.examined);
      this->LastGraspPointId = r.ok ? grasp : -1;
      in.FrameRecipe = Recipe(this, grasp);
      if (r.ok && this->RefinementIterations > 0)
      {
        this->Refine(grasp);
      }
    }
  }

  // 6. Rewrite only the vertices that moved now or last time (the moved and the refined)
  // and those an edit changed, as input + offset so unedited vertices stay the input's.
  vtkPoints* outPoints = in.OutputPoints;
  double p[3];
  for (const IdList* restore : IdLists{ &in.Deformer.previously_moved(), &in.Refined, &stale, &touched })
    for (geoshaping::index_t v : *restore)
    {
      inPoints->GetPoint(v, p);
      const Eigen::Vector3d& c = in.Deformer.committed_offset(v);
      outPoints->SetPoint(v, p[0] + c.x(), p[1] + c.y(), p[2] + c.z());
    }
  in.Refined.clear();
  if (in.Refining)
  {
    in.Refined = in.Projector->changed();
  }
  for (const IdList* write : IdLists{ &in.Deformer.moved(), &in.Refined })
    for (geoshaping::index_t v : *write)
    {
      inPoints->GetPoint(v, p);
      const Eigen::Vector3d u = in.Deformer.committed_offset(v) + in.FinalDisplacement(v);
      outPoints->SetPoint(v, p[0] + u.x(), p[1] + u.y(), p[2] + u.z());
    }
  outPoints->Modified();
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
    for (geoshaping::index_t v : in.Deformer.moved())
    {
      sponsor->SetValue(v, in.Deformer.sponsor(v));
    }
    for (const IdList* write : IdLists{ &in.Deformer.moved(), &in.Refined })
      for (geoshaping::index_t v : *write)
      {
        displacement->SetTuple(v, in.FinalDisplacement(v).data());
      }
    output->GetPointData()->AddArray(displacement);
    output->GetPointData()->AddArray(sponsor);
  }
  return 1;
}

void vtkChainMailDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GraspPointId: " << this->GraspPointId << "\n";
  os << indent << "GraspMode: " << this->GraspMode << "\n";
  os << indent << "GraspPosition: " << this->GraspPosition[0] << " " << this->GraspPosition[1]
     << " " << this->GraspPosition[2] << "\n";
  os << indent << "Displacement: " << this->Displacement[0] << " " << this->Displacement[1]
     << " " << this->Displacement[2] << "\n";
  os << indent << "DefaultMalleability: " << this->DefaultMalleability << "\n";
  os << indent << "CandidateQueue: "
     << geoshaping::queue_name(static_cast<geoshaping::QueueKind>(this->CandidateQueue)) << "\n";
  os << indent << "StretchRange: " << this->StretchRange[0] << " " << this->StretchRange[1] << "\n";
  os << indent << "CompressionRange: " << this->CompressionRange[0] << " "
     << this->CompressionRange[1] << "\n";
  os << indent << "ShearRange: " << this->ShearRange[0] << " " << this->ShearRange[1] << "\n";
  os << indent << "TransferCurveShape: " << this->TransferCurveShape << "\n";
  os << indent << "StepThreshold: " << this->StepThreshold << "\n";
  os << indent << "ExactRigidAtZero: " << this->ExactRigidAtZero << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "GenerateDiagnostics: " << this->GenerateDiagnostics << "\n";
  os << indent << "RefinementIterations: " << this->RefinementIterations << "\n";
  os << indent << "NumberOfEdits: " << this->Internals->EditRecords.size() << "\n";
  os << indent << "NumberOfRebuilds: " << this->NumberOfRebuilds << "\n";
}

void vtkChainMailDeformationFilter::Refine(vtkIdType grasp)
{
  vtkInternals& in = *this->Internals;
  const geoshaping::TransferFunction& tf = in.Deformer.transfer_function();
  if (!in.Projector || !SameTransfer(tf, in.LinksTransfer))
  {
    in.Links = geoshaping::link_mesh(in.Deformer);
    in.LinksTransfer = tf;
    in.Projector = std::make_unique<geoshaping::LinkProjector>(in.Links);
  }
  const auto start = std::chrono::steady_clock::now();
  const geoshaping::ProjectionReport report =
    geoshaping::refine_links(*in.Projector, in.Deformer, geoshaping::index_t(grasp), this->RefinementIterations);
  this->LastRefinementMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfRefinementSweeps = report.iterations;
  this->NumberOfRefinedPoints = vtkIdType(in.Projector->changed().size());
  in.Refining = true;
}

void vtkChainMailDeformationFilter::AddEdit(const char* record)
{
  this->Internals->EditRecords.emplace_back(record ? record : "");
  this->Internals->EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllEdits()
{
  this->Internals->EditRecords.clear();
  this->Internals->EditsDirty = true;
  this->Modified();
}

int vtkChainMailDeformationFilter::GetNumberOfEdits()
{
  return static_cast<int>(this->Internals->EditRecords.size());
}

const char* vtkChainMailDeformationFilter::GetEdit(int i)
{
  const auto& records = this->Internals->EditRecords;
  return i >= 0 && std::size_t(i) < records.size() ? records[std::size_t(i)].c_str() : nullptr;
}

const char* vtkChainMailDeformationFilter::GetLastEdit()
{
  return this->Internals->LastEdit.c_str();
}

int vtkChainMailDeformationFilter::GetNumberOfRedoableEdits()
{
  const vtkInternals& in = *this->Internals;
  return in.History.size() > in.EditRecords.size()
    ? static_cast<int>(in.History.size() - in.EditRecords.size())
    : 0;
}

void vtkChainMailDeformationFilter::CommitEdit()
{
  vtkInternals& in = *this->Internals;
  if (!in.GeometryValid || in.EditsDirty || this->LastGraspPointId < 0)
  {
    vtkWarningMacro("CommitEdit: nothing to commit (no deformation in the last update).");
    return;
  }
  IdList vertices = in.Deformer.moved();
  if (in.Refining)
  {
    for (geoshaping::index_t v : in.Refined)
      if (!in.Deformer.moved_this_frame(v))
        vertices.push_back(v);
  }
  std::vector<Eigen::Vector3d> displacements;
  displacements.reserve(vertices.size());
  for (geoshaping::index_t v : vertices)
    displacements.push_back(in.FinalDisplacement(v));
  in.History.commit(in.Deformer, in.FrameRecipe, vertices, displacements);
  in.LastEdit = in.History.record(in.History.applied() - 1);
  in.EditRecords.push_back(in.LastEdit);
  in.Refining = false;
  in.Projector.reset();
  // Released: the next update shows the committed shape, not the grasp applied again.
  this->LastGraspPointId = -1;
  this->GraspPointId = -1;
  std::fill(this->Displacement, this->Displacement + 3, 0.0);
  this->Modified();
}

void vtkChainMailDeformationFilter::UndoEdit()
{
  vtkInternals& in = *this->Internals;
  if (in.EditRecords.empty())
    return;
  in.EditRecords.pop_back();
  in.EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::RedoEdit()
{
  vtkInternals& in = *this->Internals;
  if (in.History.size() <= in.EditRecords.size())
    return;
  in.LastEdit = in.History.record(in.EditRecords.size());
  in.EditRecords.push_back(in.LastEdit);
  in.EditsDirty = true;
  this->Modified();
}

void vtkChainMailDeformationFilter::ResetEdits()
{
  vtkInternals& in = *this->Internals;
  if (in.EditRecords.empty())
    return;
  in.EditRecords.clear();
  in.EditsDirty = true;
  this->Modified();
}
