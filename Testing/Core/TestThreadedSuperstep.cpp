// Threaded supersteps (chainmail_deformer.h, "Threads") against the one-thread deformer:
// every frame must end in the same state, bit for bit (moved set and order,
// displacements, roots, sponsors, FrameResult), on 1..4 threads, both superstep queues,
// both region shapes, across grasps, commits and repainting. Nothing here depends on how
// the threads are scheduled: the result is the same for any interleaving.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/worker_pool.h"
#include "test_meshes.h"
#include "test_pieces.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <thread>

using namespace geoshaping;

namespace
{

using Scene = geoshaping::testing::PaintedMesh;

struct Frame
{
  index_t grasp;
  Eigen::Vector3d pull;
  bool commit_after = false;
};

void set_up(ChainMailDeformer& d, const Scene& s, bool ids)
{
  d.set_mesh(s.mesh.xyz.data(), s.mesh.size(), s.mesh.adjacency);
  if (ids)
    d.set_global_ids(s.gid.data());
  d.set_malleability(s.malleability.data());
  d.set_pinned(s.pins.data());
}

bool same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

void expect_same_frame(const ChainMailDeformer& got, const FrameResult& rg,
  const ChainMailDeformer& want, const FrameResult& rw, const std::string& what)
{
  ASSERT_EQ(rg.ok, rw.ok) << what;
  EXPECT_EQ(rg.message, rw.message) << what;
  EXPECT_EQ(rg.moved, rw.moved) << what;
  EXPECT_EQ(rg.examined, rw.examined) << what;
  EXPECT_EQ(rg.blocked, rw.blocked) << what;
  EXPECT_EQ(rg.grasp_fraction, rw.grasp_fraction) << what;
  EXPECT_EQ(rg.supersteps, rw.supersteps) << what;
  ASSERT_EQ(got.moved(), want.moved()) << what; // the same vertices in the same order
  EXPECT_EQ(got.previously_moved(), want.previously_moved()) << what;
  std::size_t differ = 0;
  for (index_t v : want.moved())
    differ += !same_bits(got.displacement(v), want.displacement(v)) ||
              got.sponsor(v) != want.sponsor(v) || !(got.root(v) == want.root(v));
  EXPECT_EQ(differ, 0u) << what;
  for (index_t v = 0; v < want.size(); ++v)
    ASSERT_EQ(got.moved_this_frame(v), want.moved_this_frame(v)) << what << " vertex " << v;
}

// Runs `frames` on a deformer with `threads` threads, every superstep of at least
// `threshold` entries threaded, and on a one-thread one. Returns the threaded supersteps.
std::size_t expect_threaded_equals_one_thread(const Scene& s, bool ids, QueueKind queue,
  ValidRegionFrame frame, int threads, const std::vector<Frame>& frames, std::size_t threshold)
{
  ChainMailDeformer threaded, plain;
  set_up(threaded, s, ids);
  set_up(plain, s, ids);
  for (ChainMailDeformer* d : { &threaded, &plain })
  {
    d->set_queue(queue);
    d->set_valid_region_frame(frame);
  }
  threaded.set_threads(threads, threads > 0 ? ChainMailDeformer::ThreadUse::always
                                            : ChainMailDeformer::ThreadUse::when_cores_free);
  threaded.set_threaded_threshold(threshold);
  std::size_t ran_threaded = 0;
  for (std::size_t f = 0; f < frames.size(); ++f)
  {
    const std::string what = std::string(queue_name(queue)) + " " + frame_name(frame) + ", " +
                             std::to_string(threads) + " threads, frame " + std::to_string(f);
    const FrameResult rg = threaded.deform(frames[f].grasp, frames[f].pull);
    const FrameResult rw = plain.deform(frames[f].grasp, frames[f].pull);
    EXPECT_EQ(rw.threaded_supersteps, 0u) << what;
    ran_threaded += rg.threaded_supersteps;
    expect_same_frame(threaded, rg, plain, rw, what);
    if (frames[f].commit_after)
    {
      threaded.commit();
      plain.commit();
    }
  }
  return ran_threaded;
}

std::vector<Frame> drag(index_t nx, index_t ny)
{
  const index_t a = (ny / 2) * nx + nx / 2, b = (ny / 3) * nx + nx / 5;
  return { { a, { 0.0, 0.0, 4.0 } }, { a, { 1.0, 0.5, 6.0 } }, { a, { -2.0, 1.0, 9.0 }, true },
    { b, { 0.0, -3.0, 7.0 } }, { b, { 0.5, -3.5, 8.0 } }, { a, { 3.0, 2.0, -5.0 } } };
}

// A quad g, a, b, c (ids 0..3, edges g-a, g-b, a-c, b-c): pulling g queues c from a and
// then from b in one superstep of exactly those two entries, which two threads split
// one each.
Scene quad(float m_a, float m_b)
{
  Scene s;
  s.mesh.xyz = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 };
  AdjacencyBuilder b(4);
  b.add_edge(0, 1);
  b.add_edge(0, 2);
  b.add_edge(1, 3);
  b.add_edge(2, 3);
  s.mesh.adjacency = b.build();
  s.malleability = { 0.0f, m_a, m_b, 1.0f };
  s.gid = { 0, 1, 2, 3 };
  s.pins.assign(4, 0);
  return s;
}

