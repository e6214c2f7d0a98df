#include "pqHapticsDockRows.h"

#include "DisplayTransform.h"
#include "pqHapticsInteractor.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLayout>
#include <QSignalBlocker>

#include <cmath>

namespace
{
QString tipOf(QLayoutItem* item)
{
  if (!item)
  {
    return QString();
  }
  if (QWidget* w = item->widget())
  {
    return w->toolTip();
  }
  QLayout* layout = item->layout();
  for (int i = 0; layout && i < layout->count(); ++i)
  {
    const QString tip = tipOf(layout->itemAt(i));
    if (!tip.isEmpty())
    {
      return tip;
    }
  }
  return QString();
}
}

QWidget* pqHapticsPullRow(QWidget* parent, pqHapticsInteractor* interactor)
{
  using geoshaping::interactor::PullConstraint;
  auto* box = new QWidget(parent);
  auto* form = new QFormLayout(box);
  form->setContentsMargins(0, 0, 0, 0);
  auto* constraint = new QComboBox(box);
  constraint->setObjectName("PullConstraint");
  constraint->addItem("Follow the cursor", int(PullConstraint::view_plane));
  constraint->addItem("Vertical only (z)", int(PullConstraint::vertical));
  constraint->addItem("Along the surface normal", int(PullConstraint::normal));
  constraint->setCurrentIndex(constraint->findData(int(interactor->pullConstraint())));
  constraint->setToolTip(
    "How a mouse pull moves the grasped point.\n"
    "Follow the cursor: it stays under the cursor, in the plane through it parallel to the "
    "screen, whatever the zoom and the data's size.\n"
    "Vertical only (z): only its elevation changes (x and y kept); moving the cursor along "
    "the vertical's direction on the screen raises or lowers it.\n"
    "Along the surface normal: it moves across the surface where it was grasped, as a "
    "horizon pushed up or down through its thickness.\n"
    "Hold Shift while dragging for fine control: the point moves a tenth of the cursor's "
    "motion.\n"
    "Keys while dragging: Z vertical, N along the normal, C follow the cursor; the key of the "
    "choice in force frees the pull again. The choice can change mid-pull, here or by key: "
    "the pull goes on from where the point is, without a jump. A stylus keeps its own "
    "workspace mapping.");
  auto* hint = new QLabel("Hold <b>Shift</b> while pulling for a tenth of the motion; "
                          "<b>Z</b> vertical, <b>N</b> normal, <b>C</b> free while dragging.",
    box);
  hint->setObjectName("PullHint");
  hint->setWordWrap(true);
  hint->setToolTip(constraint->toolTip());
  auto* mode = new QLabel(box);
  mode->setObjectName("PullMode");
  mode->setWordWrap(true);
  mode->setToolTip(constraint->toolTip());
  const auto showMode = [interactor, mode](int c)
  {
    mode->setText(QString::fromStdString(
      geoshaping::interactor::pull_mode_note(PullConstraint(c), interactor->pullConstraint())));
  };
  showMode(int(interactor->pullConstraint()));
  form->addRow("Pull", constraint);
  form->addRow(mode);
  form->addRow(hint);
  QObject::connect(constraint, QOverload<int>::of(&QComboBox::currentIndexChanged), interactor,
    [interactor, constraint]()
    { interactor->setPullConstraint(PullConstraint(constraint->currentData().toInt())); });
  // The row shows the constraint in force: a key's during its pull, then the chosen one
  // again (not a choice: the combo's signal is held).
  QObject::connect(interactor, &pqHapticsInteractor::pullConstraintChanged, constraint,
    [constraint, showMode](int c)
    {
      const QSignalBlocker quiet(constraint);
      constraint->setCurrentIndex(constraint->findData(c));
      showMode(c);
    });
  pqHapticsTipLabels(box);
  return box;
}

QWidget* pqHapticsExaggerationRow(QWidget* parent, pqHapticsInteractor* interactor)
{
  namespace gi = geoshaping::interactor;
  auto* box = new QWidget(parent);
  auto* form = new QFormLayout(box);
  form->setContentsMargins(0, 0, 0, 0);
  auto* spin = new QDoubleSpinBox(box);
  spin->setObjectName("VerticalExaggeration");
  spin->setRange(gi::min_exaggeration, gi::max_exaggeration);
  spin->setDecimals(1);
  spin->setSingleStep(1.0);
  spin->setValue(1.0);
  spin->setSuffix(" \u00d7");
  spin->setKeyboardTracking(false);
  spin->setToolTip(
    "Stretches the view of the shaped surface (and of its obstacles) along z: their display "
    "Scale becomes (1, 1, s), as Properties > Transforming > Scale does. The hand keeps "
    "working where the surface is drawn: hover, paint and pulls land under the cursor, and a "
    "pull moves the data by the cursor's motion in data units (a drawn rise over s).");
  form->addRow("Vertical exaggeration", spin);
  QObject::connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), interactor,
    [interactor](double s)
    {
      interactor->proxies().refresh();
      interactor->proxies().setVerticalExaggeration(s);
    });
  QObject::connect(interactor, &pqHapticsInteractor::frameDone, spin,
    [interactor, spin]()
    {
      const double s = interactor->proxies().verticalExaggeration();
      if (!spin->hasFocus() && std::isfinite(s) && s != spin->value())
      {
        const QSignalBlocker quiet(spin);
        spin->setValue(s);
      }
    });
  pqHapticsTipLabels(box);
  return box;
}

void pqHapticsTipLabels(QWidget* root)
{
  for (QFormLayout* form : root->findChildren<QFormLayout*>())
  {
    for (int row = 0; row < form->rowCount(); ++row)
    {
      QLayoutItem* label = form->itemAt(row, QFormLayout::LabelRole);
      QWidget* labelWidget = label ? label->widget() : nullptr;
      const QString tip = tipOf(form->itemAt(row, QFormLayout::FieldRole));
      if (labelWidget && labelWidget->toolTip().isEmpty() && !tip.isEmpty())
      {
        labelWidget->setToolTip(tip);
      }
    }
  }
}
