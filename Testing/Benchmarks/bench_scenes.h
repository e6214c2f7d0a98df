#pragma once
// Scenes for the benchmarks: painted grids and grasps sized to displace a given
// number of vertices (the paper's Table 1 counts).
#include "geoshaping/deform/chainmail_deformer.h"
#include "test_meshes.h"

namespace geoshaping::bench
{

// A square triangle grid of side `n` with malleability painted in 8 levels
// (0.3 ... 0.86, smooth bands), so the FIFO Priority queue holds several buckets.
geoshaping::testing::Mesh painted_grid(index_t n, std::vector<float>& malleability);

// Malleability as a user paints it with the project's Smooth brush (Painter, Euclidean):
// 0.5 everywhere, then strokes and dabs of several radii, values (0, 0.2, 0.8, 1) and
// strengths over the square [0, size]^2 of the xy plane, as fractions of it. A smooth
// falloff leaves many distinct values (tens of thousands on a 1001 x 1001 grid).
std::vector<float> brush_painted(
  const double* xyz, index_t n, const Adjacency& adjacency, double x0, double y0, double size);

// The vertical pull of the centre vertex whose frame under `queue` (FIFO Priority unless
// said) displaces the number of vertices closest to `target` (bisection on the pull);
// returns the pull.
double pull_for_count(ChainMailDeformer& d, index_t grasp, std::size_t target,
  QueueKind queue = QueueKind::fifo_priority);

// The vertices moved by the deformer's last frame as a mask by vertex id (1 = moved).
std::vector<std::uint8_t> moved_mask(const ChainMailDeformer& d);

// A bare breadth-first traversal from the grasp over the vertices of `region` (a
// moved_mask), through the caller's adjacency: the floor any propagation over that
// region must pay. It reads nothing of the deformer, so it measures the same work
// whatever the deformer's internal layout. Returns vertices visited.
std::size_t bfs_floor(const Adjacency& adj, index_t grasp, const std::vector<std::uint8_t>& region,
  std::vector<std::uint32_t>& mark, std::uint32_t stamp, std::vector<index_t>& queue);

} // namespace geoshaping::bench
