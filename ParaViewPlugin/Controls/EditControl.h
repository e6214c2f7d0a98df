#pragma once
// The point dabs that paint the surface the user sees, and what the dock's Redo restores,
// free of Qt, VTK and ParaView so that they are unit tested
// (Testing/GUI/TestEditControl.cpp). The edit commands and their
// bookkeeping are ParaViewPlugin/ServerManager/edit_commands.h.
#include "geoshaping/paint/brush.h"

#include <string>
#include <vector>

namespace geoshaping::interactor
{

// Paint on the surface the user sees: the points under a brush (ids, distances to its
// centre on the shown surface) -> MalleabilityPaint PointDabs triples (id, value,
// weight = strength * falloff(d / radius)), with the core's falloff (geoshaping/paint/brush.h,
// the one MalleabilityPaint applies). Points with weight 0 are left out.
void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, Falloff falloff, std::vector<double>& triples);

// What the dock's Redo restores, press after press, as its label counts it: the edits the
// deformation's RedoEdit can re-apply (`redoable_edits`) and the paint strokes waiting on
// ParaView's redo stack (`redo_labels`, top first: the steps labelled `stroke_label`).
// Steps of anything else are not counted (the dock's Redo does not step them).
int redoable_steps(
  int redoable_edits, const std::vector<std::string>& redo_labels, const std::string& stroke_label);

} // namespace geoshaping::interactor
