#pragma once
// The report on distributed data (docs/mpi.md): each scene split into
// 1-4 pieces with one ghost ring (slabs along x, and random owners), ChainMail run by the
// partitioned core (partitioned_chainmail.h) with one thread per piece exchanging through
// InProcessExchange (the stand-in for mpiexec -n pieces), every piece's owned
// displacements gathered, and the errors measured on that gathered output, not on the
// single-process run; `identical` says whether it equals the single process bit for bit.
#include "report_scenes.h"

#include "geoshaping/deform/valid_region.h"

#include <ostream>
#include <string>
#include <vector>

namespace geoshaping::report
{

struct DistributedRow
{
  ValidRegionFrame frame = ValidRegionFrame::axes;
  std::string partition; // "one process", "2 slabs", "3 random", ...
  int pieces = 1;        // 0: the single process (ChainMailDeformer on the whole mesh)
  bool identical = true; // every vertex's displacement and moved flag, bit for bit
  std::size_t displaced = 0;
  double e_rigid = 0.0, e_link = 0.0, e_temporal = 0.0;
  std::size_t supersteps = 0; // of the frame at the scene's pull
  std::size_t rounds = 0;     // its synchronisations (pieces run ahead alone)
  double bytes_per_frame = 0; // sent by all pieces, mean over the drag's frames
  double median_ms = 0.0;     // frame at the scene's pull, wall clock on piece 0
};

// FIFO Priority in both valid-region shapes; global ids are the vertex ids.
std::vector<DistributedRow> run_distributed(const Scene& scene, int repetitions, int drag_steps);

struct DistributedScene
{
  std::string title;
  std::vector<DistributedRow> rows;
};
// Whether every partitioned run equalled the single process (the report fails if not).
bool all_identical(const std::vector<DistributedScene>& scenes);
// The report.md section "On distributed data".
void write_distributed(std::ostream& md, const std::vector<DistributedScene>& scenes);

} // namespace geoshaping::report
