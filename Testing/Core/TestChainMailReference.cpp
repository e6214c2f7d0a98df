// The optimised ChainMailDeformer against a plain reference implementation of the
// deformation contract (docs/design.md) and docs/deformer.md, written for clarity: per-vertex
// std::vectors indexed by the caller's ids, the transfer function evaluated per candidate, std::
// containers for the queues (FIFO and FIFO Priority: a std::map from (malleability, generation) to
// the superstep's entries, sorted when the superstep starts). Every frame must agree
// exactly: the same vertices moved in the same order, the same sponsors, bit-identical
// displacements, the same number of candidates examined, for all four queues, across
// frames, pins, commits, set_rest and global ids.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/deform/valid_region.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <random>
#include <tuple>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{

class Reference
{
public:
  // Rest positions are taken from the deformer (so both share the local origin).
  Reference(const ChainMailDeformer& d, const Adjacency& adj)
    : adj_(adj)
  {
    const std::size_t n = std::size_t(d.size());
    rest_.resize(n);
    disp_.assign(n, Eigen::Vector3d::Zero());
    for (index_t v = 0; v < d.size(); ++v)
      rest_[v] = d.rest_local(v);
    malleability_.assign(n, 0.5f);
    gid_.resize(n);
    for (std::size_t v = 0; v < n; ++v)
      gid_[v] = std::int64_t(v);
    pinned_.assign(n, 0);
    moved_flag_.assign(n, 0);
    sponsor_.assign(n, -1);
    ranks();
  }
  void set_malleability(const std::vector<float>& m)
  {
    for (std::size_t v = 0; v < m.size(); ++v)
      malleability_[v] = std::isnan(m[v]) ? 0.0f : float(std::clamp(double(m[v]), 0.0, 1.0));
    ranks();
  }
  void set_pinned(const std::vector<std::uint8_t>& p) { pinned_ = p; }
  void set_global_ids(const std::vector<std::int64_t>& gid) { gid_ = gid; }
  void set_rest(index_t v, const Eigen::Vector3d& r) { rest_[v] = r; }
  void commit()
  {
    for (index_t v : moved_)
      rest_[v] += disp_[v];
    for (index_t v : moved_)
      disp_[v].setZero();
  }

  FrameResult deform(index_t g, const Eigen::Vector3d& d, QueueKind q, const TransferFunction& tf,
    ValidRegionFrame frame = ValidRegionFrame::axes)
  {
    for (index_t v : moved_)
    {
      disp_[v].setZero();
      moved_flag_[v] = 0;
    }
    moved_.clear();
    FrameResult r;
    if (g < 0 || g >= index_t(rest_.size()) || !d.allFinite() || !rest_[g].allFinite() ||
        pinned_[g])
      return r;
    disp_[g] = d;
    moved_flag_[g] = 1;
    sponsor_[g] = -1;
    moved_.push_back(g);
    auto required = [&](index_t c, index_t s)
    {
      const Eigen::Vector3d o = rest_[c] - rest_[s];
      if (!o.allFinite())
        return Eigen::Vector3d::Zero().eval();
      if (frame == ValidRegionFrame::link) // valid_region.h's own function for either region shape
        return required_displacement(frame, o, tf(malleability_[c]), disp_[s]);
      const Box b = displacement_bounds(o, tf(malleability_[c]));
      return Eigen::Vector3d::Zero().cwiseMax(disp_[s] + b.lo).cwiseMin(disp_[s] + b.hi).eval();
    };
    auto move = [&](index_t c, index_t s, const Eigen::Vector3d& t)
    {
      disp_[c] = t;
      moved_flag_[c] = 1;
      sponsor_[c] = s;
      moved_.push_back(c);
    };
    if (q == QueueKind::fifo || q == QueueKind::fifo_priority)
      supersteps(q == QueueKind::fifo_priority, g, required, move, r);
    else
      sequential(q, g, required, move, r);
    r.ok = true;
    r.moved = moved_.size();
    return r;
  }

