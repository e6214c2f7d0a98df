#include "bench_scenes.h"

#include <cmath>

namespace geoshaping::bench
{

geoshaping::testing::Mesh painted_grid(index_t n, std::vector<float>& malleability)
{
  auto mesh = geoshaping::testing::triangle_grid(n, n, 1.0);
  malleability.resize(std::size_t(mesh.size()));
  for (index_t j = 0; j < n; ++j)
    for (index_t i = 0; i < n; ++i)
    {
      const double s = 0.5 + 0.5 * std::sin(0.05 * i) * std::cos(0.04 * j);
      malleability[j * n + i] = float(0.3 + 0.08 * std::floor(s * 7.999));
    }
  return mesh;
}

double pull_for_count(ChainMailDeformer& d, index_t grasp, std::size_t target)
{
  const QueueKind saved = d.queue();
  d.set_queue(QueueKind::fifo_priority);
  double lo = 0.0, hi = 1.0;
  while (d.deform(grasp, { 0.0, 0.0, hi }).moved < target && hi < 1e9)
    hi *= 2.0;
  for (int it = 0; it < 60; ++it)
  {
    const double mid = 0.5 * (lo + hi);
    (d.deform(grasp, { 0.0, 0.0, mid }).moved < target ? lo : hi) = mid;
  }
  const std::size_t at_lo = d.deform(grasp, { 0.0, 0.0, lo }).moved;
  const std::size_t at_hi = d.deform(grasp, { 0.0, 0.0, hi }).moved;
  d.set_queue(saved);
  d.reset();
  return (target - at_lo < at_hi - target) ? lo : hi;
}

std::vector<std::uint8_t> moved_mask(const ChainMailDeformer& d)
{
  std::vector<std::uint8_t> mask(std::size_t(d.size()), 0);
  for (index_t v : d.moved())
    mask[std::size_t(v)] = 1;
  return mask;
}

std::size_t bfs_floor(const Adjacency& adj, index_t grasp, const std::vector<std::uint8_t>& region,
  std::vector<std::uint32_t>& mark, std::uint32_t stamp, std::vector<index_t>& queue)
{
  queue.clear();
  queue.push_back(grasp);
  mark[grasp] = stamp;
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    const index_t v = queue[head];
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      if (mark[*n] != stamp && region[*n])
      {
        mark[*n] = stamp;
        queue.push_back(*n);
      }
  }
  return queue.size();
}

} // namespace geoshaping::bench
