#include "pqHapticsDockPanel.h"

#include "pqDEMSurfaceBehavior.h"

#include "pqHapticsBrushPanel.h"
#include "pqHapticsDockRows.h"
#include "pqHapticsMarkers.h"

#include "geoshaping/haptics/openhaptics_device.h"
#include "geoshaping/paint/brush.h"

#include "pqHapticsUndo.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqCoreUtilities.h>
#include <pqUndoStack.h>

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QStringList>
#include <QToolButton>
#include <QVBoxLayout>

namespace interactor = geoshaping::interactor;
using Kind = pqHapticsInteractor::DeviceKind;

namespace
{
QString swatchStyle(double value, bool selected)
{
  const Eigen::Vector3d c = geoshaping::malleability_color(value) * 255.0;
  return QString("QToolButton { background-color: rgb(%1, %2, %3); border: %4px solid %5; }")
    .arg(int(c.x()))
    .arg(int(c.y()))
    .arg(int(c.z()))
    .arg(selected ? 3 : 1)
    .arg(selected ? "#20a0ff" : "#808080");
}
}

pqHapticsDockPanel::pqHapticsDockPanel(QWidget* parent)
  : QDockWidget("Haptics", parent)
{
  this->setObjectName("GeoShapingHapticsDock");
  this->Interactor = new pqHapticsInteractor(this);
  new pqDEMSurfaceBehavior(this); // the session's, with the dock
  this->build();
  QObject::connect(
    this->Interactor, &pqHapticsInteractor::frameDone, this, &pqHapticsDockPanel::onFrame);
  QObject::connect(this->Interactor, &pqHapticsInteractor::paletteValuePicked, this,
    &pqHapticsDockPanel::setPaintValue);
  QObject::connect(this->Interactor, &pqHapticsInteractor::editsChanged, this,
    &pqHapticsDockPanel::onEditsChanged);
  this->followEditSources();
}

void pqHapticsDockPanel::followEditSources()
{
  // The edit count is true whoever changed the list: Load State, Edit > Undo, a panel
  // button, Python. The undo stack may be made after the dock: Start connects again.
  pqApplicationCore* core = pqApplicationCore::instance();
  const auto unique = Qt::UniqueConnection;
  if (pqUndoStack* stack = core->getUndoStack())
  {
    QObject::connect(stack, SIGNAL(stackChanged(bool, QString, bool, QString)), this,
      SLOT(refreshEdits()), unique);
  }
  QObject::connect(core, SIGNAL(stateLoaded(vtkPVXMLElement*, vtkSMProxyLocator*)), this,
    SLOT(refreshEdits()), unique);
  QObject::connect(&pqActiveObjects::instance(), SIGNAL(sourceChanged(pqPipelineSource*)), this,
    SLOT(refreshEdits()), unique);
}

pqHapticsDockPanel::~pqHapticsDockPanel() = default;

