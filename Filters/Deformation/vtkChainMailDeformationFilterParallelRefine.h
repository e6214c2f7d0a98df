// Private to the GeoShaping::FiltersDeformation module: refinement on distributed data
// (docs/mpi.md, "Refinement on distributed data").
#ifndef vtkChainMailDeformationFilterParallelRefine_h
#define vtkChainMailDeformationFilterParallelRefine_h

#include "geoshaping/parallel/partitioned_envelope.h"
#include "geoshaping/passes/frame_passes.h"

#include <cstdint>
#include <memory>

namespace vtkChainMailDeformationFilterDetail
{
struct PartitionedRefinement
{
  geoshaping::ProjectionReport report;
  std::size_t refined = 0;    // points the refinement changed, all processes (each once)
  std::size_t supersteps = 0; // of its label-correcting runs
  double milliseconds = 0.0;
};

// Collective: the envelope refinement (Axes region) of the frame `deformer` holds on this
// piece, through `passes` (its result is read as a single process's is: passes.beyond(),
// FinalDisplacement). `envelope` is set up on first use (reset it when the partition
// changes). Equal to one process's refinement bit for bit (partitioned_envelope.h).
PartitionedRefinement RefinePartitioned(geoshaping::FramePasses& passes,
  const geoshaping::ChainMailDeformer& deformer,
  std::shared_ptr<geoshaping::PartitionedEnvelope>& envelope, std::int64_t grasp,
  const geoshaping::ProjectionOptions& options, geoshaping::Exchange& exchange);
} // namespace vtkChainMailDeformationFilterDetail

#endif
