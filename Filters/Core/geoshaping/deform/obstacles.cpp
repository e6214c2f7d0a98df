#include "geoshaping/deform/obstacles.h"

#include "geoshaping/mesh/triangle_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace geoshaping
{

namespace
{
using Vec = Eigen::Vector3d;
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t leaf_size = 4;

// Smaller root s in [0, 1] of A s^2 + B s + C = 0 (A > 0), else inf.
double entry_root(double A, double B, double C)
{
  if (!(A > 0.0))
    return inf;
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0)
    return inf;
  const double s = (-B - std::sqrt(disc)) / (2.0 * A);
  return s >= 0.0 && s <= 1.0 ? s : inf;
}

// First s in [0, 1] at which p + s w enters the r-neighbourhood of triangle (a, b, c),
// p outside it (the decomposition in obstacles.h); inf when it does not.
double triangle_contact(const Vec& p, const Vec& w, const Vec* v, double r)
{
  double tau = inf;
  const Vec n = (v[1] - v[0]).cross(v[2] - v[0]);
  const double nn = n.norm();
  if (nn > 0.0)
  {
    const Vec e = n / nn;
    const double dp = e.dot(p - v[0]), dq = e.dot(p + w - v[0]);
    const double target = dp > 0.0 ? r : -r;
    if (std::abs(dp) > r && (dp > 0.0 ? dq <= r : dq >= -r))
    {
      const double s = (dp - target) / (dp - dq);
      const Vec x = p + s * w;
      bool inside = true;
      for (int i = 0; i < 3; ++i)
        inside = inside && (v[(i + 1) % 3] - v[i]).cross(x - v[i]).dot(n) >= 0.0;
      if (inside)
        tau = std::min(tau, s);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    const Vec& u = v[i];
    const Vec e = v[(i + 1) % 3] - u;
    const double ee = e.squaredNorm();
    const Vec m = p - u;
    if (ee > 0.0)
    {
      const Vec mp = m - (m.dot(e) / ee) * e, wp = w - (w.dot(e) / ee) * e;
      const double s = entry_root(wp.squaredNorm(), 2.0 * mp.dot(wp), mp.squaredNorm() - r * r);
      if (s < tau)
      {
        const double lambda = (m + s * w).dot(e) / ee;
        if (lambda >= 0.0 && lambda <= 1.0)
          tau = s;
      }
    }
    tau = std::min(tau, entry_root(w.squaredNorm(), 2.0 * m.dot(w), m.squaredNorm() - r * r));
  }
  return tau;
}

// Entry and exit of p + s w, s in [0, smax], into the box [lo - r, hi + r]; false when
// it misses.
bool segment_meets_box(
  const Vec& p, const Vec& w, double smax, const Vec& lo, const Vec& hi, double r)
{
  double s0 = 0.0, s1 = smax;
  for (int i = 0; i < 3; ++i)
  {
    const double a = lo[i] - r, b = hi[i] + r;
    if (w[i] == 0.0)
    {
      if (p[i] < a || p[i] > b)
        return false;
      continue;
    }
    double t0 = (a - p[i]) / w[i], t1 = (b - p[i]) / w[i];
    if (t0 > t1)
      std::swap(t0, t1);
    s0 = std::max(s0, t0);
    s1 = std::min(s1, t1);
    if (s0 > s1)
      return false;
  }
  return true;
}
} // namespace

std::string Obstacles::set(const double* xyz, std::size_t n, const std::int64_t* triangles,
  std::size_t num_triangles, const Eigen::Vector3d& origin)
{
  points_.clear();
  tri_.clear();
  order_.clear();
  nodes_.clear();
  for (std::size_t i = 0; i < 3 * num_triangles; ++i)
    if (triangles[i] < 0 || std::size_t(triangles[i]) >= n)
      return "triangle " + std::to_string(i / 3) + " has the point index " +
             std::to_string(triangles[i]) + " outside [0, " + std::to_string(n) + ")";
  for (std::size_t i = 0; i < 3 * n; ++i)
    if (!std::isfinite(xyz[i]))
      return "point " + std::to_string(i / 3) + " is not finite";
  if (num_triangles == 0)
    return "no triangles";

  // Merge equal points (first occurrence wins), then store relative to the origin.
  std::map<std::array<double, 3>, std::int64_t> index;
  std::vector<std::int64_t> merged(n);
  Vec lo = Vec::Constant(inf), hi = Vec::Constant(-inf);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> key{ xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] };
    const auto it = index.emplace(key, std::int64_t(points_.size())).first;
    if (it->second == std::int64_t(points_.size()))
    {
      const Vec x(key[0], key[1], key[2]);
      points_.push_back(x - origin);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    merged[i] = it->second;
  }
  tri_.resize(num_triangles);
  for (std::size_t t = 0; t < num_triangles; ++t)
    for (int k = 0; k < 3; ++k)
      tri_[t][std::size_t(k)] = merged[std::size_t(triangles[3 * t + std::size_t(k)])];
  gap_ = 1e-9 * (hi - lo).norm();
  order_.resize(num_triangles);
  for (std::size_t t = 0; t < num_triangles; ++t)
    order_[t] = std::uint32_t(t);
  nodes_.reserve(2 * num_triangles / leaf_size + 2);
  build(0, std::uint32_t(num_triangles));
  return "";
}

