#include "geoshaping/metrics/error_metrics.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping
{

namespace
{
// A non-finite metric term (a NaN coordinate somewhere) reports as +Inf: std::max would
// drop or keep a NaN depending on the order of the edges.
double finite_or_inf(double x)
{
  return std::isnan(x) ? std::numeric_limits<double>::infinity() : x;
}

double rigid_term(const LinkMesh& m, const Displacements& u, index_t i, index_t j)
{
  if (!m.rigid[std::size_t(i)] || !m.rigid[std::size_t(j)])
    return 0.0;
  return finite_or_inf((u[std::size_t(i)] - u[std::size_t(j)]).norm());
}

double link_term(const LinkMesh& m, const Displacements& u, index_t i, index_t j)
{
  return std::max(link_distance(m, u, i, j), link_distance(m, u, j, i));
}

// Max of `term` over the undirected edges, each visited once.
template<class Term>
double max_over_edges(const LinkMesh& m, Term term)
{
  const Adjacency& adj = *m.adjacency;
  double worst = 0.0;
  for (index_t v = 0; v < adj.size(); ++v)
    for (const index_t* n = adj.begin(v); n != adj.end(v) && *n < v; ++n)
      worst = std::max(worst, term(v, *n));
  return worst / m.scale();
}

// Max of `term` over the edges with an end in `vertices` (some visited twice: harmless
// for a max).
template<class Term>
double max_over_edges(const LinkMesh& m, const std::vector<index_t>& vertices, Term term)
{
  const Adjacency& adj = *m.adjacency;
  double worst = 0.0;
  for (index_t v : vertices)
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      worst = std::max(worst, term(v, *n));
  return worst / m.scale();
}

void accumulate(const Displacements& u, const Displacements& r, index_t v, double& worst,
  double& sum, std::size_t& count)
{
  const Eigen::Vector3d& a = u[std::size_t(v)];
  const Eigen::Vector3d& b = r[std::size_t(v)];
  if (a.isZero(0.0) && b.isZero(0.0))
    return;
  const double d = finite_or_inf((a - b).norm());
  worst = std::max(worst, d);
  sum += d * d;
  ++count;
}

ReferenceError finish(const LinkMesh& m, double worst, double sum, std::size_t count)
{
  ReferenceError e;
  if (count == 0)
    return e;
  e.max = worst / m.scale();
  e.rms = std::sqrt(sum / double(count)) / m.scale();
  return e;
}
} // namespace

LinkMesh link_mesh(const ChainMailDeformer& d)
{
  LinkMesh m;
  m.adjacency = &d.adjacency();
  const std::size_t n = std::size_t(d.size());
  m.rest.resize(n);
  m.params.resize(n);
  m.rigid.resize(n);
  bool any_pin = false;
  for (index_t v = 0; v < d.size(); ++v)
  {
    m.rest[v] = d.rest_local(v);
    m.params[v] = d.params(v);
    m.rigid[v] = d.malleability(v) == 0.0f;
    any_pin = any_pin || d.pinned(v);
  }
  if (any_pin)
  {
    m.pinned.resize(n);
    for (index_t v = 0; v < d.size(); ++v)
      m.pinned[v] = d.pinned(v);
  }
  m.mean_edge = mean_edge_length(m.rest, d.adjacency());
  m.frame = d.valid_region_frame();
  return m;
}

LinkMesh link_mesh(const std::vector<Eigen::Vector3d>& rest, const Adjacency& adjacency,
  const std::vector<double>& malleability, const TransferFunction& tf)
{
  LinkMesh m;
  m.adjacency = &adjacency;
  m.rest = rest;
  m.params.resize(rest.size());
  m.rigid.resize(rest.size());
  for (std::size_t v = 0; v < rest.size(); ++v)
  {
    const double clean = clean_malleability(malleability[v]);
    m.params[v] = tf(clean);
    m.rigid[v] = clean == 0.0;
  }
  m.mean_edge = mean_edge_length(rest, adjacency);
  return m;
}

Displacements displacements(const ChainMailDeformer& d)
{
  Displacements u(std::size_t(d.size()));
  for (index_t v = 0; v < d.size(); ++v)
    u[v] = d.displacement(v);
  return u;
}

double mean_edge_length(const std::vector<Eigen::Vector3d>& rest, const Adjacency& adj)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (index_t v = 0; v < adj.size(); ++v)
    for (const index_t* n = adj.begin(v); n != adj.end(v) && *n < v; ++n)
    {
      const double len = (rest[std::size_t(v)] - rest[std::size_t(*n)]).norm();
      if (!std::isfinite(len))
        continue;
      sum += len;
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

double link_distance(const LinkMesh& m, const Displacements& u, index_t c, index_t s)
{
  const Eigen::Vector3d o = m.rest[std::size_t(c)] - m.rest[std::size_t(s)];
  if (!o.allFinite())
    return 0.0;
  const Eigen::Vector3d r = u[std::size_t(c)] - u[std::size_t(s)];
  return finite_or_inf(region_distance(m.frame, o, m.params[std::size_t(c)], r));
}

double rigid_error(const LinkMesh& m, const Displacements& u)
{
  return max_over_edges(m, [&](index_t i, index_t j) { return rigid_term(m, u, i, j); });
}

double rigid_error(const LinkMesh& m, const Displacements& u, const std::vector<index_t>& vertices)
{
  return max_over_edges(m, vertices, [&](index_t i, index_t j) { return rigid_term(m, u, i, j); });
}

double link_error(const LinkMesh& m, const Displacements& u)
{
  return max_over_edges(m, [&](index_t i, index_t j) { return link_term(m, u, i, j); });
}

double link_error(const LinkMesh& m, const Displacements& u, const std::vector<index_t>& vertices)
{
  return max_over_edges(m, vertices, [&](index_t i, index_t j) { return link_term(m, u, i, j); });
}

ReferenceError reference_error(const LinkMesh& m, const Displacements& u, const Displacements& r)
{
  double worst = 0.0, sum = 0.0;
  std::size_t count = 0;
  for (index_t v = 0; v < m.size(); ++v)
    accumulate(u, r, v, worst, sum, count);
  return finish(m, worst, sum, count);
}

ReferenceError reference_error(const LinkMesh& m, const Displacements& u, const Displacements& r,
  const std::vector<index_t>& vertices)
{
  double worst = 0.0, sum = 0.0;
  std::size_t count = 0;
  for (index_t v : vertices)
    accumulate(u, r, v, worst, sum, count);
  return finish(m, worst, sum, count);
}

namespace
{
// Normal (not normalised) of triangle t at positions rest + u.
Eigen::Vector3d triangle_normal(const std::vector<Eigen::Vector3d>& rest,
  const std::vector<index_t>& triangles, const Displacements& u, std::size_t t, bool deformed)
{
  Eigen::Vector3d p[3];
  for (int k = 0; k < 3; ++k)
  {
    const std::size_t v = std::size_t(triangles[3 * t + std::size_t(k)]);
    p[k] = deformed ? Eigen::Vector3d(rest[v] + u[v]) : rest[v];
  }
  return (p[1] - p[0]).cross(p[2] - p[0]);
}

double normal_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b));
}
} // namespace