  // Supersteps: every entry of the lowest (malleability, root, generation), in
  // (candidate id, sponsor id) order; a candidate takes the longest of its entries'
  // targets, the first among exactly equal lengths; the neighbours of what a superstep
  // moved are queued after it. A root (generation, -|target|^2, id) starts where an
  // entry goes down in malleability band (priority_band): the longer target first, the
  // lower id among equal lengths; it is kept within one band, and is (0, 0, 0) going up.
  template<class Required, class Move>
  void supersteps(bool banded, index_t g, Required required, Move move, FrameResult& r)
  {
    using Root = std::tuple<std::uint32_t, double, std::int64_t>;
    using Entry = std::tuple<std::int64_t, std::int64_t, index_t, index_t>; // gids, c, s
    std::map<std::tuple<std::uint32_t, Root, std::uint32_t>, std::vector<Entry>> pending;
    std::vector<Root> root(malleability_.size(), Root{ 0, 0.0, 0 });
    std::vector<index_t> this_step{ g };
    std::uint32_t step = 0;
    auto band = [&](index_t v) { return banded ? priority_band(malleability_[v]) : 0u; };
    auto queue_neighbours = [&]
    {
      for (index_t s : this_step)
        for (const index_t* it = adj_.begin(s); it != adj_.end(s); ++it)
        {
          const index_t c = *it;
          if (moved_flag_[c] || pinned_[c])
            continue;
          const Root rc = band(c) < band(s)
                            ? Root{ step + 1, -required(c, s).squaredNorm(), gid_[c] }
                          : band(c) == band(s) ? root[s]
                                               : Root{ 0, 0.0, 0 };
          pending[{ band(c), rc, step + 1 }].emplace_back(gid_[c], gid_[s], c, s);
        }
      this_step.clear();
      ++step;
    };
    queue_neighbours();
    while (!pending.empty())
    {
      const Root group_root = std::get<1>(pending.begin()->first);
      std::vector<Entry> entries = std::move(pending.begin()->second);
      pending.erase(pending.begin());
      std::sort(entries.begin(), entries.end());
      for (std::size_t k = 0; k < entries.size();)
      {
        // The entries of one candidate: the longest target wins, the first of equals.
        const index_t c = std::get<2>(entries[k]);
        index_t best = -1;
        Eigen::Vector3d best_t = Eigen::Vector3d::Zero();
        for (; k < entries.size() && std::get<2>(entries[k]) == c; ++k)
        {
          ++r.examined;
          const index_t s = std::get<3>(entries[k]);
          if (moved_flag_[c])
            continue;
          const Eigen::Vector3d t = required(c, s);
          if (!t.isZero(0.0) && (best < 0 || t.squaredNorm() > best_t.squaredNorm()))
          {
            best = s;
            best_t = t;
          }
        }
        if (best < 0)
          continue;
        move(c, best, best_t);
        root[c] = group_root;
        this_step.push_back(c);
      }
      queue_neighbours();
    }
  }

  // Priority and Max Violation: one candidate at a time, its neighbours pushed at once.
  template<class Required, class Move>
  void sequential(QueueKind q, index_t g, Required required, Move move, FrameResult& r)
  {
    struct Item
    {
      double key;
      Candidate c;
    };
    struct RankLater
    {
      bool operator()(const Item& a, const Item& b) const { return a.key > b.key; }
    };
    struct ViolationLater
    {
      bool operator()(const Item& a, const Item& b) const { return b.key > a.key; }
    };
    std::priority_queue<Item, std::vector<Item>, RankLater> heap;
    std::priority_queue<Item, std::vector<Item>, ViolationLater> violation;
    auto sponsor = [&](index_t s)
    {
      for (const index_t* it = adj_.begin(s); it != adj_.end(s); ++it)
      {
        const index_t c = *it;
        if (moved_flag_[c] || pinned_[c])
          continue;
        if (q == QueueKind::priority)
          heap.push({ double(rank_[c]), { c, s } });
        else
          violation.push({ required(c, s).norm(), { c, s } });
      }
    };
    auto pop = [&](Candidate& out)
    {
      if (q == QueueKind::priority)
      {
        if (heap.empty())
          return false;
        out = heap.top().c;
        heap.pop();
        return true;
      }
      if (violation.empty())
        return false;
      out = violation.top().c;
      violation.pop();
      return true;
    };
    sponsor(g);
    Candidate c;
    while (pop(c))
    {
      ++r.examined;
      if (moved_flag_[c.vertex])
        continue;
      const Eigen::Vector3d t = required(c.vertex, c.sponsor);
      if (t.isZero(0.0))
        continue;
      move(c.vertex, c.sponsor, t);
      sponsor(c.vertex);
    }
  }

