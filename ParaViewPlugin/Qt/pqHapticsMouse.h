#pragma once
// The mouse as a stylus, for users without a device: a left-button drag that starts on
// the surface of the render view is taken from the camera (an observer on the view's
// interactor, ahead of the interactor style) and becomes a stylus held down. The drag
// pulls the grasp with the cursor (PullControl: in the plane through the grasp parallel
// to the screen, or along the vertical or the surface normal; Shift held: a tenth of the
// motion); with Ctrl held at the press the hand paints instead, and the stylus follows
// the surface. During a pull the keys of constraint_for_key (Z, N, C) switch its
// constraint for that pull, continuing from where the grasp is.
#include "HapticsControl.h"
#include "PullControl.h"

#include <vtkWeakPointer.h>

#include <functional>

class vtkObject;
class vtkSMRenderViewProxy;

class pqHapticsMouse
{
public:
  ~pqHapticsMouse();
  // Observes `view`'s interactor (nullptr: stops observing).
  void attach(vtkSMRenderViewProxy* view);

  // The stylus this frame, world coordinates: the pressed point until the hand has seen
  // the press (`pressSeen`), then the pressed point plus the pull's displacement, seen
  // through the view's current camera; `up` is the scene's vertical. Painting: the point
  // of the surface under the cursor.
  geoshaping::interactor::StylusState stylus(bool pressSeen, const Eigen::Vector3d& up);
  // The constraint chosen for every pull, from now on, also mid-pull (without a jump:
  // PullControl).
  void setConstraint(geoshaping::interactor::PullConstraint constraint);
  // Called when the constraint in force changes without being chosen: a key switched it
  // for this pull, or the release went back to the chosen one.
  std::function<void(geoshaping::interactor::PullConstraint)> constraintShown;
  // The grasped vertex (world): the pull's plane and lines go through it.
  void setGrasp(const Eigen::Vector3d& world) { this->Pull.set_grasp(world); }
  // True for a drag that began with Ctrl held; between drags, while Ctrl is held (the
  // next press would paint).
  bool paint() const;
  // Ctrl pressed or released anywhere in the application (pqHapticsInteractor's key
  // filter): the view's interactor hears of keys only while it has the keyboard focus,
  // which hovering does not give it, and otherwise kept Ctrl held until the mouse moved.
  void setControlKey(bool held);
  // Between drags, the point of the surface under the hovering mouse (world): false when
  // the mouse is off the surface or out of the view. A pick, made again only when the
  // mouse or the camera has moved since the last one.
  bool hover(Eigen::Vector3d& world);
  // The round trip of the last pick that asked the server's ranks (the view rendering
  // remotely: GeoShapingRayPick), ms; < 0 while none did.
  double lastServerPickMilliseconds() const { return this->ServerPickMilliseconds; }

private:
  bool onEvent(vtkObject* caller, unsigned long event, void*);
  bool pointOnSurface(const int display[2], Eigen::Vector3d& world, Eigen::Vector3d& normal) const;

  vtkWeakPointer<vtkSMRenderViewProxy> View;
  vtkWeakPointer<vtkObject> Interactor;
  unsigned long Observers[6] = { 0, 0, 0, 0, 0, 0 };
  geoshaping::interactor::StylusState State; // the pressed point, or the painting point
  geoshaping::interactor::PullControl Pull;
  bool Paint = false;
  mutable double ServerPickMilliseconds = -1.0;
  Eigen::Vector3d Up = Eigen::Vector3d::UnitZ(); // the scene's vertical at the last frame
  // Hovering: the mouse's pixel in the view (none: out of it), and the last pick there.
  bool InView = false;
  int HoverPixel[2] = { 0, 0 };
  struct Pick
  {
    int pixel[2] = { -1, -1 };
    vtkMTimeType camera = 0;
    bool onSurface = false;
    Eigen::Vector3d world = Eigen::Vector3d::Zero();
  } LastPick;
};
