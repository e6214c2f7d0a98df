#pragma once
// What the exaggeration test measures of the drawn scene (pqHapticsTestScript's snapshot):
// the deformation's display Scale and its shown obstacles', the mouse's last event pixel,
// and the grasped vertex as drawn (the shown vertex scaled; Position, Orientation and
// Origin are the defaults in these tests) in display pixels, as `key = value` lines.
class QTextStream;
class pqPipelineSource;
class vtkPointSet;

void pqHapticsWriteDrawnGrasp(QTextStream& out, pqPipelineSource* deformation, vtkPointSet* shown);

// The active render view's InteractionMode ("interaction_mode", 0 3D, 1 2D), its size
// ("view_px"), and per pipeline source shown in it ("shown_NAME = visible colour-array
// x0 x1 y0 y1": the pixels its data's bounding box spans on screen).
void pqHapticsWriteShown(QTextStream& out);
