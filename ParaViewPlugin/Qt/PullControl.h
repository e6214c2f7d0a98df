#pragma once
// A mouse pull, free of Qt, VTK and ParaView so that it is unit tested
// (Testing/GUI/TestPullControl.cpp). The grasp's displacement is the cursor's motion
// carried onto the plane through the grasp parallel to the view plane, as Blender's grab
// and ParaView's handle widgets do: the grasped point keeps its place under the cursor
// whatever the data's scale and the camera. A constraint keeps the pull on a line through
// the grasp (the vertical, or the surface normal there); Shift makes the motion finer.
#include <Eigen/Core>

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

  // The displacement of the grasp (world) for the cursor so far, seen through `view`;
  // `up` is the scene's vertical in world coordinates. Zero for non-finite input or a
  // degenerate view.
  Eigen::Vector3d displacement(
    const ViewProjection& view, PullConstraint constraint, const Eigen::Vector3d& up) const;

  // The pixel the pull has reached: the press plus the cursor's (scaled) motion.
  const Eigen::Vector2d& target() const { return target_; }
  const Eigen::Vector3d& grasp() const { return grasp_; }

private:
  Eigen::Vector3d along_line(const ViewProjection& view, const Eigen::Vector3d& axis) const;

  Eigen::Vector2d press_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d last_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d target_ = Eigen::Vector2d::Zero();
  Eigen::Vector3d grasp_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_ = Eigen::Vector3d::UnitZ();
};

} // namespace geoshaping::interactor
