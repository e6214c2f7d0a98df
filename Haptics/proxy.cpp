#include "geoshaping/haptics/proxy.h"

#include "geoshaping/mesh/triangle_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace geoshaping::haptics
{

namespace
{
constexpr double edge_slack = 1e-9;

// Unit normal of triangle i of the soup, or false if it is degenerate or not finite.
bool unit_normal(const std::vector<Eigen::Vector3d>& soup, std::size_t i, Eigen::Vector3d& n)
{
  n = (soup[i + 1] - soup[i]).cross(soup[i + 2] - soup[i]);
  const double area2 = n.norm();
  if (!(area2 > 0.0) || !std::isfinite(area2))
    return false;
  n /= area2;
  return true;
}
// The point of the soup nearest to x within `reach` (q) and its triangle's unit normal
// (n, either sign); false if no triangle is that near.
bool nearest_within(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& soup,
  double reach, Eigen::Vector3d& q, Eigen::Vector3d& n)
{
  double best = reach * reach;
  bool found = false;
  for (std::size_t i = 0; i + 2 < soup.size(); i += 3)
  {
    Eigen::Vector3d normal;
    if (!unit_normal(soup, i, normal))
      continue;
    const Eigen::Vector3d c = closest_point_on_triangle(x, soup[i], soup[i + 1], soup[i + 2]);
    const double d2 = (x - c).squaredNorm();
    if (d2 <= best)
    {
      best = d2;
      q = c;
      n = normal;
      found = true;
    }
  }
  return found;
}

// Where the segment a -> b leaves the ball (c, r) that a is in (or on): a + t (b - a)
// with t the larger root of |a - c + t (b - a)| = r, clamped to [0, 1].
Eigen::Vector3d exit_point(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double r)
{
  const Eigen::Vector3d u = a - c, w = b - a;
  const double A = w.squaredNorm(), B = u.dot(w), C = u.squaredNorm() - r * r;
  if (!(A > 0.0))
    return a;
  const double t = (-B + std::sqrt(std::max(0.0, B * B - A * C))) / A;
  return a + std::clamp(t, 0.0, 1.0) * w;
}
} // namespace

SegmentHit first_hit(
  const Eigen::Vector3d& o, const Eigen::Vector3d& d, const std::vector<Eigen::Vector3d>& soup)
{
  SegmentHit best;
  for (std::size_t i = 0; i + 2 < soup.size(); i += 3)
  {
    const Eigen::Vector3d& a = soup[i];
    const Eigen::Vector3d e1 = soup[i + 1] - a, e2 = soup[i + 2] - a;
    const Eigen::Vector3d pvec = d.cross(e2);
    const double det = e1.dot(pvec);
    // Parallel to the plane (or degenerate): a sweep along a plane never crosses it.
    if (!(std::abs(det) > 1e-30) || !std::isfinite(det))
      continue;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = o - a;
    const double u = s.dot(pvec) * inv;
    if (u < -edge_slack || u > 1.0 + edge_slack)
      continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = d.dot(q) * inv;
    if (v < -edge_slack || u + v > 1.0 + edge_slack)
      continue;
    const double t = e2.dot(q) * inv;
    if (t < 0.0 || t > best.t || (best.hit && t == best.t))
      continue;
    Eigen::Vector3d n;
    if (!unit_normal(soup, i, n))
      continue;
    best.hit = true;
    best.t = t;
    best.normal = n.dot(d) > 0.0 ? Eigen::Vector3d(-n) : n;
  }
  return best;
}

void ContactProxy::reset()
{
  this->placed_ = false;
  this->planes_ = 0;
  this->has_foot_ = false;
  this->bounded_ = false;
  this->held_ = false;
  this->carried_ = 0.0;
}

void ContactProxy::place(const Eigen::Vector3d& p)
{
  this->reset();
  this->p_ = p;
  this->placed_ = true;
}

Eigen::Vector3d ContactProxy::target(const Eigen::Vector3d& x) const
{
  const Eigen::Vector3d& p = this->p_;
  switch (this->planes_)
  {
    case 0:
      return x;
    case 1:
      return x - (x - p).dot(this->normals_[0]) * this->normals_[0];
    case 2:
    {
      const Eigen::Vector3d u = this->normals_[0].cross(this->normals_[1]).normalized();
      return p + (x - p).dot(u) * u;
    }
    default:
      return p;
  }
}

void ContactProxy::add_plane(const Eigen::Vector3d& n)
{
  for (int i = 0; i < this->planes_; ++i)
  {
    if (n.cross(this->normals_[i]).squaredNorm() < 1e-12 && n.dot(this->normals_[i]) > 0.0)
    {
      this->normals_[i] = n;
      return;
    }
  }
  if (this->planes_ < max_planes)
    this->normals_[this->planes_++] = n;
}

void ContactProxy::update(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& soup,
  double clearance, double reach)
{
  if (!this->placed_)
    this->place(x);
  // The ball the proxy stays in (proxy.h); a small relative slack so that rounding at its
  // boundary, where the proxy starts, does not read as leaving it.
  const Eigen::Vector3d centre = x + this->spring_;
  const double radius = (x - this->last_x_).norm() + this->carried_;
  const double radius2 = radius * radius * (1.0 + 1e-12) + 1e-30;
  this->planes_ = 0;
  this->held_ = false;
  for (int pass = 0; pass < max_passes; ++pass)
  {
    const Eigen::Vector3d goal = this->target(x);
    const Eigen::Vector3d d = goal - this->p_;
    if (d.squaredNorm() <= clearance * clearance * 1e-6)
      break;
    // The sweep looks `clearance` past its goal, so that it never ends on (or within
    // rounding of) a triangle, where the side it came from would be lost.
    const Eigen::Vector3d ahead = d * (1.0 + clearance / d.norm());
    const SegmentHit hit = first_hit(this->p_, ahead, soup);
    // Stop on the triangle, `clearance` off it on the proxy's side; never behind the start.
    Eigen::Vector3d next = goal;
    if (hit.hit)
    {
      const Eigen::Vector3d stop = this->p_ + hit.t * ahead + clearance * hit.normal;
      next = (stop - this->p_).dot(d) > 0.0 ? stop : this->p_;
    }
    if (this->bounded_ && (next - centre).squaredNorm() > radius2)
    {
      this->p_ = exit_point(this->p_, next, centre, radius);
      this->held_ = true;
      break;
    }
    this->p_ = next;
    if (!hit.hit)
    {
      if (this->planes_ == 0)
        break;
      this->normal_ = this->normals_[0];
      this->planes_ = 0;
      continue;
    }
    this->add_plane(hit.normal);
    if (this->planes_ == max_planes)
      break;
  }
  if (this->planes_ > 0)
    this->normal_ = this->normals_[0];
  // Out of passes just after a sweep cleared the planes (a shallow concave crease, where
  // the sweeps zig-zag between its two faces within the clearance): the proxy is on the
  // surface, off the stylus, and still in contact; a tick of zero force would be a step.
  else if ((this->p_ - x).squaredNorm() > clearance * clearance)
    this->held_ = true;
  this->spring_ = this->p_ - x;
  this->last_x_ = x;
  this->carried_ = 0.0;
  this->bounded_ = true;
  this->remember_foot(soup, reach);
}

void ContactProxy::remember_foot(const std::vector<Eigen::Vector3d>& soup, double reach)
{
  Eigen::Vector3d n;
  this->has_foot_ = nearest_within(this->p_, soup, reach, this->foot_, n);
  if (this->has_foot_)
    this->foot_normal_ = n.dot(this->p_ - this->foot_) < 0.0 ? Eigen::Vector3d(-n) : n;
}

void ContactProxy::carry_over(
  std::uint64_t sequence, const std::vector<Eigen::Vector3d>& soup, double reach, double clearance)
{
  if (sequence == this->sequence_)
    return;
  this->sequence_ = sequence;
  if (!this->placed_ || !this->has_foot_)
    return;
  Eigen::Vector3d f, m;
  if (!nearest_within(this->foot_, soup, reach, f, m))
    return;
  if (m.dot(this->foot_normal_) < 0.0)
    m = -m;
  const Eigen::Vector3d before = this->p_;
  this->p_ += f - this->foot_;
  // Only a surface that came through (or onto) the proxy pushes it: one re-sent in place
  // leaves it where it is, even in a fold, where it sits nearer one face than clearance.
  const double h = (this->p_ - f).dot(m);
  if (h < 1e-3 * clearance)
    this->p_ += (clearance - h) * m;
  this->carried_ += (this->p_ - before).norm();
  this->foot_ = f;
  this->foot_normal_ = m;
}

} // namespace geoshaping::haptics
