// The fuzz targets' check: an accepted input that breaks what the target requires of it
// aborts, which libFuzzer (and the corpus replay) report as a finding.
#pragma once

#include <cstdlib>

inline void Require(bool condition)
{
  if (!condition)
    std::abort();
}
