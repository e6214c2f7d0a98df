#include "geoshaping/candidate_queue.h"

#include <gtest/gtest.h>

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
  // (candidate gid, sponsor gid, band, root): generation 1, pushed in no particular order.
  using In = std::tuple<std::int64_t, std::int64_t, std::uint32_t, SuperstepRoot>;
  for (auto [c, s, b, r] : { In{ 9, 4, 2, base }, In{ 3, 8, 1, base }, In{ 9, 2, 2, base },
         In{ 1, 5, 2, base }, In{ 3, 1, 1, base }, In{ 60, 7, 1, late }, In{ 50, 7, 1, early } })
    q.push({ c, s, r, b, index_t(c), index_t(s) });
  q.seal(1);
  for (auto [c, s, b, r] : { In{ 7, 1, 1, base }, In{ 2, 2, 0, base } })
    q.push({ c, s, r, b, index_t(c), index_t(s) });
  q.seal(2);
  using P = std::vector<std::pair<std::int64_t, std::int64_t>>;
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
      got.back().second.push_back({ q.entries()[k].candidate_gid, q.entries()[k].sponsor_gid });
  }
  const std::vector<std::pair<SuperstepKey, P>> expected = { { SuperstepQueue::key(0, base, 2),
                                                               { { 2, 2 } } },
    { SuperstepQueue::key(1, base, 1), { { 3, 1 }, { 3, 8 } } },
    { SuperstepQueue::key(1, base, 2), { { 7, 1 } } },
    { SuperstepQueue::key(1, early, 1), { { 50, 7 } } },
    { SuperstepQueue::key(1, late, 1), { { 60, 7 } } },
    { SuperstepQueue::key(2, base, 1), { { 1, 5 }, { 9, 2 }, { 9, 4 } } } };
  EXPECT_EQ(got, expected);
  const SuperstepRoot negative{ 7, -12 };
  EXPECT_EQ(SuperstepQueue::root_of(SuperstepQueue::key(3, negative, 4)).gid, -12);
  q.clear();
  EXPECT_EQ(q.top(), SuperstepQueue::none);
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

TEST(CandidateQueue, NamesRoundTrip)
{
  for (QueueKind k :
    { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority, QueueKind::max_violation })
  {
    QueueKind parsed;
    ASSERT_TRUE(parse_queue_name(queue_name(k), parsed));
    EXPECT_EQ(parsed, k);
  }
  QueueKind dummy;
  EXPECT_FALSE(parse_queue_name("Tree", dummy));
  EXPECT_FALSE(parse_queue_name(nullptr, dummy));
}
