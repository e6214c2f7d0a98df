#include "vtkMalleabilityPaintFilter.h"

#include "vtkFloatArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkSparseArrayChanges.h"
#include "vtkSparsePointChanges.h"
#include "vtkStaticPointLocator.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/brush.h"
#include "geoshaping/transfer_function.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMalleabilityPaintFilter);

namespace
{
bool SameDab(const geoshaping::Dab& a, const geoshaping::Dab& b)
{
  return a.center == b.center && a.radius == b.radius && a.value == b.value &&
         a.strength == b.strength;
}
} // namespace

struct vtkMalleabilityPaintFilter::vtkInternals
{
  // The last painted output (shallow): what an aborted painting leaves in place, since
  // the executive empties the output before each execution.
  vtkSmartPointer<vtkPointSet> LastOutput;
  void KeepOutput(vtkPointSet* output)
  {
    this->LastOutput = vtk::TakeSmartPointer(output->NewInstance());
    this->LastOutput->ShallowCopy(output);
  }
  std::vector<geoshaping::Dab> Dabs;
  std::vector<double> PointDabs; // id value weight

  // Geometry the locator, points and adjacency were built from.
  vtkPoints* GeometryPoints = nullptr;
  vtkIdType GeometrySize = -1;
  vtkMTimeType GeometryTime = 0;
  bool GeometryValid = false;
  std::vector<double> Xyz;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  bool AdjacencyValid = false;
  geoshaping::Adjacency Adjacency;

  // The last painted array, what it was painted from (input geometry, source array,
  // settings) and the dabs applied to it: an update that only appends dabs continues it.
  vtkSmartPointer<vtkFloatArray> Painted;
  std::vector<std::uintptr_t> PaintedFrom;
  std::vector<geoshaping::Dab> AppliedDabList;
  std::vector<double> AppliedPointDabs;

  // What the painted array was painted from, apart from the dabs.
  static std::vector<std::uintptr_t> Signature(
    vtkPointSet* input, vtkMalleabilityPaintFilter* self, const char* name);

  // Rebuilds what depends on the geometry when it changed; false on bad points.
  bool Update(vtkPointSet* input, vtkMalleabilityPaintFilter* self);
  geoshaping::PointQueries Queries();
};

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
    this->Locator->SetDataSet(input);
    this->Locator->BuildLocator();
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

