// The partitioned ChainMail (partitioned_chainmail.h) against the whole mesh: pieces run
// by threads exchanging through InProcessExchange must give every vertex the whole
// mesh's displacement, bit for bit, for any partition into 1..4 pieces.
#include "geoshaping/parallel/partitioned_chainmail.h"
#include "test_meshes.h"
#include "test_pieces.h"
#include "test_sheets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <random>

using namespace geoshaping;
using geoshaping::testing::Mesh;

namespace
{

using Scene = geoshaping::testing::PaintedMesh;
using Piece = geoshaping::testing::PaintedPiece;
using geoshaping::testing::painted_grid;
using geoshaping::testing::shuffled_ids;
using geoshaping::testing::split;
using geoshaping::testing::tet_slab;

struct Frame
{
  std::int64_t grasp; // global id
  Eigen::Vector3d pull;
};

// What a frame left on one piece (or the whole mesh), by local vertex.
struct Outcome
{
  FrameResult result;
  std::vector<Eigen::Vector3d> disp;
  std::vector<std::uint8_t> moved;
  std::vector<std::int64_t> sponsor_gid; // -1: none
};

Outcome record(const ChainMailDeformer& d, const FrameResult& r)
{
  Outcome o{ r, {}, {}, {} };
  for (index_t v = 0; v < d.size(); ++v)
  {
    o.disp.push_back(d.displacement(v));
    o.moved.push_back(d.moved_this_frame(v));
    const index_t s = d.moved_this_frame(v) ? d.sponsor(v) : -1;
    o.sponsor_gid.push_back(s < 0 ? -1 : d.global_id(s));
  }
  return o;
}

using PieceSetup = std::function<void(ChainMailDeformer&)>;

// Runs the frames on every piece, each in its own thread; [piece][frame].
std::vector<std::vector<Outcome>> run_pieces(std::vector<Piece>& pieces,
  const std::vector<Frame>& frames, const PieceSetup& setup,
  std::vector<std::string>* setup_errors = nullptr, std::vector<std::size_t>* bytes = nullptr)
{
  std::vector<std::vector<Outcome>> out(pieces.size());
  std::vector<std::string> errors(pieces.size());
  std::vector<std::size_t> sent(pieces.size());
  geoshaping::testing::run_in_pieces(int(pieces.size()),
    [&](int p, Exchange& ex)
    {
      Piece& piece = pieces[std::size_t(p)];
      ChainMailDeformer deformer;
      PartitionedChainMail pc(deformer);
      errors[std::size_t(p)] = pc.set_piece(piece.xyz.data(), index_t(piece.global.size()),
        piece.adjacency, piece.gid.data(), piece.owned.data(), ex);
      if (!errors[std::size_t(p)].empty())
        return;
      ChainMailDeformer& d = pc.deformer();
      d.set_malleability(piece.malleability.data());
      d.set_pinned(piece.pins.data());
      setup(d);
      for (const Frame& f : frames)
        out[std::size_t(p)].push_back(record(d, pc.deform(f.grasp, f.pull, ex)));
      sent[std::size_t(p)] = ex.bytes_sent();
    });
  if (setup_errors)
    *setup_errors = errors;
  if (bytes)
    *bytes = sent;
  return out;
}

std::vector<Outcome> run_whole(
  const Scene& s, const std::vector<Frame>& frames, const PieceSetup& setup)
{
  ChainMailDeformer d;
  d.set_mesh(s.mesh.xyz.data(), s.mesh.size(), s.mesh.adjacency);
  d.set_global_ids(s.gid.data());
  d.set_malleability(s.malleability.data());
  d.set_pinned(s.pins.data());
  setup(d);
  std::vector<Outcome> out;
  for (const Frame& f : frames)
  {
    const auto it = std::find(s.gid.begin(), s.gid.end(), f.grasp);
    out.push_back(record(d, d.deform(index_t(it - s.gid.begin()), f.pull)));
  }
  return out;
}

bool same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

// Every piece's owned vertices and ghosts equal the whole mesh's, bit for bit; each
// moved vertex is moved by exactly one piece (its owner).
void expect_same(const std::vector<Piece>& pieces, const std::vector<std::vector<Outcome>>& got,
  const std::vector<Outcome>& whole, const std::string& what)
{
  for (std::size_t f = 0; f < whole.size(); ++f)
  {
    const Outcome& w = whole[f];
    std::size_t moved = 0, examined = 0;
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      const Outcome& o = got[p][f];
      const std::string where =
        what + " frame " + std::to_string(f) + " piece " + std::to_string(p);
      ASSERT_EQ(o.result.ok, w.result.ok) << where << ": " << o.result.message;
      if (!w.result.ok)
        continue;
      moved += o.result.moved;
      examined += o.result.examined;
      for (std::size_t v = 0; v < pieces[p].global.size(); ++v)
      {
        const std::size_t g = std::size_t(pieces[p].global[v]);
        ASSERT_EQ(o.moved[v], w.moved[g]) << where << " vertex " << g;
        ASSERT_TRUE(same_bits(o.disp[v], w.disp[g])) << where << " vertex " << g;
        if (pieces[p].owned[v])
          ASSERT_EQ(o.sponsor_gid[v], w.sponsor_gid[g]) << where << " vertex " << g;
      }
    }
    if (w.result.ok)
    {
      EXPECT_EQ(moved, w.result.moved) << what << " frame " << f;
      EXPECT_EQ(examined, w.result.examined) << what << " frame " << f;
    }
  }
}

