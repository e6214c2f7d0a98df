#include "bench_scenes.h"

#include "geoshaping/paint/brush.h"

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

std::vector<float> brush_painted(
  const double* xyz, index_t n, const Adjacency& adjacency, double x0, double y0, double size)
{
  struct Stroke
  {
    double from[2], to[2], radius, value, strength; // fractions of `size`, except the last two
  };
  // A soft channel across, a rigid bar and a stiff patch over it, soft and stiff dabs.
  const Stroke strokes[] = {
    { { 0.05, 0.45 }, { 0.95, 0.55 }, 0.12, 1.0, 0.9 },
    { { 0.30, 0.10 }, { 0.35, 0.90 }, 0.05, 0.0, 1.0 },
    { { 0.60, 0.20 }, { 0.80, 0.35 }, 0.09, 0.2, 0.7 },
    { { 0.15, 0.75 }, { 0.15, 0.75 }, 0.15, 0.8, 0.6 },
    { { 0.70, 0.70 }, { 0.70, 0.70 }, 0.04, 1.0, 1.0 },
    { { 0.55, 0.48 }, { 0.55, 0.48 }, 0.07, 0.0, 0.5 },
    { { 0.40, 0.60 }, { 0.65, 0.62 }, 0.03, 0.2, 1.0 },
  };
  const PointQueries queries = brute_force_queries(xyz, n);
  std::vector<Dab> dabs;
  for (const Stroke& s : strokes)
  {
    const Eigen::Vector2d a(s.from[0], s.from[1]), b(s.to[0], s.to[1]);
    const int steps = 1 + int(std::ceil((b - a).norm() / (0.5 * s.radius)));
    for (int k = 0; k < steps; ++k)
    {
      const Eigen::Vector2d p = a + (b - a) * (steps > 1 ? double(k) / (steps - 1) : 0.0);
      Dab dab;
      dab.center = { x0 + size * p.x(), y0 + size * p.y(), 0.0 };
      dab.center.z() = xyz[3 * std::size_t(queries.nearest(dab.center)) + 2]; // on the surface
      dab.radius = size * s.radius;
      dab.value = s.value;
      dab.strength = s.strength;
      dabs.push_back(dab);
    }
  }
  std::vector<float> m(std::size_t(n), 0.5f);
  Painter painter(xyz, n, &adjacency, queries);
  painter.paint(dabs, Falloff::smooth, DistanceMode::euclidean, m.data());
  return m;
}

double pull_for_count(ChainMailDeformer& d, index_t grasp, std::size_t target, QueueKind queue)
{
  const QueueKind saved = d.queue();
  d.set_queue(queue);
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
