#include "vtkMalleabilityPaintFilterInternals.h"

#include "vtkFloatArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGeoShapingControllerExchange.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSparseArrayChanges.h"
#include "vtkSparsePointChanges.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/paint/brush.h"
#include "geoshaping/parallel/coordinate_ids.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMalleabilityPaintFilter);

using namespace vtkMalleabilityPaintFilterDetail;

namespace
{
bool SameDab(const geoshaping::Dab& a, const geoshaping::Dab& b)
{
  return a.center == b.center && a.radius == b.radius && a.value == b.value &&
         a.strength == b.strength;
}
} // namespace

void vtkMalleabilityPaintFilter::vtkInternals::UpdateIds(vtkPointSet* input)
{
  vtkDataArray* ids = vtkGeoShapingAdapter::PointGlobalIds(input);
  const vtkIdType n = input->GetNumberOfPoints();
  if (ids && (ids->GetNumberOfTuples() != n || ids->GetNumberOfComponents() != 1))
    ids = nullptr;
  if (ids == this->IdSource && (!ids || ids->GetMTime() == this->IdTime) &&
      (ids || this->IdsFromCoordinates))
    return;
  this->IdSource = ids;
  this->IdTime = ids ? ids->GetMTime() : 0;
  this->IdsFromCoordinates = !ids;
  this->Ids.clear();
  if (ids)
  {
    this->Ids.resize(std::size_t(n));
    for (vtkIdType i = 0; i < n; ++i)
      this->Ids[std::size_t(i)] = std::int64_t(ids->GetTuple1(i));
  }
  else
  {
    this->Ids = geoshaping::coordinate_ids(this->Xyz.data(), geoshaping::index_t(n));
  }
}

geoshaping::index_t vtkMalleabilityPaintFilter::vtkInternals::Nearest(const Eigen::Vector3d& p)
{
  const vtkIdType first = this->GetLocator()->FindClosestPoint(p.data());
  if (first < 0)
    return -1;
  // The distance as the core measures it (brush.cpp), and every point as near.
  const auto distance = [this, &p](vtkIdType v)
  { return (Eigen::Vector3d(&this->Xyz[3 * std::size_t(v)]) - p).norm(); };
  const auto id = [this](vtkIdType v)
  { return this->Ids.empty() ? std::int64_t(v) : this->Ids[std::size_t(v)]; };
  vtkIdType best = first;
  double nearest = distance(first);
  this->Locator->FindPointsWithinRadius(nearest * (1.0 + 1e-9), p.data(), this->Found);
  for (vtkIdType v : *this->Found)
  {
    const double d = distance(v);
    if (d < nearest || (d == nearest && id(v) < id(best)))
    {
      best = v;
      nearest = d;
    }
  }
  return geoshaping::index_t(best);
}

bool vtkMalleabilityPaintFilter::vtkInternals::Update(
  vtkPointSet* input, vtkMalleabilityPaintFilter* self)
{
  vtkPoints* points = input->GetPoints();
  const vtkMTimeType time = vtkGeoShapingAdapter::GeometryTime(input);
  if (this->GeometryPoints == points && this->GeometrySize == input->GetNumberOfPoints() &&
      this->GeometryTime == time && this->Locator)
  {
    return this->GeometryValid;
  }
  this->GeometryPoints = points;
  this->GeometrySize = input->GetNumberOfPoints();
  this->GeometryTime = time;
  this->AdjacencyValid = false;
  this->Adjacency = {};
  this->Painter.reset();
  this->IdsFromCoordinates = false; // numbered again by UpdateIds
  vtkIdType firstBad;
  const vtkIdType bad = vtkGeoShapingAdapter::PointsAsDouble(points, this->Xyz, firstBad);
  this->GeometryValid = bad == 0;
  if (bad > 0)
  {
    vtkErrorWithObjectMacro(self, "Input has " << bad
                                               << " non-finite point coordinates (first at point "
                                               << firstBad << "); no dab is applied.");
  }
  this->Locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  if (this->GeometryValid)
  {
    vtkNew<vtkPolyData> cloud; // the points alone: the input may change its cells later
    cloud->SetPoints(points);
    this->Locator->SetDataSet(cloud);
  }
  ++self->NumberOfRebuilds;
  return this->GeometryValid;
}

