#pragma once
// The Generalized ChainMail valid region (the deformation contract, docs/design.md).
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/mesh/enum_names.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping
{

// Which shape the valid region has (docs/deformer.md, "Valid-region shape"):
// - axes: the paper's box, aligned with the coordinate axes (default). Its shape depends
//   on how the link is oriented: a link at 45 degrees gets a shear allowance
//   h (|o_x| + |o_y|) = sqrt(2) h |o| per axis, one along an axis h |o|, so on a
//   triangle grid a pull spreads as a diamond and rotating the mesh changes the result.
// - link: a cylinder around the rest link (link_displacement_projection below),
//   the same whatever the orientation: rotating the mesh and the grasp displacement
//   rotates the result.
enum class ValidRegionFrame
{
  axes = 0,
  link = 1
};

inline const char* frame_name(ValidRegionFrame f)
{
  static constexpr EnumName names[] = { { int(ValidRegionFrame::axes), "Axes" },
    { int(ValidRegionFrame::link), "Link" } };
  return name_of(names, int(f));
}

// Valid region of a candidate c w.r.t. its sponsor s, for the rest offset
// o = x0[c] - x0[s] and the candidate's own (t, k, h); per axis i, S_i = sum_{j!=i} |o_j|:
//
//   o_i >= 0:  lo_i = k o_i - h S_i,   hi_i = t o_i + h S_i
//   o_i <  0:  lo_i = t o_i - h S_i,   hi_i = k o_i + h S_i
//   box = x[s] + [lo, hi]
//
// The deformer works on displacements u = x - x0, so it needs the box shifted by -o:
//   u[c] in u[s] + [lo - o, hi - o],
// with lo - o = (k - 1) o_i - h S_i etc. For a rigid vertex (t = k = 1, h = 0) both
// bounds are exactly zero, so u[c] == u[s] bit for bit: rigid regions translate exactly.
struct Box
{
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;

  Eigen::Vector3d clamp(const Eigen::Vector3d& p) const { return p.cwiseMax(lo).cwiseMin(hi); }
};

// What the region formulas below use of a candidate's (t, k, h): t - 1, k - 1 and h.
// The deformer evaluates them once per malleability value (region_params) and passes
// them to the same functions, so its boxes and projections are these, bit for bit.
struct RegionParams
{
  double stretch_minus_1;     // t - 1
  double compression_minus_1; // k - 1
  double shear;               // h
  // t = k = 1, h = 0: the region is the single point w = 0.
  bool rigid() const
  {
    return stretch_minus_1 == 0.0 && compression_minus_1 == 0.0 && shear == 0.0;
  }
};

inline RegionParams region_params(const ChainMailParams& p)
{
  return { p.stretch - 1.0, p.compression - 1.0, p.shear };
}

// Axis i of the box below: o_i and s_i = sum_{j!=i} |o_j| give [lo, hi]. Written without
// a branch on the sign of o_i (a branch the hot path mispredicts). For parameters in the
// transfer function's domain (t >= 1, k <= 1, so k - 1 <= 0 <= t - 1, each +0 or nonzero)
// near = (k - 1) o_i <= 0 <= far = (t - 1) o_i when o_i >= 0, and the reverse when
// o_i < 0, so the formula's pick (near for lo when o_i >= 0, else far; hi the other) is
// min(near, far) for lo and max(far, near) for hi, bit for bit: on a tie std::min and
// std::max return their first operand, which is the formula's pick for o_i >= 0 (+0 and
// -0 included); for o_i < 0 a tie needs both products zero, and (+0) o_i is -0 for
// both. The one exception is a product that underflows (|o_i| below ~1e-292): then lo or
// hi may be a zero of the other sign, which required_displacement's clamps absorb (a lo
// of either zero is clamped by max(0, .) to +0; a zero hi matters only if
// max(0, u + lo) > 0, i.e. lo > hi, which cannot be).
inline void axis_bounds(double o_i, double s_i, const RegionParams& p, double& lo, double& hi)
{
  const double near = p.compression_minus_1 * o_i; // toward the sponsor (compression)
  const double far = p.stretch_minus_1 * o_i;      // away from the sponsor (stretch)
  lo = std::min(near, far) - p.shear * s_i;
  hi = std::max(far, near) + p.shear * s_i;
}

// Box for the displacement of the candidate relative to the sponsor's displacement.
inline Box displacement_bounds(const Eigen::Vector3d& o, const RegionParams& p)
{
  const Eigen::Vector3d a = o.cwiseAbs();
  const Eigen::Vector3d s(a.y() + a.z(), a.x() + a.z(), a.x() + a.y());
  Box b;
  for (int i = 0; i < 3; ++i)
    axis_bounds(o[i], s[i], p, b.lo[i], b.hi[i]);
  return b;
}

inline Box displacement_bounds(const Eigen::Vector3d& o, const ChainMailParams& p)
{
  return displacement_bounds(o, region_params(p));
}

// The box of the deformation contract (docs/design.md) in positions: x[s] + [lo, hi].
inline Box valid_region(
  const Eigen::Vector3d& sponsor_position, const Eigen::Vector3d& o, const ChainMailParams& p)
{
  Box b = displacement_bounds(o, p);
  b.lo += sponsor_position + o;
  b.hi += sponsor_position + o;
  return b;
}

// The valid region in the frame of the rest link (ValidRegionFrame::link). With
// l = |o| and the unit link direction e = o / l, the candidate's offset
// d = x[c] - x[s] must satisfy
//
//   along the link:   k l <= d.e <= t l            (compression k, stretch t)
//   across the link:  |d - (d.e) e| <= h l         (shear h)
//
// a solid circular cylinder of axis e, length (t - k) l and radius h l around the
// segment [x[s] + k o, x[s] + t o]. It is built from l and e only, so a rotation R of
// the mesh maps the region of o onto the region of R o: rotation invariant. For a link
// along an axis its along-link interval is the box's interval on that axis and its
// radius the box's half-width h l across it (the box's cross-section is the square
// circumscribing the disc). In general the cylinder lies inside the box: along axis i
// a e_i spans [k o_i, t o_i] (or reversed), and p perpendicular to e has
// |p_i| = |p.(x_i - e_i e)| <= h l sqrt(1 - e_i^2) = h sqrt(sum_{j!=i} o_j^2) <= h S_i;
// so a Link result also satisfies the paper's box on its sponsor links. Why a cylinder: it keeps
// the paper's three parameters with their meaning (stretch and compression of the link length,
// shear as sideways slide relative to the link length) and, being a product of an interval and a
// disc in orthonormal coordinates, has a closed-form exact projection.
//
// In displacements w = u[c] - u[s] (d = o + w, and o.e = l, o has no part across e):
//
//   (k - 1) l <= w.e <= (t - 1) l,   |w - (w.e) e| <= h l.
//
// The exact Euclidean projection of a point w: split w = a e + p (a = w.e, p = w - a e);
// the squared distance to the cylinder's point a' e + p' is (a - a')^2 + |p - p'|^2, two
// independent terms, so
//
//   a' = clamp(a, (k - 1) l, (t - 1) l),   p' = p min(1, h l / |p|),   w' = a' e + p'.
//
// When w lies inside the cylinder w' is w itself (returned unchanged, bit for bit), so a
// candidate at rest inside its region stays exactly at rest. "Inside" allows rounding:
// a and |p| may exceed their bounds by tau = 16 eps (|w|_1 + l) (eps = 2^-52), a few
// times the error of computing them. Without it a rest position that lies exactly on a
// thin cylinder (h = 0: a segment; t = k: a disc) would be found off it by the rounding
// of e, a and p whenever the link is not along an axis, move by ~1e-16 and propagate
// such moves through the whole mesh. A rigid vertex
// (t = k = 1, h = 0) or a zero-length link makes the region the single point w = 0, and
// w' = 0 is returned exactly (computing l e would not give back o in floating point), so
// u[c] == u[s] bit for bit: rigid regions translate exactly, as with the box.
//
// `o` must be finite.
inline Eigen::Vector3d link_displacement_projection(
  const Eigen::Vector3d& o, double t_minus_1, double k_minus_1, double h, const Eigen::Vector3d& w)
{
  const double l = o.norm();
  if ((t_minus_1 == 0.0 && k_minus_1 == 0.0 && h == 0.0) || l == 0.0)
    return Eigen::Vector3d::Zero();
  const Eigen::Vector3d e = o / l;
  const double a = w.dot(e);
  const Eigen::Vector3d p = w - a * e;
  const double r2 = p.squaredNorm();
  const double lo = k_minus_1 * l, hi = t_minus_1 * l, radius = h * l;
  const double tau = 16.0 * std::numeric_limits<double>::epsilon() * (w.cwiseAbs().sum() + l);
  if (a >= lo - tau && a <= hi + tau && r2 <= (radius + tau) * (radius + tau))
    return w;
  const double a_in = a < lo ? lo : (a > hi ? hi : a);
  const double r = std::sqrt(r2);
  return r > radius ? Eigen::Vector3d(a_in * e + (radius / r) * p) : Eigen::Vector3d(a_in * e + p);
}

inline Eigen::Vector3d link_displacement_projection(
  const Eigen::Vector3d& o, const ChainMailParams& p, const Eigen::Vector3d& w)
{
  const RegionParams r = region_params(p);
  return link_displacement_projection(o, r.stretch_minus_1, r.compression_minus_1, r.shear, w);
}

// Where the candidate c must move given its sponsor s, in displacements, for either
// frame: the point of the valid region nearest to c's rest position (u[c] = 0), i.e.
// u[s] + the projection of -u[s]. Axes: clamp(0, u[s] + lo - o, u[s] + hi - o)
// per axis (the box above); Link: u[s] + link_displacement_projection(o, -u[s]), and
// exactly u[s] for a rigid vertex. The frame as a template argument is the deformer's
// hot path (with its per-rank parameters); the other overloads are the same code.
template<ValidRegionFrame Frame>
inline Eigen::Vector3d required_displacement(
  const Eigen::Vector3d& o, const RegionParams& p, const Eigen::Vector3d& sponsor_u)
{
  if constexpr (Frame == ValidRegionFrame::axes)
  {
    // clamp(0, u[s] + lo, u[s] + hi) axis by axis, the box's operations in scalars (the
    // deformer's hot path): std::max(0, .) then std::min(., .), the semantics of
    // Eigen's cwiseMax / cwiseMin, signed zeros and NaN included.
    const double ax = std::abs(o.x()), ay = std::abs(o.y()), az = std::abs(o.z());
    const double s[3] = { ay + az, ax + az, ax + ay };
    Eigen::Vector3d r;
    for (int i = 0; i < 3; ++i)
    {
      double lo, hi;
      axis_bounds(o[i], s[i], p, lo, hi);
      r[i] = std::min(std::max(0.0, sponsor_u[i] + lo), sponsor_u[i] + hi);
    }
    return r;
  }
  else
  {
    if (p.rigid())
      return sponsor_u;
    return sponsor_u + link_displacement_projection(
                         o, p.stretch_minus_1, p.compression_minus_1, p.shear, -sponsor_u);
  }
}

inline Eigen::Vector3d required_displacement(ValidRegionFrame frame, const Eigen::Vector3d& o,
  const RegionParams& p, const Eigen::Vector3d& sponsor_u)
{
  return frame == ValidRegionFrame::axes
           ? required_displacement<ValidRegionFrame::axes>(o, p, sponsor_u)
           : required_displacement<ValidRegionFrame::link>(o, p, sponsor_u);
}

inline Eigen::Vector3d required_displacement(ValidRegionFrame frame, const Eigen::Vector3d& o,
  const ChainMailParams& p, const Eigen::Vector3d& sponsor_u)
{
  return required_displacement(frame, o, region_params(p), sponsor_u);
}

// Distance from a displacement difference w = u[c] - u[s] to c's valid region w.r.t. s
// (0 inside), with either region shape.
inline double region_distance(ValidRegionFrame frame, const Eigen::Vector3d& o,
  const ChainMailParams& p, const Eigen::Vector3d& w)
{
  if (frame == ValidRegionFrame::axes)
    return (w - displacement_bounds(o, p).clamp(w)).norm();
  return (w - link_displacement_projection(o, p, w)).norm();
}

} // namespace geoshaping
