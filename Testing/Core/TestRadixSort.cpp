#include "geoshaping/mesh/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>

using namespace geoshaping;

TEST(RadixSort, SortsAsStdSortOfKeyThenArrivalOrder)
{
  // Keys that differ in every digit, in the top bit only, or not at all in most digits.
  std::mt19937_64 rng(3);
  for (const std::uint64_t mask :
    { ~std::uint64_t(0), std::uint64_t(1) << 63, std::uint64_t(0x7ff) << 20, std::uint64_t(0) })
  {
    std::vector<std::pair<std::uint64_t, int>> records, scratch;
    for (int i = 0; i < 20000; ++i)
      records.emplace_back(rng() & mask & (i % 3 ? ~std::uint64_t(0) : std::uint64_t(0xff)), i);
    auto expected = records;
    std::sort(expected.begin(), expected.end());
    radix_sort(records, scratch, [](const std::pair<std::uint64_t, int>& r) { return r.first; });
    EXPECT_EQ(records, expected) << std::hex << mask;
  }
}

TEST(RadixSort, EmptyAndSingleRecordsStayAsTheyAre)
{
  std::vector<std::uint64_t> none, one{ 42 }, scratch;
  const auto key = [](std::uint64_t k) { return k; };
  radix_sort(none, scratch, key);
  radix_sort(one, scratch, key);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(one, std::vector<std::uint64_t>{ 42 });
}