std::vector<std::uintptr_t> vtkMalleabilityPaintFilter::vtkInternals::Signature(
  vtkPointSet* input, vtkMalleabilityPaintFilter* self, const char* name)
{
  std::vector<std::uintptr_t> s{ std::uintptr_t(input->GetNumberOfPoints()),
    std::uintptr_t(vtkGeoShapingAdapter::GeometryTime(input)), std::hash<std::string>()(name),
    std::hash<double>()(self->InitialMalleability), std::uintptr_t(self->Falloff),
    std::uintptr_t(self->DistanceMode), std::uintptr_t(self->PaintPins) };
  vtkSparsePointChanges::AppendObject(input->GetPoints(), s);
  vtkSparsePointChanges::AppendObject(input->GetPointData()->GetArray(name), s);
  return s;
}

vtkStaticPointLocator* vtkMalleabilityPaintFilter::vtkInternals::GetLocator()
{
  if (this->Locator->GetDataSet() && this->Locator->GetBuildTime() == 0)
  {
    this->Locator->BuildLocator();
  }
  return this->Locator;
}

geoshaping::PointQueries vtkMalleabilityPaintFilter::vtkInternals::Queries()
{
  geoshaping::PointQueries q;
  q.nearest = [this](const Eigen::Vector3d& p) { return this->Nearest(p); };
  auto found = vtkSmartPointer<vtkIdList>::New();
  q.within = [this, found](
               const Eigen::Vector3d& p, double r, std::vector<geoshaping::index_t>& ids)
  {
    // A hair wider than asked: the core keeps exactly those within r by its own test.
    this->GetLocator()->FindPointsWithinRadius(r * (1.0 + 1e-9), p.data(), found);
    ids.assign(found->begin(), found->end());
  };
  return q;
}

vtkMalleabilityPaintFilter::vtkMalleabilityPaintFilter()
  : Internals(new vtkInternals)
{
  this->SetMalleabilityArrayName("Malleability");
  this->SetPinnedArrayName("Pinned");
}

vtkMalleabilityPaintFilter::~vtkMalleabilityPaintFilter()
{
  this->SetMalleabilityArrayName(nullptr);
  this->SetPinnedArrayName(nullptr);
}

void vtkMalleabilityPaintFilter::AddPointDab(double id, double value, double weight)
{
  this->Internals->PointDabs.insert(this->Internals->PointDabs.end(), { id, value, weight });
  this->Modified();
}

void vtkMalleabilityPaintFilter::RemoveAllPointDabs()
{
  if (!this->Internals->PointDabs.empty())
  {
    this->Internals->PointDabs.clear();
    this->Modified();
  }
}

void vtkMalleabilityPaintFilter::AddDab(
  double x, double y, double z, double radius, double value, double strength)
{
  geoshaping::Dab d;
  d.center = Eigen::Vector3d(x, y, z);
  d.radius = radius;
  d.value = value;
  d.strength = strength;
  this->Internals->Dabs.push_back(d);
  this->Modified();
}

void vtkMalleabilityPaintFilter::RemoveAllDabs()
{
  if (!this->Internals->Dabs.empty())
  {
    this->Internals->Dabs.clear();
    this->Modified();
  }
}

int vtkMalleabilityPaintFilter::GetNumberOfDabs()
{
  return static_cast<int>(this->Internals->Dabs.size());
}

bool vtkMalleabilityPaintFilter::GetDab(int i, double dab[6])
{
  if (i < 0 || i >= this->GetNumberOfDabs())
    return false;
  const geoshaping::Dab& d = this->Internals->Dabs[std::size_t(i)];
  const double values[6] = { d.center.x(), d.center.y(), d.center.z(), d.radius, d.value,
    d.strength };
  std::copy(values, values + 6, dab);
  return true;
}

int vtkMalleabilityPaintFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("Input and output must be vtkPointSet.");
    return 0;
  }
  // The same stages on one process and on several (geodesic dabs, docs/mpi.md): on several
  // the ghost ring is made and every refusal agreed, each stage collective.
  const char* name = this->SelectInput(input, output);
  if (!name || !this->CheckData(input, name))
  {
    return 1;
  }
  if (!this->PaintPins && !this->Distributed() && this->PaintIncrementally(input, output, name))
  {
    ++this->NumberOfIncrementalUpdates;
    this->Internals->KeepOutput(output);
    return 1;
  }
  vtkSmartPointer<vtkFloatArray> painted = this->StartingArray(input, name);
  if (!this->ApplyDabs(input, painted->GetPointer(0)))
  {
    this->KeepShownOutput(input, output);
    return 1;
  }
  this->ApplyPointDabs(input->GetNumberOfPoints(), painted->GetPointer(0));
  this->WriteOutput(input, output, painted);
  return 1;
}

