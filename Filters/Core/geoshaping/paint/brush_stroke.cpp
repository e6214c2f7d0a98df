#include "geoshaping/paint/brush_stroke.h"

#include <algorithm>
#include <cmath>

namespace geoshaping
{

BrushStroke::BrushStroke(double spacing_fraction)
  : spacing_fraction_(std::isfinite(spacing_fraction) && spacing_fraction > 0.0
                        ? std::min(spacing_fraction, 1.0)
                        : default_spacing_fraction)
{
}

void BrushStroke::begin(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>& centres)
{
  active_ = p.allFinite();
  if (!active_)
  {
    return;
  }
  last_ = p;
  since_dab_ = 0.0;
  centres.push_back(p);
}

void BrushStroke::move_to(
  const Eigen::Vector3d& p, double radius, std::vector<Eigen::Vector3d>& centres)
{
  if (!active_ || !p.allFinite())
  {
    return;
  }
  const Eigen::Vector3d step = p - last_;
  const double length = step.norm();
  const double spacing = spacing_fraction_ * radius;
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !std::isfinite(length))
  {
    last_ = p;
    return;
  }
  // Arc lengths along this segment, measured from last_, of the dabs it holds (a
  // radius made smaller mid-stroke can leave the first one due at last_ itself).
  double at = std::max(spacing - since_dab_, 0.0);
  std::size_t placed = 0;
  for (; at <= length && placed < max_dabs_per_move; at += spacing, ++placed)
  {
    centres.push_back(length > 0.0 ? Eigen::Vector3d(last_ + (at / length) * step) : last_);
  }
  since_dab_ = placed < max_dabs_per_move ? length - (at - spacing) : 0.0;
  last_ = p;
}

} // namespace geoshaping
