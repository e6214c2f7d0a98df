#pragma once
// What the exaggeration test measures of the drawn scene (pqHapticsTestScript's snapshot):
// the deformation's display Scale and its shown obstacles', the mouse's last event pixel,
// and the grasped vertex as drawn (the shown vertex scaled; Position, Orientation and
// Origin are the defaults in these tests) in display pixels, as `key = value` lines.
class QTextStream;
class pqPipelineSource;
class vtkPointSet;

void pqHapticsWriteDrawnGrasp(QTextStream& out, pqPipelineSource* deformation, vtkPointSet* shown);