const char* vtkMalleabilityPaintFilter::SelectInput(vtkPointSet*& input, vtkPointSet* output)
{
  // Geodesic dabs on several processes need the ghost ring: made here when the input lacks
  // it (collective), and the output is then the input with the ring, painted.
  std::string ringError;
  vtkPointSet* ringed = this->Distributed()
                          ? this->Internals->GhostRing.Ensure(
                              input, vtkMultiProcessController::GetGlobalController(), ringError)
                          : input;
  input = ringed ? ringed : input;
  output->ShallowCopy(input);
  this->NumberOfAppliedDabs = 0;
  this->NumberOfRejectedDabs = 0;
  this->NumberOfPaintedValues = 0;
  this->LastPaintMilliseconds = 0.0;
  const char* name = this->PaintPins ? this->PinnedArrayName : this->MalleabilityArrayName;
  name = name ? name : "";
  if (!*name)
  {
    vtkErrorMacro(<< (this->PaintPins ? "PinnedArrayName" : "MalleabilityArrayName")
                  << " is empty; output is the input.");
    return nullptr;
  }
  if (this->PaintPins && this->MalleabilityArrayName &&
      strcmp(name, this->MalleabilityArrayName) == 0)
  {
    vtkErrorMacro("PaintPins would overwrite the malleability array '"
                  << name << "' with a pin mask: give PinnedArrayName another name; output "
                  << "is the input.");
    return nullptr;
  }
  if (!ringed) // the same on every process
  {
    vtkErrorMacro(<< ringError << "; output is the input.");
    return nullptr;
  }
  return name;
}

bool vtkMalleabilityPaintFilter::CheckData(vtkPointSet* input, const char* name)
{
  const vtkIdType n = input->GetNumberOfPoints();
  // With several processes painting geodesically, a process that stops alone would leave
  // the others waiting in a collective: the data checks are agreed on by all.
  bool badData = false;
  if (n > vtkIdType(std::numeric_limits<geoshaping::index_t>::max()))
  {
    vtkErrorMacro("Input has " << n << " points; painting supports at most 2^31 - 1.");
    badData = true;
  }
  vtkDataArray* source = input->GetPointData()->GetArray(name);
  if (!badData && source && source->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("Point array '" << name << "' has " << source->GetNumberOfTuples()
                                  << " values for " << n << " points; output is the input.");
    badData = true;
  }
  if (this->Distributed())
  {
    vtkGeoShapingControllerExchange ex(vtkMultiProcessController::GetGlobalController(), PaintTag);
    bool all = true;
    for (const auto& v : ex.all_gather({ badData ? 0 : 1 }))
      all = all && v[0] != 0;
    if (!all && !badData)
      vtkErrorMacro("Another process refused its piece; output is the input.");
    badData = !all;
  }
  return !badData;
}

vtkSmartPointer<vtkFloatArray> vtkMalleabilityPaintFilter::StartingArray(
  vtkPointSet* input, const char* name)
{
  // A clamped float copy of the input's array, or InitialMalleability.
  const vtkIdType n = input->GetNumberOfPoints();
  auto malleability = vtkSmartPointer<vtkFloatArray>::New();
  malleability->SetName(name);
  malleability->SetNumberOfTuples(n);
  vtkAbstractArray* named = input->GetPointData()->GetAbstractArray(name);
  vtkDataArray* source = vtkDataArray::SafeDownCast(named);
  if (named && !source)
  {
    vtkWarningMacro("Point array '"
                    << name << "' is not numeric (" << named->GetClassName()
                    << "); it is replaced by "
                    << (this->PaintPins ? "an empty mask." : "InitialMalleability."));
  }
  if (source && source->GetNumberOfComponents() != 1)
  {
    vtkWarningMacro("Point array '" << name << "' has " << source->GetNumberOfComponents()
                                    << " components; it is replaced by InitialMalleability.");
    source = nullptr;
  }
  float* m = malleability->GetPointer(0);
  if (source)
  {
    vtkIdType clamped = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double v =
        this->PaintPins ? double(source->GetComponent(i, 0) != 0.0) : source->GetComponent(i, 0);
      const double c = geoshaping::clean_malleability(v);
      clamped += c != v;
      m[i] = static_cast<float>(c);
    }
    if (clamped > 0)
    {
      vtkWarningMacro(<< clamped << " values of '" << name
                      << "' are outside [0, 1] or NaN; they were clamped (NaN reads as 0).");
    }
  }
  else
  {
    malleability->Fill(this->PaintPins ? 0.0 : this->InitialMalleability);
  }
  return malleability;
}

