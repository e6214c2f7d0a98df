#pragma once
// The haptic interactor: one hand per device (or the mouse), a timer on the GUI thread
// at ~60 Hz that takes each device's latest snapshot from its servo loop, maps it into
// the scene through the active view's camera, lets the hand's controller decide, drives
// the proxies (pqHapticsProxies), moves the stylus cursors, renders, and publishes the
// scene snapshot (grasp anchor, stiffness) back to the servo loop for the force.
// After ParaView's CAVEInteraction plugin: device thread -> snapshot -> QTimer.
#include "BrushControl.h"
#include "HapticsControl.h"
#include "PullControl.h"
#include "geoshaping/haptics/force_model.h"
#include "pqHapticsProxies.h"
#include "undo_step.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <array>
#include <chrono>
#include <memory>

class pqHapticsInteractor : public QObject
{
  Q_OBJECT

public:
  enum DeviceKind
  {
    NoDevice,
    ReplayFile,
    Simulated,
    OpenHaptics,
    Mouse
  };
  struct HandSetup
  {
    DeviceKind device = NoDevice;
    QString file; // trace for ReplayFile, optional keyframes for Simulated
    geoshaping::interactor::Tool tool = geoshaping::interactor::Tool::deform;
    // When not empty, the hand's stylus is recorded to this trace file (device coordinates,
    // the format of docs/haptics.md), so it can be replayed as a Replay file device.
    QString record;
  };
  struct Figures
  {
    std::array<double, 2> servoHz{ { 0.0, 0.0 } };
    // The device's error while running (a fault mid-run: its force is zero), or empty.
    std::array<QString, 2> deviceError;
    double framesPerSecond = 0.0;
    double deformationMilliseconds = 0.0;
    long long displacedPoints = 0;
    long long displacedAtRelease = 0; // NumberOfDisplacedPoints of the last committed drag
    // While a hand drags a surface with obstacles: the vertices they held back this
    // frame (NumberOfObstacleBlockedPoints); -1 otherwise.
    long long obstacleBlockedPoints = -1;
    int frames = 0;
    double sceneUnitsPerMetre = 0.0;   // the workspace mapping's scale, first device hand
    long long contactTriangles = 0;    // sent to the servo loop in the last frame (all hands)
    long long maxContactTriangles = 0; // the most sent in one frame since start
    long long contactTicks = 0;        // device snapshots taken in contact since start
    // The contact patch asked of the server in the last frame (the client holds no
    // geometry): its round trips (ms, < 0 when none was asked), the triangles' payload
    // (bytes), and why a patch could not be had or came late (empty: it came in time).
    double serverPatchMilliseconds = -1.0;
    // The round trip of the mouse's last pick that asked the server's ranks (the view
    // rendering remotely), ms; < 0 while none did.
    double serverPickMilliseconds = -1.0;
    long long serverPatchBytes = 0;
    QString serverPatchMessage;
    std::array<long long, 2> recordedSamples{ { 0, 0 } };
    // Per device hand: the force its last published scene asks for at the stylus, at rest
    // (haptics::force_at_rest: what the servo renders while the scene is fresh, whatever
    // the frame rate).
    std::array<geoshaping::haptics::ForceResult, 2> force;
  };

  // Contact patch sent to each servo loop: the triangles within this distance of the
  // stylus (device metres; one frame of fast hand motion), at most this many.
  static constexpr double ContactReachMetres = 0.02;
  static constexpr std::size_t MaxContactTriangles = 256;

  explicit pqHapticsInteractor(QObject* parent = nullptr);
  ~pqHapticsInteractor() override;

  // Opens the devices and starts their servo loops and the frame timer; false with
  // `error` when a device does not open (nothing is left running then).
  bool start(const std::array<HandSetup, 2>& hands, QString& error);
  void stop();
  bool isRunning() const { return this->Timer.isActive(); }

  void setTool(int hand, geoshaping::interactor::Tool tool);
  void setBrush(const geoshaping::interactor::Brush& brush) { this->Brush = brush; }
  const geoshaping::interactor::Brush& brush() const { return this->Brush; }
  // How every mouse pull moves the grasp (PullControl.h), the dock's choice; can change
  // mid-pull, from where the grasp is. A key during a pull (Z, N, C: PullControl.h)
  // changes it for that pull only; pullConstraintChanged() tells the constraint in force
  // then, and again when the release goes back to this one.
  void setPullConstraint(geoshaping::interactor::PullConstraint c);
  geoshaping::interactor::PullConstraint pullConstraint() const { return this->Pull; }
  // The brush fitted to the data (pqHapticsInteractorBrush.cxx): the radius is the paint's
  // BrushRadius (kept in the state) or, while that is 0, 3 % of the data's diagonal.
  // refreshBrush() reads both and the scene's unit; setBrushRadius() sets the property
  // (0: back to the default).
  void refreshBrush();
  void setBrushRadius(double radius);
  bool brushRadiusIsDefault() const { return this->BrushRadiusIsDefault; }
  // False until there is a surface to fit the brush to (the radius is then a placeholder).
  bool brushFitsData() const { return this->BrushFitsData; }
  const std::string& sceneUnit() const { return this->SceneUnit; }
  // What the last stroke did: its dabs, and why some were not stored (BrushControl.h).
  const QString& brushNote() const { return this->BrushNote; }
  const Figures& figures() const { return this->Stats; }