std::int32_t Obstacles::build(std::uint32_t first, std::uint32_t count)
{
  const auto id = std::int32_t(nodes_.size());
  nodes_.emplace_back();
  Vec lo = Vec::Constant(inf), hi = Vec::Constant(-inf), clo = lo, chi = hi;
  auto centre = [this](std::uint32_t t)
  {
    const auto& k = tri_[t];
    return Vec(
      (points_[std::size_t(k[0])] + points_[std::size_t(k[1])] + points_[std::size_t(k[2])]) / 3.0);
  };
  for (std::uint32_t i = first; i < first + count; ++i)
  {
    for (std::int64_t k : tri_[order_[i]])
    {
      lo = lo.cwiseMin(points_[std::size_t(k)]);
      hi = hi.cwiseMax(points_[std::size_t(k)]);
    }
    clo = clo.cwiseMin(centre(order_[i]));
    chi = chi.cwiseMax(centre(order_[i]));
  }
  nodes_[std::size_t(id)].lo = lo;
  nodes_[std::size_t(id)].hi = hi;
  if (count <= leaf_size)
  {
    nodes_[std::size_t(id)].first = first;
    nodes_[std::size_t(id)].count = count;
    return id;
  }
  // Median split of the centres along the longest axis of their box.
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  const std::uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
    order_.begin() + first + count,
    [&](std::uint32_t a, std::uint32_t b) { return centre(a)[axis] < centre(b)[axis]; });
  const std::int32_t left = build(first, half);
  const std::int32_t right = build(first + half, count - half);
  nodes_[std::size_t(id)].left = left;
  nodes_[std::size_t(id)].right = right;
  return id;
}

template<class Visit>
void Obstacles::visit_segment(const Vec& p, const Vec& w, double r, double& best, Visit visit) const
{
  // Depth-first over the nodes whose box grown by r the segment meets before `best`.
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = nodes_[std::size_t(stack[--top])];
    if (!segment_meets_box(p, w, best, node.lo, node.hi, r))
      continue;
    if (node.left < 0)
    {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        visit(order_[i]);
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = node.left;
  }
}

double Obstacles::first_crossing(const Vec& p, const Vec& w, double touch) const
{
  const Vec q = p + w;
  const Vec d = q - p;
  double f = 1.0, reach = 1.0;
  visit_segment(p, w, 0.0, reach,
    [&](std::uint32_t t)
    {
      const auto& k = tri_[t];
      const Vec& a = points_[std::size_t(k[0])];
      const Vec n = (points_[std::size_t(k[1])] - a).cross(points_[std::size_t(k[2])] - a);
      const double sp = n.dot(p - a), sq = n.dot(q - a);
      const double on = touch > 0.0 ? touch * n.norm() : 0.0;
      if (!((sp > on && sq < -on) || (sp < -on && sq > on)))
        return;
      double e[3];
      for (int i = 0; i < 3; ++i)
      {
        const std::int64_t u = k[std::size_t(i)], v = k[std::size_t((i + 1) % 3)];
        const std::int64_t lo = std::min(u, v), hi = std::max(u, v);
        const double value =
          (points_[std::size_t(lo)] - p).cross(points_[std::size_t(hi)] - p).dot(d);
        e[i] = u < v ? value : -value;
      }
      const bool through =
        (e[0] >= 0.0 && e[1] >= 0.0 && e[2] >= 0.0) || (e[0] <= 0.0 && e[1] <= 0.0 && e[2] <= 0.0);
      if (!through)
        return;
      const double t_plane = std::clamp(sp / (sp - sq), 0.0, 1.0);
      f = std::min(f, std::max(0.0, t_plane - gap_ * n.norm() / std::abs(sp - sq)));
    });
  return f;
}

