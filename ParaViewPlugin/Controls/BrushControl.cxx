#include "BrushControl.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace geoshaping::interactor
{

double default_brush_radius(const double bounds[6])
{
  double squared = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double low = bounds[2 * axis], high = bounds[2 * axis + 1];
    if (!std::isfinite(low) || !std::isfinite(high) || high < low)
    {
      return 0.0;
    }
    squared += (high - low) * (high - low);
  }
  const double radius = default_radius_fraction * std::sqrt(squared);
  return std::isfinite(radius) ? radius : 0.0;
}

namespace
{
std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}

std::string scene_unit(const std::vector<std::string>& axis_units, bool has_projection)
{
  if (axis_units.size() >= 2 && !axis_units[0].empty() && axis_units[0] == axis_units[1])
  {
    const std::string u = lower(axis_units[0]);
    const char* metre[] = { "m", "meter", "metre", "meters", "metres" };
    return std::find(std::begin(metre), std::end(metre), u) != std::end(metre) ? "m"
                                                                               : axis_units[0];
  }
  return has_projection ? "m" : "";
}

std::string radius_about(double radius, const std::string& unit, bool is_default, bool fitted)
{
  if (!fitted)
  {
    return "Fits the surface once there is one to paint: 3 % of its diagonal";
  }
  std::string about = format_length(radius, unit);
  about +=
    is_default ? ": 3 % of the data's diagonal" : ": set for this surface (kept in the state)";
  return unit.empty() ? about + "; the data names no unit" : about;
}

std::string format_length(double length, const std::string& unit)
{
  std::string u = unit.empty() ? "scene units" : unit;
  if (unit == "m" && std::abs(length) >= 1000.0)
  {
    length /= 1000.0;
    u = "km";
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.3g %s", length, u.c_str());
  return text;
}

double cursor_radius(double brush_radius, double scene_per_pixel)
{
  const double least = min_cursor_pixels * scene_per_pixel;
  if (!std::isfinite(least) || !(least > 0.0))
  {
    return brush_radius;
  }
  return std::isfinite(brush_radius) ? std::max(brush_radius, least) : least;
}

namespace
{
// The smaller of two distances, < 0 meaning not known.
double leastKnown(double a, double b)
{
  return a < 0.0 ? b : (b < 0.0 ? a : std::min(a, b));
}
}

void StrokeOutcome::add_unreached(double distance)
{
  ++unreached;
  nearest = leastKnown(nearest, distance);
}

void StrokeOutcome::add(const StrokeOutcome& other)
{
  stored += other.stored;
  unreached += other.unreached;
  nearest = leastKnown(nearest, other.nearest);
}

std::string stroke_note(const StrokeOutcome& outcome, double radius, const std::string& unit)
{
  if (outcome.unreached == 0)
  {
    return outcome.stored == 0 ? std::string()
                               : "Last stroke: " + std::to_string(outcome.stored) + " dabs.";
  }
  std::string note = outcome.stored == 0
                       ? std::string("Last stroke painted nothing: ")
                       : "Last stroke: " + std::to_string(outcome.stored) + " dabs; ";
  note += std::to_string(outcome.unreached) + (outcome.unreached == 1 ? " dab" : " dabs") +
          " reached no vertex within the brush radius (" + format_length(radius, unit) + ")";
  if (outcome.nearest >= 0.0)
  {
    note += ", the nearest vertex was " + format_length(outcome.nearest, unit) + " away";
  }
  note += ", and " + std::string(outcome.unreached == 1 ? "was" : "were") + " not stored: " +
          (outcome.nearest >= 0.0 ? "enlarge the brush." : "paint on the surface.");
  return note;
}

} // namespace geoshaping::interactor
