#pragma once
// The point dabs that paint the surface the user sees, free of Qt, VTK and ParaView so that
// they are unit tested (Testing/GUI/TestEditControl.cpp). The edit commands and their
// bookkeeping are ParaViewPlugin/ServerManager/edit_commands.h.
#include "geoshaping/paint/brush.h"

#include <vector>

namespace geoshaping::interactor
{

// Paint on the surface the user sees: the points under a brush (ids, distances to its
// centre on the shown surface) -> MalleabilityPaint PointDabs triples (id, value,
// weight = strength * falloff(d / radius)), with the core's falloff (geoshaping/paint/brush.h,
// the one MalleabilityPaint applies). Points with weight 0 are left out.
void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, Falloff falloff, std::vector<double>& triples);

} // namespace geoshaping::interactor
