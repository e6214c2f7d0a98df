// Refinement on distributed data: the partitioned envelope (geoshaping/
// partitioned_envelope.h) run through the filter's FramePasses, so the output is written
// as in one process (docs/mpi.md, "Refinement on distributed data").
#include "vtkChainMailDeformationFilterParallelRefine.h"

#include <chrono>

namespace vtkChainMailDeformationFilterDetail
{
PartitionedRefinement RefinePartitioned(geoshaping::FramePasses& passes,
  const geoshaping::ChainMailDeformer& deformer,
  std::shared_ptr<geoshaping::PartitionedEnvelope>& envelope, std::int64_t grasp,
  const geoshaping::ProjectionOptions& options, geoshaping::Exchange& exchange)
{
  const auto start = std::chrono::steady_clock::now();
  PartitionedRefinement out;
  out.report = passes.refine_with(deformer,
    [&](const geoshaping::LinkMesh& mesh, geoshaping::LinkProjector& projector)
    {
      if (!envelope)
      {
        envelope = std::make_shared<geoshaping::PartitionedEnvelope>();
        envelope->set_piece(deformer, mesh, exchange);
      }
      geoshaping::Displacements values;
      values.reserve(deformer.moved().size());
      for (geoshaping::index_t v : deformer.moved())
        values.push_back(deformer.displacement(v));
      const geoshaping::ProjectionReport r =
        envelope->project(mesh, grasp, deformer.moved(), values, options, exchange);
      values.clear();
      for (geoshaping::index_t v : envelope->region())
        values.push_back(envelope->displacements()[std::size_t(v)]);
      projector.assign(envelope->region(), values, envelope->changed());
      return r;
    });
  out.refined = envelope->changed_total();
  out.supersteps = envelope->supersteps();
  out.milliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}
} // namespace vtkChainMailDeformationFilterDetail