std::vector<int> striped(const Scene& s, int pieces)
{
  return geoshaping::testing::striped_owner(s.mesh.xyz, pieces);
}

std::vector<int> random_owner(const Scene& s, const std::vector<int>& choices, unsigned seed)
{
  return geoshaping::testing::random_owner(s.mesh.size(), choices, seed);
}

std::int64_t gid_at(const Scene& s, index_t v)
{
  return s.gid[std::size_t(v)];
}

void expect_partitions_match(
  const Scene& s, const std::vector<Frame>& frames, const std::string& what)
{
  for (QueueKind q : { QueueKind::fifo_priority, QueueKind::fifo })
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
    {
      const PieceSetup setup = [&](ChainMailDeformer& d)
      {
        d.set_queue(q);
        d.set_valid_region_frame(f);
      };
      const auto whole = run_whole(s, frames, setup);
      for (int pieces = 1; pieces <= 4; ++pieces)
      {
        const std::string name = what + " " + queue_name(q) + " " + frame_name(f) + " " +
                                 std::to_string(pieces) + " pieces";
        auto parts = split(s, striped(s, pieces), pieces);
        expect_same(parts, run_pieces(parts, frames, setup), whole, name + " striped");
        std::vector<int> all(static_cast<std::size_t>(pieces));
        std::iota(all.begin(), all.end(), 0);
        auto random = split(s, random_owner(s, all, unsigned(pieces)), pieces, {}, 9);
        expect_same(random, run_pieces(random, frames, setup), whole, name + " random");
      }
    }
}

} // namespace

TEST(PartitionedChainMail, PaintedGridEqualsTheWholeMeshForAnyPartition)
{
  const index_t nx = 36, ny = 30;
  const Scene s = painted_grid(nx, ny);
  expect_partitions_match(s,
    { { gid_at(s, (ny / 2) * nx + nx / 2), { 0.5, -0.3, 6.0 } },
      { gid_at(s, (ny / 2 + 2) * nx + nx / 3 + 2), { 3.0, 2.0, 10.0 } }, // inside the rigid block
      { gid_at(s, 3), { -1.0, 0.0, 25.0 } } },
    "painted grid");
}

