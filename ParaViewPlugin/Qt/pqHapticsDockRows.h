#pragma once
// Pieces of the Haptics dock (pqHapticsDockPanel): the Pull row, the vertical
// exaggeration row, and the tooltips of the dock's row labels.
class QWidget;
class pqHapticsInteractor;

// The "Pull" row: how a mouse pull moves the grasped point (PullControl.h), as a combo box
// named "PullConstraint" that sets the interactor's constraint, and a line under it that
// says Shift makes the motion finer.
QWidget* pqHapticsPullRow(QWidget* parent, pqHapticsInteractor* interactor);

// The "Vertical exaggeration" row: a spin box named "VerticalExaggeration" that gives the
// shaped surface and its obstacles the display Scale (1, 1, s) together
// (pqHapticsProxies::setVerticalExaggeration), and shows the surface's own while the
// interactor runs (a Scale set in the Properties panel too).
QWidget* pqHapticsExaggerationRow(QWidget* parent, pqHapticsInteractor* interactor);

// Gives every label of a form row under `root` the tooltip of its field (the field's own,
// or that of the first widget with one in the field's layout), so pointing at the words
// explains them as pointing at the control does.
void pqHapticsTipLabels(QWidget* root);
