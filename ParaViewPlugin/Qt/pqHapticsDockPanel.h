#pragma once
// The "Haptics" dock: a device and a tool for each hand, the brush radius, the
// malleability palette (click a swatch to paint that value), start/stop and live figures.
// Thin: every decision is in pqHapticsInteractor and HapticsControl.
#include "pqHapticsInteractor.h"

#include <QDockWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QShortcut;
class QToolButton;

class pqHapticsDockPanel : public QDockWidget
{
  Q_OBJECT

public:
  explicit pqHapticsDockPanel(QWidget* parent = nullptr);
  ~pqHapticsDockPanel() override;

  pqHapticsInteractor* interactor() const { return this->Interactor; }
  // Chooses a hand's device (as the combo boxes would) and starts.
  void setHand(int hand, pqHapticsInteractor::DeviceKind device, const QString& file,
    geoshaping::interactor::Tool tool);
  // The trace file hand 1 records to (empty: no recording); hand 2 records next to it
  // with "-hand2" before the extension.
  void setRecordPath(const QString& path);
  bool start();
  void stop();

private Q_SLOTS:
  void onStartStop();
  void onFrame();
  void setPaintValue(double value);
  void runEdit(int command);
  void onEditsChanged();
  // Reads the target's edits afresh (Load State, Edit > Undo, a panel button, Start).
  void refreshEdits();

private:
  struct HandWidgets
  {
    QComboBox* device = nullptr;
    QLineEdit* file = nullptr;
    QComboBox* tool = nullptr;
  };
  void build();
  QWidget* buildHand(int hand);
  QWidget* buildPalette();
  QWidget* buildEdits();
  void showEdits(const geoshaping::interactor::EditResult& r);
  void followEditSources();

  pqHapticsInteractor* Interactor = nullptr;
  HandWidgets Hands[2];
  QLineEdit* Record = nullptr;
  QLabel* PaintValue = nullptr;
  QList<QToolButton*> Swatches;
  QPushButton* StartStop = nullptr;
  QLabel* Figures = nullptr;
  QLabel* Status = nullptr;
  QPushButton* Undo = nullptr;
  QPushButton* Redo = nullptr;
  QPushButton* Reset = nullptr;
  QPushButton* Snap = nullptr;
  QLabel* Edits = nullptr;
  QList<QShortcut*> Shortcuts;
};