// One frame pulling g up, threaded on two threads (every superstep) and not.
void expect_quad_sponsor(const Scene& s, index_t want_sponsor)
{
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
  {
    ChainMailDeformer threaded, plain;
    set_up(threaded, s, true);
    set_up(plain, s, true);
    threaded.set_queue(q);
    plain.set_queue(q);
    threaded.set_threads(2, ChainMailDeformer::ThreadUse::always);
    threaded.set_threaded_threshold(1);
    const FrameResult rg = threaded.deform(0, { 0.0, 0.0, 1.0 });
    const FrameResult rw = plain.deform(0, { 0.0, 0.0, 1.0 });
    EXPECT_EQ(rg.threaded_supersteps, rg.supersteps) << queue_name(q);
    ASSERT_TRUE(plain.moved_this_frame(3)) << queue_name(q);
    EXPECT_EQ(plain.sponsor(3), want_sponsor) << queue_name(q);
    expect_same_frame(threaded, rg, plain, rw, queue_name(q));
  }
}

} // namespace

TEST(ThreadedSuperstep, PaintedGridEqualsOneThreadOnOneToFourThreads)
{
  const Scene s = geoshaping::testing::painted_grid(48, 40);
  const auto frames = drag(48, 40);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    for (int threads = 1; threads <= 4; ++threads)
    {
      const std::size_t ran =
        expect_threaded_equals_one_thread(s, true, q, ValidRegionFrame::axes, threads, frames, 8);
      if (threads > 1)
        EXPECT_GT(ran, 10u) << queue_name(q) << " " << threads;
      else
        EXPECT_EQ(ran, 0u);
    }
}

// Threads that yield to the load (ThreadUse::when_cores_free, the default) may go to one
// thread for a while when the machine is busy: frames are the one-thread frames either
// way, however the threads were scheduled.
TEST(ThreadedSuperstep, AutomaticThreadsEqualOneThreadHoweverBusyTheMachine)
{
  const Scene s = geoshaping::testing::painted_grid(48, 40);
  const auto frames = drag(48, 40);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    expect_threaded_equals_one_thread(s, true, q, ValidRegionFrame::axes, 0, frames, 8);
  ChainMailDeformer d;
  EXPECT_EQ(d.thread_use(), ChainMailDeformer::ThreadUse::when_cores_free);
  d.set_threads(0);
  EXPECT_GE(d.threads(), 1);                              // the hardware's concurrency
  d.set_threads(2, ChainMailDeformer::ThreadUse::always); // tests, benchmarks
  EXPECT_EQ(d.thread_use(), ChainMailDeformer::ThreadUse::always);
  EXPECT_EQ(d.threads(), 2);
}

TEST(ThreadedSuperstep, CallerIdsAndLinkRegionEqualOneThread)
{
  const Scene s = geoshaping::testing::painted_grid(40, 36);
  const auto frames = drag(40, 36);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
  {
    EXPECT_GT(
      expect_threaded_equals_one_thread(s, false, q, ValidRegionFrame::link, 3, frames, 5), 10u);
    EXPECT_GT(
      expect_threaded_equals_one_thread(s, false, q, ValidRegionFrame::axes, 2, frames, 1), 10u);
  }
}