  std::vector<index_t> moved_;
  std::vector<index_t> sponsor_;
  std::vector<Eigen::Vector3d> disp_, rest_;
  std::vector<std::uint8_t> moved_flag_;

private:
  void ranks()
  {
    std::vector<float> distinct = malleability_;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    rank_.resize(malleability_.size());
    for (std::size_t v = 0; v < malleability_.size(); ++v)
      rank_[v] = index_t(
        std::lower_bound(distinct.begin(), distinct.end(), malleability_[v]) - distinct.begin());
  }

  const Adjacency& adj_;
  std::vector<std::int64_t> gid_;
  std::vector<float> malleability_;
  std::vector<index_t> rank_;
  std::vector<std::uint8_t> pinned_;
};

bool same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

// Runs one frame on both and compares everything the public API shows.
void expect_same_frame(ChainMailDeformer& d, Reference& ref, index_t g, const Eigen::Vector3d& u,
  const std::string& what)
{
  const std::vector<index_t> before = d.moved();
  const FrameResult a = d.deform(g, u);
  const FrameResult b = ref.deform(g, u, d.queue(), d.transfer_function(), d.valid_region_frame());
  const std::string where =
    what + " / " + queue_name(d.queue()) + " / " + frame_name(d.valid_region_frame());
  ASSERT_EQ(a.ok, b.ok) << where;
  EXPECT_EQ(d.previously_moved(), before) << where;
  if (!a.ok)
  {
    EXPECT_TRUE(d.moved().empty()) << where;
    return;
  }
  ASSERT_EQ(a.moved, b.moved) << where;
  ASSERT_EQ(a.examined, b.examined) << where;
  ASSERT_EQ(d.moved(), ref.moved_) << where;
  for (index_t v = 0; v < d.size(); ++v)
  {
    ASSERT_TRUE(same_bits(d.displacement(v), ref.disp_[v])) << where << " vertex " << v;
    ASSERT_EQ(d.moved_this_frame(v), ref.moved_flag_[v] != 0) << where << " vertex " << v;
    ASSERT_TRUE(same_bits(d.rest_local(v), ref.rest_[v])) << where << " vertex " << v;
    if (d.moved_this_frame(v))
      ASSERT_EQ(d.sponsor(v), ref.sponsor_[v]) << where << " vertex " << v;
  }
}

constexpr ValidRegionFrame all_frames[] = { ValidRegionFrame::axes, ValidRegionFrame::link };
constexpr QueueKind all_queues[] = { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority,
  QueueKind::max_violation };

// A grid with jittered rest positions, so offsets are not all axis-aligned.
geoshaping::testing::Mesh jittered(geoshaping::testing::Mesh m, unsigned seed, double amount)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (double& x : m.xyz)
    x += u(rng);
  return m;
}

} // namespace

