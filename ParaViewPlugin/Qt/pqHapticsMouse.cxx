#include "pqHapticsMouse.h"

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
}

bool pqHapticsMouse::pointOnSurface(const int display[2], Eigen::Vector3d& world) const
{
  double p[3], normal[3];
  if (!this->View || !this->View->ConvertDisplayToPointOnSurface(display, p, normal))
  {
    return false;
  }
  world = Eigen::Vector3d(p[0], p[1], p[2]);
  return world.allFinite();
}

Eigen::Vector3d pqHapticsMouse::pointOnDragPlane(const int display[2]) const
{
  vtkRenderer* renderer = this->View ? this->View->GetRenderer() : nullptr;
  if (!renderer)
  {
    return this->State.position;
  }
  const Eigen::Vector3d& anchor = this->State.position;
  renderer->SetWorldPoint(anchor.x(), anchor.y(), anchor.z(), 1.0);
  renderer->WorldToDisplay();
  const double depth = renderer->GetDisplayPoint()[2];
  renderer->SetDisplayPoint(display[0], display[1], depth);
  renderer->DisplayToWorld();
  const double* w = renderer->GetWorldPoint();
  if (w[3] == 0.0)
  {
    return anchor;
  }
  return Eigen::Vector3d(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
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
    Eigen::Vector3d world;
    if (this->pointOnSurface(display, world))
    {
      this->State.position = world;
      this->State.button = true;
      this->Paint = interactor->GetControlKey() != 0;
      consumed = true;
    }
  }
  else if (event == vtkCommand::MouseMoveEvent && this->State.button)
  {
    Eigen::Vector3d world;
    if (!this->Paint)
    {
      this->State.position = this->pointOnDragPlane(display);
    }
    else if (this->pointOnSurface(display, world))
    {
      this->State.position = world;
    }
    consumed = true;
  }
  else if (event == vtkCommand::LeftButtonReleaseEvent && this->State.button)
  {
    this->State.button = false;
    consumed = true;
  }
  // true aborts the event: the interactor style (the camera) does not see it.
  return consumed;
}
