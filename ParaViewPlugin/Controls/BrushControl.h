#pragma once
// The brush of the Haptics dock fitted to the data, free of Qt, VTK and ParaView so that
// it is unit tested (Testing/GUI/TestBrushControl.cpp): the default radius, the scene's
// length unit, the cursor's size on screen, and what to tell when dabs reach nothing.
#include <cstddef>
#include <string>
#include <vector>

namespace geoshaping::interactor
{

// The default brush radius: 3 % of the diagonal of the data's bounding box
// (xmin xmax ymin ymax zmin zmax), so a brush covers a few per cent of the surface at any
// scale: 42.4 km on a 1,000 km square, 1.5 on the 50-unit fault-step horizon. 0 for
// empty or non-finite bounds (VTK's uninitialised bounds have min > max).
constexpr double default_radius_fraction = 0.03;
double default_brush_radius(const double bounds[6]);

// The scene's length unit, from what the readers put in the field data: the GOCAD TSurf
// reader's AxisUnit strings (x, y, z: the x and y units when they agree, "m" for
// m/meter/metre/meters/metres), or "m" when the data has a Projection (the DEM surfaces
// are in metres, UTM or the raster's projected CRS). "" when unknown.
std::string scene_unit(const std::vector<std::string>& axis_units, bool has_projection);

// A length for the dock, three significant digits and the unit: "42.4 km" (metres of
// 1,000 and more read as km), "5 m", "0.25 ft", "1.5 scene units" for an unknown unit.
std::string format_length(double length, const std::string& unit);

// What the dock says of the brush radius: its length and whether it is the default (3 %
// of the data's diagonal) or set for this surface (kept in the state), and when the data
// names no unit, that it does. `fitted` false (no surface to fit yet): only that the brush
// will fit the data, without a length or unit.
std::string radius_about(double radius, const std::string& unit, bool is_default, bool fitted);

// The brush cursor's radius: the brush's, but at least `min_pixels` pixels on screen
// (`scene_per_pixel`: the scene length of one pixel at the cursor), so a brush smaller
// than a pixel still shows where it paints.
constexpr double min_cursor_pixels = 4.0;
double cursor_radius(double brush_radius, double scene_per_pixel);

// What the dock says after a stroke: how many dabs were stored, and when some reached no
// vertex (not stored), why, with the distance to the nearest vertex when known (< 0: not
// known, e.g. the dab was beyond the data's bounds).
struct StrokeOutcome
{
  std::size_t stored = 0;
  std::size_t unreached = 0;
  double nearest = -1.0; // the least distance from an unreached dab to a vertex

  // One more dab that reached no vertex, `distance` from the nearest (< 0: not known).
  void add_unreached(double distance);
  void add(const StrokeOutcome& other);
};
std::string stroke_note(const StrokeOutcome& outcome, double radius, const std::string& unit);

} // namespace geoshaping::interactor
