#include "geoshaping/candidate_queue.h"

#include <gtest/gtest.h>

using namespace geoshaping;

namespace
{
template <class Q>
std::vector<index_t> drain(Q& q)
{
  std::vector<index_t> order;
  Candidate c;
  while (q.pop(c))
    order.push_back(c.vertex);
  return order;
}
} // namespace

TEST(CandidateQueue, FifoKeepsInsertionOrder)
{
  FifoQueue q;
  for (index_t v : { 5, 3, 9 })
    q.push({ v, 0 }, 9 - v, 0.0);
  EXPECT_EQ(drain(q), (std::vector<index_t>{ 5, 3, 9 }));
}

TEST(CandidateQueue, FifoPriorityIsLowestRankFirstAndFifoAmongEquals)
{
  BucketFifoPriorityQueue q;
  q.reset_ranks(3);
  // (vertex, rank): equal ranks must leave in arrival order.
  const std::pair<index_t, index_t> input[] = { { 10, 2 }, { 11, 1 }, { 12, 2 }, { 13, 0 },
    { 14, 1 }, { 15, 2 }, { 16, 0 } };
  for (auto [v, r] : input)
    q.push({ v, 0 }, r, 0.0);
  EXPECT_EQ(drain(q), (std::vector<index_t>{ 13, 16, 11, 14, 10, 12, 15 }));
}

TEST(CandidateQueue, FifoPriorityInterleavedPushPopAgreesWithStableSortModel)
{
  BucketFifoPriorityQueue q;
  q.reset_ranks(4);
  std::vector<std::pair<index_t, index_t>> model; // (rank, arrival)
  std::vector<index_t> got, expected;
  unsigned seed = 7;
  for (index_t i = 0; i < 2000; ++i)
  {
    seed = seed * 1103515245u + 12345u;
    const index_t rank = index_t((seed >> 16) % 4);
    q.push({ i, 0 }, rank, 0.0);
    model.push_back({ rank, i });
    if ((seed >> 8) % 3 == 0)
    {
      Candidate c;
      ASSERT_TRUE(q.pop(c));
      got.push_back(c.vertex);
      auto best = std::min_element(model.begin(), model.end());
      expected.push_back(best->second);
      model.erase(best);
    }
  }
  EXPECT_EQ(got, expected);
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
