#pragma once
// The mouse as a stylus, for users without a device: a left-button drag that starts on
// the surface of the render view is taken from the camera (an observer on the view's
// interactor, ahead of the interactor style) and becomes a stylus held down. The drag
// moves in the plane through the pressed point parallel to the screen; with Ctrl held
// at the press the hand paints instead of deforming, and the stylus follows the surface.
#include "HapticsControl.h"

#include <vtkWeakPointer.h>

class vtkObject;
class vtkSMRenderViewProxy;

class pqHapticsMouse
{
public:
  ~pqHapticsMouse();
  // Observes `view`'s interactor (nullptr: stops observing).
  void attach(vtkSMRenderViewProxy* view);

  // World coordinates. `paint` is true for a drag that began with Ctrl held.
  const geoshaping::interactor::StylusState& state() const { return this->State; }
  bool paint() const { return this->Paint; }

private:
  bool onEvent(vtkObject* caller, unsigned long event, void*);
  bool pointOnSurface(const int display[2], Eigen::Vector3d& world) const;
  Eigen::Vector3d pointOnDragPlane(const int display[2]) const;

  vtkWeakPointer<vtkSMRenderViewProxy> View;
  vtkWeakPointer<vtkObject> Interactor;
  unsigned long Observers[3] = { 0, 0, 0 };
  geoshaping::interactor::StylusState State;
  bool Paint = false;
};