void pqHapticsDockPanel::build()
{
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->addWidget(this->buildHand(0));
  layout->addWidget(this->buildHand(1));
  layout->addWidget(pqHapticsPullRow(body, this->Interactor));
  layout->addWidget(pqHapticsExaggerationRow(body, this->Interactor));
  auto* help = new QLabel("<b>Mouse</b>: left-drag the surface to pull it; <b>Ctrl</b>+left-drag "
                          "paints. <b>Stylus</b>: hold the button to use the hand's tool. "
                          "A release commits (Alt+Z undoes).",
    body);
  help->setObjectName("Help");
  help->setWordWrap(true);
  layout->addWidget(help);
  layout->addWidget(new pqHapticsBrushPanel(this->Interactor, body));
  auto* brush = new QFormLayout();
  this->Record = new QLineEdit(body);
  this->Record->setObjectName("Record");
  this->Record->setPlaceholderText("none");
  this->Record->setToolTip(
    "Records each hand's stylus (device coordinates) while running, to replay "
    "it later as a Replay file; hand 2 gets \"-hand2\" in its name.");
  auto* recordBrowse = new QToolButton(body);
  recordBrowse->setText("…");
  auto* recordRow = new QHBoxLayout();
  recordRow->addWidget(this->Record);
  recordRow->addWidget(recordBrowse);
  brush->addRow("Record traces to", recordRow);
  layout->addLayout(brush);
  QObject::connect(recordBrowse, &QToolButton::clicked, this,
    [this]()
    {
      const QString path = QFileDialog::getSaveFileName(
        this, "Record stylus trace", QString(), "Stylus traces (*.trace *.txt);;All files (*)");
      if (!path.isEmpty())
      {
        this->Record->setText(path);
      }
    });
  layout->addWidget(this->buildPalette());
  layout->addWidget(this->buildEdits());
  this->StartStop = new QPushButton("Start", body);
  this->StartStop->setObjectName("StartStop");
  layout->addWidget(this->StartStop);
  this->Figures = new QLabel("frame — fps · deformation — ms", body);
  this->Figures->setObjectName("Figures");
  this->Figures->setWordWrap(true);
  this->Figures->setToolTip(
    "Per hand: its servo loop's rate in updates per second and the force the stylus is "
    "asked to render where it is, in newtons (a force-feedback device; the servo fades a "
    "grasp's pull out while the view updates less than about twice a second), or "
    "\"mouse\". Then the view's frames per second, the time of the last deformation in "
    "milliseconds, and how many vertices it moved; while a drag meets the shaped surface's "
    "Obstacles, how many vertices they held back this frame (the grasp marker then sits on "
    "the grasped vertex, with a line to the cursor).");
  layout->addWidget(this->Figures);
  this->Status = new QLabel(body);
  this->Status->setWordWrap(true);
  layout->addWidget(this->Status);
  layout->addStretch(1);
  // Scrolls rather than clips when the window is short; never scrolls sideways, so long
  // text wraps to the dock's width.
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setWidget(body);
  this->setWidget(scroll);
  pqHapticsTipLabels(body);

  QObject::connect(this->StartStop, &QPushButton::clicked, this, &pqHapticsDockPanel::onStartStop);
  this->setPaintValue(this->Interactor->brush().value);
}

QWidget* pqHapticsDockPanel::buildHand(int hand)
{
  auto* box = new QWidget(this);
  auto* form = new QFormLayout(box);
  form->setContentsMargins(0, 0, 0, 0);
  HandWidgets& w = this->Hands[hand];
  w.device = new QComboBox(box);
  w.device->addItem("None", Kind::NoDevice);
  w.device->addItem("Replay file", Kind::ReplayFile);
  w.device->addItem("Simulated", Kind::Simulated);
  if (geoshaping::haptics::openhaptics_loads()) // GEOSHAPING_LIBHD or libHD.so
  {
    w.device->addItem("OpenHaptics", Kind::OpenHaptics);
  }
  w.device->addItem("Mouse", Kind::Mouse);
  w.device->setCurrentIndex(w.device->findData(hand == 0 ? Kind::Mouse : Kind::NoDevice));
  w.device->setToolTip("What moves this hand: the mouse (drag on the surface), a haptic "
                       "stylus (OpenHaptics), a simulated stylus, or a recorded stylus trace "
                       "replayed from a file.");
  w.file = new QLineEdit(box);
  w.file->setPlaceholderText("trace file (t x y z qw qx qy qz buttons)");
  w.file->setToolTip("Replay file: the recorded stylus trace to play back. Simulated: its "
                     "keyframes (empty: a circle).");
  auto* browse = new QToolButton(box);
  browse->setText("…");
  auto* fileRow = new QHBoxLayout();
  fileRow->addWidget(w.file);
  fileRow->addWidget(browse);
  w.tool = new QComboBox(box);
  w.tool->addItem("Paint", int(interactor::Tool::paint));
  w.tool->addItem("Deform", int(interactor::Tool::deform));
  w.tool->addItem("Hold and turn", int(interactor::Tool::hold_and_turn));
  w.tool->setCurrentIndex(hand == 0 ? 1 : 2);
  w.tool->setToolTip("What the hand does while its button is held. Paint: set how malleable "
                     "the surface is under the brush. Deform: grasp the nearest vertex and "
                     "pull the surface with it. Hold and turn: move and turn the whole "
                     "surface in the view.");
  form->addRow(QString("<b>Hand %1</b> device").arg(hand + 1), w.device);
  form->addRow("Trace", fileRow);
  form->addRow("Tool", w.tool);

  QObject::connect(browse, &QToolButton::clicked, this,
    [this, hand]()
    {
      const QString path = QFileDialog::getOpenFileName(
        this, "Stylus trace", QString(), "Stylus traces (*.trace *.txt);;All files (*)");
      if (!path.isEmpty())
      {
        this->Hands[hand].file->setText(path);
      }
    });
  QObject::connect(w.tool, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
    [this, hand]()
    {
      this->Interactor->setTool(
        hand, interactor::Tool(this->Hands[hand].tool->currentData().toInt()));
    });
  return box;
}

