// OpenHapticsDevice against the fake HD library (FakeHD/): the real backend code, the
// real HD call sequence and constants, a scripted device. The fake's scheduler is held
// and stepped tick by tick wherever a test asserts values, so nothing here depends on
// the machine's speed; the ServoLoop test waits for conditions, never for a time.
#include "fake_hd.h"

#include "geoshaping/haptics/device_factory.h"
#include "geoshaping/haptics/openhaptics_device.h"
#include "geoshaping/haptics/servo_loop.h"

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cstdlib>
#include <thread>

using namespace geoshaping::haptics;
using namespace std::chrono_literals;

namespace
{
constexpr unsigned int hd_nominal_max_damping = 0x2609; // hdDefines.h

// The fake's test controls, resolved from the same file the backend dlopen()s: one
// library instance, one state.
struct FakeHD
{
  void* handle = dlopen(GEOSHAPING_FAKE_HD, RTLD_NOW | RTLD_LOCAL);
#define FAKEHD_SYMBOL(name) decltype(&::name) name = resolve<decltype(&::name)>(#name)
  template<class F>
  F resolve(const char* name) const
  {
    return handle ? reinterpret_cast<F>(dlsym(handle, name)) : nullptr;
  }
  FAKEHD_SYMBOL(fakehd_reset);
  FAKEHD_SYMBOL(fakehd_state);
  FAKEHD_SYMBOL(fakehd_calls);
  FAKEHD_SYMBOL(fakehd_set_position);
  FAKEHD_SYMBOL(fakehd_set_rotation);
  FAKEHD_SYMBOL(fakehd_set_buttons);
  FAKEHD_SYMBOL(fakehd_set_nominal);
  FAKEHD_SYMBOL(fakehd_set_workspace);
  FAKEHD_SYMBOL(fakehd_reject_parameter);
  FAKEHD_SYMBOL(fakehd_inject_fault);
  FAKEHD_SYMBOL(fakehd_clear_fault);
  FAKEHD_SYMBOL(fakehd_last_force);
  FAKEHD_SYMBOL(fakehd_hold);
  FAKEHD_SYMBOL(fakehd_step);
  FAKEHD_SYMBOL(fakehd_scheduler_rate);
#undef FAKEHD_SYMBOL
  ~FakeHD()
  {
    if (handle)
      dlclose(handle);
  }

  FakeHDState state() const
  {
    FakeHDState s;
    fakehd_state(&s);
    return s;
  }
  Eigen::Vector3d last_force() const
  {
    Eigen::Vector3d f;
    fakehd_last_force(f.data());
    return f;
  }
};

class OpenHaptics : public ::testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_NE(fake.handle, nullptr) << dlerror();
    ASSERT_NE(fake.fakehd_scheduler_rate, nullptr);
    fake.fakehd_reset();
  }
  // Whatever a test did, the backend kept HD's rules: frames only on the scheduler
  // thread, forces only inside frames, one initialisation per disable.
  void TearDown() override
  {
    if (fake.handle)
      EXPECT_EQ(fake.state().misuse, 0u);
  }

  FakeHD fake;
};

DeviceSample read_one(OpenHapticsDevice& device)
{
  DeviceSample s;
  EXPECT_TRUE(device.read(s)) << device.error();
  return s;
}
} // namespace

TEST_F(OpenHaptics, OpenRunsTheHDSequenceAndTheSchedulerAt1kHz)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  EXPECT_TRUE(device.is_open());
  EXPECT_STREQ(fake.fakehd_calls(), "init make_current enable rate=1000 schedule start");
  const FakeHDState s = fake.state();
  EXPECT_EQ(s.initialized, 1);
  EXPECT_EQ(s.force_output, 1);
  EXPECT_EQ(s.scheduler_running, 1);
  EXPECT_EQ(s.callbacks, 1);
  EXPECT_EQ(fake.fakehd_scheduler_rate(), 1000u);

  // Time stamps count HD ticks at the asked rate: 25 ticks are 25 ms, and reading the
  // same tick twice gives the same time (no velocity from a repeated sample).
  fake.fakehd_hold(1);
  const double t0 = read_one(device).t;
  EXPECT_EQ(read_one(device).t, t0);
  ASSERT_EQ(fake.fakehd_step(25), 1);
  EXPECT_NEAR(read_one(device).t - t0, 0.025, 1e-12);
}

