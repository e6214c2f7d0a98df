#pragma once
// The markers drawn as spheres coloured by misfit (docs/markers.md, "Seen in the view"):
// the dock's "Show markers" adds a Marker Misfit filter on the deformation and its
// Markers input, shown in `view` with the Point Gaussian representation coloured by
// `Misfit` (a diverging map centred on 0), the spheres' radius 1 % of the surface's size.
// One step of ParaView's undo stack. Holds no rule: Marker Misfit measures.
#include <QString>

class pqPipelineSource;
class pqView;

namespace pqHapticsMarkers
{
// The new filter, or null with `why` set (no deformation, no markers connected).
pqPipelineSource* show(pqPipelineSource* deformation, pqView* view, QString& why);
}
