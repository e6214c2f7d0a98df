#include "pqHapticsInteractor.h"

#include "DisplayTransform.h"
#include "pqHapticsMouse.h"

#include "geoshaping/haptics/device_factory.h"
#include "geoshaping/haptics/servo_loop.h"
#include "geoshaping/haptics/trace.h"
#include "geoshaping/mesh/nearest_triangles.h"
#include "geoshaping/paint/brush.h"

#include <pqRenderView.h>

#include <QCoreApplication>
#include <QKeyEvent>

#include <vtkActor.h>
#include <vtkLineSource.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSMRenderViewProxy.h>
#include <vtkSphereSource.h>
#include <vtkWeakPointer.h>

#include <algorithm>
#include <cmath>

namespace interactor = geoshaping::interactor;
namespace haptics = geoshaping::haptics;

struct pqHapticsInteractor::Hand
{
  DeviceKind kind = NoDevice;
  interactor::Tool tool = interactor::Tool::deform; // chosen in the dock; Ctrl in mouse mode paints
  std::unique_ptr<haptics::HapticDevice> device;
  std::unique_ptr<haptics::ServoLoop> servo;
  pqHapticsMouse mouse;
  interactor::HandController controller;
  haptics::DeviceSnapshot latest;
  interactor::WorkspaceMapping mapping; // frozen while the button is held
  haptics::SceneSnapshot sent;          // a copy of the last scene published to the servo loop
  bool stiffnessPending = false;        // the grasp's malleability still to read from the server
  haptics::TraceRecorder recorder;      // open when the hand records its stylus
  double recordedUntil = -1.0;          // t of the last recorded sample
  std::chrono::steady_clock::time_point since = std::chrono::steady_clock::now();
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero(); // device coordinates
  Eigen::Vector3d press = Eigen::Vector3d::Zero();  // the stylus at the press, object coordinates
  double stiffness = 0.0;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkActor> cursor;
  Eigen::Vector3d graspRest =
    Eigen::Vector3d::Zero();    // the grasped vertex at the press, object coordinates
  vtkNew<vtkLineSource> tether; // from the grasped vertex to the cursor (showGrasps)
  vtkNew<vtkPolyDataMapper> tetherMapper;
  vtkNew<vtkActor> tetherLine;
  vtkNew<vtkMatrix4x4> cage;         // the cursor's matrix: the brush as drawn (onFrame)
  interactor::StylusPalette palette; // device hands: shown while the second button is held
  vtkNew<vtkSphereSource> swatchSphere;
  vtkNew<vtkPolyDataMapper> swatchMapper;
  std::array<vtkNew<vtkActor>, interactor::StylusPalette::count> swatches;
  vtkWeakPointer<vtkRenderer> renderer;

  Hand()
  {
    this->sphere->SetThetaResolution(16);
    this->sphere->SetPhiResolution(12);
    this->mapper->SetInputConnection(this->sphere->GetOutputPort());
    this->cursor->SetMapper(this->mapper);
    this->cursor->PickableOff();
    this->cursor->UseBoundsOff(); // Reset Camera frames the data, not the stylus
    this->tetherMapper->SetInputConnection(this->tether->GetOutputPort());
    this->tetherLine->SetMapper(this->tetherMapper);
    this->tetherLine->PickableOff();
    this->tetherLine->UseBoundsOff();
    this->tetherLine->VisibilityOff();
    this->tetherLine->GetProperty()->SetColor(1.0, 0.8, 0.2);
    this->tetherLine->GetProperty()->SetLineWidth(2.0);
    this->swatchSphere->SetThetaResolution(16);
    this->swatchSphere->SetPhiResolution(12);
    this->swatchMapper->SetInputConnection(this->swatchSphere->GetOutputPort());
    for (int i = 0; i < interactor::StylusPalette::count; ++i)
    {
      const Eigen::Vector3d c = geoshaping::malleability_color(interactor::StylusPalette::value(i));
      this->swatches[i]->SetMapper(this->swatchMapper);
      this->swatches[i]->GetProperty()->SetColor(c.x(), c.y(), c.z());
      this->swatches[i]->PickableOff();
      this->swatches[i]->UseBoundsOff();
      this->swatches[i]->VisibilityOff();
    }
  }
  ~Hand()
  {
    if (this->servo)
    {
      this->servo->stop();
    }
    this->recorder.close();
    this->setRenderer(nullptr);
  }
  void setRenderer(vtkRenderer* r)
  {
    if (r != this->renderer)
    {
      if (this->renderer)
      {
        this->renderer->RemoveActor(this->cursor);
        this->renderer->RemoveActor(this->tetherLine);
        for (auto& swatch : this->swatches)
        {
          this->renderer->RemoveActor(swatch);
        }
      }
      this->renderer = r;
      if (r)
      {
        r->AddActor(this->cursor);
        r->AddActor(this->tetherLine);
        for (auto& swatch : this->swatches)
        {
          r->AddActor(swatch);
        }
      }
    }
  }
  // The 3D palette's swatches where the palette says, in the scene.
  void showPalette()
  {
    const double size = interactor::StylusPalette::radius * this->mapping.scale();
    this->swatchSphere->SetRadius(size);
    for (int i = 0; i < interactor::StylusPalette::count; ++i)
    {
      const Eigen::Vector3d c = this->mapping.to_scene(this->palette.centre(i));
      this->swatches[i]->SetPosition(c.x(), c.y(), c.z());
      this->swatches[i]->SetScale(i == this->palette.touched() ? 1.5 : 1.0);
      this->swatches[i]->SetVisibility(this->palette.shown());
    }
  }
};