TEST_F(OpenHaptics, PositionMillimetresBecomeMetresTransformAQuaternionButtonsABitmask)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  fake.fakehd_hold(1);
  // A rotation of 0.7 rad about (1, 2, 3)/|.|, given to the fake row-major; the fake
  // serves it column-major as HD does, so reading it transposed would give -0.7 rad.
  const Eigen::AngleAxisd rotation(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = rotation.toRotationMatrix();
  fake.fakehd_set_rotation(r.data());
  fake.fakehd_set_position(12.5, -40.0, 7.0);
  fake.fakehd_set_buttons(0x1 | 0x2); // HD_DEVICE_BUTTON_1 | HD_DEVICE_BUTTON_2
  ASSERT_EQ(fake.fakehd_step(1), 1);
  const DeviceSample s = read_one(device);
  EXPECT_NEAR((s.position - Eigen::Vector3d(0.0125, -0.040, 0.007)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(s.orientation.angularDistance(Eigen::Quaterniond(rotation)), 0.0, 1e-12);
  EXPECT_EQ(s.buttons, 3u);
}

TEST_F(OpenHaptics, ForcesInNewtonsReachTheDeviceClampedToItsNominalMaximum)
{
  fake.fakehd_set_nominal(2.0, 1.0, 0.0025);
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  fake.fakehd_hold(1);
  ASSERT_TRUE(device.set_force(Eigen::Vector3d(1.0, -1.5, 0.5)));
  ASSERT_EQ(fake.fakehd_step(1), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d(1.0, -1.5, 0.5));
  // 3 N along (3, 0, -4)/5 is more than the device's 2 N: sent as 2 N, same direction.
  ASSERT_TRUE(device.set_force(Eigen::Vector3d(1.8, 0.0, -2.4)));
  ASSERT_EQ(fake.fakehd_step(1), 1);
  EXPECT_NEAR((fake.last_force() - Eigen::Vector3d(1.2, 0.0, -1.6)).norm(), 0.0, 1e-15);
  device.set_force(Eigen::Vector3d(std::nan(""), 0.0, 0.0));
  ASSERT_EQ(fake.fakehd_step(1), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d::Zero());
}

TEST_F(OpenHaptics, LimitsComeFromTheDeviceInSIUnits)
{
  fake.fakehd_set_nominal(2.5, 0.9, 0.004); // N, N/mm, N s/mm
  const double box[6] = { -100, -50, -20, 100, 70, 60 };
  fake.fakehd_set_workspace(box);
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  const DeviceLimits& l = device.limits();
  EXPECT_DOUBLE_EQ(l.max_force, 2.5);
  EXPECT_DOUBLE_EQ(l.max_stiffness, 900.0);
  EXPECT_DOUBLE_EQ(l.max_damping, 4.0);
  EXPECT_NEAR((l.workspace_min - Eigen::Vector3d(-0.1, -0.05, -0.02)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((l.workspace_max - Eigen::Vector3d(0.1, 0.07, 0.06)).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(l.workspace_radius, 0.04); // half the smallest extent, 80 mm
}

TEST_F(OpenHaptics, ALimitTheDriverLacksKeepsItsDefaultAndTheDeviceStillOpens)
{
  fake.fakehd_set_nominal(2.5, 0.9, 0.004);
  fake.fakehd_reject_parameter(hd_nominal_max_damping);
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  EXPECT_DOUBLE_EQ(device.limits().max_damping, DeviceLimits().max_damping);
  EXPECT_DOUBLE_EQ(device.limits().max_stiffness, 900.0);
  DeviceSample s;
  EXPECT_TRUE(device.read(s)) << device.error();
}

TEST_F(OpenHaptics, ADeviceFaultZeroesTheForceAtOnceAndLatchesAClearError)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  fake.fakehd_hold(1);
  fake.fakehd_set_position(5.0, 0.0, 0.0);
  ASSERT_TRUE(device.set_force(Eigen::Vector3d(-1.5, 0.0, 0.0))); // pulling, mid-grasp
  ASSERT_EQ(fake.fakehd_step(1), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d(-1.5, 0.0, 0.0));
  read_one(device);

  // The fault tick itself sends what it was given (HD says so only at its end); the
  // next tick sends zero on its own, before the servo side has even read the fault.
  fake.fakehd_inject_fault();
  fake.fakehd_set_position(9.0, 9.0, 9.0); // not served: every HD call now fails
  ASSERT_EQ(fake.fakehd_step(2), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d::Zero());

  DeviceSample s;
  EXPECT_FALSE(device.read(s));
  ASSERT_TRUE(device.has_error());
  EXPECT_NE(device.error().find("HD_DEVICE_FAULT (0x0300"), std::string::npos) << device.error();
  EXPECT_NE(device.error().find("force output stopped"), std::string::npos) << device.error();
  EXPECT_FALSE(device.set_force(Eigen::Vector3d(-1.5, 0.0, 0.0)));

  // The device comes back by itself: the backend still sends nothing until reopened.
  fake.fakehd_clear_fault();
  ASSERT_EQ(fake.fakehd_step(40), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d::Zero());
  EXPECT_FALSE(device.read(s));
  EXPECT_TRUE(device.has_error());

  device.close();
  fake.fakehd_hold(0);
  ASSERT_TRUE(device.open()) << device.error();
  EXPECT_FALSE(device.has_error());
  fake.fakehd_hold(1);
  ASSERT_EQ(fake.fakehd_step(1), 1);
  EXPECT_NEAR(
    (read_one(device).position - Eigen::Vector3d(0.009, 0.009, 0.009)).norm(), 0.0, 1e-15);
}

TEST_F(OpenHaptics, AFaultBetweenTwoServoReadsIsNotLost)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  fake.fakehd_hold(1);
  // One faulty tick, then many healthy ones, all between two reads of the servo thread
  // (the triple buffer only keeps the newest frame).
  fake.fakehd_inject_fault();
  ASSERT_EQ(fake.fakehd_step(1), 1);
  fake.fakehd_clear_fault();
  ASSERT_EQ(fake.fakehd_step(40), 1);
  DeviceSample s;
  EXPECT_FALSE(device.read(s));
  EXPECT_NE(device.error().find("HD_DEVICE_FAULT"), std::string::npos) << device.error();
}

TEST_F(OpenHaptics, AFaultMidGraspUnderTheServoLoopGivesZeroForceAndNoCrash)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  fake.fakehd_set_position(5.0, 0.0, 0.0); // 5 mm from the grasp anchor
  ServoLoop loop(device);
  ASSERT_TRUE(loop.start()) << loop.error();

  // The graphics side: a fresh grasp scene at every poll; the fake runs free at 1 kHz.
  std::uint64_t sequence = 0;
  auto poll_until = [&](auto done)
  {
    DeviceSnapshot snap;
    for (const auto give_up = Clock::now() + 10s; Clock::now() < give_up;)
    {
      SceneSnapshot& scene = loop.scene_back();
      scene.stamp = Clock::now();
      scene.sequence = ++sequence;
      scene.grasping = true;
      scene.grasp_anchor = Eigen::Vector3d::Zero();
      scene.grasp_stiffness = 200.0;
      loop.publish_scene();
      loop.poll_device(snap);
      if (done(snap))
        return true;
      std::this_thread::sleep_for(2ms);
    }
    return false;
  };
  ASSERT_TRUE(poll_until([&](const DeviceSnapshot& s)
    { return s.status == ForceStatus::ok && fake.last_force().x() < -0.5; }))
    << "the grasp never pulled: " << fake.last_force().transpose();

  fake.fakehd_inject_fault();
  EXPECT_TRUE(poll_until([&](const DeviceSnapshot& s)
    { return s.status == ForceStatus::device_error && !s.device_ok; }));
  EXPECT_TRUE(device.has_error());
  EXPECT_NE(device.error().find("HD_DEVICE_FAULT"), std::string::npos) << device.error();
  ASSERT_EQ(fake.fakehd_step(2), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d::Zero());

  fake.fakehd_clear_fault(); // the servo keeps running; the force stays zero
  ASSERT_EQ(fake.fakehd_step(50), 1);
  EXPECT_EQ(fake.last_force(), Eigen::Vector3d::Zero());
  EXPECT_TRUE(loop.running());
  loop.stop();
  device.close();
  EXPECT_EQ(fake.state().scheduler_running, 0);
  EXPECT_EQ(fake.state().initialized, 0);
}

TEST_F(OpenHaptics, CloseStopsTheSchedulerUnschedulesAndDisablesTheDevice)
{
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  ASSERT_TRUE(device.open()) << device.error();
  device.close();
  EXPECT_FALSE(device.is_open());
  EXPECT_STREQ(fake.fakehd_calls(),
    "init make_current enable rate=1000 schedule start stop unschedule disable");
  const FakeHDState s = fake.state();
  EXPECT_EQ(s.scheduler_running, 0);
  EXPECT_EQ(s.scheduler_stops, 1);
  EXPECT_EQ(s.callbacks, 0);
  EXPECT_EQ(s.initialized, 0);
  EXPECT_EQ(s.disabled, 1);
  EXPECT_EQ(s.force_output, 0);
  EXPECT_EQ(fake.fakehd_step(1), 0) << "no tick after close";
  device.close(); // twice is harmless
  EXPECT_EQ(fake.state().disabled, 1);
  ASSERT_TRUE(device.open()) << device.error(); // the device was released: it reopens
}

TEST_F(OpenHaptics, AnUnknownDeviceNameFailsWithHDsReasonAndReleasesEverything)
{
  OpenHapticsDevice device("Phantom 7", GEOSHAPING_FAKE_HD);
  EXPECT_FALSE(device.open());
  EXPECT_EQ(device.error().rfind("OpenHaptics: cannot initialise device 'Phantom 7': ", 0), 0u)
    << device.error();
  EXPECT_NE(device.error().find("HD_COMM_CONFIG_ERROR"), std::string::npos) << device.error();
  EXPECT_EQ(fake.state().scheduler_running, 0);
  EXPECT_STREQ(fake.fakehd_calls(), "init");
}

TEST_F(OpenHaptics, ASchedulerThatNeverTicksFailsOpenInsteadOfServingNoSample)
{
  fake.fakehd_hold(1); // the scheduler will start parked
  OpenHapticsDevice device({}, GEOSHAPING_FAKE_HD);
  EXPECT_FALSE(device.open());
  EXPECT_NE(device.error().find("no servo tick"), std::string::npos) << device.error();
  EXPECT_FALSE(device.is_open());
  const FakeHDState s = fake.state();
  EXPECT_EQ(s.scheduler_running, 0);
  EXPECT_EQ(s.initialized, 0);
  EXPECT_EQ(s.callbacks, 0);
}

TEST_F(OpenHaptics, TheLibraryIsTheOneGEOSHAPING_LIBHDNames)
{
  const char* saved = std::getenv("GEOSHAPING_LIBHD");
  const std::string restore = saved ? saved : "";
  unsetenv("GEOSHAPING_LIBHD");
  EXPECT_EQ(openhaptics_library(), "libHD.so");

  setenv("GEOSHAPING_LIBHD", GEOSHAPING_FAKE_HD, 1);
  EXPECT_EQ(openhaptics_library(), GEOSHAPING_FAKE_HD);
  std::string why;
  EXPECT_TRUE(openhaptics_loads(&why)) << why;
  const auto device = make_device("openhaptics");
  EXPECT_TRUE(device->open()) << device->error();
  device->close();
  EXPECT_EQ(fake.state().disabled, 1);

  setenv("GEOSHAPING_LIBHD", "/nonexistent/libHD.so", 1);
  EXPECT_FALSE(openhaptics_loads(&why));
  EXPECT_NE(why.find("/nonexistent/libHD.so"), std::string::npos) << why;
  const auto absent = make_device("openhaptics");
  EXPECT_FALSE(absent->open());
  EXPECT_NE(absent->error().find("/nonexistent/libHD.so"), std::string::npos) << absent->error();

  if (saved)
    setenv("GEOSHAPING_LIBHD", restore.c_str(), 1);
  else
    unsetenv("GEOSHAPING_LIBHD");
}
