#pragma once
// Auto-start of the test-only GeoShapingTesting plugin: once the GeoShaping plugin's
// Haptics dock exists, hands it to pqHapticsTestHook (which does nothing unless the
// environment asks for it). The product plugin knows nothing of this.
#include <QObject>

class pqGeoShapingTestStarter : public QObject
{
  Q_OBJECT

public:
  explicit pqGeoShapingTestStarter(QObject* parent = nullptr);
  ~pqGeoShapingTestStarter() override;

  void onStartup();
  void onShutdown() {}

private Q_SLOTS:
  void findDock();

private:
  int Polls = 0;
};
