#pragma once
// Stable sorts of per-vertex records by 64-bit keys, for the set-up of a big mesh (the
// deformer's Morton order, the coordinate ids): least significant digit first, 11 bits a
// pass, and a pass whose digit is the same in every record is skipped (coordinates of one
// magnitude share their exponent bits, float elevations their low mantissa). O(n) a pass,
// one scratch copy of the records.
#include "geoshaping/mesh/huge_pages.h"

#include <array>
#include <cstdint>
#include <vector>

namespace geoshaping
{

// Sorts `records` stably by key(record) (a std::uint64_t, compared unsigned): records with
// equal keys keep their order. `scratch` is working space (resized as needed).
template<class Record, class Key>
void radix_sort(std::vector<Record>& records, std::vector<Record>& scratch, const Key& key)
{
  constexpr int bits = 11, passes = (64 + bits - 1) / bits;
  constexpr std::size_t buckets = std::size_t(1) << bits;
  std::vector<std::array<std::size_t, buckets>> count(passes);
  for (auto& c : count)
    c.fill(0);
  for (const Record& r : records)
  {
    const std::uint64_t k = key(r);
    for (int p = 0; p < passes; ++p)
      ++count[std::size_t(p)][(k >> (bits * p)) & (buckets - 1)];
  }
  if (scratch.capacity() < records.size())
    fresh_huge(scratch, records.size());
  scratch.resize(records.size());
  for (int p = 0; p < passes; ++p)
  {
    std::array<std::size_t, buckets>& c = count[std::size_t(p)];
    bool constant = false;
    for (std::size_t b = 0; b < buckets && !constant; ++b)
      constant = c[b] == records.size();
    if (constant)
      continue;
    std::size_t start = 0;
    for (std::size_t& b : c)
    {
      const std::size_t size = b;
      b = start;
      start += size;
    }
    for (const Record& r : records)
      scratch[c[(key(r) >> (bits * p)) & (buckets - 1)]++] = r;
    records.swap(scratch);
  }
}

} // namespace geoshaping