TEST(PartitionedChainMail, TetrahedralSlabEqualsTheWholeMeshForAnyPartition)
{
  const Scene s = tet_slab(14, 10, 5);
  expect_partitions_match(s,
    { { gid_at(s, (2 * 10 + 5) * 14 + 7), { 1.0, -2.0, 4.0 } },
      { gid_at(s, 0), { 0.5, 0.5, 3.0 } } },
    "tet slab");
}

TEST(PartitionedChainMail, RigidRegionMovesAsOneAcrossPieceBordersAndPinsBlock)
{
  const auto island = geoshaping::testing::rigid_island();
  Scene s{ island.mesh, island.malleability,
    std::vector<std::uint8_t>(island.malleability.size(), 0), shuffled_ids(island.mesh.size(), 3) };
  // Pins: a row below the grasp.
  for (index_t i = 5; i < 26; ++i)
    s.pins[std::size_t(4 * 31 + i)] = 1;
  const std::vector<Frame> frames = { { gid_at(s, island.grasp),
    Eigen::Vector3d(island.pull[0], island.pull[1], island.pull[2]) } };
  const PieceSetup setup = [](ChainMailDeformer&) {};
  auto parts = split(s, random_owner(s, { 0, 1, 2, 3 }, 4), 4);
  const auto got = run_pieces(parts, frames, setup);
  expect_same(parts, got, run_whole(s, frames, setup), "island");
  // Independently of the whole mesh: the island's vertices, on whichever piece owns
  // them, all have one displacement, and no pinned vertex moved.
  std::vector<Eigen::Vector3d> rigid;
  std::size_t pinned_moved = 0, moved = 0;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (std::size_t v = 0; v < parts[p].global.size(); ++v)
    {
      if (!parts[p].owned[v])
        continue;
      moved += got[p][0].moved[v];
      pinned_moved += parts[p].pins[v] && got[p][0].moved[v];
      if (parts[p].malleability[v] == 0.0f)
        rigid.push_back(got[p][0].disp[v]);
    }
  ASSERT_EQ(rigid.size(), 49u);
  EXPECT_GT(moved, 49u);
  EXPECT_EQ(pinned_moved, 0u);
  EXPECT_FALSE(rigid.front().isZero(0.0));
  for (const auto& d : rigid)
    EXPECT_TRUE(same_bits(d, rigid.front()));
}

TEST(PartitionedChainMail, EmptyPieceAndGhostOnlyPieceTakePart)
{
  const Scene s = painted_grid(24, 20);
  const std::vector<Frame> frames = { { gid_at(s, 10 * 24 + 12), { 0.0, 1.0, 8.0 } } };
  const PieceSetup setup = [](ChainMailDeformer&) {};
  const auto whole = run_whole(s, frames, setup);
  // Piece 1 holds nothing at all.
  auto empty = split(s, random_owner(s, { 0, 2 }, 5), 3);
  ASSERT_TRUE(empty[1].global.empty());
  expect_same(empty, run_pieces(empty, frames, setup), whole, "empty piece");
  // Piece 2 owns nothing but holds ghosts around the grasp.
  std::vector<index_t> ghosts;
  for (index_t j = 6; j < 14; ++j)
    for (index_t i = 8; i < 16; ++i)
      ghosts.push_back(j * 24 + i);
  auto ghost_only = split(s, striped(s, 2), 3, { {}, {}, ghosts });
  ASSERT_FALSE(ghost_only[2].global.empty());
  expect_same(ghost_only, run_pieces(ghost_only, frames, setup), whole, "ghost-only piece");
}

