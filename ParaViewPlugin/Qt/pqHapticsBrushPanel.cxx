#include "pqHapticsBrushPanel.h"

#include "pqHapticsInteractor.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqServerManagerModel.h>

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

namespace interactor = geoshaping::interactor;

pqHapticsBrushPanel::pqHapticsBrushPanel(pqHapticsInteractor* haptics, QWidget* parent)
  : QWidget(parent)
  , Interactor(haptics)
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout();
  layout->addLayout(form);
  this->Radius = new QDoubleSpinBox(this);
  this->Radius->setObjectName("BrushRadius");
  this->Radius->setRange(0.0, 1e12);
  this->Radius->setDecimals(3);
  this->Radius->setSpecialValueText("fit to the data");
  this->Radius->setToolTip("Brush radius, in the unit of the data (metres for geographic or "
                           "projected data). Until you set it, 3 % of the diagonal of the "
                           "data's bounding box; kept with the state (MalleabilityPaint's "
                           "BrushRadius).");
  this->Default = new QToolButton(this);
  this->Default->setObjectName("BrushRadiusDefault");
  this->Default->setText("Fit");
  this->Default->setToolTip("Back to the radius that fits the data: 3 % of its diagonal.");
  auto* row = new QHBoxLayout();
  row->addWidget(this->Radius, 1);
  row->addWidget(this->Default);
  auto* radiusLabel = new QLabel("Brush radius", this);
  radiusLabel->setToolTip(this->Radius->toolTip());
  form->addRow(radiusLabel, row);
  this->About = new QLabel(this);
  this->About->setObjectName("BrushRadiusAbout");
  this->About->setWordWrap(true);
  form->addRow(QString(), this->About);
  this->Strength = new QDoubleSpinBox(this);
  this->Strength->setObjectName("BrushStrength");
  this->Strength->setRange(0.0, 1.0);
  this->Strength->setSingleStep(0.05);
  this->Strength->setDecimals(2);
  this->Strength->setValue(haptics->brush().strength);
  this->Strength->setToolTip("How far each dab moves the malleability toward the swatch's "
                             "value at the brush's centre: 1 paints the value itself, 0.5 "
                             "half way (the falloff lowers it toward the rim).");
  auto* strengthLabel = new QLabel("Strength", this);
  strengthLabel->setToolTip(this->Strength->toolTip());
  form->addRow(strengthLabel, this->Strength);
  this->Note = new QLabel(this);
  this->Note->setObjectName("BrushNote");
  this->Note->setWordWrap(true);
  layout->addWidget(this->Note); // wraps to the dock's width (a form row would clip it)

  QObject::connect(this->Radius, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double radius) { this->Interactor->setBrushRadius(radius); });
  QObject::connect(this->Default, &QToolButton::clicked, this,
    [this]() { this->Interactor->setBrushRadius(0.0); });
  QObject::connect(this->Strength, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double strength)
    {
      interactor::Brush b = this->Interactor->brush();
      b.strength = strength;
      this->Interactor->setBrush(b);
    });
  QObject::connect(
    haptics, &pqHapticsInteractor::brushChanged, this, &pqHapticsBrushPanel::showBrush);
  // The data may change without the interactor running: a new source, Apply, Load State.
  QObject::connect(&pqActiveObjects::instance(), &pqActiveObjects::sourceChanged, this,
    &pqHapticsBrushPanel::refresh);
  QObject::connect(pqApplicationCore::instance()->getServerManagerModel(),
    &pqServerManagerModel::dataUpdated, this, &pqHapticsBrushPanel::refresh);
  this->refresh();
  this->showBrush();
}

void pqHapticsBrushPanel::refresh()
{
  this->Interactor->refreshBrush();
}

void pqHapticsBrushPanel::showBrush()
{
  const interactor::Brush& brush = this->Interactor->brush();
  const std::string& unit = this->Interactor->sceneUnit();
  const bool fitted = this->Interactor->brushFitsData();
  {
    // Before data, 0: the spin box's special text ("fit to the data", as 0 typed means).
    const QSignalBlocker blocker(this->Radius);
    this->Radius->setSuffix(unit.empty() ? QString() : QString(" %1").arg(unit.c_str()));
    this->Radius->setValue(fitted ? brush.radius : 0.0);
  }
  this->About->setText(QString::fromStdString(interactor::radius_about(
    brush.radius, unit, this->Interactor->brushRadiusIsDefault(), fitted)));
  this->Note->setText(this->Interactor->brushNote());
}
