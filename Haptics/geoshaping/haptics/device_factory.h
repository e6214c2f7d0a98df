#pragma once
// The backends by name, for the dock's device menu and the tools: the one place that knows
// every HapticDevice subclass (device.h stays the interface alone).
#include "geoshaping/haptics/device.h"

#include <memory>
#include <string>

namespace geoshaping::haptics
{

// Builds a backend by name (not opened):
//   "null"                             NullDevice
//   "simulated" [keyframe trace path]  SimulatedDevice (default motion without a path)
//   "replay"    trace path             ReplayDevice
//   "openhaptics" [HD device name]     OpenHapticsDevice
// An unknown kind gives a NullDevice whose open() fails and names the known kinds.
std::unique_ptr<HapticDevice> make_device(const std::string& kind, const std::string& arg = {});

} // namespace geoshaping::haptics
