#include "geoshaping/haptics/replay_device.h"
#include "geoshaping/haptics/trace.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

using namespace geoshaping::haptics;

namespace
{
std::string temp_path(const std::string& name)
{
  return std::string(GEOSHAPING_HAPTICS_TEST_DIR) + "/" + name;
}

void write_file(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

TraceParseResult parse(const std::string& text)
{
  std::istringstream in(text);
  return parse_trace(in, "mem");
}

bool bit_identical(const DeviceSample& a, const DeviceSample& b)
{
  return std::memcmp(&a.t, &b.t, sizeof(double)) == 0 &&
         std::memcmp(a.position.data(), b.position.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(
           a.orientation.coeffs().data(), b.orientation.coeffs().data(), 4 * sizeof(double)) == 0 &&
         a.buttons == b.buttons;
}
} // namespace

TEST(Trace, ParsesSamplesAndSkipsCommentsAndBlankLines)
{
  const TraceParseResult r = parse("# a stylus trace\n"
                                   "\n"
                                   "0 0.01 -0.02 0.03 1 0 0 0 0\n"
                                   "0.001 0.011 -0.02 0.03 0 0 0 2 1   # quaternion normalised\n"
                                   "  0.002\t0.012 -0.02 0.03 1 0 0 0 3\n");
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.samples.size(), 3u);
  EXPECT_EQ(r.samples[1].t, 0.001);
  EXPECT_EQ(r.samples[1].position, Eigen::Vector3d(0.011, -0.02, 0.03));
  EXPECT_EQ(r.samples[1].orientation.z(), 1.0);
  EXPECT_EQ(r.samples[1].buttons, 1u);
  EXPECT_EQ(r.samples[2].buttons, 3u);
}

TEST(Trace, BadLineGivesAnErrorWithItsLineNumber)
{
  const char* good = "0 0 0 0 1 0 0 0 0\n# comment\n";
  EXPECT_EQ(parse(std::string(good) + "0.1 0 0 1 0 0 0 0\n").message,
    "mem:3: expected 9 fields 't x y z qw qx qy qz buttons', found 8");
  EXPECT_EQ(parse(std::string(good) + "0.1 0 zero 0 1 0 0 0 0\n").message,
    "mem:3: field y 'zero' is not a number");
  EXPECT_EQ(parse(std::string(good) + "0.1 0 0 0 1 0 0 0 -1\n").message,
    "mem:3: buttons '-1' is not an unsigned integer");
  EXPECT_EQ(parse(std::string(good) + "0.1 0 0 0 0 0 0 0 0\n").message,
    "mem:3: orientation quaternion has zero length");
  EXPECT_EQ(parse(std::string(good) + "\n-1 0 0 0 1 0 0 0 0\n")
              .message.rfind("mem:4: time goes backwards", 0),
    0u);
  EXPECT_FALSE(parse(std::string(good) + "0.1 0 0 0 1 0 0 0 0\n0.2 0 0 0 1 0 0 0 x\n").ok);
}

TEST(Trace, NonFiniteValuesAreRejected)
{
  for (const char* bad : { "0 nan 0 0 1 0 0 0 0", "0 0 inf 0 1 0 0 0 0", "0 0 0 0 1 -inf 0 0 0",
         "0 1e999 0 0 1 0 0 0 0" })
  {
    const TraceParseResult r = parse(std::string("# header\n") + bad + "\n");
    EXPECT_FALSE(r.ok) << bad;
    EXPECT_EQ(r.message.rfind("mem:2: field", 0), 0u) << r.message;
    EXPECT_TRUE(r.samples.empty());
  }
}

TEST(Trace, PositionsTooLargeToInterpolateAreRejected)
{
  const TraceParseResult r = parse("0 1e308 0 0 1 0 0 0 0\n1 -1e308 0 0 1 0 0 0 0\n");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.message.rfind("mem:1: field x '1e308' is beyond", 0), 0u) << r.message;
  EXPECT_TRUE(parse("0 1e6 -1e6 0 1 0 0 0 0\n").ok);
  EXPECT_FALSE(parse("0 0 0 -1.5e6 1 0 0 0 0\n").ok);
}

TEST(Trace, MissingFileIsReportedByName)
{
  const TraceParseResult r = read_trace_file(temp_path("no_such_trace.txt"));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("no_such_trace.txt: cannot open"), std::string::npos);
  ReplayDevice device(temp_path("no_such_trace.txt"));
  EXPECT_FALSE(device.open());
  EXPECT_TRUE(device.has_error());
}

