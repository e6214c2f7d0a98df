#pragma once
// Stylus traces: the plain-text file format shared by ReplayDevice, SimulatedDevice
// keyframes and TraceRecorder, and interpolation between samples.
//
// One sample per line, whitespace separated, SI units in device coordinates:
//
//   t x y z qw qx qy qz buttons
//
//   t        seconds, non-decreasing down the file
//   x y z    stylus position, metres, each within +-1e6 (so interpolation stays finite)
//   qw..qz   orientation quaternion (normalised on reading if its length is not 1
//            within 1e-9; must not be zero)
//   buttons  unsigned decimal bitmask, bit 0 = first button
//
// Blank lines and everything after '#' are ignored. Numbers are read and written in
// the C locale; the recorder writes the shortest text that reads back to the same
// double, so record -> replay is bit-identical.
#include "geoshaping/haptics/device.h"

#include <fstream>
#include <iosfwd>
#include <string>
#include <vector>

namespace geoshaping::haptics
{

struct TraceParseResult
{
  bool ok = false;
  std::string message; // "<source>:<line>: <what is wrong>" when !ok
  std::vector<DeviceSample> samples;
};

// Parses a whole trace; stops at the first bad line. `source` names the input in messages.
TraceParseResult parse_trace(std::istream& in, const std::string& source = "trace");
TraceParseResult read_trace_file(const std::string& path);
// One line of the format above, without the newline.
std::string format_trace_sample(const DeviceSample& s);

// The sample at time t: positions interpolate linearly and orientations by slerp between
// the two samples around t; buttons are those of the sample at or before t (a press is
// never invented between samples). Before the first sample: the first; after the last:
// the last (the stylus rests). `samples` must be non-empty and sorted by t.
DeviceSample sample_trace_at(const std::vector<DeviceSample>& samples, double t);

// Writes samples in the format above. Writing is plain buffered file I/O, so call it
// from the graphics thread with device snapshots, never from the servo thread.
class TraceRecorder
{
public:
  // Creates or truncates `path` and writes a header comment; false with error() if not.
  bool open(const std::string& path);
  bool record(const DeviceSample& s);
  // Flushes and closes; false if any write failed (a rejected sample does not count).
  bool close();
  bool is_open() const { return out_.is_open(); }
  const std::string& error() const { return error_; }
  std::size_t samples() const { return count_; }

private:
  std::ofstream out_;
  std::string path_;
  std::string error_;
  std::size_t count_ = 0;
};

} // namespace geoshaping::haptics