TEST(ChainMailReference, PaintedGridMatchesForEveryQueueAndPull)
{
  // The benchmark's painting (8 bands) on a smaller grid, plus continuous values.
  const index_t n = 90;
  auto mesh = jittered(geoshaping::testing::triangle_grid(n, n, 1.0), 7, 0.2);
  std::vector<float> banded(std::size_t(mesh.size())), smooth(banded.size());
  for (index_t j = 0; j < n; ++j)
    for (index_t i = 0; i < n; ++i)
    {
      const double s = 0.5 + 0.5 * std::sin(0.15 * i) * std::cos(0.12 * j);
      banded[j * n + i] = float(0.3 + 0.08 * std::floor(s * 7.999));
      smooth[j * n + i] = float(s);
    }
  for (const auto* m : { &banded, &smooth })
    for (QueueKind q : all_queues)
      for (ValidRegionFrame f : all_frames)
      {
        ChainMailDeformer d;
        d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
        d.set_malleability(m->data());
        d.set_queue(q);
        d.set_valid_region_frame(f);
        Reference ref(d, mesh.adjacency);
        ref.set_malleability(*m);
        for (double pull : { 0.5, 3.0, 12.0, 40.0 })
          expect_same_frame(d, ref, (n / 2) * n + n / 3, { 0.1 * pull, -0.05 * pull, pull },
            "painted grid pull " + std::to_string(pull));
        // Frames in a row reuse the stamps and the sparse reset.
        expect_same_frame(d, ref, 5, { 2.0, 1.0, -3.0 }, "corner");
        expect_same_frame(d, ref, n * n - 1, { 0.0, 0.0, 0.0 }, "zero pull");
      }
}

TEST(ChainMailReference, RigidIslandTetsAndTransferCurvesMatch)
{
  const auto island = geoshaping::testing::rigid_island();
  TransferFunction smooth;
  smooth.stretch.shape = CurveShape::smooth;
  smooth.shear = { 0.0, 1.2, CurveShape::step, 0.4, {} };
  smooth.compression = { 1.0, 0.2, CurveShape::piecewise, 0.5,
    { { 0.0, 1.0 }, { 0.3, 0.9 }, { 0.7, 0.4 }, { 1.0, 0.2 } } };
  for (const TransferFunction& tf : { TransferFunction(), smooth })
    for (QueueKind q : all_queues)
      for (ValidRegionFrame f : all_frames)
      {
        ChainMailDeformer d;
        d.set_mesh(island.mesh.xyz.data(), island.mesh.size(), island.mesh.adjacency);
        d.set_malleability(island.malleability.data());
        d.set_transfer_function(tf);
        d.set_queue(q);
        d.set_valid_region_frame(f);
        Reference ref(d, island.mesh.adjacency);
        ref.set_malleability(island.malleability);
        expect_same_frame(d, ref, island.grasp, Eigen::Vector3d(island.pull), "rigid island");
        expect_same_frame(d, ref, 0, { -3.0, 2.0, 9.0 }, "island corner");
      }

  // A random tetrahedral-like graph: jittered 3-D lattice with diagonal edges.
  const index_t nx = 14, ny = 12, nz = 9;
  std::vector<double> xyz;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  for (index_t k = 0; k < nz; ++k)
    for (index_t j = 0; j < ny; ++j)
      for (index_t i = 0; i < nx; ++i)
        for (double c : { double(i), double(j), double(k) })
          xyz.push_back(1e5 + c + jitter(rng)); // UTM-sized
  const index_t nv = nx * ny * nz;
  AdjacencyBuilder builder(nv);
  auto id = [&](index_t i, index_t j, index_t k) { return (k * ny + j) * nx + i; };
  for (index_t k = 0; k + 1 < nz; ++k)
    for (index_t j = 0; j + 1 < ny; ++j)
      for (index_t i = 0; i + 1 < nx; ++i)
      {
        const std::int64_t ids[4] = { id(i, j, k), id(i + 1, j, k), id(i, j + 1, k),
          id(i, j, k + 1) };
        builder.add_cell(CellKind::tetra, ids, 4);
        const std::int64_t ids2[4] = { id(i + 1, j + 1, k + 1), id(i + 1, j + 1, k),
          id(i, j + 1, k + 1), id(i + 1, j, k + 1) };
        builder.add_cell(CellKind::tetra, ids2, 4);
      }
  const Adjacency adj = builder.build();
  std::vector<float> m(static_cast<std::size_t>(nv));
  std::uniform_real_distribution<float> um(-0.2f, 1.2f);
  for (float& x : m)
    x = um(rng);
  m[17] = std::numeric_limits<float>::quiet_NaN();
  for (QueueKind q : all_queues)
    for (ValidRegionFrame f : all_frames)
    {
      ChainMailDeformer d;
      d.set_mesh(xyz.data(), nv, adj);
      d.set_malleability(m.data());
      d.set_queue(q);
      d.set_valid_region_frame(f);
      Reference ref(d, adj);
      ref.set_malleability(m);
      expect_same_frame(d, ref, id(7, 6, 4), { 1.0, -2.0, 4.0 }, "tets");
      expect_same_frame(d, ref, id(0, 0, 0), { 0.5, 0.5, 0.5 }, "tets corner");
    }
}

