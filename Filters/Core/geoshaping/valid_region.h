#pragma once
// The Generalized ChainMail valid region (DESIGN.md section 4).
#include "geoshaping/transfer_function.h"

#include <Eigen/Core>

namespace geoshaping
{

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

// Box for the displacement of the candidate relative to the sponsor's displacement.
inline Box displacement_bounds(const Eigen::Vector3d& o, const ChainMailParams& p)
{
  const Eigen::Vector3d a = o.cwiseAbs();
  const Eigen::Vector3d s(a.y() + a.z(), a.x() + a.z(), a.x() + a.y());
  const double t1 = p.stretch - 1.0;
  const double k1 = p.compression - 1.0;
  Box b;
  for (int i = 0; i < 3; ++i)
  {
    const double near = k1 * o[i]; // toward the sponsor (compression)
    const double far = t1 * o[i];  // away from the sponsor (stretch)
    const double lo = o[i] >= 0.0 ? near : far;
    const double hi = o[i] >= 0.0 ? far : near;
    b.lo[i] = lo - p.shear * s[i];
    b.hi[i] = hi + p.shear * s[i];
  }
  return b;
}

// The box of DESIGN.md section 4 in positions: x[s] + [lo, hi].
inline Box valid_region(const Eigen::Vector3d& sponsor_position, const Eigen::Vector3d& o,
  const ChainMailParams& p)
{
  Box b = displacement_bounds(o, p);
  b.lo += sponsor_position + o;
  b.hi += sponsor_position + o;
  return b;
}

} // namespace geoshaping
