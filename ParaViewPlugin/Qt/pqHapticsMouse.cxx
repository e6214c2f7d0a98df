#include "pqHapticsMouse.h"

#include "pqHapticsDisplay.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSMRenderViewProxy.h>

pqHapticsMouse::~pqHapticsMouse()
{
  this->attach(nullptr);
}

void pqHapticsMouse::attach(vtkSMRenderViewProxy* view)
{
  if (view == this->View && (view == nullptr || this->Interactor))
  {
    return;
  }
  if (this->Interactor)
  {
    for (unsigned long& tag : this->Observers)
    {
      this->Interactor->RemoveObserver(tag);
      tag = 0;
    }
  }
  this->View = view;
  this->Interactor = view ? view->GetInteractor() : nullptr;
  this->State.button = false;
  this->InView = false;
  this->LastPick = Pick();
  if (!this->Interactor)
  {
    return;
  }
  // Priority above the interactor style's observers, so an aborted event never
  // reaches the camera.
  const float priority = 10.0f;
  this->Observers[0] = this->Interactor->AddObserver(
    vtkCommand::LeftButtonPressEvent, this, &pqHapticsMouse::onEvent, priority);
  this->Observers[1] = this->Interactor->AddObserver(
    vtkCommand::MouseMoveEvent, this, &pqHapticsMouse::onEvent, priority);
  this->Observers[2] = this->Interactor->AddObserver(
    vtkCommand::LeftButtonReleaseEvent, this, &pqHapticsMouse::onEvent, priority);
  // Qt's key press reaches the interactor as KeyPressEvent then CharEvent: both are kept
  // from the style (ParaView's keys) while a key switches a pull.
  this->Observers[3] = this->Interactor->AddObserver(
    vtkCommand::KeyPressEvent, this, &pqHapticsMouse::onEvent, priority);
  this->Observers[4] =
    this->Interactor->AddObserver(vtkCommand::CharEvent, this, &pqHapticsMouse::onEvent, priority);
  this->Observers[5] =
    this->Interactor->AddObserver(vtkCommand::LeaveEvent, this, &pqHapticsMouse::onEvent, priority);
}

namespace
{
// vtkRenderer's own display <-> world conversions (those of ParaView's widgets).
class RendererProjection : public geoshaping::interactor::ViewProjection
{
public:
  explicit RendererProjection(vtkRenderer* renderer)
    : Renderer(renderer)
  {
  }
  Eigen::Vector3d to_display(const Eigen::Vector3d& world) const override
  {
    this->Renderer->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
    this->Renderer->WorldToDisplay();
    return Eigen::Map<const Eigen::Vector3d>(this->Renderer->GetDisplayPoint());
  }
  Eigen::Vector3d to_world(const Eigen::Vector3d& display) const override
  {
    this->Renderer->SetDisplayPoint(display.data());
    this->Renderer->DisplayToWorld();
    const double* w = this->Renderer->GetWorldPoint();
    return Eigen::Vector3d(w[0], w[1], w[2]) / w[3];
  }

private:
  vtkRenderer* Renderer;
};
}

bool pqHapticsMouse::pointOnSurface(
  const int display[2], Eigen::Vector3d& world, Eigen::Vector3d& normal) const
{
  return pqHapticsPickSurface(this->View, display, world, normal, &this->ServerPickMilliseconds);
}

geoshaping::interactor::StylusState pqHapticsMouse::stylus(
  bool pressSeen, const Eigen::Vector3d& up)
{
  this->Up = up;
  geoshaping::interactor::StylusState s = this->State;
  vtkRenderer* renderer = this->View ? this->View->GetRenderer() : nullptr;
  if (s.button && !this->Paint && pressSeen && renderer)
  {
    s.position += this->Pull.displacement(RendererProjection(renderer), up);
  }
  return s;
}

void pqHapticsMouse::setControlKey(bool held)
{
  if (auto* interactor = vtkRenderWindowInteractor::SafeDownCast(this->Interactor))
  {
    interactor->SetControlKey(held ? 1 : 0);
  }
}