TEST(ChainMailReference, PinsCommitsSetRestAndErrorsMatch)
{
  const index_t n = 40;
  auto mesh = jittered(geoshaping::testing::quad_grid(n, n, 2.0), 3, 0.3);
  // A non-finite rest position: never moves anything from it.
  mesh.xyz[3 * 77 + 2] = std::numeric_limits<double>::infinity();
  std::vector<float> m(std::size_t(mesh.size()));
  for (index_t v = 0; v < mesh.size(); ++v)
    m[v] = float((v * 37) % 11) / 10.0f;
  std::vector<std::uint8_t> pins(m.size(), 0);
  for (index_t i = 5; i < 30; ++i)
    pins[std::size_t(grid_id(n, i, 25))] = 1;
  for (QueueKind q : all_queues)
  {
    ChainMailDeformer d;
    d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    d.set_malleability(m.data());
    d.set_pinned(pins.data());
    d.set_queue(q);
    Reference ref(d, mesh.adjacency);
    ref.set_malleability(m);
    ref.set_pinned(pins);
    expect_same_frame(d, ref, grid_id(n, 20, 10), { 0.0, 3.0, 15.0 }, "pinned");
    d.commit();
    ref.commit();
    expect_same_frame(d, ref, grid_id(n, 17, 30), { 1.0, -9.0, 2.0 }, "after commit");
    expect_same_frame(d, ref, grid_id(n, 10, 25), { 1.0, 0.0, 0.0 }, "grasp pinned");
    expect_same_frame(d, ref, -1, { 1.0, 0.0, 0.0 }, "grasp out of range");
    expect_same_frame(d, ref, 77, { 1.0, 0.0, 0.0 }, "grasp non-finite");
    expect_same_frame(d, ref, 3, { 1.0, NAN, 0.0 }, "non-finite pull");
    d.reset();
    const Eigen::Vector3d r = d.rest_local(300) + Eigen::Vector3d(0.5, -0.25, 4.0);
    d.set_rest(300, r, Eigen::Vector3d(0.5, -0.25, 4.0));
    ref.set_rest(300, r);
    EXPECT_EQ(d.committed_offset(300), Eigen::Vector3d(0.5, -0.25, 4.0));
    d.set_pinned(nullptr);
    ref.set_pinned(std::vector<std::uint8_t>(m.size(), 0));
    d.set_uniform_malleability(0.25);
    ref.set_malleability(std::vector<float>(m.size(), 0.25f));
    expect_same_frame(d, ref, grid_id(n, 20, 20), { 0.0, 0.0, 30.0 }, "uniform after set_rest");
    EXPECT_FLOAT_EQ(d.malleability(5), 0.25f);
  }
}

