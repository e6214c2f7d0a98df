#pragma once
// Auto-start of the GeoShaping plugin in the paraview GUI: makes the
// "Malleability (black-body)" colour map available in the preset list.
#include <QObject>

class pqGeoShapingStarter : public QObject
{
  Q_OBJECT

public:
  explicit pqGeoShapingStarter(QObject* parent = nullptr);
  ~pqGeoShapingStarter() override = default;

  void onStartup();
  void onShutdown() {}
};
