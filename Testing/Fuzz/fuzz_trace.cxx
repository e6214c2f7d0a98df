// libFuzzer target: the stylus trace parser of the Replay device (Haptics/trace.cpp) on
// any bytes, then interpolation between the samples of an accepted trace (finite).
#include "fuzz_require.h"
#include "geoshaping/haptics/trace.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream input(std::string(reinterpret_cast<const char*>(data), size));
  const geoshaping::haptics::TraceParseResult r =
    geoshaping::haptics::parse_trace(input, "fuzz.trace");
  if (!r.ok)
  {
    Require(r.samples.empty() && !r.message.empty());
    return 0;
  }
  for (std::size_t i = 0; i < r.samples.size(); ++i)
  {
    const auto& s = r.samples[i];
    Require(std::isfinite(s.t) && s.position.allFinite());
    Require(std::abs(s.orientation.norm() - 1.0) < 1e-6);
    Require(i == 0 || r.samples[i - 1].t <= s.t);
    // A sample written and read back is the same sample.
    std::istringstream again(geoshaping::haptics::format_trace_sample(s) + "\n");
    const auto back = geoshaping::haptics::parse_trace(again, "again");
    Require(back.ok && back.samples.size() == 1 && back.samples[0].t == s.t &&
            back.samples[0].position == s.position && back.samples[0].buttons == s.buttons);
  }
  if (!r.samples.empty())
  {
    const double first = r.samples.front().t, last = r.samples.back().t;
    // Positions are bounded (1e6 m), so interpolating between them stays finite.
    for (const double t : { first - 1.0, first, 0.5 * first + 0.5 * last, last, last + 1.0 })
    {
      const auto s = geoshaping::haptics::sample_trace_at(r.samples, t);
      Require(s.position.allFinite() && s.orientation.coeffs().allFinite());
    }
  }
  return 0;
}
