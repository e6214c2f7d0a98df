#pragma once
// The brush part of the Haptics dock: the radius in the scene's unit (from the data
// unless set, kept in the state), the strength, and what the last stroke did. Thin: the
// rules are in BrushControl.h and pqHapticsInteractor.
#include <QWidget>

class pqHapticsInteractor;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

class pqHapticsBrushPanel : public QWidget
{
  Q_OBJECT

public:
  pqHapticsBrushPanel(pqHapticsInteractor* interactor, QWidget* parent = nullptr);

private Q_SLOTS:
  void refresh();
  void showBrush();

private:
  pqHapticsInteractor* Interactor;
  QDoubleSpinBox* Radius = nullptr;
  QToolButton* Default = nullptr;
  QLabel* About = nullptr;
  QDoubleSpinBox* Strength = nullptr;
  QLabel* Note = nullptr;
};
