#include "EditControl.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::interactor
{

double falloff_weight(int falloff, double r)
{
  if (!(r >= 0.0))
    r = 0.0;
  if (r > 1.0)
    return 0.0;
  switch (falloff)
  {
    case 0:
      return 1.0;
    case 1:
      return 1.0 - r;
    case 2:
      return 1.0 - r * r * (3.0 - 2.0 * r);
    case 3:
    {
      const double a = 4.5; // 1 / (2 s^2), s = 1/3
      const double rim = std::exp(-a);
      return (std::exp(-a * r * r) - rim) / (1.0 - rim);
    }
    default:
      return 0.0;
  }
}

void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, int falloff, std::vector<double>& triples)
{
  if (!(radius > 0.0) || ids.size() != distances.size())
  {
    return;
  }
  value = std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0;
  strength = std::isfinite(strength) ? std::clamp(strength, 0.0, 1.0) : 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    const double w = strength * falloff_weight(falloff, distances[i] / radius);
    if (ids[i] >= 0 && w > 0.0)
    {
      triples.insert(triples.end(), { double(ids[i]), value, w });
    }
  }
}

} // namespace geoshaping::interactor
