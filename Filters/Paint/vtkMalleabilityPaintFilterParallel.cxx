// What vtkMalleabilityPaintFilter does only for geodesic dabs on several processes
// (docs/painting.md, "Distributed data"): the pieces set up (the adapter's set-up, shared
// with ChainMailDeformation) and the dabs painted across them (the core's
// PartitionedGeodesic over the global vtkMultiProcessController).
#include "vtkMalleabilityPaintFilterInternals.h"

#include "vtkDataArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGeoShapingControllerExchange.h"
#include "vtkMultiProcessController.h"
#include "vtkPoints.h"

#include <string>

using namespace vtkMalleabilityPaintFilterDetail;

namespace
{
// What a refusal on several processes leaves.
constexpr const char* NoGeodesicDab = "no geodesic dab is applied on any process.";
} // namespace

bool vtkMalleabilityPaintFilter::Distributed() const
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return this->DistanceMode == GEODESIC && controller && controller->GetNumberOfProcesses() > 1;
}

int vtkMalleabilityPaintFilter::ComputeInputUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::ComputeInputUpdateExtent(request, inputVector, outputVector))
    return 0;
  if (this->Distributed())
  {
    // One ring of ghosts: every neighbour of an owned point is on this process.
    vtkGeoShapingAdapter::RequestGhostRing(inputVector, outputVector);
  }
  return 1;
}

bool vtkMalleabilityPaintFilter::ApplyDabsDistributed(
  vtkPointSet* input, float* m, std::size_t first, std::vector<vtkIdType>* touched)
{
  vtkGeoShapingControllerExchange ex(vtkMultiProcessController::GetGlobalController(), PaintTag);
  if (!this->SetUpPieces(input, ex))
  {
    return true; // refused on every process: no dab is applied
  }
  const auto start = std::chrono::steady_clock::now();
  const geoshaping::PaintReport report = this->PaintPieces(input, m, first, touched, ex);
  this->ReportPainting(report, first, MillisecondsSince(start));
  return true;
}

bool vtkMalleabilityPaintFilter::SetUpPieces(vtkPointSet* input, geoshaping::Exchange& ex)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  // Local checks and whether the piece changed, agreed on by every process.
  vtkDataArray* gids = vtkGeoShapingAdapter::PointGlobalIds(input);
  std::string problem = vtkGeoShapingAdapter::PieceArraysProblem(input);
  const bool stale = !in.Geodesic || in.GeometryPoints != input->GetPoints() ||
                     in.GeometrySize != n ||
                     in.GeometryTime != vtkGeoShapingAdapter::GeometryTime(input) ||
                     in.IdSource != gids || (gids && in.IdTime != gids->GetMTime());
  if (problem.empty() && n > 0 && !in.Update(input, this))
    problem = "non-finite point coordinates";
  if (n == 0)
  {
    // Remembered like any other piece, or it would look changed at every update.
    in.GeometryPoints = input->GetPoints();
    in.GeometrySize = 0;
    in.GeometryTime = vtkGeoShapingAdapter::GeometryTime(input);
  }
  const auto pieces =
    vtkGeoShapingAdapter::AgreeOnPieces(&ex, problem.empty(), stale, n, gids != nullptr);
  if (!problem.empty())
    vtkErrorMacro("Process " << ex.piece() << ": " << problem << "; " << NoGeodesicDab);
  else if (!pieces.Refusal.empty())
    vtkErrorMacro(<< pieces.Refusal << "; " << NoGeodesicDab);
  if (!pieces.Ok)
  {
    in.Geodesic.reset();
    return false;
  }
  return !pieces.AnyChanged || this->SetUpPiece(input, pieces.WithIds, ex);
}

bool vtkMalleabilityPaintFilter::SetUpPiece(
  vtkPointSet* input, bool globalIds, geoshaping::Exchange& ex)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* gids = globalIds ? vtkGeoShapingAdapter::PointGlobalIds(input) : nullptr;
  in.IdSource = gids;
  in.IdTime = gids ? gids->GetMTime() : 0;
  in.IdsFromCoordinates = !gids;
  std::vector<std::uint8_t> owned;
  std::string refusal;
  if (!vtkGeoShapingAdapter::IdentifyPiece(
        input, in.Xyz.data(), globalIds, ex, in.Ids, owned, refusal))
  {
    vtkErrorMacro(<< refusal << "; " << NoGeodesicDab);
    in.Geodesic.reset();
    return false;
  }
  in.Adjacency = {};
  in.Adjacency.offsets.assign(1, 0);
  if (n > 0)
    in.Adjacency = vtkGeoShapingAdapter::BuildAdjacency(this, input, "", GeodesicSkips);
  in.AdjacencyValid = true;
  in.Geodesic = std::make_unique<geoshaping::PartitionedGeodesic>();
  in.Geodesic->set_piece(
    in.Xyz.data(), geoshaping::index_t(n), &in.Adjacency, in.Ids.data(), owned.data(), ex);
  return true;
}

geoshaping::PaintReport vtkMalleabilityPaintFilter::PaintPieces(vtkPointSet* input, float* m,
  std::size_t first, std::vector<vtkIdType>* touched, geoshaping::Exchange& ex)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = input->GetNumberOfPoints();
  const auto falloff = static_cast<geoshaping::Falloff>(this->Falloff);
  geoshaping::Reach reach;
  geoshaping::StrokeAccumulator stroke; // the rule of one process (brush.h)
  std::vector<geoshaping::index_t> written;
  std::int64_t painted = 0;
  geoshaping::PaintReport report;
  for (std::size_t i = first; i < in.Dabs.size(); ++i)
  {
    const geoshaping::Dab& dab = in.Dabs[i];
    const char* why = geoshaping::validate_dab(dab);
    if (*why)
    {
      report.rejected.emplace_back(i - first, why); // the same on every process
      continue;
    }
    in.Geodesic->compute(dab.center, dab.radius, n > 0 ? in.Nearest(dab.center) : -1, reach, ex);
    if (stroke.continues(dab))
      stroke.move(dab.center);
    else
      stroke.begin(dab, falloff);
    written.clear();
    const std::size_t before = stroke.members().size();
    stroke.add(reach, m, &written);
    for (std::size_t k = before; k < stroke.members().size(); ++k)
      painted += in.Geodesic->pieces().owned(stroke.members()[k]);
    if (touched)
      touched->insert(touched->end(), written.begin(), written.end());
    ++report.applied;
  }
  std::int64_t total = 0;
  for (const auto& v : ex.all_gather({ painted }))
    total += v[0];
  report.painted = std::size_t(total);
  return report;
}
