#pragma once
// The paper's scale: the Table 1 grid pulled until FIFO Priority displaces 29,241
// vertices, as a Scene (with triangles, for the ARAP peer), and the refinement's cost
// there against the ChainMail frame.
#include "report_scenes.h"

#include <string>
#include <vector>

namespace geoshaping::report
{

// The painted `side` x `side` grid of Table 1 (bench_scenes.h), centre grasp, pulled up
// until FIFO Priority displaces the count closest to `target`.
Scene table1_scene(int side, std::size_t target);

struct ScaleRow
{
  std::string solver; // "ADMM to 1e-3 L", "Dykstra 16", ...
  double ms = 0.0;    // median, ChainMail frame + refinement
  double e_link = 0.0;
  int iterations = 0;
  int factorisations = 0;
  std::size_t region = 0;
};

struct ScaleResult
{
  std::size_t displaced = 0;
  double chainmail_ms = 0.0; // FIFO Priority frame, median, same run
  double e_link = 0.0;       // of the ChainMail frame
  std::vector<ScaleRow> rows;
};

// FIFO Priority (Axes) on `scene`, then each refinement; `repetitions` frames each,
// interleaved with the ChainMail frame alone.
ScaleResult run_scale(const Scene& scene, int repetitions);

} // namespace geoshaping::report
