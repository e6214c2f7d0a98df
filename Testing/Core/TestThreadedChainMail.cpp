// The threaded frame (threaded_chainmail.h) against the one-thread deformer: the whole
// deformer must end every frame in the same state, bit for bit (moved set and order,
// displacements, roots, sponsors, FrameResult), on 1..4 threads, both superstep queues,
// both region shapes, across grasps, commits and repainting. Nothing here depends on
// how the threads are scheduled: the result is the same for any interleaving.
#include "geoshaping/parallel/threaded_chainmail.h"
#include "test_meshes.h"
#include "test_pieces.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

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

// Runs `frames` on a threaded whole deformer and a plain one; every frame after the
// first runs threaded (threshold 0) unless `threads` is 1. Returns the threaded frames.
std::size_t expect_threaded_equals_one_thread(const Scene& s, bool ids, QueueKind queue,
  ValidRegionFrame frame, int threads, const std::vector<Frame>& frames, index_t block)
{
  ChainMailDeformer threaded, plain;
  set_up(threaded, s, ids);
  set_up(plain, s, ids);
  for (ChainMailDeformer* d : { &threaded, &plain })
  {
    d->set_queue(queue);
    d->set_valid_region_frame(frame);
  }
  ThreadedChainMail driver;
  driver.set_threads(threads);
  driver.set_threshold(0);
  driver.set_per_superstep(0.0);
  driver.set_block(block);
  std::size_t ran_threaded = 0;
  for (std::size_t f = 0; f < frames.size(); ++f)
  {
    const std::string what = std::string(queue_name(queue)) + " " + frame_name(frame) + ", " +
                             std::to_string(threads) + " threads, frame " + std::to_string(f);
    const FrameResult rg = driver.deform(threaded, frames[f].grasp, frames[f].pull);
    const FrameResult rw = plain.deform(frames[f].grasp, frames[f].pull);
    ran_threaded += driver.last_threaded();
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

} // namespace

TEST(ThreadedChainMail, PaintedGridEqualsOneThreadOnOneToFourThreads)
{
  const Scene s = geoshaping::testing::painted_grid(48, 40);
  const auto frames = drag(48, 40);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    for (int threads = 1; threads <= 4; ++threads)
    {
      const std::size_t ran =
        expect_threaded_equals_one_thread(s, true, q, ValidRegionFrame::axes, threads, frames, 37);
      // The first frame has no prediction; the rest go threaded when threads > 1.
      EXPECT_EQ(ran, threads > 1 ? frames.size() - 1 : 0u);
    }
}

TEST(ThreadedChainMail, CallerIdsAndLinkRegionEqualOneThread)
{
  const Scene s = geoshaping::testing::painted_grid(40, 36);
  const auto frames = drag(40, 36);
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
  {
    EXPECT_EQ(expect_threaded_equals_one_thread(s, false, q, ValidRegionFrame::link, 3, frames, 50),
      frames.size() - 1);
    EXPECT_EQ(expect_threaded_equals_one_thread(s, false, q, ValidRegionFrame::axes, 2, frames, 1),
      frames.size() - 1);
  }
}

TEST(ThreadedChainMail, TetrahedralSlabEqualsOneThread)
{
  const Scene s = geoshaping::testing::tet_slab(14, 12, 5);
  const index_t a = (2 * 12 + 6) * 14 + 7;
  const std::vector<Frame> frames = { { a, { 0.0, 0.0, 1.5 } }, { a, { 0.4, 0.0, 2.5 }, true },
    { a + 3, { -1.0, 0.5, 2.0 } } };
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    EXPECT_EQ(expect_threaded_equals_one_thread(s, true, q, ValidRegionFrame::axes, 4, frames, 64),
      frames.size() - 1);
}

TEST(ThreadedChainMail, RepaintingBetweenFramesIsFollowed)
{
  Scene s = geoshaping::testing::painted_grid(30, 30);
  ChainMailDeformer threaded, plain;
  set_up(threaded, s, true);
  set_up(plain, s, true);
  ThreadedChainMail driver;
  driver.set_threads(2);
  driver.set_threshold(0);
  driver.set_per_superstep(0.0);
  driver.set_block(40);
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
    const FrameResult rg = driver.deform(threaded, g, pull);
    const FrameResult rw = plain.deform(g, pull);
    EXPECT_EQ(driver.last_threaded(), f > 0);
    expect_same_frame(threaded, rg, plain, rw, "frame " + std::to_string(f));
  }
}

TEST(ThreadedChainMail, SmallGraspsSequentialQueuesAndBadGraspsStayOnOneThread)
{
  const Scene s = geoshaping::testing::painted_grid(30, 30);
  ChainMailDeformer d;
  set_up(d, s, true);
  ThreadedChainMail driver;
  driver.set_threads(2);
  const index_t g = 15 * 30 + 15;
  // Below the default threshold: one thread, frame after frame.
  for (int f = 0; f < 3; ++f)
  {
    EXPECT_TRUE(driver.deform(d, g, { 0.0, 0.0, 5.0 }).ok);
    EXPECT_FALSE(driver.last_threaded());
    EXPECT_GT(driver.supersteps(), 0u);
    EXPECT_EQ(driver.rounds(), 0u);
  }
  driver.set_threshold(0);
  driver.set_per_superstep(0.0);
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  EXPECT_TRUE(driver.last_threaded());
  EXPECT_GT(driver.rounds(), 0u);
  EXPECT_LE(driver.rounds(), driver.supersteps());
  // The one-thread frame's refusals and queues stay its own.
  const FrameResult pinned = driver.deform(d, (30 / 4) * 30 + 10, { 0.0, 0.0, 1.0 });
  EXPECT_FALSE(pinned.ok);
  EXPECT_FALSE(driver.last_threaded());
  EXPECT_FALSE(driver.deform(d, -1, { 0.0, 0.0, 1.0 }).ok);
  EXPECT_FALSE(driver.deform(d, g, { 0.0, 0.0, std::nan("") }).ok);
  driver.deform(d, g, { 0.0, 0.0, 5.0 }); // no prediction after a refusal
  EXPECT_FALSE(driver.last_threaded());
  d.set_queue(QueueKind::priority);
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  EXPECT_FALSE(driver.last_threaded());
  d.set_queue(QueueKind::fifo);
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  driver.set_threads(1);
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  EXPECT_FALSE(driver.last_threaded());
  // Few vertices per superstep: one thread.
  driver.set_threads(2);
  driver.set_per_superstep(1e9);
  driver.deform(d, g, { 0.0, 0.0, 5.0 });
  EXPECT_FALSE(driver.last_threaded());
}

TEST(ThreadedChainMail, ObstaclesStayOnOneThread)
{
  const Scene s = geoshaping::testing::painted_grid(20, 20);
  ChainMailDeformer d;
  set_up(d, s, true);
  const double tri[9] = { -5.0, -5.0, 2.0, 40.0, -5.0, 2.0, -5.0, 40.0, 2.0 };
  const std::int64_t ids[3] = { 0, 1, 2 };
  ASSERT_EQ(d.set_obstacles(tri, 3, ids, 1), "");
  ThreadedChainMail driver;
  driver.set_threads(2);
  driver.set_threshold(0);
  driver.set_per_superstep(0.0);
  for (int f = 0; f < 2; ++f)
  {
    EXPECT_TRUE(driver.deform(d, 10 * 20 + 10, { 0.0, 0.0, 5.0 }).ok);
    EXPECT_FALSE(driver.last_threaded());
  }
}