void vtkMalleabilityPaintFilter::KeepShownOutput(vtkPointSet* input, vtkPointSet* output)
{
  // Keep what was shown: the executive would otherwise empty the output on an abort.
  output->ShallowCopy(this->Internals->LastOutput ? this->Internals->LastOutput.Get() : input);
  this->SetAbortOutput(false);
  this->SetAbortExecute(0);
  this->Internals->Painted = nullptr; // the painter's open stroke is not that array's
  vtkErrorMacro("Painting was aborted after "
                << this->NumberOfAppliedDabs << " of " << this->Internals->Dabs.size()
                << " dabs; the output is the previous one (change a property to paint again).");
}

void vtkMalleabilityPaintFilter::WriteOutput(
  vtkPointSet* input, vtkPointSet* output, vtkFloatArray* painted)
{
  vtkInternals& in = *this->Internals;
  const char* name = painted->GetName();
  if (this->PaintPins)
  {
    const vtkIdType n = painted->GetNumberOfTuples();
    vtkNew<vtkUnsignedCharArray> pins;
    pins->SetName(name);
    pins->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      pins->SetValue(i, painted->GetValue(i) >= 0.5f ? 1 : 0);
    output->GetPointData()->AddArray(pins);
    in.Painted = nullptr; // the painter's open stroke is the mask's
  }
  else
  {
    output->GetPointData()->AddArray(painted);
    output->GetPointData()->SetActiveScalars(name);
    // Recording from the start: consumers see the same rule on every later update.
    vtkSparseArrayChanges::ValuesChanged(painted, nullptr, 0);
    in.Painted = painted;
    in.PaintedFrom = in.Signature(input, this, name);
    in.AppliedDabList = in.Dabs;
    in.AppliedPointDabs = in.PointDabs;
  }
  in.KeepOutput(output);
}

bool vtkMalleabilityPaintFilter::PaintIncrementally(
  vtkPointSet* input, vtkPointSet* output, const char* name)
{
  vtkInternals& in = *this->Internals;
  if (!in.Painted || in.Signature(input, this, name) != in.PaintedFrom)
  {
    return false;
  }
  // Only appends, in an order a full update would apply them in: dabs first, then point
  // dabs, so new dabs continue only an array without point dabs.
  const bool dabsAppended =
    in.Dabs.size() >= in.AppliedDabList.size() &&
    std::equal(in.AppliedDabList.begin(), in.AppliedDabList.end(), in.Dabs.begin(), SameDab);
  const bool pointDabsAppended =
    in.PointDabs.size() >= in.AppliedPointDabs.size() &&
    std::equal(in.AppliedPointDabs.begin(), in.AppliedPointDabs.end(), in.PointDabs.begin());
  const bool newDabs = in.Dabs.size() > in.AppliedDabList.size();
  if (!dabsAppended || !pointDabsAppended || (newDabs && !in.PointDabs.empty()))
  {
    return false;
  }
  std::vector<vtkIdType> touched;
  float* m = in.Painted->GetPointer(0);
  const vtkIdType n = input->GetNumberOfPoints();
  this->ApplyDabs(input, m, in.AppliedDabList.size(), &touched);
  this->ApplyPointDabs(n, m, in.AppliedPointDabs.size() / 3, &touched);
  if (!touched.empty())
  {
    vtkSparseArrayChanges::ValuesChanged(in.Painted, touched.data(), vtkIdType(touched.size()));
  }
  in.AppliedDabList = in.Dabs;
  in.AppliedPointDabs = in.PointDabs;
  output->GetPointData()->AddArray(in.Painted);
  output->GetPointData()->SetActiveScalars(name);
  return true;
}

void vtkMalleabilityPaintFilter::ApplyPointDabs(
  vtkIdType n, float* m, std::size_t first, std::vector<vtkIdType>* touched)
{
  const std::vector<double>& d = this->Internals->PointDabs;
  for (std::size_t i = 3 * first; i + 2 < d.size(); i += 3)
  {
    const double id = d[i], value = d[i + 1], weight = d[i + 2];
    if (!(id >= 0 && id < double(n) && id == std::floor(id) && value >= 0 && value <= 1 &&
          weight >= 0 && weight <= 1))
    {
      vtkErrorMacro(
        "Point dab " << i / 3 << " (" << id << " " << value << " " << weight
                     << ") is skipped: id outside the mesh or value/weight outside [0, 1].");
      ++this->NumberOfRejectedDabs;
      continue;
    }
    if (touched)
    {
      touched->push_back(static_cast<vtkIdType>(id));
    }
    float& x = m[static_cast<vtkIdType>(id)];
    x = static_cast<float>(std::min(1.0, std::max(0.0, x + weight * (value - x))));
    ++this->NumberOfPaintedValues;
  }
}

