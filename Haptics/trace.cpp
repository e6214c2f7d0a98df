#include "geoshaping/haptics/trace.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>

namespace geoshaping::haptics
{

namespace
{

// Whitespace-separated tokens of one line, '#' to the end of line dropped.
std::vector<std::string_view> tokens(std::string_view line)
{
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    if (i > start)
      out.push_back(line.substr(start, i - start));
  }
  return out;
}

// from_chars: locale-independent and exact; the whole token must be consumed.
template<class T>
bool parse_number(std::string_view s, T& value)
{
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  return ec == std::errc() && ptr == end;
}

constexpr const char* field_names[] = { "t", "x", "y", "z", "qw", "qx", "qy", "qz" };

// A stylus reaches tens of centimetres; the bound keeps every difference, interpolation
// and workspace-to-scene mapping of positions finite (1e308 would interpolate to inf).
constexpr double max_position = 1e6; // m

} // namespace

TraceParseResult parse_trace(std::istream& in, const std::string& source)
{
  TraceParseResult result;
  std::string line;
  std::size_t line_number = 0;
  auto fail = [&](const std::string& what)
  {
    result.message = source + ":" + std::to_string(line_number) + ": " + what;
    result.samples.clear();
    return result;
  };
  while (std::getline(in, line))
  {
    ++line_number;
    const std::vector<std::string_view> f = tokens(line);
    if (f.empty())
      continue;
    if (f.size() != 9)
      return fail(
        "expected 9 fields 't x y z qw qx qy qz buttons', found " + std::to_string(f.size()));
    double v[8];
    for (int i = 0; i < 8; ++i)
    {
      if (!parse_number(f[i], v[i]))
        return fail(
          "field " + std::string(field_names[i]) + " '" + std::string(f[i]) + "' is not a number");
      if (!std::isfinite(v[i]))
        return fail("field " + std::string(field_names[i]) + " is not finite");
    }
    for (int i = 1; i < 4; ++i)
      if (std::abs(v[i]) > max_position)
        return fail("field " + std::string(field_names[i]) + " '" + std::string(f[i]) +
                    "' is beyond the 1e6 m a stylus position may reach");
    DeviceSample s;
    if (!parse_number(f[8], s.buttons))
      return fail("buttons '" + std::string(f[8]) + "' is not an unsigned integer");
    s.t = v[0];
    s.position = Eigen::Vector3d(v[1], v[2], v[3]);
    s.orientation = Eigen::Quaterniond(v[4], v[5], v[6], v[7]);
    const double norm = s.orientation.norm();
    if (!(norm > 1e-12) || !std::isfinite(norm))
      return fail("orientation quaternion has zero length");
    // Already-unit quaternions are kept bit for bit so record -> replay is exact.
    if (std::abs(norm - 1.0) > 1e-9)
      s.orientation.coeffs() /= norm;
    if (!result.samples.empty() && s.t < result.samples.back().t)
      return fail("time goes backwards (" + std::string(f[0]) + " after " +
                  std::to_string(result.samples.back().t) + ")");
    result.samples.push_back(s);
  }
  if (in.bad())
    return fail("read error");
  result.ok = true;
  return result;
}

TraceParseResult read_trace_file(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    TraceParseResult r;
    r.message = path + ": cannot open trace file";
    return r;
  }
  return parse_trace(in, path);
}

std::string format_trace_sample(const DeviceSample& s)
{
  const double v[8] = { s.t, s.position.x(), s.position.y(), s.position.z(), s.orientation.w(),
    s.orientation.x(), s.orientation.y(), s.orientation.z() };
  std::string out;
  char buffer[32];
  for (double x : v)
  {
    // Shortest round-trip representation: the text reads back to the same double.
    const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x);
    out.append(buffer, r.ptr);
    out.push_back(' ');
  }
  out += std::to_string(s.buttons);
  return out;
}

DeviceSample sample_trace_at(const std::vector<DeviceSample>& samples, double t)
{
  if (!(t > samples.front().t)) // also catches NaN t
    return samples.front();
  if (t >= samples.back().t)
    return samples.back();
  // First sample strictly after t; its predecessor is at or before t.
  const auto hi = std::upper_bound(samples.begin(), samples.end(), t,
    [](double time, const DeviceSample& s) { return time < s.t; });
  const DeviceSample& b = *hi;
  const DeviceSample& a = *(hi - 1);
  const double span = b.t - a.t;
  const double u = span > 0.0 ? (t - a.t) / span : 0.0;
  DeviceSample s;
  s.t = t;
  s.position = a.position + u * (b.position - a.position);
  s.orientation = a.orientation.slerp(u, b.orientation);
  s.buttons = a.buttons;
  return s;
}

bool TraceRecorder::open(const std::string& path)
{
  close();
  path_ = path;
  count_ = 0;
  error_.clear();
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_)
  {
    error_ = path + ": cannot create trace file";
    return false;
  }
  out_ << "# GeoShaping stylus trace: t x y z qw qx qy qz buttons\n"
          "# seconds, metres (device coordinates), unit quaternion, button bitmask\n";
  return bool(out_);
}

bool TraceRecorder::record(const DeviceSample& s)
{
  if (!out_.is_open())
  {
    error_ = "trace recorder is not open";
    return false;
  }
  if (!s.position.allFinite() || !s.orientation.coeffs().allFinite() || !std::isfinite(s.t))
  {
    error_ = path_ + ": sample " + std::to_string(count_) + " is not finite, not recorded";
    return false;
  }
  out_ << format_trace_sample(s) << '\n';
  ++count_;
  if (!out_)
    error_ = path_ + ": write failed";
  return bool(out_);
}

bool TraceRecorder::close()
{
  if (!out_.is_open())
    return true;
  // The stream's state, not error(): a rejected non-finite sample is not a failed write.
  bool ok = bool(out_);
  out_.close();
  ok = ok && !out_.fail();
  if (!ok)
    error_ = path_ + ": write failed";
  return ok;
}

} // namespace geoshaping::haptics
