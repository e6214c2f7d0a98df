#pragma once
// The brush of the Haptics dock fitted to the data, free of Qt, VTK and ParaView so that
// it is unit tested (Testing/GUI/TestBrushControl.cpp): the default radius, the scene's
// length unit, the cursor's size on screen, what to tell when dabs reach nothing, and the
// dock's undo order of strokes and committed edits.
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

// The dabs one stroke appended to MalleabilityPaint's Dabs and PointDabs lists.
struct Stroke
{
  std::size_t dabs_begin = 0; // the lists' sizes when the stroke began
  std::size_t point_dabs_begin = 0;
  std::vector<double> dabs; // what the stroke appended to each
  std::vector<double> point_dabs;
  bool empty() const { return dabs.empty() && point_dabs.empty(); }
};

// The stroke over lists `dabs`, `point_dabs` that held `dabs_begin`, `point_dabs_begin`
// values when it began.
Stroke stroke_between(const std::vector<double>& dabs, const std::vector<double>& point_dabs,
  std::size_t dabs_begin, std::size_t point_dabs_begin);
// Removes the stroke from the lists; false (lists unchanged) when they no longer end with
// it (changed since, e.g. from Python).
bool remove_stroke(
  const Stroke& stroke, std::vector<double>& dabs, std::vector<double>& point_dabs);
// Appends it again; false (lists unchanged) when they do not hold what they held when the
// stroke began.
bool restore_stroke(
  const Stroke& stroke, std::vector<double>& dabs, std::vector<double>& point_dabs);

// The dock's Undo and Redo order: the user's strokes and committed edits, latest last.
// Undo takes the latest done action (an edit when none is recorded: the deformation's own
// list may hold edits made elsewhere or loaded from a state) and moves it to the redoable
// ones; a new action forgets the redoable ones.
class ActionHistory
{
public:
  enum class Kind
  {
    edit,
    stroke
  };
  void push_edit();
  void push_stroke(Stroke stroke);
  // The action Undo (Redo) acts on; `stroke` is set for a stroke.
  Kind next_undo(const Stroke** stroke = nullptr) const;
  Kind next_redo(const Stroke** stroke = nullptr) const;
  // After Undo (Redo) has been carried out: `done` moves the action over, otherwise it
  // is dropped (it could not be undone: e.g. the edits were reset).
  void undone(bool done);
  void redone(bool done);
  std::size_t strokes() const;
  void clear();

private:
  struct Action
  {
    Kind kind;
    Stroke stroke;
  };
  std::vector<Action> done_;
  std::vector<Action> undone_;
};

} // namespace geoshaping::interactor