BendingError bending_error(const std::vector<Eigen::Vector3d>& rest,
  const std::vector<index_t>& triangles, const Displacements& u,
  const std::vector<index_t>& vertices)
{
  const std::size_t n = std::min(rest.size(), u.size());
  std::vector<std::uint8_t> in_region(n, 0);
  for (index_t v : vertices)
    if (v >= 0 && std::size_t(v) < n)
      in_region[std::size_t(v)] = 1;
  // (low end, high end, triangle) of each edge of a triangle inside the region.
  struct Side
  {
    index_t a, b;
    std::size_t t;
    bool operator<(const Side& o) const
    {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : t < o.t;
    }
  };
  std::vector<Side> sides;
  for (std::size_t t = 0; 3 * t + 2 < triangles.size(); ++t)
  {
    const index_t* c = triangles.data() + 3 * t;
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      inside = inside && c[k] >= 0 && std::size_t(c[k]) < n && in_region[std::size_t(c[k])];
    if (!inside)
      continue;
    for (int k = 0; k < 3; ++k)
    {
      const index_t a = c[k], b = c[(k + 1) % 3];
      if (a != b)
        sides.push_back({ std::min(a, b), std::max(a, b), t });
    }
  }
  std::sort(sides.begin(), sides.end());
  BendingError e;
  double sum = 0.0;
  for (std::size_t i = 0; i < sides.size();)
  {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b)
      ++j;
    if (j - i == 2)
    {
      const Eigen::Vector3d r1 = triangle_normal(rest, triangles, u, sides[i].t, false);
      const Eigen::Vector3d r2 = triangle_normal(rest, triangles, u, sides[i + 1].t, false);
      const Eigen::Vector3d d1 = triangle_normal(rest, triangles, u, sides[i].t, true);
      const Eigen::Vector3d d2 = triangle_normal(rest, triangles, u, sides[i + 1].t, true);
      if (!r1.isZero(0.0) && !r2.isZero(0.0) && !d1.isZero(0.0) && !d2.isZero(0.0))
      {
        const double bend = finite_or_inf(std::abs(normal_angle(d1, d2) - normal_angle(r1, r2)));
        e.max = std::max(e.max, bend);
        sum += bend * bend;
        ++e.edges;
      }
    }
    i = j;
  }
  e.rms = e.edges > 0 ? std::sqrt(sum / double(e.edges)) : 0.0;
  return e;
}