pqHapticsInteractor::pqHapticsInteractor(QObject* parent)
  : QObject(parent)
{
  this->Timer.setInterval(16);
  this->Timer.setTimerType(Qt::PreciseTimer);
  QObject::connect(&this->Timer, &QTimer::timeout, this, &pqHapticsInteractor::onFrame);
}

pqHapticsInteractor::~pqHapticsInteractor()
{
  this->stop();
}

bool pqHapticsInteractor::start(const std::array<HandSetup, 2>& setups, QString& error)
{
  this->stop();
  for (std::size_t i = 0; i < setups.size(); ++i)
  {
    const HandSetup& setup = setups[i];
    if (setup.device == NoDevice)
    {
      continue;
    }
    auto hand = std::make_unique<Hand>();
    hand->kind = setup.device;
    hand->mouse.setConstraint(this->Pull);
    hand->mouse.constraintShown = [this](interactor::PullConstraint c)
    { Q_EMIT this->pullConstraintChanged(int(c)); };
    hand->tool = setup.tool;
    hand->controller.set_tool(setup.tool);
    if (setup.device != Mouse)
    {
      const char* kinds[] = { "null", "replay", "simulated", "openhaptics" };
      hand->device = haptics::make_device(kinds[setup.device], setup.file.toStdString());
      hand->servo = std::make_unique<haptics::ServoLoop>(*hand->device);
      if (!hand->servo->start())
      {
        error = QString("Hand %1: %2").arg(i + 1).arg(QString::fromStdString(hand->servo->error()));
        this->stop();
        return false;
      }
    }
    if (!setup.record.isEmpty() && !hand->recorder.open(setup.record.toStdString()))
    {
      error = QString("Hand %1: %2").arg(i + 1).arg(QString::fromStdString(hand->recorder.error()));
      this->stop();
      return false;
    }
    this->Hands[i] = std::move(hand);
  }
  this->Stats = Figures();
  this->FramePeriodSeconds = 0.0;
  this->LastFrameEnd = std::chrono::steady_clock::time_point();
  this->FpsSince = std::chrono::steady_clock::now();
  this->FramesSince = 0;
  this->Timer.start();
  QCoreApplication::instance()->installEventFilter(this);
  return true;
}

bool pqHapticsInteractor::eventFilter(QObject* watched, QEvent* event)
{
  const bool press = event->type() == QEvent::KeyPress;
  if (press || event->type() == QEvent::KeyRelease)
  {
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() == Qt::Key_Control && !key->isAutoRepeat())
    {
      for (auto& hand : this->Hands)
      {
        if (hand && hand->kind == Mouse)
        {
          hand->mouse.setControlKey(press);
        }
      }
    }
  }
  return QObject::eventFilter(watched, event);
}

void pqHapticsInteractor::stop()
{
  if (QCoreApplication* application = QCoreApplication::instance())
  {
    application->removeEventFilter(this);
  }
  this->Timer.stop();
  for (auto& hand : this->Hands)
  {
    hand.reset();
  }
  this->OpenStrokes = 0;
  this->StrokeExclude.reset(); // a stroke cut short by Stop is no step
  this->StrokeStep.reset();
  this->Proxies.render();
}

