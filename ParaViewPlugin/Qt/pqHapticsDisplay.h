#pragma once
// The interactor's link between the view and the data (DisplayTransform.h): a
// representation's display transform, and the pick of the surface under a pixel through it.
#include "DisplayTransform.h"

class vtkSMProxy;
class vtkSMRenderViewProxy;

// The display transform of a representation (its Position, Orientation, Origin, Scale);
// the identity for nullptr or a representation without them.
geoshaping::interactor::DisplayTransform pqHapticsDisplayTransform(vtkSMProxy* representation);

// The point of the surface shown at display pixel `display` of `view`, and the surface's
// normal there (toward the viewer), world coordinates: the view's one-pixel cell
// selection names the representation and the cell; the view ray, carried into that
// representation's data coordinates (DisplayTransform), meets the cell there (ParaView's
// PickingHelper, on the server), and the point found is carried back. ParaView's own
// ConvertDisplayToPointOnSurface meets the world ray with the data's cell, which misses
// under any Scale but 1 (a vertical exaggeration). False when no surface shows there.
// `serverMilliseconds`, when given: the round trip of the ranks' ray pick when the view
// renders remotely (GeoShapingRayPick), else left as it is.
bool pqHapticsPickSurface(vtkSMRenderViewProxy* view, const int display[2], Eigen::Vector3d& world,
  Eigen::Vector3d& normal, double* serverMilliseconds = nullptr);
