#include "pqGeoShapingStarter.h"

#include <vtkSMTransferFunctionPresets.h>

#include <QFileInfo>

pqGeoShapingStarter::pqGeoShapingStarter(QObject* parent)
  : QObject(parent)
{
}

void pqGeoShapingStarter::onStartup()
{
  // The preset ships in the source tree (ParaViewPlugin/Presets); ParaView 5.11 has no
  // way for a plugin to install one, so import it by path when it is there.
  const char* name = "Malleability (black-body)";
  const QString path = QStringLiteral(GEOSHAPING_PRESET_FILE);
  auto* presets = vtkSMTransferFunctionPresets::GetInstance();
  if (!presets->HasPreset(name) && QFileInfo::exists(path))
  {
    presets->ImportPresets(path.toUtf8().constData());
  }
}