bool pqHapticsMouse::paint() const
{
  if (this->State.button)
  {
    return this->Paint;
  }
  auto* interactor = vtkRenderWindowInteractor::SafeDownCast(this->Interactor);
  return this->InView && interactor && interactor->GetControlKey() != 0;
}

bool pqHapticsMouse::hover(Eigen::Vector3d& world)
{
  vtkRenderer* renderer = this->View ? this->View->GetRenderer() : nullptr;
  if (this->State.button || !this->InView || !renderer)
  {
    return false;
  }
  const vtkMTimeType camera = renderer->GetActiveCamera()->GetMTime();
  Pick& last = this->LastPick;
  if (last.pixel[0] != this->HoverPixel[0] || last.pixel[1] != this->HoverPixel[1] ||
      last.camera != camera)
  {
    Eigen::Vector3d normal;
    last.onSurface = this->pointOnSurface(this->HoverPixel, last.world, normal);
    last.pixel[0] = this->HoverPixel[0];
    last.pixel[1] = this->HoverPixel[1];
    last.camera = camera;
  }
  world = last.world;
  return last.onSurface;
}

void pqHapticsMouse::setConstraint(geoshaping::interactor::PullConstraint constraint)
{
  vtkRenderer* renderer = this->View ? this->View->GetRenderer() : nullptr;
  this->Pull.choose(constraint);
  if (renderer && this->State.button && !this->Paint)
  {
    this->Pull.constrain(constraint, RendererProjection(renderer), this->Up);
  }
}

bool pqHapticsMouse::onEvent(vtkObject* caller, unsigned long event, void*)
{
  auto* interactor = vtkRenderWindowInteractor::SafeDownCast(caller);
  if (!interactor)
  {
    return false;
  }
  const int* display = interactor->GetEventPosition();
  bool consumed = false;
  if (event == vtkCommand::LeftButtonPressEvent)
  {
    Eigen::Vector3d world, normal;
    if (this->pointOnSurface(display, world, normal))
    {
      this->State.position = world;
      this->State.button = true;
      this->Paint = interactor->GetControlKey() != 0;
      this->Pull.press(Eigen::Vector2d(display[0], display[1]), world, normal);
      consumed = true;
    }
  }
  else if (event == vtkCommand::MouseMoveEvent && !this->State.button)
  {
    // Hovering: the style still sees it (a drag of the camera).
    this->InView = true;
    this->HoverPixel[0] = display[0];
    this->HoverPixel[1] = display[1];
  }
  else if (event == vtkCommand::LeaveEvent)
  {
    this->InView = false;
  }
  else if (event == vtkCommand::MouseMoveEvent && this->State.button)
  {
    Eigen::Vector3d world, normal;
    if (!this->Paint)
    {
      this->Pull.move(Eigen::Vector2d(display[0], display[1]), interactor->GetShiftKey() != 0);
    }
    else if (this->pointOnSurface(display, world, normal))
    {
      this->State.position = world;
    }
    consumed = true;
  }
  else if (event == vtkCommand::LeftButtonReleaseEvent && this->State.button)
  {
    this->State.button = false;
    if (this->Pull.release() && this->constraintShown)
    {
      this->constraintShown(this->Pull.constraint());
    }
    consumed = true;
  }
  else if ((event == vtkCommand::KeyPressEvent || event == vtkCommand::CharEvent) &&
           this->State.button && !this->Paint)
  {
    const auto constraint =
      geoshaping::interactor::constraint_for_key(interactor->GetKeyCode(), this->Pull.constraint());
    vtkRenderer* renderer = this->View ? this->View->GetRenderer() : nullptr;
    if (constraint && event == vtkCommand::KeyPressEvent && renderer)
    {
      this->Pull.constrain(*constraint, RendererProjection(renderer), this->Up);
      if (this->constraintShown)
      {
        this->constraintShown(*constraint);
      }
    }
    consumed = constraint.has_value();
  }
  // true aborts the event: the interactor style (the camera) does not see it.
  return consumed;
}