bool vtkMalleabilityPaintFilter::ApplyDabs(
  vtkPointSet* input, float* m, std::size_t first, std::vector<vtkIdType>* touched)
{
  if (this->Distributed())
  {
    return this->ApplyDabsDistributed(input, m, first, touched);
  }
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0 || first >= in.Dabs.size() || !in.Update(input, this))
  {
    return true;
  }
  const auto mode = static_cast<geoshaping::DistanceMode>(this->DistanceMode);
  if (mode == geoshaping::DistanceMode::geodesic)
  {
    in.UpdateIds(input); // the nearest vertex's tie rule
    if (!in.AdjacencyValid)
    {
      in.Adjacency = vtkGeoShapingAdapter::BuildAdjacency(this, input, "", GeodesicSkips);
      in.AdjacencyValid = true;
    }
  }

  const auto start = std::chrono::steady_clock::now();
  if (!in.Painter)
  {
    in.Painter = std::make_unique<geoshaping::Painter>(
      in.Xyz.data(), geoshaping::index_t(n), &in.Adjacency, in.Queries());
  }
  std::vector<geoshaping::Dab> appended;
  if (first > 0)
    appended.assign(in.Dabs.begin() + std::ptrdiff_t(first), in.Dabs.end());
  const std::vector<geoshaping::Dab>& dabs = first > 0 ? appended : in.Dabs;
  const auto falloff = static_cast<geoshaping::Falloff>(this->Falloff);
  geoshaping::PaintReport report;
  if (touched)
  {
    // Appended dabs: a few, painted in place, continuing the last stroke.
    std::vector<geoshaping::index_t> written;
    report = in.Painter->append(dabs, falloff, mode, m, written);
    touched->insert(touched->end(), written.begin(), written.end());
  }
  else
  {
    report = in.Painter->paint(dabs, falloff, mode, m,
      [this](double done)
      {
        this->UpdateProgress(done);
        return !this->CheckAbort();
      });
  }
  this->ReportPainting(report, first, MillisecondsSince(start));
  return !report.aborted;
}

void vtkMalleabilityPaintFilter::ReportPainting(
  const geoshaping::PaintReport& report, std::size_t first, double milliseconds)
{
  const std::vector<geoshaping::Dab>& dabs = this->Internals->Dabs;
  this->LastPaintMilliseconds = milliseconds;
  this->NumberOfAppliedDabs = static_cast<int>(report.applied);
  this->NumberOfRejectedDabs = static_cast<int>(report.rejected.size());
  this->NumberOfPaintedValues = static_cast<vtkIdType>(report.painted);
  if (report.rejected.empty())
  {
    return;
  }
  std::ostringstream msg;
  msg << report.rejected.size() << " of " << dabs.size() - first
      << " dabs were skipped (the others are applied):";
  const std::size_t shown = std::min<std::size_t>(report.rejected.size(), 10);
  for (std::size_t i = 0; i < shown; ++i)
  {
    const std::size_t k = first + report.rejected[i].first;
    const geoshaping::Dab& d = dabs[k];
    msg << "\n  dab " << k << " (" << d.center.x() << " " << d.center.y() << " " << d.center.z()
        << " " << d.radius << " " << d.value << " " << d.strength
        << "): " << report.rejected[i].second;
  }
  if (shown < report.rejected.size())
    msg << "\n  ...";
  vtkErrorMacro(<< msg.str());
}

void vtkMalleabilityPaintFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MalleabilityArrayName: "
     << (this->MalleabilityArrayName ? this->MalleabilityArrayName : "(none)") << "\n";
  os << indent << "InitialMalleability: " << this->InitialMalleability << "\n";
  os << indent << "NumberOfDabs: " << this->Internals->Dabs.size() << "\n";
  os << indent
     << "Falloff: " << geoshaping::falloff_name(static_cast<geoshaping::Falloff>(this->Falloff))
     << "\n";
  os << indent << "DistanceMode: "
     << geoshaping::distance_mode_name(static_cast<geoshaping::DistanceMode>(this->DistanceMode))
     << "\n";
  os << indent << "PaintPins: " << this->PaintPins << " ("
     << (this->PinnedArrayName ? this->PinnedArrayName : "(none)") << ")\n";
  os << indent << "NumberOfPointDabs: " << this->Internals->PointDabs.size() / 3 << "\n";
  os << indent << "NumberOfRebuilds: " << this->NumberOfRebuilds << "\n";
}
