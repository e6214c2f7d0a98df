#pragma once
// The GUI tests' checks of ParaView's undo stack against the Haptics dock's edits
// (docs/editing.md, "ParaView's undo stack"): Edit > Undo / Redo after a drag, the edit
// count after File > Load State, and the bounds (the filter's output, the Information
// panel's, Reset Camera) once the shape settles. Written as `key = value` lines.
class QTextStream;
class pqHapticsDockPanel;

namespace pqHapticsUndoChecks
{

// After a committed drag: triggers Edit > Undo then Edit > Redo (the menu's actions),
// then the dock's Undo and Redo, and writes what each left (grasp, points, bounds) and
// the labels of ParaView's undo steps. Leaves the released shape, as it found it.
void writeEditMenu(QTextStream& out, pqHapticsDockPanel* dock);

// GEOSHAPING_GUI_STATE=<file.pvsm>: loads it as File > Load State does; true once done.
// False without the variable.
bool loadStateIfRequested();

// After Load State and Start: what the dock's edit line says, then the dock's Undo, and
// the bounds and Reset Camera after it.
void writeLoadedState(QTextStream& out, pqHapticsDockPanel* dock);

} // namespace pqHapticsUndoChecks
