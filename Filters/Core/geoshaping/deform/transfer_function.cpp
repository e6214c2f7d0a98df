#include "geoshaping/deform/transfer_function.h"

#include <algorithm>
#include <cmath>

namespace geoshaping
{

double Curve::operator()(double m) const
{
  switch (shape)
  {
    case CurveShape::linear:
      return at_rigid + (at_soft - at_rigid) * m;
    case CurveShape::smooth:
      return at_rigid + (at_soft - at_rigid) * (m * m * (3.0 - 2.0 * m));
    case CurveShape::step:
      return m < threshold ? at_rigid : at_soft;
    case CurveShape::piecewise:
    {
      if (points.empty())
        return at_rigid + (at_soft - at_rigid) * m;
      if (m <= points.front().first)
        return points.front().second;
      if (m >= points.back().first)
        return points.back().second;
      auto hi = std::upper_bound(points.begin(), points.end(), m,
        [](double x, const std::pair<double, double>& p) { return x < p.first; });
      auto lo = hi - 1;
      const double span = hi->first - lo->first;
      const double u = span > 0.0 ? (m - lo->first) / span : 1.0;
      return lo->second + (hi->second - lo->second) * u;
    }
  }
  return at_rigid;
}

TransferFunction::TransferFunction() = default;

ChainMailParams TransferFunction::operator()(double m) const
{
  m = std::clamp(m, 0.0, 1.0);
  if (m == 0.0)
    return {};
  ChainMailParams p;
  p.stretch = std::max(1.0, stretch(m));
  p.compression = std::clamp(compression(m), 0.0, 1.0);
  p.shear = std::max(0.0, shear(m));
  return p;
}

const char* TransferFunction::validate() const
{
  for (const Curve* c : { &stretch, &compression, &shear })
  {
    if (!std::isfinite(c->at_rigid) || !std::isfinite(c->at_soft) || !std::isfinite(c->threshold))
      return "a transfer curve has a non-finite value";
    for (std::size_t i = 0; i < c->points.size(); ++i)
    {
      if (!std::isfinite(c->points[i].first) || !std::isfinite(c->points[i].second))
        return "a piecewise transfer curve has a non-finite point";
      if (i > 0 && c->points[i].first < c->points[i - 1].first)
        return "the points of a piecewise transfer curve must be sorted by malleability";
    }
  }
  return "";
}

} // namespace geoshaping