QWidget* pqHapticsDockPanel::buildPalette()
{
  auto* box = new QWidget(this);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setSpacing(2);
  auto* title = new QLabel("Malleability (rigid → soft)", box);
  title->setToolTip("The value a brush paints: 0 (black) rigid, moves as one block; 1 (white) "
                    "soft, bends sharply; red and yellow between bend gradually.");
  grid->addWidget(title, 0, 0, 1, 11);
  for (int i = 0; i <= 10; ++i)
  {
    const double value = i / 10.0;
    auto* swatch = new QToolButton(box);
    swatch->setObjectName(QString("Swatch%1").arg(i));
    swatch->setFixedSize(22, 22);
    swatch->setToolTip(QString("Paint malleability %1").arg(value, 0, 'f', 1));
    swatch->setProperty("malleability", value);
    QObject::connect(
      swatch, &QToolButton::clicked, this, [this, value]() { this->setPaintValue(value); });
    grid->addWidget(swatch, 1, i);
    this->Swatches.append(swatch);
  }
  this->PaintValue = new QLabel(box);
  this->PaintValue->setWordWrap(true);
  grid->addWidget(this->PaintValue, 2, 0, 1, 11);
  return box;
}

QWidget* pqHapticsDockPanel::buildEdits()
{
  auto* box = new QWidget(this);
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(0, 0, 0, 0);
  struct
  {
    QPushButton** button;
    const char* text;
    const char* name;
    interactor::EditCommand command;
    const char* tip;
  } buttons[] = {
    { &this->Undo, "Undo", "UndoEdit", interactor::EditCommand::undo,
      "Undo the last committed edit (Alt+Z while the interactor runs)" },
    { &this->Redo, "Redo", "RedoEdit", interactor::EditCommand::redo,
      "Redo the last undone edit (Alt+Shift+Z or Alt+Y while the interactor runs)" },
    { &this->Reset, "Reset", "ResetEdits", interactor::EditCommand::reset,
      "Back to the original surface; every edit stays redoable" },
    { &this->Snap, "Snap to markers", "SnapToMarkers", interactor::EditCommand::snap,
      "Move the surface onto the deformation's markers through ChainMail, as one edit "
      "(one Undo)" },
  };
  int column = 0;
  for (const auto& b : buttons)
  {
    *b.button = new QPushButton(b.text, box);
    (*b.button)->setObjectName(b.name);
    (*b.button)->setToolTip(b.tip);
    const int command = int(b.command);
    QObject::connect(
      *b.button, &QPushButton::clicked, this, [this, command]() { this->runEdit(command); });
    grid->addWidget(*b.button, 0, column++);
  }
  this->Edits = new QLabel("Edits: 0", box);
  this->Edits->setObjectName("Edits");
  this->Edits->setWordWrap(true); // messages wrap instead of widening the dock
  grid->addWidget(this->Edits, 1, 0, 1, column);
  // The markers as spheres coloured by misfit (a Marker Misfit filter, pqHapticsMarkers.h).
  auto* showMarkers = new QPushButton("Show markers", box);
  showMarkers->setObjectName("ShowMarkerMisfit");
  showMarkers->setToolTip("Draw the deformation's markers as spheres coloured by their misfit "
                          "(adds a Marker Misfit filter)");
  QObject::connect(showMarkers, &QPushButton::clicked, this,
    [this]()
    {
      this->Interactor->proxies().refresh();
      QString why;
      if (!pqHapticsMarkers::show(this->Interactor->proxies().deformation(),
            pqActiveObjects::instance().activeView(), why))
      {
        this->Edits->setText(why);
      }
    });
  grid->addWidget(showMarkers, 2, 0, 1, 2);

  // Alt, not Ctrl: ParaView's own undo stack owns Ctrl+Z / Ctrl+Y (Edit menu). Enabled
  // only while the interactor runs, so they never shadow anything otherwise.
  QWidget* window = pqCoreUtilities::mainWidget();
  const std::pair<const char*, interactor::EditCommand> keys[] = {
    { "Alt+Z", interactor::EditCommand::undo },
    { "Alt+Shift+Z", interactor::EditCommand::redo },
    { "Alt+Y", interactor::EditCommand::redo },
  };
  for (const auto& key : keys)
  {
    auto* shortcut = new QShortcut(QKeySequence(key.first), window ? window : this);
    shortcut->setContext(Qt::ApplicationShortcut);
    shortcut->setEnabled(false);
    const int command = int(key.second);
    QObject::connect(
      shortcut, &QShortcut::activated, this, [this, command]() { this->runEdit(command); });
    QObject::connect(this, &QObject::destroyed, shortcut, &QObject::deleteLater);
    this->Shortcuts.append(shortcut);
  }
  return box;
}