void pqHapticsInteractor::setTool(int hand, interactor::Tool tool)
{
  if (hand >= 0 && hand < 2 && this->Hands[hand])
  {
    this->Hands[hand]->tool = tool;
    this->apply(*this->Hands[hand], this->Hands[hand]->controller.set_tool(tool));
  }
}

void pqHapticsInteractor::setPullConstraint(interactor::PullConstraint c)
{
  if (c == this->Pull)
  {
    return;
  }
  this->Pull = c;
  for (auto& hand : this->Hands)
  {
    if (hand && hand->kind == Mouse)
    {
      hand->mouse.setConstraint(c);
    }
  }
  Q_EMIT this->pullConstraintChanged(int(c));
}

bool pqHapticsInteractor::stylusOf(
  Hand& hand, const interactor::WorkspaceMapping& mapping, interactor::StylusState& world)
{
  if (hand.kind == Mouse)
  {
    const Eigen::Matrix3d turn = this->Proxies.objectMatrix().topLeftCorner<3, 3>();
    world =
      hand.mouse.stylus(hand.controller.held(), (turn * Eigen::Vector3d::UnitZ()).normalized());
    return true;
  }
  hand.servo->poll_device(hand.latest);
  if (!hand.controller.held())
  {
    hand.mapping = mapping;
    this->Stats.sceneUnitsPerMetre = mapping.scale();
  }
  const haptics::DeviceSample& sample = hand.latest.sample;
  world.position = hand.mapping.to_scene(sample.position);
  world.orientation = hand.mapping.rotation_to_scene(sample.orientation);
  world.button = hand.latest.device_ok && (sample.buttons & 1u) != 0;
  return hand.latest.device_ok;
}

void pqHapticsInteractor::apply(Hand& hand, const interactor::HandActions& actions)
{
  if (actions.grasp)
  {
    this->Proxies.grasp(actions.grasp_position);
    Eigen::Vector3d vertex = actions.grasp_position;
    double malleability = 0.5;
    // A builtin session reads the grasped vertex's malleability at once; against a
    // remote server the filter reports it after its next update (publishScene).
    hand.stiffnessPending = !this->Proxies.graspedVertex(vertex, malleability);
    Eigen::Vector3d shown;
    hand.graspRest = actions.grasp_position;
    if (this->Proxies.shownGraspedVertex(shown))
    {
      hand.graspRest = shown;
      if (hand.kind == Mouse)
      {
        hand.mouse.setGrasp((this->Proxies.objectMatrix() * shown.homogeneous()).hnormalized());
      }
    }
    if (hand.device)
    {
      hand.press = actions.grasp_position;
      const Eigen::Vector3d world =
        (this->Proxies.objectMatrix() * actions.grasp_position.homogeneous()).hnormalized();
      hand.anchor = hand.mapping.to_device(world);
      hand.stiffness =
        haptics::coupling_stiffness(malleability, haptics::ForceParams(), hand.device->limits());
    }
  }
  if (actions.set_displacement)
  {
    this->Proxies.setDisplacement(actions.displacement);
    this->LastDisplacement = actions.displacement;
  }
  if (actions.release)
  {
    // Releasing the Deform tool commits: the shape the user sees becomes the rest shape
    // of the next grasp, and EditHistory gets its record.
    this->Proxies.lastDeformationMilliseconds(); // updates the information properties
    this->Stats.displacedAtRelease = this->Proxies.numberOfDisplacedPoints();
    this->LastEdit = this->Proxies.runEdit(interactor::EditCommand::commit);
    Q_EMIT this->editsChanged();
  }
  if (actions.begin_stroke)
  {
    this->beginStroke();
  }
  if (!actions.dabs.empty())
  {
    // Dabs land on the surface the user sees: while a hand drags, or once edits are
    // committed, it is not the paint filter's input.
    this->Outcome.add(this->Proxies.appendDabs(
      actions.dabs, this->anyHandDragging() || this->Proxies.numberOfEdits() > 0));
  }
  if (actions.end_stroke)
  {
    this->endStroke();
  }
  if (actions.begin_hold)
  {
    this->HoldStart = this->Proxies.objectMatrix();
  }
  if (actions.set_motion)
  {
    this->Proxies.setObjectMatrix(actions.motion.matrix() * this->HoldStart);
  }
}

