#include "geoshaping/haptics/device_factory.h"
#include "geoshaping/haptics/null_device.h"
#include "geoshaping/haptics/openhaptics_device.h"
#include "recording_device.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace geoshaping::haptics;

TEST(Devices, OpenHapticsWithoutTheSdkFailsToOpenWithAClearMessage)
{
  // A library name that cannot exist stands in for a machine without OpenHaptics, so
  // the test holds even where the SDK is installed.
  OpenHapticsDevice device({}, "libHD_geoshaping_absent.so");
  EXPECT_FALSE(device.open());
  EXPECT_FALSE(device.is_open());
  EXPECT_TRUE(device.has_error());
  EXPECT_EQ(device.error().rfind("OpenHaptics (libHD.so) not found: ", 0), 0u) << device.error();
  DeviceSample s;
  EXPECT_FALSE(device.read(s));
  EXPECT_FALSE(device.set_force(Eigen::Vector3d(1, 0, 0)));
}

TEST(Devices, MakeDeviceBuildsEveryKindAndRefusesUnknownOnes)
{
  EXPECT_EQ(make_device("null")->name(), "null");
  EXPECT_EQ(make_device("simulated")->name(), "simulated");
  EXPECT_EQ(make_device("replay", "x.txt")->name(), "replay");
  EXPECT_EQ(make_device("openhaptics")->name(), "openhaptics");
  const auto unknown = make_device("phantom-omni");
  EXPECT_FALSE(unknown->open());
  EXPECT_NE(unknown->error().find("unknown haptic device kind 'phantom-omni'"), std::string::npos);
}

TEST(Devices, NullDeviceOpensAndRestsAtTheOrigin)
{
  NullDevice device;
  ASSERT_TRUE(device.open());
  DeviceSample s;
  s.position.x() = 5;
  EXPECT_TRUE(device.read(s));
  EXPECT_EQ(s.position, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.buttons, 0u);
  EXPECT_TRUE(device.set_force(Eigen::Vector3d(1, 2, 3)));
}

TEST(Devices, SimulatedDeviceFollowsItsScriptOnASteppedClock)
{
  SimulatedDevice device(
    [](double t)
    {
      DeviceSample s;
      s.position = Eigen::Vector3d(t, 2 * t, 0);
      s.buttons = t >= 0.005 ? 1u : 0u;
      return s;
    });
  device.set_time_step(0.001);
  ASSERT_TRUE(device.open());
  DeviceSample s;
  for (int i = 0; i <= 6; ++i)
    ASSERT_TRUE(device.read(s));
  EXPECT_DOUBLE_EQ(s.t, 0.006);
  EXPECT_DOUBLE_EQ(s.position.y(), 0.012);
  EXPECT_EQ(s.buttons, 1u);
}

TEST(Devices, SimulatedDeviceInErrorStopsReadingAndClampsForces)
{
  RecordingDevice device;
  ASSERT_TRUE(device.open());
  device.set_force(Eigen::Vector3d(100, 0, 0));
  EXPECT_DOUBLE_EQ(device.last_force().x(), device.limits().max_force);
  device.set_force(Eigen::Vector3d(std::nan(""), 0, 0));
  EXPECT_EQ(device.last_force(), Eigen::Vector3d::Zero());
  device.inject_error("encoder fault");
  DeviceSample s;
  EXPECT_FALSE(device.read(s));
  EXPECT_EQ(device.error(), "encoder fault");
  device.clear_error();
  EXPECT_TRUE(device.read(s));
}