TEST(PartitionedChainMail, SequentialQueuesAndBadGraspsFailOnEveryPiece)
{
  const Scene s = painted_grid(16, 12);
  const index_t pinned = 3 * 16 + 6; // on the wall of pins
  ASSERT_TRUE(s.pins[std::size_t(pinned)]);
  const std::vector<Frame> frames = { { gid_at(s, 50), { 0.0, 0.0, 2.0 } },
    { -5, { 0.0, 0.0, 2.0 } }, { gid_at(s, pinned), { 0.0, 0.0, 2.0 } },
    { gid_at(s, 50), { 0.0, NAN, 2.0 } } };
  for (QueueKind q : { QueueKind::priority, QueueKind::max_violation, QueueKind::fifo_priority })
  {
    auto parts = split(s, striped(s, 3), 3);
    const auto got = run_pieces(parts, frames, [q](ChainMailDeformer& d) { d.set_queue(q); });
    for (std::size_t f = 0; f < frames.size(); ++f)
      for (const auto& piece : got)
      {
        EXPECT_EQ(piece[f].result.ok, q == QueueKind::fifo_priority && f == 0) << f;
        EXPECT_EQ(piece[f].result.message, got[0][f].result.message);
        if (!piece[f].result.ok)
          EXPECT_EQ(std::count(piece[f].moved.begin(), piece[f].moved.end(), 1), 0);
      }
  }
}

TEST(PartitionedChainMail, GhostOwnedByNoPieceIsRefusedOnEveryPiece)
{
  const Scene s = painted_grid(16, 12);
  auto parts = split(s, striped(s, 2), 2);
  // Piece 0 gives up ownership of one of its vertices that piece 1 holds as a ghost.
  for (std::size_t v = 0; v < parts[0].global.size(); ++v)
    if (parts[0].owned[v] &&
        std::find(parts[1].gid.begin(), parts[1].gid.end(), parts[0].gid[v]) != parts[1].gid.end())
    {
      parts[0].owned[v] = 0;
      break;
    }
  std::vector<std::string> errors;
  run_pieces(
    parts, {}, [](ChainMailDeformer&) {}, &errors);
  ASSERT_FALSE(errors[0].empty());
  EXPECT_EQ(errors[0], errors[1]);
}

TEST(PartitionedChainMail, OnlyTheMovedFrontierCrossesPieces)
{
  // Two stripes: what crosses is the moved vertices on the border, 32 bytes each.
  const Scene s = painted_grid(40, 20);
  const std::vector<Frame> frames = { { gid_at(s, 10 * 40 + 5), { 0.0, 0.0, 3.0 } } };
  auto parts = split(s, striped(s, 2), 2);
  std::vector<std::size_t> bytes;
  const auto got = run_pieces(
    parts, frames, [](ChainMailDeformer&) {}, nullptr, &bytes);
  std::size_t moved_held_elsewhere = 0; // moved owned vertices the other piece holds
  for (std::size_t v = 0; v < parts[0].global.size(); ++v)
    if (parts[0].owned[v] && got[0][0].moved[v] &&
        std::find(parts[1].gid.begin(), parts[1].gid.end(), parts[0].gid[v]) != parts[1].gid.end())
      ++moved_held_elsewhere;
  // Plus one marker record per message of a superstep that piece 0 ran ahead alone.
  ASSERT_EQ(bytes[0] % sizeof(MovedVertex), 0u);
  const std::size_t records = bytes[0] / sizeof(MovedVertex);
  EXPECT_GE(records, moved_held_elsewhere);
  EXPECT_LE(records, moved_held_elsewhere + 3) << "markers: at most a few rounds send one";
}

