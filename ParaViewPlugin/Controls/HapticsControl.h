#pragma once
// The haptic interactor's decisions, free of Qt, VTK and ParaView so that they are unit
// tested (Testing/GUI/TestHapticsControl.cpp): where the device workspace sits in the
// scene, and what one hand asks of the pipeline each frame.
#include "geoshaping/paint/brush_stroke.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace geoshaping::interactor
{

// The active view's camera, in scene units (what vtkCamera reports).
struct CameraPose
{
  Eigen::Vector3d position = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d focal_point = Eigen::Vector3d::Zero();
  Eigen::Vector3d view_up = Eigen::Vector3d::UnitY();
  double view_angle_deg = 30.0;
  bool parallel = false;
  double parallel_scale = 1.0;
};

// Device workspace (metres; x right, y up, z toward the user, as PHANToM and CHAI3D
// devices report) -> scene. The workspace centre sits at the camera's focal point, its
// axes follow the screen (x right, y up, z toward the viewer) and its radius spans half
// the view height at the focal distance: the stylus moves where the user looks, and a
// zoom makes the same hand motion finer.
class WorkspaceMapping
{
public:
  WorkspaceMapping() = default;
  WorkspaceMapping(const CameraPose& camera, double workspace_radius);

  // False for a degenerate camera (position on the focal point, up along the view);
  // the mapping is then the identity.
  bool valid() const { return valid_; }
  double scale() const { return scale_; } // scene units per metre

  Eigen::Vector3d to_scene(const Eigen::Vector3d& device) const;
  Eigen::Vector3d to_device(const Eigen::Vector3d& scene) const;
  Eigen::Vector3d vector_to_scene(const Eigen::Vector3d& device) const;
  Eigen::Quaterniond rotation_to_scene(const Eigen::Quaterniond& device) const;

private:
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity(); // columns: screen x, y, z in scene
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double scale_ = 1.0;
  bool valid_ = false;
};

enum class Tool
{
  paint,
  deform,
  hold_and_turn
};

// One hand's stylus this frame, in the coordinates of the object it acts on.
struct StylusState
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  bool button = false;
};

struct Brush
{
  double radius = 5.0;   // scene units (the interactor sets it: BrushControl.h)
  double value = 1.0;    // malleability painted, [0, 1]
  double strength = 1.0; // per dab, [0, 1]: 1 paints `value` itself under the dab's centre
};

// A rigid motion x -> rotation * (x - pivot) + pivot + translation.
struct RigidMotion
{
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Matrix4d matrix() const;
};

// What a hand asks of the pipeline this frame; the ParaView side carries it out.
struct HandActions
{
  bool grasp = false; // Deform press: grasp the vertex nearest to grasp_position
  Eigen::Vector3d grasp_position = Eigen::Vector3d::Zero();
  bool set_displacement = false; // Deform held: the grasped vertex's displacement
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  bool release = false;                    // Deform released (the shape stays as it is)
  std::vector<std::array<double, 6>> dabs; // Paint: x y z radius value strength
  bool begin_stroke = false;               // Paint press: a stroke (one undo step) begins
  bool end_stroke = false;                 // Paint released: the stroke is over
  bool begin_hold = false;                 // Hold-and-turn press: remember the object's pose
  bool set_motion = false;                 // Hold-and-turn held: motion since the press
  RigidMotion motion;
  bool end_hold = false;
};

// The per-hand state machine. Deform: the press grasps, holding drags by the stylus
// motion since the press, releasing stops. Paint: a stroke from the press to the
// release, its dabs a quarter of the brush radius apart along the stylus's path, also
// between two frames (geoshaping/paint/brush_stroke.h). Hold-and-turn: the object
// follows the stylus's translation and rotation since the press (6 DoF, about the
// stylus tip). Changing the tool ends what the old tool was doing.
class HandController
{
public:
  Tool tool() const { return tool_; }
  HandActions set_tool(Tool tool);
  HandActions update(const StylusState& stylus, const Brush& brush);
  bool held() const { return held_; }
  // Forget the press without any action (an undo during a drag): a button still held
  // counts as a new press at the next update.
  void cancel() { held_ = false; }

private:
  HandActions finish();

  Tool tool_ = Tool::deform;
  bool held_ = false;
  Eigen::Vector3d press_position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond press_orientation_ = Eigen::Quaterniond::Identity();
  BrushStroke stroke_;
};

// Where a grasp an obstacle held back is, on the stylus's side, in the coordinates of
// the object (docs/obstacles.md, docs/interactor.md "Forces"): `press` (the stylus at the
// press) moved by what the grasp made of `displacement` in the filter's last update.
// `fraction` is that update's LastGraspObstacleFraction: NaN (no grasp yet) returns
// false. `moved`, when known (finite), is where the grasp landed: that update's
// LastGraspDisplacement (a sliding grasp's landed point included, at fraction 1 too);
// equal to `displacement` (the grasp went where the stylus put it) it returns false, and
// the coupling stays as it is. Without it the grasp made fraction x displacement, and
// fraction >= 1 returns false. Non-finite results return false.
bool stopped_grasp(const Eigen::Vector3d& press, const Eigen::Vector3d& displacement,
  double fraction, const Eigen::Vector3d* moved, Eigen::Vector3d& stopped);

// The 3D palette near the stylus: 11 swatches of malleability 0, 0.1 ... 1 that appear
// while the stylus's second button is held, in a row along the device's x axis (the
// screen's right) 1 cm apart, 2 cm above (device y, the screen's up) where the button
// was pressed; the row is shifted along x to stay inside the workspace. Touching a
// swatch (the stylus within 4 mm of its centre) picks its value. All in device coordinates
// (metres), so the palette keeps its size on screen whatever the zoom.
class StylusPalette
{
public:
  static constexpr int count = 11;
  static constexpr double spacing = 0.01;
  static constexpr double lift = 0.02;
  static constexpr double radius = 0.004;

  // Feeds the second button and the stylus; returns the value of a swatch touched this
  // frame and not the frame before, or NaN. Non-finite positions touch nothing.
  double update(bool button, const Eigen::Vector3d& stylus, double workspace_radius);
  bool shown() const { return shown_; }
  Eigen::Vector3d centre(int i) const;
  int touched() const { return touched_; } // -1 when none
  static double value(int i) { return i / double(count - 1); }

private:
  bool shown_ = false;
  int touched_ = -1;
  Eigen::Vector3d row_centre_ = Eigen::Vector3d::Zero();
};

} // namespace geoshaping::interactor
