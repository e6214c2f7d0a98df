#include "pqGeoShapingTestStarter.h"

#include "pqHapticsDockPanel.h"
#include "pqHapticsTestHook.h"

#include <pqCoreUtilities.h>

#include <QTimer>
#include <QWidget>

pqGeoShapingTestStarter::pqGeoShapingTestStarter(QObject* parent)
  : QObject(parent)
{
}

pqGeoShapingTestStarter::~pqGeoShapingTestStarter() = default;

void pqGeoShapingTestStarter::onStartup()
{
  this->findDock();
}

// The dock is created when the GeoShaping plugin's interfaces are loaded, which may be
// before or after this plugin's: look for it every 100 ms for up to 30 s.
void pqGeoShapingTestStarter::findDock()
{
  QWidget* window = pqCoreUtilities::mainWidget();
  auto* dock = window ? window->findChild<pqHapticsDockPanel*>() : nullptr;
  if (dock)
  {
    pqHapticsTestHook::installIfRequested(dock);
    return;
  }
  if (++this->Polls < 300)
  {
    QTimer::singleShot(100, this, &pqGeoShapingTestStarter::findDock);
  }
  else
  {
    qWarning("GeoShapingTesting: no Haptics dock after 30 s; is the GeoShaping plugin loaded?");
  }
}
