#include "geoshaping/deform/candidate_queue.h"

#include <gtest/gtest.h>

#include <cmath>
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

// Groups come in (band, root, generation) order whatever the order they were opened in,
// each in push order; only the lowest key pops; clear() empties; generations must grow.
TEST(CandidateQueue, SuperstepsComeByBandRootAndGenerationEachInPushOrder)
{
  SuperstepQueue q;
  const SuperstepRoot base{}, early{ 1, 0, 50 }, late{ 1, 0, 60 };
  // (vertex, sponsor, band, root): generation 1, groups opened in no particular order.
  using In = std::tuple<index_t, index_t, std::uint32_t, SuperstepRoot>;
  for (auto [c, s, b, r] : { In{ 9, 4, 2, base }, In{ 3, 8, 1, base }, In{ 9, 2, 2, base },
         In{ 1, 5, 2, base }, In{ 3, 1, 1, base }, In{ 60, 7, 1, late }, In{ 50, 7, 1, early } })
    q.append(q.open(b, r), c, s);
  q.seal_in_push_order(1);
  for (auto [c, s, b, r] : { In{ 7, 1, 1, base }, In{ 2, 2, 0, base } })
    q.append(q.open(b, r), c, s);
  q.seal_in_push_order(2);
  using P = std::vector<std::pair<index_t, index_t>>;
  std::vector<std::pair<SuperstepKey, P>> got;
  for (SuperstepKey key; (key = q.top()) != SuperstepQueue::none;)
  {
    std::size_t b, e;
    SuperstepKey later = key;
    ++later[2];
    ASSERT_FALSE(q.pop(later, b, e)); // only the lowest key pops
    ASSERT_TRUE(q.pop(key, b, e));
    got.push_back({ key, {} });
    for (std::size_t k = b; k < e; ++k)
      got.back().second.push_back({ q.entries()[k].vertex, q.entries()[k].sponsor });
  }
  const std::vector<std::pair<SuperstepKey, P>> expected = { { SuperstepQueue::key(0, base, 2),
                                                               { { 2, 2 } } },
    { SuperstepQueue::key(1, base, 1), { { 3, 8 }, { 3, 1 } } },
    { SuperstepQueue::key(1, base, 2), { { 7, 1 } } },
    { SuperstepQueue::key(1, early, 1), { { 50, 7 } } },
    { SuperstepQueue::key(1, late, 1), { { 60, 7 } } },
    { SuperstepQueue::key(2, base, 1), { { 9, 4 }, { 9, 2 }, { 1, 5 } } } };
  EXPECT_EQ(got, expected);
  const SuperstepRoot negative{ 7, 5, -12 };
  EXPECT_EQ(SuperstepQueue::root_of(SuperstepQueue::key(3, negative, 4)), negative);
  q.clear();
  EXPECT_EQ(q.top(), SuperstepQueue::none);
  // Chains rely on generations growing: a generation that does not is refused, unless
  // nothing was appended (then nothing is filed).
  q.append(q.open(0, base), 1, 2);
  q.seal_in_push_order(5);
  q.open(0, base);
  EXPECT_NO_THROW(q.seal_in_push_order(5));
  q.append(q.open(0, base), 3, 2);
  EXPECT_THROW(q.seal_in_push_order(5), std::invalid_argument);
  q.clear(); // clear() restarts the generations
  q.append(q.open(0, base), 3, 2);
  EXPECT_NO_THROW(q.seal_in_push_order(1));
  EXPECT_EQ(q.top(), SuperstepQueue::key(0, base, 1));
}

// The deformer's path: open() and append() then seal_in_push_order() files a generation into one
// group per (band, root) that keeps push order, the groups in key order:
// compared with a std::map of push-ordered lists on random generations of 1 to 2,000
// entries in 1 group, a few (linear look-up) or up to 40 (hashed).
TEST(CandidateQueue, AppendedGroupsComeInKeyOrderEachInPushOrder)
{
  std::mt19937_64 rng(26);
  using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint64_t, std::int64_t, std::uint32_t>;
  using Pairs = std::vector<std::pair<index_t, index_t>>;
  for (int trial = 0; trial < 30; ++trial)
  {
    const std::uint32_t kinds = trial % 3 == 0 ? 1 : (trial % 3 == 1 ? 5 : 40);
    SuperstepQueue q;
    std::map<Key, Pairs> expected;
    for (std::uint32_t generation = 1; generation <= 3; ++generation)
    {
      const std::size_t k = std::size_t(1 + rng() % (trial % 2 ? 2000 : 40));
      for (std::size_t i = 0; i < k; ++i)
      {
        const auto kind = std::uint32_t(rng() % kinds);
        const std::uint32_t band = 0x3e800000u + (kind % 3) * 0x100000u;
        const SuperstepRoot root =
          kind < 3 ? SuperstepRoot{}
                   : SuperstepRoot{ generation, std::uint64_t(kind % 4), std::int64_t(kind) - 20 };
        const index_t vertex = index_t(rng() % 1000), sponsor = index_t(rng() % 1000);
        q.append(q.open(band, root), vertex, sponsor);
        expected[{ band, root.generation, root.order, root.gid, generation }].push_back(
          { vertex, sponsor });
      }
      q.seal_in_push_order(generation);
    }
    std::map<Key, Pairs> got;
    std::vector<Key> keys;
    for (SuperstepKey key; (key = q.top()) != SuperstepQueue::none;)
    {
      std::size_t b, e;
      ASSERT_TRUE(q.pop(key, b, e));
      const SuperstepRoot root = SuperstepQueue::root_of(key);
      const Key full{ std::uint32_t(key[0] >> 32), root.generation, root.order, root.gid,
        std::uint32_t(key[3]) };
      keys.push_back(full);
      for (std::size_t i = b; i < e; ++i)
        got[full].push_back({ q.entries()[i].vertex, q.entries()[i].sponsor });
    }
    EXPECT_EQ(got, expected) << "trial " << trial;
    std::vector<Key> want;
    for (const auto& [key, pairs] : expected)
      want.push_back(key);
    EXPECT_EQ(keys, want) << "trial " << trial; // one group per key, in key order
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

TEST(CandidateQueue, PriorityBandIsRigidAloneThenSixtyFourLevels)
{
  EXPECT_EQ(priority_levels, 64u);
  EXPECT_EQ(priority_band(0.0f), 0u);
  EXPECT_EQ(priority_band(-0.0f), 0u);
  EXPECT_EQ(priority_band(1e-30f), 1u); // any softness leaves the rigid band
  EXPECT_EQ(priority_band(1.0f / 64.0f), 2u);
  EXPECT_EQ(priority_band(0.5f), 33u);
  EXPECT_EQ(priority_band(std::nextafter(0.5f, 0.0f)), 32u);
  EXPECT_EQ(priority_band(63.0f / 64.0f), 64u); // the last level ...
  EXPECT_EQ(priority_band(1.0f), 64u);          // ... holds 1
  // Monotone, and values 1/64 apart always fall in different bands.
  std::uint32_t last = 0;
  for (int i = 0; i <= 100000; ++i)
  {
    const float m = float(i) / 100000.0f;
    EXPECT_GE(priority_band(m), last);
    last = priority_band(m);
    if (m + 1.0f / 64.0f <= 1.0f)
      EXPECT_LT(priority_band(m), priority_band(m + 1.0f / 64.0f)) << m;
  }
}
