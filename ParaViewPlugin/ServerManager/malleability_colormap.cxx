#include "malleability_colormap.h"

#include "geoshaping/paint/malleability_preset.h" // its name and points, for the core
#include "geoshaping_malleability_preset.h"       // ../Presets/Malleability_black-body.json

#include "vtkLogger.h"
#include "vtkSMSettings.h"
#include "vtkSMTransferFunctionPresets.h"

#include <vtk_jsoncpp.h>

#include <memory>
#include <sstream>

namespace geoshaping::colormap
{

namespace
{
constexpr const char* array_name = "Malleability";
// Below a site's (0.5) and the user's (1.0) settings files.
constexpr double settings_priority = 0.25;
}

bool register_malleability_colormap()
{
  static bool registered = false;
  if (registered)
  {
    return true;
  }
  Json::Value presets;
  std::string errors;
  Json::CharReaderBuilder builder;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  const char* text = geoshaping_malleability_preset;
  if (!reader->parse(text, text + std::char_traits<char>::length(text), &presets, &errors) ||
      !presets.isArray() || presets.size() != 1 ||
      presets[0]["Name"].asString() != geoshaping::malleability_preset_name)
  {
    vtkLog(ERROR, "GeoShaping: the embedded Malleability preset is not one preset named '"
                    << geoshaping::malleability_preset_name << "': " << errors);
    return false;
  }
  auto* list = vtkSMTransferFunctionPresets::GetInstance();
  if (!list->HasPreset(geoshaping::malleability_preset_name))
  {
    list->ImportPresets(presets);
  }

  Json::Value settings;
  settings["standard_presets"][array_name] = geoshaping::malleability_preset_name;
  Json::Value& table = settings["array_lookup_tables"][array_name];
  table["Title"] = array_name;
  Json::Value& lut = table["PVLookupTable"];
  lut["AutomaticRescaleRangeMode"] = "Never";
  for (const char* annotation : { "0", "rigid", "1", "soft" })
  {
    lut["Annotations"].append(annotation);
  }
  registered = vtkSMSettings::GetInstance()->AddCollectionFromString(
    Json::writeString(Json::StreamWriterBuilder(), settings), settings_priority);
  return registered;
}

namespace
{
// The plugin's load: ParaView has no per-plugin hook outside the GUI, and pvpython,
// pvbatch and the GUI all load this library with the plugin.
const bool registered_at_load = register_malleability_colormap();
}

} // namespace geoshaping::colormap
