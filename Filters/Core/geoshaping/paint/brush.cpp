#include "geoshaping/paint/brush.h"
#include "geoshaping/mesh/enum_names.h"
#include "geoshaping/paint/malleability_preset.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace geoshaping
{

namespace
{
constexpr double infinity = std::numeric_limits<double>::infinity();

constexpr auto distance = brush_distance;
constexpr auto edge_length = brush_edge_length;

} // namespace

const char* falloff_name(Falloff f)
{
  static constexpr EnumName names[] = { { int(Falloff::constant), "Constant" },
    { int(Falloff::linear), "Linear" }, { int(Falloff::smooth), "Smooth" },
    { int(Falloff::gaussian), "Gaussian" } };
  return name_of(names, int(f));
}

const char* distance_mode_name(DistanceMode m)
{
  static constexpr EnumName names[] = { { int(DistanceMode::euclidean), "Euclidean" },
    { int(DistanceMode::geodesic), "Geodesic" } };
  return name_of(names, int(m));
}

double falloff_weight(Falloff f, double r)
{
  if (!(r >= 0.0)) // negative or NaN
    r = 0.0;
  if (r > 1.0)
    return 0.0;
  if (r <= brush_core)
    return 1.0;
  r = (r - brush_core) / (1.0 - brush_core);
  switch (f)
  {
    case Falloff::constant:
      return 1.0;
    case Falloff::linear:
      return 1.0 - r;
    case Falloff::smooth:
      return 1.0 - r * r * (3.0 - 2.0 * r);
    case Falloff::gaussian:
    {
      const double a = 4.5; // 1 / (2 s^2), s = 1/3
      const double rim = std::exp(-a);
      return (std::exp(-a * r * r) - rim) / (1.0 - rim);
    }
  }
  return 0.0;
}

const char* validate_dab(const Dab& dab)
{
  if (!dab.center.allFinite())
    return "its centre is not finite";
  if (!std::isfinite(dab.radius))
    return "its radius is not finite";
  if (dab.radius < 0.0)
    return "its radius is negative";
  if (!(dab.value >= 0.0 && dab.value <= 1.0))
    return "its value is outside [0, 1]";
  if (!(dab.strength >= 0.0 && dab.strength <= 1.0))
    return "its strength is outside [0, 1]";
  return "";
}

void apply_dab(const Dab& dab, Falloff falloff, const Reach& reach, float* m)
{
  if (!(dab.radius > 0.0))
    return;
  for (std::size_t i = 0; i < reach.vertices.size(); ++i)
  {
    const double w = dab.strength * falloff_weight(falloff, reach.distances[i] / dab.radius);
    if (w <= 0.0)
      continue;
    float& v = m[reach.vertices[i]];
    const double next = double(v) + w * (dab.value - double(v));
    v = float(std::clamp(next, 0.0, 1.0));
  }
}

void GeodesicReach::compute(const Adjacency& adjacency, const double* xyz, index_t source,
  double start_distance, double radius, Reach& out)
{
  out.clear();
  for (index_t v : touched_)
    distance_[std::size_t(v)] = infinity;
  touched_.clear();
  heap_.clear();
  if (source < 0 || !(start_distance <= radius))
    return;
  const std::size_t n =
    std::max<std::size_t>(std::size_t(adjacency.size()), std::size_t(source) + 1);
  if (distance_.size() < n)
    distance_.resize(n, infinity);

  const auto later = std::greater<Item>();
  distance_[std::size_t(source)] = start_distance;
  touched_.push_back(source);
  heap_.push_back({ start_distance, source });
  while (!heap_.empty())
  {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Item top = heap_.back();
    heap_.pop_back();
    if (top.distance > distance_[std::size_t(top.vertex)])
      continue; // stale entry: the vertex was settled closer already
    out.vertices.push_back(top.vertex);
    out.distances.push_back(top.distance);
    if (top.vertex >= adjacency.size())
      continue;
    for (const index_t* nb = adjacency.begin(top.vertex); nb != adjacency.end(top.vertex); ++nb)
    {
      const double d = top.distance + edge_length(xyz, top.vertex, *nb);
      double& best = distance_[std::size_t(*nb)];
      if (d <= radius && d < best)
      {
        if (best == infinity)
          touched_.push_back(*nb);
        best = d;
        heap_.push_back({ d, *nb });
        std::push_heap(heap_.begin(), heap_.end(), later);
      }
    }
  }
}

PointQueries brute_force_queries(const double* xyz, index_t n)
{
  PointQueries q;
  q.nearest = [xyz, n](const Eigen::Vector3d& p)
  {
    index_t best = -1;
    double best_d = infinity;
    for (index_t v = 0; v < n; ++v)
    {
      const double d = distance(xyz, v, p);
      if (d < best_d)
      {
        best_d = d;
        best = v;
      }
    }
    return best;
  };
  q.within = [xyz, n](const Eigen::Vector3d& p, double r, std::vector<index_t>& ids)
  {
    ids.clear();
    for (index_t v = 0; v < n; ++v)
      if (distance(xyz, v, p) <= r)
        ids.push_back(v);
  };
  return q;
}

Painter::Painter(const double* xyz, index_t n, const Adjacency* adjacency, PointQueries queries)
  : xyz_(xyz)
  , n_(n)
  , adjacency_(adjacency)
  , queries_(std::move(queries))
{
}

void Painter::reach(const Dab& dab, DistanceMode mode, Reach& out)
{
  out.clear();
  if (n_ == 0 || !(dab.radius > 0.0))
    return;
  if (mode == DistanceMode::euclidean)
  {
    queries_.within(dab.center, dab.radius, ids_);
    // Locators return ids in bin order; sorting keeps the result independent of it.
    std::sort(ids_.begin(), ids_.end());
    for (index_t v : ids_)
    {
      const double d = distance(xyz_, v, dab.center);
      if (d <= dab.radius)
      {
        out.vertices.push_back(v);
        out.distances.push_back(d);
      }
    }
    return;
  }
  const index_t source = queries_.nearest(dab.center);
  if (source < 0)
    return;
  static const Adjacency no_edges;
  geodesic_.compute(adjacency_ ? *adjacency_ : no_edges, xyz_, source,
    distance(xyz_, source, dab.center), dab.radius, out);
}

Eigen::Vector3d malleability_color(double m)
{
  const double* p = malleability_rgb_points;
  const int last = malleability_rgb_point_count - 1;
  m = std::isfinite(m) ? std::clamp(m, p[0], p[4 * last]) : p[0];
  int i = 0;
  while (i < last - 1 && m > p[4 * (i + 1)])
  {
    ++i;
  }
  const double* a = p + 4 * i;
  const double* b = a + 4;
  const double f = b[0] > a[0] ? (m - a[0]) / (b[0] - a[0]) : 0.0;
  return Eigen::Vector3d(a[1], a[2], a[3]) +
         f * Eigen::Vector3d(b[1] - a[1], b[2] - a[2], b[3] - a[3]);
}

bool StrokeAccumulator::continues(const Dab& dab) const
{
  if (!open_ || dab.radius != brush_.radius || dab.value != brush_.value ||
      dab.strength != brush_.strength)
    return false;
  const double step = (dab.center - brush_.center).norm();
  return step > 0.0 && step <= dab.radius;
}

void StrokeAccumulator::begin(const Dab& dab, Falloff falloff)
{
  for (index_t v : members_)
    distance_[std::size_t(v)] = infinity;
  members_.clear();
  open_ = true;
  brush_ = dab;
  falloff_ = falloff;
}

std::size_t StrokeAccumulator::add(const Reach& reach, float* m, std::vector<index_t>* written)
{
  std::size_t first = 0;
  if (!reach.vertices.empty())
  {
    const std::size_t size =
      std::size_t(*std::max_element(reach.vertices.begin(), reach.vertices.end())) + 1;
    if (size > distance_.size())
    {
      distance_.resize(size, infinity);
      base_.resize(size);
    }
  }
  for (std::size_t i = 0; i < reach.vertices.size(); ++i)
  {
    const std::size_t v = std::size_t(reach.vertices[i]);
    double& d = distance_[v];
    if (d == infinity)
    {
      base_[v] = m[v];
      members_.push_back(index_t(v));
      ++first;
    }
    else if (!(reach.distances[i] < d))
      continue;
    d = reach.distances[i];
    if (written)
      written->push_back(index_t(v));
    // apply_dab's expression, from the value before the stroke.
    const double w = brush_.strength * falloff_weight(falloff_, d / brush_.radius);
    const double b = base_[v];
    m[v] = w > 0.0 ? float(std::clamp(b + w * (brush_.value - b), 0.0, 1.0)) : base_[v];
  }
  return first;
}

PaintReport Painter::paint(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode,
  float* malleability, const Progress& progress)
{
  stroke_.end();
  return run(dabs, falloff, mode, malleability, progress, nullptr);
}

PaintReport Painter::append(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode,
  float* malleability, std::vector<index_t>& touched)
{
  return run(dabs, falloff, mode, malleability, {}, &touched);
}

PaintReport Painter::run(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode, float* m,
  const Progress& progress, std::vector<index_t>* touched)
{
  PaintReport report;
  ProgressTicker ticker(progress, dabs.size());
  const bool euclidean = mode == DistanceMode::euclidean;
  if (euclidean && !grid_ && n_ > 0)
    grid_ = std::make_unique<VertexGrid>(xyz_, n_);
  // A Euclidean stroke's centres wait here until the stroke ends, then paint at once.
  centres_.clear();
  const auto flush = [&]
  {
    if (centres_.empty())
      return;
    union_.compute(*grid_, xyz_, centres_, stroke_.brush().radius, falloff != Falloff::constant,
      reach_.vertices, reach_.distances);
    report.painted += stroke_.add(reach_, m, touched);
    centres_.clear();
  };
  for (std::size_t i = 0; i < dabs.size(); ++i)
  {
    const Dab& dab = dabs[i];
    const char* problem = validate_dab(dab);
    if (*problem)
    {
      report.rejected.emplace_back(i, problem);
    }
    else
    {
      if (stroke_.continues(dab))
      {
        stroke_.move(dab.center);
      }
      else
      {
        // A Euclidean stroke is painted whole: progress and a stop come between strokes.
        const bool pending = !centres_.empty();
        flush();
        if (pending && !ticker.tick(i))
        {
          report.aborted = true;
          return report;
        }
        stroke_.begin(dab, falloff);
      }
      ++report.applied;
      if (!euclidean)
      {
        reach(dab, mode, reach_);
        report.painted += stroke_.add(reach_, m, touched);
      }
      else if (n_ > 0 && dab.radius > 0.0)
      {
        centres_.push_back(dab.center);
      }
    }
    if (centres_.empty() && !ticker.tick(i + 1))
    {
      report.aborted = i + 1 < dabs.size();
      return report;
    }
  }
  flush();
  ticker.finish(); // every dab applied: a stop asked now has nothing left to stop
  return report;
}

} // namespace geoshaping
