#include "geoshaping/candidate_queue.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>

using namespace geoshaping;

namespace
{
template<class Q>
std::vector<index_t> drain(Q& q)
{
  std::vector<index_t> order;
  Candidate c;
  while (q.pop(c))
    order.push_back(c.vertex);
  return order;
}
} // namespace

TEST(CandidateQueue, SuperstepsComeByBandRootAndGenerationEachSortedByIds)
{
  SuperstepQueue q;
  const SuperstepRoot base{}, early{ 1, 50 }, late{ 1, 60 };
  // (candidate gid, band, root, entries): generation 1, pushed in no particular order.
  using In = std::tuple<std::int64_t, std::uint32_t, SuperstepRoot, std::uint32_t>;
  for (auto [c, b, r, n] : { In{ 9, 2, base, 2 }, In{ 3, 1, base, 2 }, In{ 1, 2, base, 1 },
         In{ 60, 1, late, 1 }, In{ 50, 1, early, 1 } })
    q.push({ c, r, b, b, index_t(c), n });
  q.seal(1);
  for (auto [c, b, r, n] : { In{ 7, 1, base, 1 }, In{ 2, 0, base, 3 } })
    q.push({ c, r, b, b, index_t(c), n });
  q.seal(2);
  struct Got
  {
    SuperstepKey key;
    std::vector<index_t> candidates;
    std::size_t entries;
    bool operator==(const Got& o) const
    {
      return key == o.key && candidates == o.candidates && entries == o.entries;
    }
  };
  std::vector<Got> got;
  for (SuperstepKey key; (key = q.top()) != SuperstepQueue::none;)
  {
    Superstep g;
    SuperstepKey later = key;
    ++later[2];
    ASSERT_FALSE(q.pop(later, g)); // only the lowest key pops
    ASSERT_TRUE(q.pop(key, g));
    got.push_back({ key, {}, g.entries });
    for (std::size_t k = g.begin; k < g.end; ++k)
      got.back().candidates.push_back(q.entries()[k].vertex);
  }
  const std::vector<Got> expected = { { SuperstepQueue::key(0, base, 2), { 2 }, 3 },
    { SuperstepQueue::key(1, base, 1), { 3 }, 2 }, { SuperstepQueue::key(1, base, 2), { 7 }, 1 },
    { SuperstepQueue::key(1, early, 1), { 50 }, 1 }, { SuperstepQueue::key(1, late, 1), { 60 }, 1 },
    { SuperstepQueue::key(2, base, 1), { 1, 9 }, 3 } };
  EXPECT_TRUE(got == expected);
  const SuperstepRoot negative{ 7, -12 };
  EXPECT_EQ(SuperstepQueue::root_of(SuperstepQueue::key(3, negative, 4)).gid, -12);
  q.clear();
  EXPECT_EQ(q.top(), SuperstepQueue::none);
  // Chains rely on generations growing: a seal that does not is refused.
  q.push({ 1, base, 0, 0, 1 });
  q.seal(5);
  q.push({ 3, base, 0, 0, 3 });
  EXPECT_THROW(q.seal(5), std::invalid_argument);
}

// The queue sorts a generation by a cheap 64-bit word (order hint, candidate id), radix
// or insertion, and checks the result on the full key, falling back to a comparison
// sort. Whatever the path, the groups and their candidates must be the full key's order:
// compared here with a std::map over (band, root, generation | c id, vertex) on random
// generations of 1 to 2,000 candidates (every sort path), with the hint
// right (the band's rank), constant, or reversed, ids of a small or the full 64-bit
// range (the word does not fit), roots shared, per candidate, mixed, duplicated
// candidate ids on different vertices, and generations pushed nearly sorted.
TEST(CandidateQueue, SuperstepOrderIsTheFullKeysWhateverTheSortPath)
{
  std::mt19937_64 rng(14);
  using Full = std::tuple<std::uint32_t, std::uint32_t, std::int64_t, std::uint32_t, std::int64_t,
    index_t>; // band, root, generation, candidate id, vertex
  for (int trial = 0; trial < 60; ++trial)
  {
    const int hint = trial % 3; // 0: rank of the band, 1: constant, 2: reversed
    const bool wide = trial % 4 == 3;
    const int roots = trial % 5; // 0: shared, 1: per candidate downhill, else mixed
    SuperstepQueue q;
    std::map<Full, int> expected;
    for (std::uint32_t generation = 1; generation <= 3; ++generation)
    {
      const std::size_t k = std::size_t(1 + rng() % (trial % 2 ? 2000 : 40));
      for (std::size_t i = 0; i < k; ++i)
      {
        const std::uint32_t band_rank = std::uint32_t(rng() % 4);
        const std::uint32_t band = 0x3e800000u + band_rank * 0x100000u;
        std::int64_t c = std::int64_t(rng() % 300);
        if (trial % 6 == 5) // nearly sorted: ids grow with a little jitter
          c = std::int64_t(i) + std::int64_t(rng() % 5);
        if (wide)
          c = std::int64_t(rng());
        SuperstepRoot root{ 2, 77 };
        if (roots == 1 || (roots > 1 && rng() % 3 == 0))
          root = { generation, c };
        if (roots > 2 && rng() % 4 == 0)
          root = {};
        const std::uint32_t order = hint == 0 ? band_rank : (hint == 1 ? 0 : 3 - band_rank);
        const index_t vertex = index_t(rng() % 1000);
        q.push({ c, root, band, order, vertex });
        const Full full{ band, root.generation, root.gid, generation, c, vertex };
        ++expected[full];
      }
      q.seal(generation);
    }
    std::vector<Full> want;
    for (const auto& [full, count] : expected)
      want.insert(want.end(), std::size_t(count), full);
    std::vector<Full> got;
    for (SuperstepKey key; (key = q.top()) != SuperstepQueue::none;)
    {
      Superstep g;
      ASSERT_TRUE(q.pop(key, g));
      ASSERT_LT(g.begin, g.end);
      ASSERT_EQ(g.entries, g.end - g.begin);
      const SuperstepRoot root = SuperstepQueue::root_of(key);
      for (std::size_t i = g.begin; i < g.end; ++i)
        got.push_back({ std::uint32_t(key[0] >> 32), root.generation, root.gid,
          std::uint32_t(key[2]), 0, q.entries()[i].vertex });
    }
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
    {
      // The popped candidates carry the vertex only: compare it and the group.
      Full w = want[i];
      std::get<4>(w) = 0;
      ASSERT_EQ(got[i], w) << "trial " << trial << " entry " << i;
    }
  }
}

TEST(CandidateQueue, HeapPriorityIsLowestRankFirstButNotFifoAmongEquals)
{
  HeapPriorityQueue q;
  for (index_t v = 0; v < 8; ++v)
    q.push({ v, 0 }, 0, 0.0);
  q.push({ 99, 0 }, -1, 0.0);
  const std::vector<index_t> order = drain(q);
  EXPECT_EQ(order.front(), 99);
  EXPECT_NE(order, (std::vector<index_t>{ 99, 0, 1, 2, 3, 4, 5, 6, 7 }));
}

TEST(CandidateQueue, MaxViolationIsLargestFirst)
{
  MaxViolationQueue q;
  q.push({ 1, 0 }, 0, 0.5);
  q.push({ 2, 0 }, 0, 3.0);
  q.push({ 3, 0 }, 0, 1.0);
  EXPECT_EQ(drain(q), (std::vector<index_t>{ 2, 3, 1 }));
}