void pqHapticsInteractor::record(
  Hand& hand, const interactor::WorkspaceMapping& mapping, const interactor::StylusState& world)
{
  if (!hand.recorder.is_open())
  {
    return;
  }
  haptics::DeviceSample sample;
  if (hand.device)
  {
    sample = hand.latest.sample; // the device's own time and frame
  }
  else
  {
    // The mouse in device coordinates of the current view, timed since start.
    sample.t = std::chrono::duration<double>(std::chrono::steady_clock::now() - hand.since).count();
    sample.position = mapping.to_device(world.position);
    sample.buttons = world.button ? 1u : 0u;
  }
  if (sample.t > hand.recordedUntil && hand.recorder.record(sample))
  {
    hand.recordedUntil = sample.t;
  }
  const std::size_t index = &hand == this->Hands[0].get() ? 0 : 1;
  this->Stats.recordedSamples[index] = (long long)hand.recorder.samples();
}

bool pqHapticsInteractor::anyHandDragging() const
{
  return std::any_of(this->Hands.begin(), this->Hands.end(),
    [](const auto& hand) {
      return hand && hand->controller.held() && hand->controller.tool() == interactor::Tool::deform;
    });
}

interactor::EditResult pqHapticsInteractor::runEdit(interactor::EditCommand command)
{
  this->Proxies.refresh();
  for (auto& hand : this->Hands)
  {
    // An undo/redo/reset ends a drag without committing it.
    if (hand && hand->controller.held() && hand->controller.tool() == interactor::Tool::deform &&
        command != interactor::EditCommand::commit)
    {
      hand->controller.cancel();
    }
  }
  if (!this->strokeEdit(command))
  {
    this->LastEdit = this->Proxies.runEdit(command);
  }
  this->Proxies.render();
  Q_EMIT this->editsChanged();
  return this->LastEdit;
}

void pqHapticsInteractor::publishScene(Hand& hand, const Eigen::Vector3d& stylus, bool anyDragging)
{
  if (!hand.servo)
  {
    return;
  }
  haptics::SceneSnapshot& scene = hand.servo->scene_back();
  scene.stamp = haptics::Clock::now();
  scene.sequence = ++this->Sequence;
  // A slow renderer's snapshot stays valid for three of its frames (the force model
  // caps this at 500 ms, so a frozen GUI still zeroes the force).
  scene.valid_for = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::duration<double>(3.0 * this->FramePeriodSeconds));
  scene.grasping = hand.controller.held() && hand.controller.tool() == interactor::Tool::deform;
  double malleability = 0.0;
  if (scene.grasping && hand.stiffnessPending && this->Proxies.lastGraspMalleability(malleability))
  {
    hand.stiffness =
      haptics::coupling_stiffness(malleability, haptics::ForceParams(), hand.device->limits());
    hand.stiffnessPending = false;
  }
  scene.grasp_anchor = hand.anchor;
  scene.grasp_stiffness = hand.stiffness;
  // An obstacle held the grasp back in the last update (which ran with
  // RenderedDisplacement): the coupling pulls toward where the grasp stopped.
  double fraction = 1.0;
  Eigen::Vector3d moved = Eigen::Vector3d::Zero(), stopped;
  if (scene.grasping && this->Proxies.lastGraspObstacleFraction(fraction))
  {
    // Where the grasp landed (LastGraspDisplacement: a sliding grasp's landed point too).
    const bool known = this->Proxies.lastGraspDisplacement(moved);
    if (interactor::stopped_grasp(
          hand.press, this->RenderedDisplacement, fraction, known ? &moved : nullptr, stopped))
    {
      haptics::hold_grasp_back(scene,
        hand.mapping.to_device(
          (this->Proxies.objectMatrix() * stopped.homogeneous()).hnormalized()),
        haptics::ForceParams(), hand.device->limits());
    }
  }
  // Contact: the surfaces near the stylus, in device coordinates, in any winding (the
  // servo's proxy keeps the side the stylus came from). The shape being dragged is left
  // out while any hand drags it (the stylus would fight its own grasp, and its locator
  // would be rebuilt every frame); otherwise the stylus feels it too, e.g. while
  // painting or before a grasp.
  scene.contact_triangles.clear();
  const haptics::DeviceSample& sample = hand.latest.sample;
  if (hand.latest.device_ok)
  {
    this->Proxies.contactTriangles(stylus, ContactReachMetres * hand.mapping.scale(), !anyDragging,
      MaxContactTriangles, scene.contact_triangles);
    for (Eigen::Vector3d& p : scene.contact_triangles)
    {
      p = hand.mapping.to_device(p);
    }
    geoshaping::keep_nearest(scene.contact_triangles, sample.position, MaxContactTriangles);
    const pqHapticsProxies::ServerPatchFigures& patch = this->Proxies.serverPatchFigures();
    if (patch.milliseconds >= 0.0)
    {
      this->Stats.serverPatchMilliseconds =
        std::max(this->Stats.serverPatchMilliseconds, 0.0) + patch.milliseconds;
      this->Stats.serverPatchBytes += patch.bytes;
    }
    if (!patch.message.empty())
    {
      this->Stats.serverPatchMessage = QString::fromStdString(patch.message);
    }
  }
  this->Stats.contactTriangles += (long long)(scene.contact_triangles.size() / 3);
  this->Stats.contactTicks += hand.latest.in_contact ? 1 : 0;
  hand.sent = scene;
  hand.servo->publish_scene();
  const std::size_t index = &hand == this->Hands[0].get() ? 0 : 1;
  this->Stats.force[index] =
    haptics::force_at_rest(hand.latest, hand.sent, haptics::ForceParams(), hand.device->limits());
}