geoshaping::PointQueries vtkMalleabilityPaintFilter::vtkInternals::Queries()
{
  vtkStaticPointLocator* locator = this->Locator;
  geoshaping::PointQueries q;
  q.nearest = [locator](const Eigen::Vector3d& p)
  { return geoshaping::index_t(locator->FindClosestPoint(p.data())); };
  auto found = vtkSmartPointer<vtkIdList>::New();
  q.within = [locator, found](
               const Eigen::Vector3d& p, double r, std::vector<geoshaping::index_t>& ids)
  {
    // A hair wider than asked: the core keeps exactly those within r by its own test.
    locator->FindPointsWithinRadius(r * (1.0 + 1e-9), p.data(), found);
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
    return 1;
  }
  if (this->PaintPins && this->MalleabilityArrayName &&
      strcmp(name, this->MalleabilityArrayName) == 0)
  {
    vtkErrorMacro("PaintPins would overwrite the malleability array '"
                  << name << "' with a pin mask: give PinnedArrayName another name; output "
                  << "is the input.");
    return 1;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  if (n > vtkIdType(std::numeric_limits<geoshaping::index_t>::max()))
  {
    vtkErrorMacro("Input has " << n << " points; painting supports at most 2^31 - 1.");
    return 1;
  }

  if (!this->PaintPins && this->PaintIncrementally(input, output, name))
  {
    ++this->NumberOfIncrementalUpdates;
    this->Internals->KeepOutput(output);
    return 1;
  }

  // The array to paint: a clamped float copy of the input's, or InitialMalleability.
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
  if (source && source->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("Point array '" << name << "' has " << source->GetNumberOfTuples()
                                  << " values for " << n << " points; output is the input.");
    return 1;
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
  if (!this->ApplyDabs(input, m))
  {
    // Keep what was shown: the executive would otherwise empty the output on an abort.
    output->ShallowCopy(this->Internals->LastOutput ? this->Internals->LastOutput.Get()
                                                    : static_cast<vtkPointSet*>(input));
    this->SetAbortOutput(false);
    this->SetAbortExecute(0);
    vtkErrorMacro("Painting was aborted after "
                  << this->NumberOfAppliedDabs << " of " << this->Internals->Dabs.size()
                  << " dabs; the output is the previous one (change a property to paint again).");
    return 1;
  }
  this->ApplyPointDabs(n, m);
  if (this->PaintPins)
  {
    vtkNew<vtkUnsignedCharArray> pins;
    pins->SetName(name);
    pins->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      pins->SetValue(i, m[i] >= 0.5f ? 1 : 0);
    output->GetPointData()->AddArray(pins);
  }
  else
  {
    output->GetPointData()->AddArray(malleability);
    output->GetPointData()->SetActiveScalars(name);
    vtkInternals& in = *this->Internals;
    // Recording from the start: consumers see the same rule on every later update.
    vtkSparseArrayChanges::ValuesChanged(malleability, nullptr, 0);
    in.Painted = malleability;
    in.PaintedFrom = in.Signature(input, this, name);
    in.AppliedDabList = in.Dabs;
    in.AppliedPointDabs = in.PointDabs;
  }
  this->Internals->KeepOutput(output);
  return 1;
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
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0 || first >= in.Dabs.size() || !in.Update(input, this))
  {
    return true;
  }
  const auto mode = static_cast<geoshaping::DistanceMode>(this->DistanceMode);
  if (mode == geoshaping::DistanceMode::geodesic && !in.AdjacencyValid)
  {
    vtkIdType skipped = 0;
    in.Adjacency = vtkGeoShapingAdapter::BuildAdjacency(input, skipped);
    in.AdjacencyValid = true;
    if (skipped > 0)
    {
      vtkWarningMacro(<< skipped
                      << " cells are of an unsupported type or have invalid point "
                         "ids; geodesic paths do not follow their edges.");
    }
  }

  const auto start = std::chrono::steady_clock::now();
  geoshaping::Painter painter(in.Xyz.data(), geoshaping::index_t(n), &in.Adjacency, in.Queries());
  const std::vector<geoshaping::Dab> dabs(in.Dabs.begin() + std::ptrdiff_t(first), in.Dabs.end());
  if (touched)
  {
    geoshaping::Reach reach;
    for (const geoshaping::Dab& dab : dabs)
    {
      if (*geoshaping::validate_dab(dab) == '\0')
      {
        painter.reach(dab, mode, reach);
        touched->insert(touched->end(), reach.vertices.begin(), reach.vertices.end());
      }
    }
  }
  const geoshaping::PaintReport report =
    painter.paint(dabs, static_cast<geoshaping::Falloff>(this->Falloff), mode, m,
      touched ? geoshaping::Progress() // appended dabs: a few, painted in place
              : [this](double done)
      {
        this->UpdateProgress(done);
        return !this->CheckAbort();
      });
  this->LastPaintMilliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->NumberOfAppliedDabs = static_cast<int>(report.applied);
  this->NumberOfRejectedDabs = static_cast<int>(report.rejected.size());
  this->NumberOfPaintedValues = static_cast<vtkIdType>(report.painted);
  if (!report.rejected.empty())
  {
    std::ostringstream msg;
    msg << report.rejected.size() << " of " << dabs.size()
        << " dabs were skipped (the others are applied):";
    const std::size_t shown = std::min<std::size_t>(report.rejected.size(), 10);
    for (std::size_t i = 0; i < shown; ++i)
    {
      const geoshaping::Dab& d = dabs[report.rejected[i].first];
      msg << "\n  dab " << first + report.rejected[i].first << " (" << d.center.x() << " "
          << d.center.y() << " " << d.center.z() << " " << d.radius << " " << d.value << " "
          << d.strength << "): " << report.rejected[i].second;
    }
    if (shown < report.rejected.size())
      msg << "\n  ...";
    vtkErrorMacro(<< msg.str());
  }
  return !report.aborted;
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