TEST(Trace, RecorderOutputReadsBackBitIdentical)
{
  std::vector<DeviceSample> in;
  for (int i = 0; i < 50; ++i)
  {
    DeviceSample s;
    s.t = i * 0.001;
    s.position = Eigen::Vector3d(std::sin(i * 0.1) / 3.0, 1e-7 * i, -0.1 / (i + 1));
    s.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * i, Eigen::Vector3d(1, 2, 3).normalized()));
    s.buttons = std::uint32_t(i % 4);
    in.push_back(s);
  }
  const std::string path = temp_path("recorded_trace.txt");
  TraceRecorder recorder;
  ASSERT_TRUE(recorder.open(path)) << recorder.error();
  for (const DeviceSample& s : in)
    ASSERT_TRUE(recorder.record(s));
  DeviceSample broken;
  broken.position.x() = std::nan("");
  EXPECT_FALSE(recorder.record(broken));
  EXPECT_TRUE(recorder.close());
  EXPECT_EQ(recorder.samples(), in.size());

  const TraceParseResult out = read_trace_file(path);
  ASSERT_TRUE(out.ok) << out.message;
  ASSERT_EQ(out.samples.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    EXPECT_TRUE(bit_identical(in[i], out.samples[i])) << "sample " << i;
}

TEST(Replay, InterpolatesBetweenSamplesAndRestsAfterTheEnd)
{
  std::vector<DeviceSample> keys(2);
  keys[0].t = 0.0;
  keys[1].t = 1.0;
  keys[1].position = Eigen::Vector3d(0.1, 0, 0);
  keys[1].orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  keys[1].buttons = 1;
  const DeviceSample mid = sample_trace_at(keys, 0.25);
  EXPECT_NEAR(mid.position.x(), 0.025, 1e-15);
  EXPECT_NEAR(Eigen::AngleAxisd(mid.orientation).angle(), 0.25, 1e-12);
  EXPECT_EQ(mid.buttons, 0u); // a press is not invented before it was recorded
  EXPECT_EQ(sample_trace_at(keys, 7.0).position, keys[1].position);
  EXPECT_EQ(sample_trace_at(keys, -1.0).position, keys[0].position);
  EXPECT_EQ(sample_trace_at(keys, std::nan("")).position, keys[0].position);
}

TEST(Replay, IsDeterministicAndFollowsTheFile)
{
  const std::string path = temp_path("replay_trace.txt");
  write_file(path, "# t x y z qw qx qy qz buttons\n"
                   "10.0 0 0 0 1 0 0 0 0\n"
                   "10.1 0.01 0 0 1 0 0 0 1\n"
                   "10.2 0.01 0.02 0 0.7071 0 0 0.7071 1\n");
  // Two devices replaying the same file on a stepped clock give the same samples, bit
  // for bit, and the trace plays from its first time stamp.
  ReplayDevice a(path, 0.001), b(path, 0.001);
  ASSERT_TRUE(a.open()) << a.error();
  ASSERT_TRUE(b.open()) << b.error();
  DeviceSample sa, sb;
  for (int i = 0; i < 250; ++i)
  {
    ASSERT_TRUE(a.read(sa));
    ASSERT_TRUE(b.read(sb));
    ASSERT_TRUE(bit_identical(sa, sb)) << "read " << i;
    if (i == 50)
    {
      EXPECT_NEAR(sa.t, 0.05, 1e-12);
      EXPECT_NEAR(sa.position.x(), 0.005, 1e-12);
      EXPECT_EQ(sa.buttons, 0u);
    }
    if (i == 150)
    {
      EXPECT_NEAR(sa.position.y(), 0.01, 1e-9);
      EXPECT_EQ(sa.buttons, 1u);
    }
  }
  EXPECT_TRUE(a.finished());
  EXPECT_NEAR(sa.position.y(), 0.02, 1e-15);
  EXPECT_NEAR(sa.orientation.norm(), 1.0, 1e-15);
}

TEST(Replay, BadTraceFileFailsToOpenWithTheLineNumber)
{
  const std::string path = temp_path("bad_trace.txt");
  write_file(path, "0 0 0 0 1 0 0 0 0\n0.1 0 0 0 1 0 0 0 0 extra\n");
  ReplayDevice device(path);
  EXPECT_FALSE(device.open());
  EXPECT_EQ(device.error(), path + ":2: expected 9 fields 't x y z qw qx qy qz buttons', found 10");
}
