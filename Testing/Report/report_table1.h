#pragma once
// The paper's Table 1 at its displaced-vertex counts, the bare BFS floor over the same
// region, and the deformer's memory per vertex.
#include <cstddef>
#include <string>
#include <vector>

namespace geoshaping::report
{

struct Table1Row
{
  std::size_t target = 0;
  std::size_t displaced[4] = {}; // per queue (FIFO, Priority, FIFO Priority, Max Violation)
  double ms[4] = {};             // median frame time per queue
  double bfs_ms = 0.0;           // BFS over the FIFO Priority region
  double paper_ms[3] = {};       // FIFO, Priority, FIFO Priority (Faeth et al., Table 1)
};

struct Table1
{
  std::size_t mesh_vertices = 0;
  std::vector<Table1Row> rows;
  double bytes_per_vertex = 0.0;  // ChainMailDeformer::memory_bytes() / n
  std::size_t large_vertices = 0; // a larger mesh for the same figure
  double large_bytes_per_vertex = 0.0;
};

// `side`: the painted grid's side; `repetitions` frames per variant, interleaved.
Table1 run_table1(int side, int repetitions, bool progress);

} // namespace geoshaping::report
