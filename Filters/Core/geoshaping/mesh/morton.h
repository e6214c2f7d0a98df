#pragma once
// Morton (Z-order) codes: points close in space get close codes, so sorting by code puts
// neighbours close in memory (the deformer's layout) and cutting the sorted order into
// runs gives compact patches (the threaded frame's pieces).
#include <Eigen/Core>

#include <algorithm>
#include <cstdint>

namespace geoshaping
{

// Spreads the low 21 bits of x so that two zero bits separate each (Morton interleave).
inline std::uint64_t spread3(std::uint64_t x)
{
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// The code of p on a 2^21 lattice over the box [lo, lo + extent]; all ones when p is not
// finite (such points sort last).
inline std::uint64_t morton_code(
  const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& extent)
{
  if (!p.allFinite())
    return ~std::uint64_t(0);
  std::uint64_t code = 0;
  for (int i = 0; i < 3; ++i)
  {
    const double f = extent[i] > 0.0 ? (p[i] - lo[i]) / extent[i] : 0.0;
    const auto q = std::uint64_t(std::clamp(f, 0.0, 1.0) * double(0x1fffff));
    code |= spread3(q) << i;
  }
  return code;
}

} // namespace geoshaping
