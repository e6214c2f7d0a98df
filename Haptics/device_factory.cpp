#include "geoshaping/haptics/device_factory.h"

#include "geoshaping/haptics/null_device.h"
#include "geoshaping/haptics/openhaptics_device.h"
#include "geoshaping/haptics/replay_device.h"
#include "geoshaping/haptics/simulated_device.h"
#include "geoshaping/haptics/trace.h"

namespace geoshaping::haptics
{

std::unique_ptr<HapticDevice> make_device(const std::string& kind, const std::string& arg)
{
  if (kind == "null")
    return std::make_unique<NullDevice>();
  if (kind == "simulated")
  {
    if (arg.empty())
      return std::make_unique<SimulatedDevice>();
    TraceParseResult keys = read_trace_file(arg);
    if (!keys.ok)
      return std::make_unique<NullDevice>(keys.message);
    return std::make_unique<SimulatedDevice>(std::move(keys.samples));
  }
  if (kind == "replay")
    return std::make_unique<ReplayDevice>(arg);
  if (kind == "openhaptics")
    return std::make_unique<OpenHapticsDevice>(arg);
  return std::make_unique<NullDevice>(
    "unknown haptic device kind '" + kind + "' (known: null, simulated, replay, openhaptics)");
}

} // namespace geoshaping::haptics