void pqHapticsInteractor::onFrame()
{
  this->refreshBrush();
  pqRenderView* view = this->Proxies.view();
  vtkSMRenderViewProxy* viewProxy = view ? view->getRenderViewProxy() : nullptr;
  const interactor::CameraPose camera = this->Proxies.camera();
  const Eigen::Matrix4d object = this->Proxies.objectMatrix();
  const Eigen::Matrix4d toObject = object.inverse();
  this->Stats.contactTriangles = 0;
  this->Stats.serverPatchMilliseconds = -1.0;
  this->Stats.serverPatchBytes = 0;
  this->Stats.serverPatchMessage.clear();
  for (auto& handPtr : this->Hands)
  {
    if (!handPtr)
    {
      continue;
    }
    Hand& hand = *handPtr;
    const double radius = hand.device ? hand.device->limits().workspace_radius : 0.08;
    const interactor::WorkspaceMapping mapping(camera, radius);
    interactor::StylusState world;
    if (hand.kind == Mouse)
    {
      hand.mouse.attach(viewProxy);
      this->Stats.serverPickMilliseconds = hand.mouse.lastServerPickMilliseconds();
    }
    this->stylusOf(hand, mapping, world);
    this->record(hand, mapping, world);
    const bool mousePaints = hand.kind == Mouse && hand.mouse.paint();
    this->apply(hand, hand.controller.set_tool(mousePaints ? interactor::Tool::paint : hand.tool));

    interactor::StylusState local = world;
    if (hand.controller.tool() != interactor::Tool::hold_and_turn)
    {
      local.position = (toObject * world.position.homogeneous()).hnormalized();
    }
    this->apply(hand, hand.controller.update(local, this->Brush));

    const bool painting = hand.controller.tool() == interactor::Tool::paint;
    const Eigen::Vector3d color = painting ? geoshaping::malleability_color(this->Brush.value)
                                  : hand.controller.held() ? Eigen::Vector3d(0.2, 1.0, 0.3)
                                                           : Eigen::Vector3d(0.2, 0.6, 1.0);
    // A mouse hand shows where it is while held and, about to paint (the Paint tool, or
    // Ctrl held), where a dab would land while it hovers over the surface.
    Eigen::Vector3d at = world.position;
    const bool shown = hand.kind != Mouse || world.button || (painting && hand.mouse.hover(at));
    hand.sphere->SetCenter(at.data());
    hand.sphere->SetRadius(
      painting ? this->brushCursorRadius(at, camera) : 0.004 * mapping.scale());
    // The cage is the brush as drawn: its sphere in the data through the display
    // transform, about where a dab lands (an ellipsoid under a vertical exaggeration).
    const Eigen::Matrix4d cage =
      painting ? interactor::DisplayTransform(object).about(at) : Eigen::Matrix4d::Identity();
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        hand.cage->SetElement(i, j, cage(i, j));
      }
    }
    hand.cursor->SetUserMatrix(hand.cage);
    hand.cursor->GetProperty()->SetColor(color.x(), color.y(), color.z());
    // A cage while painting: the paint under the brush shows through (a translucent
    // sphere would turn on depth peeling, slower than the frame).
    hand.cursor->GetProperty()->SetRepresentation(painting ? VTK_WIREFRAME : VTK_SURFACE);
    hand.cursor->SetVisibility(shown);
    hand.setRenderer(viewProxy ? viewProxy->GetRenderer() : nullptr);
    if (hand.device)
    {
      const haptics::DeviceSample& sample = hand.latest.sample;
      const double picked = hand.palette.update(hand.latest.device_ok && (sample.buttons & 2u),
        sample.position, hand.device->limits().workspace_radius);
      if (!std::isnan(picked))
      {
        this->Brush.value = picked;
        Q_EMIT this->paletteValuePicked(picked);
      }
      hand.showPalette();
    }
  }
  this->showGrasps(object);
  // After every hand has acted, so that a grasp made this frame counts as dragging.
  const bool anyDragging = this->anyHandDragging();
  for (auto& hand : this->Hands)
  {
    if (hand && hand->device)
    {
      const haptics::DeviceSample& sample = hand->latest.sample;
      this->publishScene(*hand, hand->mapping.to_scene(sample.position), anyDragging);
    }
  }
  this->Stats.maxContactTriangles =
    std::max(this->Stats.maxContactTriangles, this->Stats.contactTriangles);
  this->Proxies.render();
  this->RenderedDisplacement = this->LastDisplacement;
  this->updateFigures();
  Q_EMIT this->frameDone();
}