TEST(PartitionedChainMail, PiecesRunAheadAloneWhileTheyHaveNothingToSend)
{
  // One piece: a frame is one round. Two stripes, a grasp far from the border: most
  // supersteps run on piece 0 alone, with no synchronisation; the same bits (the tests
  // above) and the same superstep count as the whole mesh's frame.
  const Scene s = painted_grid(40, 20);
  const std::vector<Frame> frames = { { gid_at(s, 10 * 40 + 5), { 0.0, 0.0, 3.0 } } };
  for (int pieces : { 1, 2, 3 })
  {
    auto parts = split(s, striped(s, pieces), pieces);
    std::vector<std::size_t> supersteps(parts.size()), rounds(parts.size());
    geoshaping::testing::run_in_pieces(pieces,
      [&](int p, Exchange& ex)
      {
        Piece& piece = parts[std::size_t(p)];
        ChainMailDeformer d;
        PartitionedChainMail pc(d);
        ASSERT_EQ(pc.set_piece(piece.xyz.data(), piece.size(), piece.adjacency, piece.gid.data(),
                    piece.owned.data(), ex),
          "");
        d.set_malleability(piece.malleability.data());
        d.set_pinned(piece.pins.data());
        ASSERT_TRUE(pc.deform(frames[0].grasp, frames[0].pull, ex).ok);
        supersteps[std::size_t(p)] = pc.supersteps();
        rounds[std::size_t(p)] = pc.rounds();
      });
    for (int p = 1; p < pieces; ++p)
    {
      EXPECT_EQ(supersteps[std::size_t(p)], supersteps[0]);
      EXPECT_EQ(rounds[std::size_t(p)], rounds[0]);
    }
    EXPECT_GT(supersteps[0], 20u);
    if (pieces == 1)
      EXPECT_EQ(rounds[0], 1u);
    else
      EXPECT_LT(2 * rounds[0], supersteps[0]) << pieces << " pieces";
  }
}

TEST(PartitionedChainMail, TheMarkersGlobalIdIsRefusedOnEveryPiece)
{
  Scene s = painted_grid(12, 10);
  s.gid[5] = std::numeric_limits<std::int64_t>::min();
  auto parts = split(s, striped(s, 2), 2);
  std::vector<std::string> errors;
  run_pieces(
    parts, {}, [](ChainMailDeformer&) {}, &errors);
  for (const std::string& e : errors)
    EXPECT_NE(e.find("reserved"), std::string::npos) << e;
}

TEST(PartitionedChainMail, APointHeldTwiceByAPieceMovesAsOne)
{
  // VTK pieces may hold a point twice (the same global id), each copy in some of its
  // cells: the copies are one vertex.
  const Scene s = painted_grid(20, 16);
  const std::vector<Frame> frames = { { gid_at(s, 8 * 20 + 10), { 0.5, 0.0, 7.0 } } };
  const PieceSetup setup = [](ChainMailDeformer&) {};
  auto parts = split(s, striped(s, 2), 2);
  for (Piece& piece : parts)
  {
    const index_t n = index_t(piece.global.size());
    std::vector<std::vector<index_t>> rows{ static_cast<std::size_t>(n) };
    for (index_t v = 0; v < n; ++v)
      rows[std::size_t(v)].assign(piece.adjacency.begin(v), piece.adjacency.end(v));
    for (index_t v = 0; v < n; v += 3) // a copy of every third point takes half its edges
    {
      const index_t copy = index_t(rows.size());
      rows.emplace_back();
      auto& row = rows[std::size_t(v)];
      for (std::size_t k = 0; k < row.size(); k += 2)
      {
        const index_t u = row[k];
        rows.back().push_back(u);
        auto& back = rows[std::size_t(u)];
        std::replace(back.begin(), back.end(), v, copy);
        row[k] = -1;
      }
      row.erase(std::remove(row.begin(), row.end(), -1), row.end());
      piece.global.push_back(piece.global[std::size_t(v)]);
      piece.xyz.insert(
        piece.xyz.end(), &piece.xyz[3 * std::size_t(v)], &piece.xyz[3 * std::size_t(v)] + 3);
      piece.gid.push_back(piece.gid[std::size_t(v)]);
      piece.owned.push_back(piece.owned[std::size_t(v)]);
      piece.pins.push_back(piece.pins[std::size_t(v)]);
      piece.malleability.push_back(piece.malleability[std::size_t(v)]);
    }
    piece.adjacency.offsets.assign(1, 0);
    piece.adjacency.neighbors.clear();
    for (auto& row : rows)
    {
      std::sort(row.begin(), row.end());
      piece.adjacency.neighbors.insert(piece.adjacency.neighbors.end(), row.begin(), row.end());
      piece.adjacency.offsets.push_back(std::int64_t(piece.adjacency.neighbors.size()));
    }
  }
  const auto got = run_pieces(parts, frames, setup);
  const auto whole = run_whole(s, frames, setup);
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (std::size_t v = 0; v < parts[p].global.size(); ++v)
    {
      const std::size_t g = std::size_t(parts[p].global[v]);
      ASSERT_EQ(got[p][0].moved[v], whole[0].moved[g]) << p << " " << v;
      ASSERT_TRUE(same_bits(got[p][0].disp[v], whole[0].disp[g])) << p << " " << v;
    }
  EXPECT_GT(whole[0].result.moved, 20u);
}