double temporal_error(
  const std::vector<Eigen::Vector3d>& drags, const std::vector<Displacements>& frames)
{
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < std::min(drags.size(), frames.size()); ++k)
  {
    const double step = (drags[k + 1] - drags[k]).norm();
    if (!(step > 0.0))
      continue;
    const Displacements& a = frames[k];
    const Displacements& b = frames[k + 1];
    double jump = 0.0;
    for (std::size_t v = 0; v < std::min(a.size(), b.size()); ++v)
      jump = std::max(jump, finite_or_inf((b[v] - a[v]).norm()));
    worst = std::max(worst, jump / step);
  }
  return worst;
}

TemporalError::TemporalError(index_t n)
  : previous_(std::size_t(n), Eigen::Vector3d::Zero())
  , stamp_(std::size_t(n), 0)
{
}

void TemporalError::add_frame(
  const Eigen::Vector3d& drag, const std::vector<index_t>& vertices, const Displacements& values)
{
  if (++frame_ == 0)
  {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    frame_ = 1;
  }
  // The first frame only sets the baseline.
  const double step = started_ ? (drag - previous_drag_).norm() : 0.0;
  started_ = true;
  double jump = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const index_t v = vertices[i];
    jump = std::max(jump, finite_or_inf((values[i] - previous_[v]).norm()));
    stamp_[v] = frame_;
  }
  for (index_t v : previous_vertices_)
    if (stamp_[v] != frame_)
      jump = std::max(jump, finite_or_inf(previous_[v].norm()));
  if (step > 0.0)
    worst_ = std::max(worst_, jump / step);

  for (index_t v : previous_vertices_)
    previous_[v].setZero();
  for (std::size_t i = 0; i < vertices.size(); ++i)
    previous_[vertices[i]] = values[i];
  previous_vertices_ = vertices;
  previous_drag_ = drag;
}

double temporal_error(
  ChainMailDeformer& d, index_t grasp, const std::vector<Eigen::Vector3d>& drags)
{
  TemporalError e(d.size());
  Displacements values;
  for (const Eigen::Vector3d& drag : drags)
  {
    d.deform(grasp, drag);
    values.clear();
    for (index_t v : d.moved())
      values.push_back(d.displacement(v));
    e.add_frame(drag, d.moved(), values);
  }
  return e.value();
}

} // namespace geoshaping