void pqHapticsInteractor::showGrasps(const Eigen::Matrix4d& object)
{
  const auto drags = [](const Hand& hand)
  { return hand.controller.held() && hand.controller.tool() == interactor::Tool::deform; };
  this->Stats.obstacleBlockedPoints = -1;
  if (!this->anyHandDragging())
  {
    for (auto& hand : this->Hands)
    {
      if (hand)
      {
        hand->tetherLine->VisibilityOff();
      }
    }
    return;
  }
  // What the filter makes of this frame's pull, before the frame is drawn.
  this->Proxies.update();
  if (this->Proxies.hasObstacles())
  {
    this->Stats.obstacleBlockedPoints = this->Proxies.numberOfObstacleBlockedPoints();
  }
  for (auto& handPtr : this->Hands)
  {
    if (!handPtr)
    {
      continue;
    }
    Hand& hand = *handPtr;
    Eigen::Vector3d vertex;
    if (!drags(hand) || !this->Proxies.graspedVertexNow(hand.graspRest, vertex))
    {
      hand.tetherLine->VisibilityOff();
      continue;
    }
    Eigen::Vector3d cursor;
    hand.sphere->GetCenter(cursor.data());
    const Eigen::Vector3d at = (object * vertex.homogeneous()).hnormalized();
    hand.sphere->SetCenter(at.data());
    hand.tether->SetPoint1(at.data());
    hand.tether->SetPoint2(cursor.data());
    // Apart by more than the marker's radius: the line shows where the cursor is.
    hand.tetherLine->SetVisibility((at - cursor).norm() > hand.sphere->GetRadius());
  }
}

void pqHapticsInteractor::updateFigures()
{
  const auto frameEnd = std::chrono::steady_clock::now();
  if (this->LastFrameEnd != std::chrono::steady_clock::time_point())
  {
    // Smoothed frame period, for how long a scene snapshot stays valid.
    const double period = std::chrono::duration<double>(frameEnd - this->LastFrameEnd).count();
    this->FramePeriodSeconds =
      this->FramePeriodSeconds > 0.0 ? 0.8 * this->FramePeriodSeconds + 0.2 * period : period;
  }
  this->LastFrameEnd = frameEnd;
  ++this->Stats.frames;
  ++this->FramesSince;
  for (std::size_t i = 0; i < this->Hands.size(); ++i)
  {
    const Hand* hand = this->Hands[i].get();
    const bool failed = hand && hand->device && hand->device->has_error();
    this->Stats.deviceError[i] = failed ? QString::fromStdString(hand->device->error()) : QString();
  }
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - this->FpsSince).count();
  if (seconds < 0.5)
  {
    return;
  }
  this->Stats.framesPerSecond = this->FramesSince / seconds;
  this->FramesSince = 0;
  this->FpsSince = now;
  for (std::size_t i = 0; i < this->Hands.size(); ++i)
  {
    const Hand* hand = this->Hands[i].get();
    this->Stats.servoHz[i] = hand && hand->servo ? hand->servo->period_summary().mean_rate_hz : 0.0;
  }
  if (this->Proxies.hasDeformation())
  {
    this->Stats.deformationMilliseconds = this->Proxies.lastDeformationMilliseconds();
    this->Stats.displacedPoints = this->Proxies.numberOfDisplacedPoints();
  }
}
