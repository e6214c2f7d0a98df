#include "geoshaping/haptics/snapshots.h"
#include "geoshaping/haptics/triple_buffer.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

using namespace geoshaping::haptics;

TEST(TripleBuffer, ReaderSeesNothingNewUntilSomethingIsPublished)
{
  TripleBuffer<int> buffer(7);
  EXPECT_FALSE(buffer.update());
  EXPECT_EQ(buffer.front(), 7);
  buffer.write(8);
  buffer.write(9);
  EXPECT_TRUE(buffer.update());
  EXPECT_EQ(buffer.front(), 9); // the latest; 8 was overtaken
  EXPECT_FALSE(buffer.update());
  EXPECT_EQ(buffer.front(), 9);
}

TEST(TripleBuffer, WriterNeverGetsBackTheSlotTheReaderHolds)
{
  TripleBuffer<int> buffer(0);
  buffer.write(1);
  ASSERT_TRUE(buffer.update());
  const int* held = &buffer.front();
  for (int i = 2; i < 10; ++i)
  {
    EXPECT_NE(&buffer.back(), held);
    buffer.write(i);
  }
  EXPECT_EQ(*held, 1);
}

// A writer publishes scene snapshots whose every field derives from one sequence number
// (triangle count varies, so vectors reallocate); the reader checks each snapshot it
// takes is whole and never older than the one before. Any torn read fails. The writer
// goes on until it has published 200,000 snapshots and the reader has taken 1,000, so
// the overlap does not depend on how the machine schedules the two threads.
TEST(TripleBuffer, TwoThreadStressDeliversOnlyCompleteSnapshotsInOrder)
{
  constexpr std::uint64_t min_published = 200000, min_taken = 1000;
  TripleBuffer<SceneSnapshot> buffer;
  std::atomic<bool> done{ false };
  std::atomic<std::uint64_t> taken_so_far{ 0 };
  std::uint64_t last = 0;
  std::thread writer(
    [&]
    {
      for (std::uint64_t seq = 1; seq <= min_published || taken_so_far.load() < min_taken; ++seq)
      {
        SceneSnapshot& s = buffer.back();
        const double v = double(seq);
        s.sequence = seq;
        s.grasp_anchor = Eigen::Vector3d(v, -v, 2 * v);
        s.grasp_stiffness = v;
        s.contact_triangles.assign(3 * (seq % 17), Eigen::Vector3d(v, v, v));
        buffer.publish();
        last = seq;
      }
      done.store(true);
    });

  std::uint64_t previous = 0, taken = 0, torn = 0, backwards = 0;
  auto check = [&]
  {
    const SceneSnapshot& s = buffer.front();
    const double v = double(s.sequence);
    bool whole = s.grasp_anchor == Eigen::Vector3d(v, -v, 2 * v) && s.grasp_stiffness == v &&
                 s.contact_triangles.size() == 3 * (s.sequence % 17);
    for (const Eigen::Vector3d& p : s.contact_triangles)
      whole = whole && p == Eigen::Vector3d(v, v, v);
    torn += !whole;
    backwards += s.sequence < previous;
    previous = s.sequence;
    taken_so_far.store(++taken);
  };
  while (!done.load())
    if (buffer.update())
      check();
  writer.join();
  if (buffer.update())
    check();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_GE(taken, min_taken);
  EXPECT_EQ(buffer.front().sequence, last); // the latest complete snapshot
}