double Obstacles::first_contact(const Vec& p, const Vec& w, double r) const
{
  double tau = 1.0;
  bool hit = false;
  visit_segment(p, w, r, tau,
    [&](std::uint32_t t)
    {
      const auto& k = tri_[t];
      const Vec v[3] = { points_[std::size_t(k[0])], points_[std::size_t(k[1])],
        points_[std::size_t(k[2])] };
      const double s = triangle_contact(p, w, v, r);
      if (s <= tau)
      {
        tau = s;
        hit = true;
      }
    });
  return hit ? tau : 1.0;
}

double Obstacles::admissible_fraction(const Vec& p, const Vec& w, double clearance) const
{
  if (tri_.empty() || w.isZero(0.0))
    return 1.0;
  if (clearance > 0.0 && distance(p) >= clearance)
    return first_contact(p, w, clearance + gap_);
  return first_crossing(p, w);
}

Vec Obstacles::slide(const Vec& p, const Vec& w, double& fraction) const
{
  const auto land = [&](double s)
  {
    Vec x;
    distance(p + s * w, &x);
    return Vec(x - p);
  };
  const auto clear = [&](const Vec& u)
  { return u.isZero(0.0) || first_crossing(p, u, gap_) == 1.0; };
  fraction = 1.0;
  Vec u = land(1.0);
  if (clear(u))
    return u;
  // Rare (a chord through a fold of the surface): bisect between the clear s = 0 and 1.
  double lo = 0.0, hi = 1.0;
  u = land(0.0);
  for (int i = 0; i < 40; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    const Vec m = land(mid);
    if (clear(m))
    {
      lo = mid;
      u = m;
    }
    else
      hi = mid;
  }
  fraction = lo;
  return u;
}

double Obstacles::distance(const Vec& p, Vec* closest) const
{
  if (nodes_.empty())
    return inf;
  double best2 = inf;
  Vec best_point = Vec::Zero();
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  auto box2 = [&p](const Node& node)
  { return (p - p.cwiseMax(node.lo).cwiseMin(node.hi)).squaredNorm(); };
  while (top > 0)
  {
    const Node& node = nodes_[std::size_t(stack[--top])];
    if (box2(node) > best2)
      continue;
    if (node.left < 0)
    {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
      {
        const auto& k = tri_[order_[i]];
        const Vec x = closest_point_on_triangle(
          p, points_[std::size_t(k[0])], points_[std::size_t(k[1])], points_[std::size_t(k[2])]);
        const double d2 = (x - p).squaredNorm();
        if (d2 < best2)
        {
          best2 = d2;
          best_point = x;
        }
      }
      continue;
    }
    // Nearer child last, so it is popped first.
    const std::int32_t a = node.left, b = node.right;
    const bool a_nearer = box2(nodes_[std::size_t(a)]) <= box2(nodes_[std::size_t(b)]);
    stack[top++] = a_nearer ? b : a;
    stack[top++] = a_nearer ? a : b;
  }
  if (closest)
    *closest = best_point;
  return std::sqrt(best2);
}

std::size_t Obstacles::memory_bytes() const
{
  return points_.capacity() * sizeof(Vec) + tri_.capacity() * sizeof(tri_[0]) +
         order_.capacity() * sizeof(std::uint32_t) + nodes_.capacity() * sizeof(Node);
}

} // namespace geoshaping