TEST(ThreadedSuperstep, TetrahedralSlabEqualsOneThread)
{
  const Scene s = geoshaping::testing::tet_slab(14, 12, 5);
  const index_t a = (2 * 12 + 6) * 14 + 7;
  const std::vector<Frame> frames = { { a, { 0.0, 0.0, 1.5 } }, { a, { 0.4, 0.0, 2.5 }, true },
    { a + 3, { -1.0, 0.5, 2.0 } } };
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    EXPECT_GT(
      expect_threaded_equals_one_thread(s, true, q, ValidRegionFrame::axes, 4, frames, 4), 3u);
}

TEST(ThreadedSuperstep, RepaintingBetweenFramesIsFollowed)
{
  Scene s = geoshaping::testing::painted_grid(30, 30);
  ChainMailDeformer threaded, plain;
  set_up(threaded, s, true);
  set_up(plain, s, true);
  threaded.set_threads(2, ChainMailDeformer::ThreadUse::always);
  threaded.set_threaded_threshold(2);
  const index_t g = 15 * 30 + 15;
  for (int f = 0; f < 4; ++f)
  {
    if (f == 2)
    {
      for (float& m : s.malleability)
        m = 1.0f - m;
      threaded.set_malleability(s.malleability.data());
      plain.set_malleability(s.malleability.data());
      threaded.set_pinned(nullptr);
      plain.set_pinned(nullptr);
    }
    const Eigen::Vector3d pull(0.0, 1.0, 3.0 + f);
    const FrameResult rg = threaded.deform(g, pull);
    const FrameResult rw = plain.deform(g, pull);
    EXPECT_GT(rg.threaded_supersteps, 0u);
    expect_same_frame(threaded, rg, plain, rw, "frame " + std::to_string(f));
  }
}

TEST(ThreadedSuperstep, LaterEntryInAnotherChunkMovesWhatTheEarlierLeft)
{
  // a soft: it moves half as far as g, and c (soft) lies inside its box w.r.t. a; b rigid
  // moves with g and pulls c. The entry (c, a) in the first chunk proposes nothing, the
  // entry (c, b) in the second moves c.
  expect_quad_sponsor(quad(1.0f, 0.0f), 2);
}

TEST(ThreadedSuperstep, EarlierEntryWinsWhenBothChunksMoveTheCandidate)
{
  // a and b rigid: both move with g and both entries move c; the first in push order, a's,
  // must win (sponsor a).
  expect_quad_sponsor(quad(0.0f, 0.0f), 1);
}