namespace
{
// The painted grid under a tilted ceiling (z = 3 + 0.1 x), with a wall (y = 2.5) that
// the vertices of row 2 slide on: obstacles.h's scene for the partitioned tests.
geoshaping::testing::Sheet ceiling_and_wall()
{
  using geoshaping::testing::sheet;
  auto s = sheet(14, { -3.0, -3.0, 2.7 }, { 42.0, 0.0, 4.2 }, { 0.0, 36.0, 0.0 });
  s.add(sheet(9, { -3.0, 2.5, -6.0 }, { 42.0, 0.0, 0.0 }, { 0.0, 0.0, 40.0 }));
  return s;
}

// Owners with the rigid block (malleability 0) given whole to the owner of its first vertex.
std::vector<int> rigid_block_whole(const Scene& s, std::vector<int> owner)
{
  int block = -1;
  for (std::size_t v = 0; v < owner.size(); ++v)
    if (s.malleability[v] == 0.0f)
      owner[v] = block = block < 0 ? owner[v] : block;
  return owner;
}
} // namespace

TEST(PartitionedChainMail, ObstaclesGiveTheWholeMeshsBitsForAnyPartition)
{
  const index_t nx = 36, ny = 30;
  const Scene s = painted_grid(nx, ny);
  const auto obstacle = ceiling_and_wall();
  std::vector<std::uint8_t> sliding(std::size_t(s.mesh.size()), 0);
  for (index_t i = 0; i < nx; ++i)
    sliding[std::size_t(2 * nx + i)] = !s.pins[std::size_t(2 * nx + i)];
  const std::vector<Frame> frames = { { gid_at(s, (ny / 2) * nx + nx / 2), { 0.5, -0.3, 6.0 } },
    { gid_at(s, (ny / 2 + 2) * nx + nx / 3 + 2), { 3.0, 2.0, 10.0 } }, // the rigid block
    { gid_at(s, 2 * nx + 20), { 4.0, 1.0, 5.0 } },                     // a sliding grasp
    { gid_at(s, 3), { -1.0, 0.0, 25.0 } } };
  std::size_t blocked_frames = 0;
  for (double clearance : { 0.0, 0.3 })
    for (QueueKind q : { QueueKind::fifo_priority, QueueKind::fifo })
      for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
      {
        // The piece's sliding flags, by its vertices' positions in the whole mesh.
        auto setup_with = [&](const std::vector<std::uint8_t>& mask)
        {
          return [&, mask](ChainMailDeformer& d)
          {
            d.set_queue(q);
            d.set_valid_region_frame(f);
            ASSERT_EQ(d.set_obstacles(obstacle.xyz.data(), obstacle.points(), obstacle.tri.data(),
                        obstacle.triangles()),
              "");
            ASSERT_TRUE(d.set_obstacle_clearance(clearance));
            d.set_sliding(mask.data());
          };
        };
        const auto whole = run_whole(s, frames, setup_with(sliding));
        for (const Outcome& w : whole)
        {
          ASSERT_TRUE(w.result.ok) << w.result.message;
          blocked_frames += w.result.blocked > 0;
        }
        EXPECT_LT(whole[0].result.grasp_fraction, 1.0); // the centre's pull hits the ceiling
        for (int pieces = 1; pieces <= 4; ++pieces)
        {
          std::vector<int> all(static_cast<std::size_t>(pieces));
          std::iota(all.begin(), all.end(), 0);
          const std::string name = std::string(queue_name(q)) + " " + frame_name(f) +
                                   " clearance " + std::to_string(clearance) + " " +
                                   std::to_string(pieces) + " pieces";
          for (int random = 0; random < 2; ++random)
          {
            const auto owner = rigid_block_whole(
              s, random ? random_owner(s, all, unsigned(pieces)) : striped(s, pieces));
            auto parts = split(s, owner, pieces, {}, 9);
            const PieceSetup setup = [&](ChainMailDeformer& d)
            {
              // This piece: the one whose vertex count matches (set up in its thread).
              for (const auto& part : parts)
                if (index_t(part.global.size()) == d.size() && part.gid[0] == d.global_id(0))
                  setup_with(part.gather(sliding))(d);
            };
            const auto got = run_pieces(parts, frames, setup);
            const std::string where = name + (random ? " random" : " striped");
            expect_same(parts, got, whole, where);
            for (std::size_t k = 0; k < frames.size(); ++k)
            {
              std::size_t blocked = 0, owners = 0;
              for (std::size_t p = 0; p < parts.size(); ++p)
              {
                blocked += got[p][k].result.blocked;
                for (std::size_t v = 0; v < parts[p].gid.size(); ++v)
                  if (parts[p].owned[v] && parts[p].gid[v] == frames[k].grasp)
                  {
                    ++owners;
                    EXPECT_EQ(got[p][k].result.grasp_fraction, whole[k].result.grasp_fraction)
                      << where << " frame " << k;
                  }
              }
              EXPECT_EQ(owners, 1u);
              EXPECT_EQ(blocked, whole[k].result.blocked) << where << " frame " << k;
            }
          }
        }
      }
  // The obstacles act: 30 of the 32 whole-mesh frames held vertices back.
  EXPECT_EQ(blocked_frames, 30u);
}