  // Commit / undo / redo / reset on the target ChainMailDeformation, keeping its
  // EditHistory in step (docs/editing.md), then render. Works running or not. A Deform
  // hand's release commits the same way.
  geoshaping::interactor::EditResult runEdit(geoshaping::interactor::EditCommand command);
  const geoshaping::interactor::EditResult& lastEditResult() const { return this->LastEdit; }
  int numberOfEdits() { return this->Proxies.numberOfEdits(); }
  pqHapticsProxies& proxies() { return this->Proxies; }

Q_SIGNALS:
  void frameDone();
  void editsChanged();
  void brushChanged();                        // radius, unit or note
  void pullConstraintChanged(int constraint); // the PullConstraint in force
  // A device hand touched a swatch of the 3D palette (second button held): the brush
  // now paints `value`.
  void paletteValuePicked(double value);

protected:
  // Ctrl pressed or released wherever the keyboard focus is: tells the mouse hands
  // (pqHapticsMouse::setControlKey). Installed on the application while running.
  bool eventFilter(QObject* watched, QEvent* event) override;

private Q_SLOTS:
  void onFrame();

private:
  struct Hand;
  bool stylusOf(Hand& hand, const geoshaping::interactor::WorkspaceMapping& mapping,
    geoshaping::interactor::StylusState& world);
  void apply(Hand& hand, const geoshaping::interactor::HandActions& actions);
  void publishScene(Hand& hand, const Eigen::Vector3d& stylus, bool anyDragging);
  void record(Hand& hand, const geoshaping::interactor::WorkspaceMapping& mapping,
    const geoshaping::interactor::StylusState& world);
  void updateFigures();
  // The grasp markers of the hands that drag, where their grasped vertices are this frame
  // (an obstacle may hold one back from the cursor), each with a line to its cursor when
  // they are apart; and the count held back (Figures::obstacleBlockedPoints).
  void showGrasps(const Eigen::Matrix4d& object);
  bool anyHandDragging() const;
  void beginStroke();
  void endStroke();
  // Undo or redo of a stroke, when ParaView's next step that way is a stroke of the
  // target's paint (pqHapticsInteractorBrush.cxx); false: not a stroke.
  bool strokeEdit(geoshaping::interactor::EditCommand command);
  // The paint cursor's radius at `at`: the brush's, at least a few pixels on screen.
  double brushCursorRadius(
    const Eigen::Vector3d& at, const geoshaping::interactor::CameraPose& camera) const;

  std::array<std::unique_ptr<Hand>, 2> Hands;
  pqHapticsProxies Proxies;
  QTimer Timer;
  geoshaping::interactor::Brush Brush;
  geoshaping::interactor::PullConstraint Pull = geoshaping::interactor::PullConstraint::view_plane;
  Figures Stats;
  Eigen::Vector3d LastDisplacement = Eigen::Vector3d::Zero();
  Eigen::Vector3d RenderedDisplacement = Eigen::Vector3d::Zero(); // of the last render
  Eigen::Matrix4d HoldStart = Eigen::Matrix4d::Identity();
  std::chrono::steady_clock::time_point FpsSince;
  std::chrono::steady_clock::time_point LastFrameEnd;
  double FramePeriodSeconds = 0.0;
  int FramesSince = 0;
  std::uint64_t Sequence = 0;
  geoshaping::interactor::EditResult LastEdit;
  // A stroke is one step of ParaView's undo stack ("Paint Stroke": the paint proxy's
  // state from the first press to the last release of the hands painting it).
  std::unique_ptr<geoshaping::undo::Step> StrokeStep;
  std::unique_ptr<geoshaping::undo::Exclude> StrokeExclude; // held while a stroke is open
  int OpenStrokes = 0;                                      // hands painting a stroke
  geoshaping::interactor::StrokeOutcome Outcome;            // of the open stroke
  bool BrushRadiusIsDefault = true;
  bool BrushFitsData = false;
  std::string SceneUnit;
  QString BrushNote;
};