void pqHapticsDockPanel::runEdit(int command)
{
  this->Interactor->runEdit(interactor::EditCommand(command));
}

void pqHapticsDockPanel::onEditsChanged()
{
  this->showEdits(this->Interactor->lastEditResult());
}

void pqHapticsDockPanel::refreshEdits()
{
  this->Interactor->proxies().refresh();
  const auto* deformation = this->Interactor->proxies().deformation();
  this->showEdits(pqHapticsUndo::status(deformation ? deformation->getProxy() : nullptr));
}

void pqHapticsDockPanel::showEdits(const interactor::EditResult& r)
{
  this->Edits->setText(QString::fromStdString(pqHapticsUndo::editsText(r)));
}

void pqHapticsDockPanel::setPaintValue(double value)
{
  interactor::Brush b = this->Interactor->brush();
  b.value = value;
  this->Interactor->setBrush(b);
  for (QToolButton* swatch : this->Swatches)
  {
    const double m = swatch->property("malleability").toDouble();
    swatch->setStyleSheet(swatchStyle(m, std::abs(m - value) < 1e-9));
  }
  this->PaintValue->setText(QString("Paint value %1").arg(value, 0, 'f', 2));
}

void pqHapticsDockPanel::setHand(
  int hand, pqHapticsInteractor::DeviceKind device, const QString& file, interactor::Tool tool)
{
  HandWidgets& w = this->Hands[hand];
  w.device->setCurrentIndex(w.device->findData(device));
  w.file->setText(file);
  w.tool->setCurrentIndex(w.tool->findData(int(tool)));
}

void pqHapticsDockPanel::setRecordPath(const QString& path)
{
  this->Record->setText(path);
}