TEST(PartitionedChainMail, ARigidRegionSplitAcrossPiecesWithObstaclesIsRefusedOnEveryPiece)
{
  const index_t nx = 36, ny = 30;
  const Scene s = painted_grid(nx, ny);
  const auto obstacle = ceiling_and_wall();
  // Two stripes: the border x = 18 runs through the rigid block (x from 12 to 17) only
  // when the block is given to both; striped_owner cuts at the middle.
  auto owner = striped(s, 2);
  std::size_t left = 0, right = 0;
  for (std::size_t v = 0; v < owner.size(); ++v)
    if (s.malleability[v] == 0.0f)
    {
      owner[v] = int(v % std::size_t(nx) >= 15);
      (owner[v] ? right : left)++;
    }
  ASSERT_GT(left, 0u);
  ASSERT_GT(right, 0u);
  const std::vector<Frame> frames = { { gid_at(s, (ny / 2) * nx + nx / 2), { 0.5, -0.3, 6.0 } } };
  for (bool with : { false, true })
  {
    auto parts = split(s, owner, 2);
    const auto got = run_pieces(parts, frames,
      [&](ChainMailDeformer& d)
      {
        if (with)
          ASSERT_EQ(d.set_obstacles(obstacle.xyz.data(), obstacle.points(), obstacle.tri.data(),
                      obstacle.triangles()),
            "");
      });
    for (const auto& piece : got)
    {
      EXPECT_EQ(piece[0].result.ok, !with) << piece[0].result.message;
      EXPECT_EQ(piece[0].result.message, got[0][0].result.message);
      if (with)
      {
        EXPECT_NE(
          piece[0].result.message.find("rigid region split across pieces"), std::string::npos);
        EXPECT_EQ(std::count(piece[0].moved.begin(), piece[0].moved.end(), 1), 0);
      }
    }
  }
}