TEST(ChainMailReference, CallerIdsAdjacencyAndMalleabilityReadBackAsGiven)
{
  // The deformer renumbers vertices internally; everything public is in the caller's ids.
  auto mesh = jittered(geoshaping::testing::triangle_grid(23, 17, 1.5), 5, 0.4);
  std::vector<float> m(std::size_t(mesh.size()));
  for (index_t v = 0; v < mesh.size(); ++v)
    m[v] = float((v * 7919) % 101) / 100.0f;
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  d.set_malleability(m.data());
  EXPECT_EQ(d.adjacency().offsets, mesh.adjacency.offsets);
  EXPECT_EQ(d.adjacency().neighbors, mesh.adjacency.neighbors);
  for (index_t v = 0; v < d.size(); ++v)
  {
    EXPECT_EQ(d.malleability(v), m[v]);
    const Eigen::Vector3d p(mesh.xyz[3 * v], mesh.xyz[3 * v + 1], mesh.xyz[3 * v + 2]);
    EXPECT_EQ(d.position(v), d.origin() + (p - d.origin()));
    EXPECT_FALSE(d.moved_this_frame(v));
    EXPECT_TRUE(d.displacement(v).isZero(0.0));
  }
  ASSERT_TRUE(d.deform(40, { 0.0, 0.0, 6.0 }).ok);
  EXPECT_EQ(d.moved().front(), 40);
  EXPECT_EQ(d.sponsor(40), -1);
  EXPECT_EQ(d.displacement(40), Eigen::Vector3d(0.0, 0.0, 6.0));
  // A copy is independent and answers the same.
  const ChainMailDeformer copy = d;
  EXPECT_EQ(copy.moved(), d.moved());
  EXPECT_EQ(&copy.adjacency() == &d.adjacency(), true); // shared, immutable
  d.set_mesh(mesh.xyz.data(), mesh.size(), geoshaping::testing::chain(mesh.size(), 1.0).adjacency);
  EXPECT_NE(copy.adjacency().neighbors, d.adjacency().neighbors);
  EXPECT_EQ(copy.adjacency().neighbors, mesh.adjacency.neighbors);
}

TEST(ChainMailReference, GlobalIdsDecideTheOrderAndRenumberingChangesNothing)
{
  const index_t n = 50;
  auto mesh = jittered(geoshaping::testing::triangle_grid(n, n, 1.0), 13, 0.25);
  const std::size_t nv = std::size_t(mesh.size());
  std::vector<float> m(nv);
  for (std::size_t v = 0; v < nv; ++v)
    m[v] = float(0.2 + 0.1 * double((v * 7) % 5));
  std::vector<std::int64_t> gid(nv);
  std::iota(gid.begin(), gid.end(), std::int64_t(0));
  std::shuffle(gid.begin(), gid.end(), std::mt19937(3));
  // The same mesh numbered backwards, with the same global ids.
  geoshaping::testing::Mesh back;
  std::vector<float> m_back(nv);
  std::vector<std::int64_t> gid_back(nv);
  AdjacencyBuilder builder(mesh.size());
  auto flip = [&](index_t v) { return index_t(nv) - 1 - v; };
  for (index_t v = 0; v < mesh.size(); ++v)
  {
    const index_t w = flip(v);
    back.xyz.insert(
      back.xyz.end(), &mesh.xyz[3 * std::size_t(w)], &mesh.xyz[3 * std::size_t(w)] + 3);
    m_back[std::size_t(v)] = m[std::size_t(w)];
    gid_back[std::size_t(v)] = gid[std::size_t(w)];
    for (const index_t* it = mesh.adjacency.begin(w); it != mesh.adjacency.end(w); ++it)
    {
      const std::int64_t edge[2] = { v, flip(*it) };
      builder.add_cell(CellKind::line, edge, 2);
    }
  }
  back.adjacency = builder.build();
  for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
  {
    ChainMailDeformer d, e;
    d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    e.set_mesh(back.xyz.data(), back.size(), back.adjacency);
    d.set_malleability(m.data());
    e.set_malleability(m_back.data());
    d.set_global_ids(gid.data());
    e.set_global_ids(gid_back.data());
    d.set_queue(q);
    e.set_queue(q);
    Reference ref(d, mesh.adjacency);
    ref.set_malleability(m);
    ref.set_global_ids(gid);
    const index_t g = (n / 2) * n + n / 2;
    expect_same_frame(d, ref, g, { 1.0, 0.5, 9.0 }, "global ids");
    const FrameResult r = e.deform(flip(g), { 1.0, 0.5, 9.0 });
    ASSERT_EQ(r.moved, d.moved().size());
    EXPECT_GT(r.moved, 100u);
    for (index_t v = 0; v < mesh.size(); ++v)
    {
      ASSERT_TRUE(same_bits(d.displacement(v), e.displacement(flip(v)))) << v;
      if (d.moved_this_frame(v) && d.sponsor(v) >= 0)
        ASSERT_EQ(d.sponsor(v), flip(e.sponsor(flip(v)))) << v;
    }
    EXPECT_EQ(d.global_id(7), gid[7]);
  }
}
