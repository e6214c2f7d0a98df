#pragma once
// A mouse pull, free of Qt, VTK and ParaView so that it is unit tested
// (Testing/GUI/TestPullControl.cpp). The grasp's displacement is the cursor's motion
// carried onto the plane through the grasp parallel to the view plane, as Blender's grab
// and ParaView's handle widgets do: the grasped point keeps its place under the cursor
// whatever the data's scale and the camera. A constraint keeps the pull on a line through
// the grasp (the vertical, or the surface normal there), and can change mid-pull without
// a jump; Shift makes the motion finer.
#include <Eigen/Core>

#include <optional>
#include <string>

namespace geoshaping::interactor
{

// A view's display <-> world conversion: display x, y in pixels (VTK's display
// coordinates, origin at the bottom left) and a depth in [0, 1] from the near to the far
// clipping plane, as vtkRenderer's WorldToDisplay and DisplayToWorld give them.
class ViewProjection
{
public:
  virtual ~ViewProjection() = default;
  virtual Eigen::Vector3d to_display(const Eigen::Vector3d& world) const = 0;
  virtual Eigen::Vector3d to_world(const Eigen::Vector3d& display) const = 0;
};

enum class PullConstraint
{
  view_plane, // free, in the plane through the grasp parallel to the screen
  vertical,   // along the scene's vertical (z) through the grasp: x and y are kept
  normal      // along the surface normal at the grasp
};

// The keys that switch the constraint during a pull (the letter, either case): Z the
// vertical (z, as Blender's grab constrains to an axis), N the surface normal, C the
// cursor (free); the key of the constraint in force frees the pull again (Blender's
// toggle). None of them is a shortcut of ParaView's render view (S, D, F, G, B select,
// V finds data). Another key: none.
std::optional<PullConstraint> constraint_for_key(char key, PullConstraint current);

// What the dock says of the pull mode: the chosen constraint holds for every pull until
// changed; a key's constraint (`in_force` differs from `chosen`) holds for this drag, and
// the release goes back to the chosen one.
std::string pull_mode_note(PullConstraint in_force, PullConstraint chosen);

// One mouse pull, from the press to the release.
//
// Free: with W(c) the point of the plane through the grasp g parallel to the view plane
// that shows at display pixel c (the display depth of g kept),
//     displacement = W(c) - W(c_press),
// so g's image moves exactly with the cursor (the plane maps affinely to the screen).
//
// On a line through g with unit direction a: the cursor's motion is projected onto the
// line's image on the screen (the direction from g's image to that of g + a), and the
// displacement is the point of the line that shows at the resulting pixel T (the line
// meets T's view ray there): t a with
//     t = (b e - d) / (1 - b^2),   b = a.r, d = a.(g - o), e = r.(g - o)
// for the ray o + s r through T (r a unit vector), the closest point of two lines. When
// the line is within 5 degrees of the view direction its image is a point: the motion
// along the line is then the cursor's upward motion measured on the view plane, toward
// the viewer for an upward motion. t is kept within a hundred view heights.
//
// Precision (Shift, Blender's convention): while it is held, each cursor motion counts a
// tenth, so pressing or releasing Shift mid-pull does not jump.
//
// The chosen constraint (`choose`, the dock's) holds for every pull; a constraint switched
// mid-pull (`constrain`, a key) holds until the release, which goes back to the chosen one.
// A switch does not jump either: the pull is a chain
// of segments, each under one constraint. At the switch the displacement so far, D0 (under
// the old constraint, through the view of that moment), is kept, the grasp is taken where
// it now is (g + D0), and the new constraint moves it from there with the cursor's motion
// since the switch, T - T0:
//     displacement = D0 + d_new(g + D0, T - T0),   d_new(., 0) = 0.
// Free after the switch, the grasp's image moves exactly as the cursor does (as before):
// under the cursor if it was there at the switch (a free pull keeps it there); after a
// constraint it keeps its offset from the cursor (jumping under the cursor would be the
// jump). A line after a free pull: the grasp was under the cursor, so it shows at the
// cursor's foot on the line's image, as for a line chosen at the press.
class PullControl
{
public:
  static constexpr double precision_factor = 0.1;

  // The press: the cursor's pixel, the point pressed (world) and the surface normal there.
  void press(
    const Eigen::Vector2d& cursor, const Eigen::Vector3d& grasp, const Eigen::Vector3d& normal);
  // The grasped vertex (world), which may lie a little off the pressed point: the drag
  // plane and the constraint lines go through it.
  void set_grasp(const Eigen::Vector3d& grasp) { grasp_ = grasp; }
  void move(const Eigen::Vector2d& cursor, bool precise);
  // From now on the pull keeps to `constraint`, continuing from where the grasp is (above);
  // `view` and `up` as for displacement(). The same constraint again changes nothing.
  // It lasts this pull (a key's switch): the release goes back to the chosen one.
  void constrain(PullConstraint constraint, const ViewProjection& view, const Eigen::Vector3d& up);
  // The constraint chosen for every pull (the dock's Pull row): in force from the next
  // press on, and at once between pulls; a pull under way keeps its own (constrain() it).
  void choose(PullConstraint constraint);
  // The pull is over: the chosen constraint is in force again. True when that changed it
  // (a key had switched the pull).
  bool release();
  // The constraint in force (the pull's own during a pull), and the chosen one.
  PullConstraint constraint() const { return constraint_; }
  PullConstraint chosen() const { return chosen_; }

  // The displacement of the grasp (world) for the cursor so far, seen through `view`;
  // `up` is the scene's vertical in world coordinates. Zero for non-finite input or a
  // degenerate view.
  Eigen::Vector3d displacement(const ViewProjection& view, const Eigen::Vector3d& up) const;

  // The pixel the pull has reached: the press plus the cursor's (scaled) motion.
  const Eigen::Vector2d& target() const { return target_; }
  const Eigen::Vector3d& grasp() const { return grasp_; }

private:
  // The current segment's displacement from the grasp where the segment began.
  Eigen::Vector3d segment(const ViewProjection& view, const Eigen::Vector3d& up) const;
  Eigen::Vector3d along_line(
    const ViewProjection& view, const Eigen::Vector3d& from, const Eigen::Vector3d& axis) const;

  PullConstraint constraint_ = PullConstraint::view_plane;
  PullConstraint chosen_ = PullConstraint::view_plane;
  bool pulling_ = false;
  Eigen::Vector2d press_ = Eigen::Vector2d::Zero(); // the pixel where the segment began
  Eigen::Vector2d last_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d target_ = Eigen::Vector2d::Zero();
  Eigen::Vector3d grasp_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d base_ = Eigen::Vector3d::Zero(); // the displacement where the segment began
};

} // namespace geoshaping::interactor