TEST(ThreadedSuperstep, SmallSuperstepsSequentialQueuesObstaclesAndPiecesStayOnOneThread)
{
  const Scene s = geoshaping::testing::painted_grid(30, 30);
  ChainMailDeformer d;
  set_up(d, s, true);
  d.set_threads(2, ChainMailDeformer::ThreadUse::always);
  const index_t g = 15 * 30 + 15;
  // Below the default threshold: one thread, frame after frame.
  for (int f = 0; f < 3; ++f)
  {
    const FrameResult r = d.deform(g, { 0.0, 0.0, 5.0 });
    EXPECT_TRUE(r.ok);
    EXPECT_GT(r.supersteps, 0u);
    EXPECT_EQ(r.threaded_supersteps, 0u);
  }
  d.set_threaded_threshold(1);
  EXPECT_GT(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  EXPECT_EQ(d.threads(), 2);
  d.set_queue(QueueKind::priority);
  EXPECT_EQ(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  d.set_queue(QueueKind::fifo);
  d.set_threads(1);
  EXPECT_EQ(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  d.set_threads(2, ChainMailDeformer::ThreadUse::always);
  const double tri[9] = { -5.0, -5.0, 2.0, 40.0, -5.0, 2.0, -5.0, 40.0, 2.0 };
  const std::int64_t ids[3] = { 0, 1, 2 };
  ASSERT_EQ(d.set_obstacles(tri, 3, ids, 1), "");
  EXPECT_EQ(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  d.clear_obstacles();
  EXPECT_GT(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  std::vector<std::uint8_t> owned(s.malleability.size(), 1);
  owned[0] = 0;
  d.set_owned(owned.data());
  EXPECT_EQ(d.deform(g, { 0.0, 0.0, 5.0 }).threaded_supersteps, 0u);
  d.set_owned(nullptr);
  d.set_threads(0); // the hardware's concurrency
  EXPECT_GE(d.threads(), 1);
}

TEST(ThreadedSuperstep, CopiesRunTheirOwnThreads)
{
  const Scene s = geoshaping::testing::painted_grid(30, 30);
  ChainMailDeformer d, plain;
  set_up(d, s, true);
  set_up(plain, s, true);
  d.set_threads(3, ChainMailDeformer::ThreadUse::always);
  d.set_threaded_threshold(1);
  const index_t g = 15 * 30 + 15;
  d.deform(g, { 0.0, 0.0, 5.0 }); // makes the pool
  plain.deform(g, { 0.0, 0.0, 5.0 });
  ChainMailDeformer copy = d;
  const FrameResult rc = copy.deform(g, { 1.0, 0.0, 6.0 });
  const FrameResult rd = d.deform(g, { 1.0, 0.0, 6.0 });
  const FrameResult rw = plain.deform(g, { 1.0, 0.0, 6.0 });
  EXPECT_GT(rc.threaded_supersteps, 0u);
  expect_same_frame(copy, rc, plain, rw, "copy");
  expect_same_frame(d, rd, plain, rw, "original");
  EXPECT_EQ(copy.moved(), d.moved());
}

// A busy machine (chainmail_deformer.h, "Threads"): a thread kept off its core makes the
// others wait at a barrier for longer than they worked, which the pool reports so the
// deformer can go on alone. The sleep stands in for the scheduler; a wait it forces is at
// least its length whatever the machine does, so the test cannot pass by luck.
TEST(WorkerPool, ThreadKeptOffItsCoreIsReportedAsAStall)
{
  WorkerPool pool(2);
  int ran[2] = { 0, 0 };
  auto job = [&](int t)
  {
    if (t == 1)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    pool.barrier();
    ++ran[t];
  };
  pool.run(job);
  EXPECT_TRUE(pool.stalled());
  EXPECT_EQ(ran[0], 1);
  EXPECT_EQ(ran[1], 1);
  auto alone = [&](int t) { ++ran[t]; };
  WorkerPool one(1);
  one.run(alone);
  EXPECT_FALSE(one.stalled()); // one thread never waits
  EXPECT_EQ(ran[0], 2);
}

// A busy machine seen before a run (worker_pool.h): the runnable threads of the machine
// come from /proc/loadavg's fourth field, and T threads are short of cores when more
// others run than the cores T leaves.
TEST(WorkerPool, RunnableThreadsAreReadFromLoadavg)
{
  EXPECT_EQ(WorkerPool::runnable_in_loadavg("0.52 0.58 0.59 3/467 1234\n"), 3);
  EXPECT_EQ(WorkerPool::runnable_in_loadavg("12.00 8.10 4.02 17/2048 99"), 17);
  EXPECT_EQ(WorkerPool::runnable_in_loadavg("0.52 0.58 0.59"), -1);
  EXPECT_EQ(WorkerPool::runnable_in_loadavg("garbage"), -1);
  EXPECT_EQ(WorkerPool::runnable_in_loadavg(""), -1);
#if defined(__linux__)
  EXPECT_GE(WorkerPool::others_running(nullptr), 0); // read, whatever else runs
#endif
}

TEST(WorkerPool, CoresAreShortWhenOtherThreadsHoldThem)
{
  EXPECT_FALSE(WorkerPool::cores_short(0, 2, 2)); // idle: both cores ours
  EXPECT_TRUE(WorkerPool::cores_short(1, 2, 2));  // a spinner on one of two cores
  EXPECT_FALSE(WorkerPool::cores_short(2, 4, 2)); // two others, two cores left
  EXPECT_TRUE(WorkerPool::cores_short(3, 4, 2));
  EXPECT_FALSE(WorkerPool::cores_short(-1, 2, 2)); // unknown: the stall rule decides
}