bool pqHapticsDockPanel::start()
{
  std::array<pqHapticsInteractor::HandSetup, 2> setups;
  const QString record = this->Record->text().trimmed();
  const QFileInfo info(record);
  for (int i = 0; i < 2; ++i)
  {
    setups[i].device = Kind(this->Hands[i].device->currentData().toInt());
    setups[i].file = this->Hands[i].file->text();
    setups[i].tool = interactor::Tool(this->Hands[i].tool->currentData().toInt());
    if (!record.isEmpty())
    {
      setups[i].record =
        i == 0 ? record
               : info.dir().filePath(info.completeBaseName() + "-hand2" +
                                     (info.suffix().isEmpty() ? "" : "." + info.suffix()));
    }
  }
  QString error;
  const bool started = this->Interactor->start(setups, error);
  this->followEditSources();
  this->refreshEdits();
  this->Status->setText(started ? QString() : error);
  this->StartStop->setText(started ? "Stop" : "Start");
  for (QShortcut* shortcut : this->Shortcuts)
  {
    shortcut->setEnabled(started);
  }
  for (const HandWidgets& w : this->Hands)
  {
    w.device->setEnabled(!started);
    w.file->setEnabled(!started);
  }
  this->Record->setEnabled(!started);
  return started;
}

void pqHapticsDockPanel::stop()
{
  this->Interactor->stop();
  this->StartStop->setText("Start");
  for (QShortcut* shortcut : this->Shortcuts)
  {
    shortcut->setEnabled(false);
  }
  for (const HandWidgets& w : this->Hands)
  {
    w.device->setEnabled(true);
    w.file->setEnabled(true);
  }
  this->Record->setEnabled(true);
  const auto& recorded = this->Interactor->figures().recordedSamples;
  if (recorded[0] + recorded[1] > 0)
  {
    this->Status->setText(
      QString("Recorded %1 + %2 stylus samples").arg(recorded[0]).arg(recorded[1]));
  }
}

void pqHapticsDockPanel::onStartStop()
{
  if (this->Interactor->isRunning())
  {
    this->stop();
  }
  else
  {
    this->start();
  }
}

void pqHapticsDockPanel::onFrame()
{
  const pqHapticsInteractor::Figures& f = this->Interactor->figures();
  // Per hand in use: the servo loop's rate, or that the mouse has none.
  QStringList hands;
  for (int i = 0; i < 2; ++i)
  {
    const Kind kind = Kind(this->Hands[i].device->currentData().toInt());
    if (kind == Kind::Mouse)
    {
      hands << QString("hand %1: mouse, no force feedback").arg(i + 1);
    }
    else if (!f.deviceError[i].isEmpty())
    {
      hands << QString("hand %1: %2").arg(i + 1).arg(f.deviceError[i]);
    }
    else if (kind != Kind::NoDevice)
    {
      hands << QString("hand %1: servo %2 Hz, force %3 N")
                 .arg(i + 1)
                 .arg(f.servoHz[i], 0, 'f', 0)
                 .arg(f.force[i].force.norm(), 0, 'f', 2);
    }
  }
  QString text = QString("%1\nframe %2 fps · deformation %3 ms, %4 points displaced")
                   .arg(hands.join(" · "))
                   .arg(f.framesPerSecond, 0, 'f', 1)
                   .arg(f.deformationMilliseconds, 0, 'f', 2)
                   .arg(f.displacedPoints);
  if (f.obstacleBlockedPoints >= 0)
  {
    text += QString("\nheld back by obstacles: %1").arg(f.obstacleBlockedPoints);
  }
  if (f.markersInside >= 0)
  {
    text += QString("\nmarkers: vertical misfit RMS %1, max %2 (%3 inside)")
              .arg(f.markerMisfitRMS, 0, 'g', 4)
              .arg(f.markerMisfitMax, 0, 'g', 4)
              .arg(f.markersInside);
  }
  if (f.serverPatchMilliseconds >= 0.0)
  {
    text += QString("\ncontact patch from the server: %1 ms, %2 bytes")
              .arg(f.serverPatchMilliseconds, 0, 'f', 1)
              .arg(f.serverPatchBytes);
  }
  if (f.serverPickMilliseconds >= 0.0)
  {
    text += QString("\nlast pick on the server: %1 ms").arg(f.serverPickMilliseconds, 0, 'f', 1);
  }
  if (!f.serverPatchMessage.isEmpty())
  {
    text += "\n" + f.serverPatchMessage;
  }
  this->Figures->setText(text);
}
