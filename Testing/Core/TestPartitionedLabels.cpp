// Label correction on pieces (partitioned_labels.h) against the whole mesh: pieces run
// by threads exchanging through InProcessExchange must give every copy of every vertex
// the whole mesh's result, bit for bit, for any partition into 1..4 pieces:
// - the envelope refinement (partitioned_envelope.h) against LinkProjector's envelope,
//   after a partitioned ChainMail frame and from random starts with pins, rigid vertices
//   and a grasp;
// - the geodesic brush reach (partitioned_geodesic.h) against GeodesicReach.
#include "geoshaping/parallel/in_process_exchange.h"
#include "geoshaping/parallel/partitioned_chainmail.h"
#include "geoshaping/parallel/partitioned_envelope.h"
#include "geoshaping/parallel/partitioned_geodesic.h"
#include "test_meshes.h"
#include "test_pieces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <set>

using namespace geoshaping;
using geoshaping::testing::Mesh;

namespace
{

using Scene = geoshaping::testing::PaintedMesh;
using Piece = geoshaping::testing::PaintedPiece;
using geoshaping::testing::painted_grid;

// Each piece keeps only the links with an owned end (as a ghost cell layer of lines).
std::vector<Piece> split_ghost_cells(const Scene& s, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra = {}, unsigned seed = 1)
{
  return geoshaping::testing::split(
    s, owner, pieces, extra, seed, geoshaping::testing::GhostLinks::to_owned);
}

// The shared slab with a second pin next to the first.
Scene tet_slab(index_t nx, index_t ny, index_t nz)
{
  Scene s = geoshaping::testing::tet_slab(nx, ny, nz);
  s.pins[std::size_t((0 * ny + 1) * nx + nx / 2 + 1)] = 1;
  return s;
}

std::vector<int> striped(const Scene& s, int pieces)
{
  return geoshaping::testing::striped_owner(s.mesh.xyz, pieces);
}

std::vector<int> random_owner(const Scene& s, const std::vector<int>& choices, unsigned seed)
{
  return geoshaping::testing::random_owner(s.mesh.size(), choices, seed);
}

bool same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

// A start: either a ChainMail frame grasping `grasp` (whole-mesh vertex) by `pull`, or
// (random_start) random displacements on a ball of rings around the grasp.
struct Case
{
  index_t grasp;
  Eigen::Vector3d pull;
  bool random_start = false;
  unsigned seed = 1;
};

ChainMailDeformer& setup(ChainMailDeformer& d, const float* malleability, const std::uint8_t* pins)
{
  d.set_malleability(malleability);
  d.set_pinned(pins);
  d.set_queue(QueueKind::fifo_priority);
  d.set_valid_region_frame(ValidRegionFrame::axes);
  return d;
}

// Random start values on the vertices within `rings` of the grasp (whole mesh).
std::vector<std::pair<index_t, Eigen::Vector3d>> random_start(
  const Scene& s, const Case& c, int rings)
{
  std::vector<index_t> ball{ c.grasp };
  std::set<index_t> seen{ c.grasp };
  for (int r = 0; r < rings; ++r)
  {
    const std::vector<index_t> front = ball;
    for (index_t v : front)
      for (const index_t* n = s.mesh.adjacency.begin(v); n != s.mesh.adjacency.end(v); ++n)
        if (seen.insert(*n).second)
          ball.push_back(*n);
  }
  std::sort(ball.begin(), ball.end());
  std::mt19937 rng(c.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::pair<index_t, Eigen::Vector3d>> start;
  for (index_t v : ball)
    if (u(rng) > -0.6) // some holes
      start.push_back({ v, v == c.grasp ? c.pull : Eigen::Vector3d(u(rng), u(rng), u(rng)) });
  if (start.empty() || start.front().first != c.grasp)
    start.insert(start.begin(), { c.grasp, c.pull });
  return start;
}

struct Whole
{
  Displacements u;
  ProjectionReport report;
  std::size_t changed = 0;
};

Whole run_whole(const Scene& s, const Case& c)
{
  ChainMailDeformer d;
  d.set_mesh(s.mesh.xyz.data(), s.mesh.size(), s.mesh.adjacency);
  d.set_global_ids(s.gid.data());
  setup(d, s.malleability.data(), s.pins.data());
  const LinkMesh mesh = link_mesh(d);
  LinkProjector projector(mesh);
  ProjectionOptions options;
  options.solver = ProjectionSolver::envelope;
  options.max_iterations = 1;
  Whole w;
  if (c.random_start)
  {
    std::vector<index_t> vertices;
    Displacements values;
    for (const auto& [v, x] : random_start(s, c, 4))
    {
      vertices.push_back(v);
      values.push_back(x);
    }
    w.report = projector.project(c.grasp, vertices, values, options);
  }
  else
  {
    EXPECT_TRUE(d.deform(c.grasp, c.pull).ok);
    w.report = refine_links(projector, d, c.grasp, options);
  }
  w.u = projector.displacements();
  w.changed = projector.changed().size();
  return w;
}

struct PieceResult
{
  Displacements u;
  std::vector<std::uint8_t> changed;
  ProjectionReport report;
  std::size_t changed_total = 0, supersteps = 0, bytes = 0;
};

std::vector<PieceResult> run_pieces(const Scene& s, std::vector<Piece>& pieces, const Case& c)
{
  std::vector<PieceResult> out(pieces.size());
  std::vector<std::pair<index_t, Eigen::Vector3d>> start;
  if (c.random_start)
    start = random_start(s, c, 4);
  geoshaping::testing::run_in_pieces(int(pieces.size()),
    [&](int p, Exchange& ex)
    {
      Piece& piece = pieces[std::size_t(p)];
      ChainMailDeformer deformer;
      PartitionedChainMail pc(deformer);
      const std::string error = pc.set_piece(piece.xyz.data(), index_t(piece.global.size()),
        piece.adjacency, piece.gid.data(), piece.owned.data(), ex);
      EXPECT_EQ(error, "");
      setup(deformer, piece.malleability.data(), piece.pins.data());
      const LinkMesh mesh = link_mesh(deformer);
      PartitionedEnvelope envelope;
      envelope.set_piece(deformer, mesh, ex);
      std::vector<index_t> vertices;
      Displacements values;
      const std::int64_t grasp = s.gid[std::size_t(c.grasp)];
      if (c.random_start)
      {
        std::vector<index_t> local_of(std::size_t(s.mesh.size()), -1);
        for (std::size_t i = 0; i < piece.global.size(); ++i)
          local_of[std::size_t(piece.global[i])] = index_t(i);
        for (const auto& [v, x] : start)
          if (local_of[std::size_t(v)] >= 0)
          {
            vertices.push_back(local_of[std::size_t(v)]);
            values.push_back(x);
          }
      }
      else
      {
        EXPECT_TRUE(pc.deform(grasp, c.pull, ex).ok);
        vertices = deformer.moved();
        for (index_t v : vertices)
          values.push_back(deformer.displacement(v));
      }
      const std::size_t before = ex.bytes_sent();
      ProjectionOptions options;
      options.solver = ProjectionSolver::envelope;
      PieceResult& r = out[std::size_t(p)];
      r.report = envelope.project(mesh, grasp, vertices, values, options, ex);
      r.u = envelope.displacements();
      r.changed.assign(piece.global.size(), 0);
      for (index_t v : envelope.changed())
        r.changed[std::size_t(v)] = 1;
      r.changed_total = envelope.changed_total();
      r.supersteps = envelope.supersteps();
      r.bytes = ex.bytes_sent() - before;
    });
  return out;
}

// Every copy of every vertex on every piece equals the whole mesh's result, bit for bit.
void expect_same(const Scene& s, const std::vector<int>& owner, int n, const Case& c,
  const std::string& what, const std::vector<std::vector<index_t>>& extra = {})
{
  const Whole w = run_whole(s, c);
  ASSERT_GT(w.changed, 0u) << what << ": nothing to refine";
  std::vector<Piece> pieces = split_ghost_cells(s, owner, n, extra);
  const std::vector<PieceResult> got = run_pieces(s, pieces, c);
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const PieceResult& r = got[p];
    EXPECT_EQ(r.changed_total, w.changed) << what << " piece " << p;
    EXPECT_EQ(r.supersteps, got[0].supersteps) << what << " piece " << p;
    EXPECT_EQ(r.report.region, w.report.region) << what << " piece " << p;
    EXPECT_EQ(r.report.converged, w.report.converged) << what << " piece " << p;
    EXPECT_NEAR(r.report.violation, w.report.violation, 1e-9 * (1.0 + w.report.violation))
      << what << " piece " << p;
    for (std::size_t v = 0; v < pieces[p].global.size(); ++v)
    {
      const index_t g = pieces[p].global[v];
      ASSERT_TRUE(same_bits(r.u[v], w.u[std::size_t(g)]))
        << what << " piece " << p << " vertex " << g << ": " << r.u[v].transpose() << " vs "
        << w.u[std::size_t(g)].transpose();
    }
  }
}

void expect_partitions_match(const Scene& s, const Case& c, const std::string& what)
{
  for (int n = 1; n <= 4; ++n)
  {
    expect_same(s, striped(s, n), n, c, what + " striped " + std::to_string(n));
    std::vector<int> choices(static_cast<std::size_t>(n));
    std::iota(choices.begin(), choices.end(), 0);
    expect_same(
      s, random_owner(s, choices, 7 + unsigned(n)), n, c, what + " random " + std::to_string(n));
  }
}

} // namespace

TEST(PartitionedEnvelope, SurfaceAfterChainMailEqualsWholeMesh)
{
  const Scene s = painted_grid(40, 30);
  const index_t grasp = 15 * 40 + 20;
  expect_partitions_match(s, { grasp, Eigen::Vector3d(0.3, -0.2, 2.5) }, "grid frame");
  // Next to the pins and the rigid block.
  expect_partitions_match(s, { 8 * 40 + 12, Eigen::Vector3d(-1.0, 0.5, -3.0) }, "grid pins");
}

TEST(PartitionedEnvelope, SlabAfterChainMailEqualsWholeMesh)
{
  const Scene s = tet_slab(12, 10, 5);
  expect_partitions_match(s, { (2 * 10 + 2) * 12 + 6, Eigen::Vector3d(0.2, 0.1, 1.5) }, "slab");
}

TEST(PartitionedEnvelope, RandomStartsWithPinsAndRigidEqualWholeMesh)
{
  const Scene grid = painted_grid(40, 30);
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    // Near the wall of pins (row 7) and the rigid block (rows 15-19, columns 13-18).
    expect_partitions_match(grid, { 9 * 40 + 14, Eigen::Vector3d(0.5, -2.0, 1.0), true, seed },
      "grid random " + std::to_string(seed));
    expect_partitions_match(grid,
      { 16 * 40 + 15, Eigen::Vector3d(-1.5, 0.5, 0.7), true, seed + 10 },
      "grid rigid random " + std::to_string(seed));
  }
  const Scene slab = tet_slab(12, 10, 5);
  expect_partitions_match(
    slab, { (0 * 10 + 2) * 12 + 6, Eigen::Vector3d(1.0, -0.5, 0.8), true, 5 }, "slab random");
}

TEST(PartitionedEnvelope, EmptyPieceAndPieceOfGhostsOnly)
{
  const Scene s = painted_grid(30, 20);
  const Case c{ 10 * 30 + 15, Eigen::Vector3d(0.4, 0.3, 2.0) };
  // Piece 2 of 4 owns nothing and holds nothing; then it holds only ghosts.
  expect_same(s, random_owner(s, { 0, 1, 3 }, 3), 4, c, "empty piece");
  std::vector<std::vector<index_t>> extra(4);
  for (index_t v = 9 * 30 + 10; v < 9 * 30 + 20; ++v)
    extra[2].push_back(v);
  expect_same(s, random_owner(s, { 0, 1, 3 }, 3), 4, c, "ghost-only piece", extra);
}

TEST(PartitionedEnvelope, BytesAreTheLoweredBorderLabels)
{
  const Scene s = painted_grid(40, 30);
  const Case c{ 15 * 40 + 20, Eigen::Vector3d(0.3, -0.2, 2.5) };
  std::vector<Piece> one = split_ghost_cells(s, striped(s, 1), 1);
  const auto single = run_pieces(s, one, c);
  EXPECT_EQ(single[0].bytes, 0u);
  std::vector<Piece> two = split_ghost_cells(s, striped(s, 2), 2);
  const auto got = run_pieces(s, two, c);
  EXPECT_GT(got[0].bytes + got[1].bytes, 0u);
  EXPECT_EQ((got[0].bytes + got[1].bytes) % sizeof(MovedVertex), 0u);
  // The lowered labels cross the border only: far fewer than the touched vertices x runs.
  EXPECT_LT((got[0].bytes + got[1].bytes) / sizeof(MovedVertex), 12 * single[0].changed_total);
}

namespace
{
struct DabCase
{
  Eigen::Vector3d center;
  double radius;
};

// The vertex nearest `c` among `vertices` (whole-mesh ids), ties to the lowest global id.
index_t nearest(const Scene& s, const std::vector<index_t>& vertices, const Eigen::Vector3d& c)
{
  index_t best = -1;
  double d_best = 0.0;
  for (index_t v : vertices)
  {
    const double* q = &s.mesh.xyz[3 * std::size_t(v)];
    const double d = (Eigen::Vector3d(q[0], q[1], q[2]) - c).norm();
    if (best < 0 || d < d_best || (d == d_best && s.gid[std::size_t(v)] < s.gid[std::size_t(best)]))
    {
      best = v;
      d_best = d;
    }
  }
  return best;
}

void expect_same_reach(const Scene& s, const std::vector<int>& owner, int n,
  const std::vector<DabCase>& dabs, const std::string& what,
  const std::vector<std::vector<index_t>>& extra = {})
{
  std::vector<index_t> all(static_cast<std::size_t>(s.mesh.size()));
  std::iota(all.begin(), all.end(), 0);
  std::vector<std::vector<double>> whole; // per dab: distance per vertex (inf: not reached)
  for (const DabCase& d : dabs)
  {
    GeodesicReach g;
    Reach r;
    const index_t src = nearest(s, all, d.center);
    const double* q = &s.mesh.xyz[3 * std::size_t(src)];
    g.compute(s.mesh.adjacency, s.mesh.xyz.data(), src,
      (Eigen::Vector3d(q[0], q[1], q[2]) - d.center).norm(), d.radius, r);
    whole.emplace_back(std::size_t(s.mesh.size()), std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < r.vertices.size(); ++i)
      whole.back()[std::size_t(r.vertices[i])] = r.distances[i];
  }
  std::vector<Piece> pieces = split_ghost_cells(s, owner, n, extra);
  std::vector<std::vector<Reach>> got(pieces.size());
  std::vector<std::vector<std::size_t>> steps(pieces.size());
  geoshaping::testing::run_in_pieces(int(pieces.size()),
    [&](int p, Exchange& ex)
    {
      const Piece& piece = pieces[std::size_t(p)];
      PartitionedGeodesic geodesic;
      geodesic.set_piece(piece.xyz.data(), index_t(piece.global.size()), &piece.adjacency,
        piece.gid.data(), piece.owned.data(), ex);
      for (const DabCase& d : dabs)
      {
        const index_t g = nearest(s, piece.global, d.center);
        const index_t local = g < 0
                                ? -1
                                : index_t(std::find(piece.global.begin(), piece.global.end(), g) -
                                          piece.global.begin());
        Reach r;
        geodesic.compute(d.center, d.radius, local, r, ex);
        got[std::size_t(p)].push_back(r);
        steps[std::size_t(p)].push_back(geodesic.supersteps());
      }
    });
  for (std::size_t k = 0; k < dabs.size(); ++k)
  {
    std::size_t reached = 0;
    for (double x : whole[k])
      reached += x < std::numeric_limits<double>::infinity();
    ASSERT_GT(reached, 5u) << what << " dab " << k << ": reaches too little to test";
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      const std::string where = what + " dab " + std::to_string(k) + " piece " + std::to_string(p);
      EXPECT_EQ(steps[p][k], steps[0][k]) << where;
      const Reach& r = got[p][k];
      std::vector<double> mine(pieces[p].global.size(), std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < r.vertices.size(); ++i)
      {
        ASSERT_EQ(mine[std::size_t(r.vertices[i])], std::numeric_limits<double>::infinity())
          << where << ": a vertex listed twice";
        mine[std::size_t(r.vertices[i])] = r.distances[i];
      }
      for (std::size_t v = 0; v < mine.size(); ++v)
      {
        const double w = whole[k][std::size_t(pieces[p].global[v])];
        ASSERT_EQ(std::memcmp(&mine[v], &w, sizeof(double)), 0)
          << where << " vertex " << pieces[p].global[v] << ": " << mine[v] << " vs " << w;
      }
    }
  }
}

std::vector<DabCase> grid_dabs()
{
  // Off-grid centres; one exactly between two grid points of the unjittered grid (a tie
  // for the nearest vertex); a radius crossing the whole mesh; a tiny one.
  return { { Eigen::Vector3d(12.3, 9.7, 0.4), 6.5 }, { Eigen::Vector3d(20.5, 15.0, 0.0), 4.0 },
    { Eigen::Vector3d(5.0, 5.0, 0.0), 60.0 }, { Eigen::Vector3d(30.2, 3.1, -0.3), 2.5 } };
}
} // namespace

TEST(PartitionedGeodesic, GridReachEqualsWholeMesh)
{
  const Scene jittered = painted_grid(40, 30);
  Scene plain = jittered;
  plain.mesh = geoshaping::testing::triangle_grid(40, 30, 1.0); // unjittered: ties
  for (const Scene* s : { &jittered, static_cast<const Scene*>(&plain) })
    for (int n = 1; n <= 4; ++n)
    {
      expect_same_reach(*s, striped(*s, n), n, grid_dabs(), "grid striped " + std::to_string(n));
      std::vector<int> choices(static_cast<std::size_t>(n));
      std::iota(choices.begin(), choices.end(), 0);
      expect_same_reach(*s, random_owner(*s, choices, 3 + unsigned(n)), n, grid_dabs(),
        "grid random " + std::to_string(n));
    }
}

TEST(PartitionedGeodesic, SlabReachEqualsWholeMesh)
{
  const Scene s = tet_slab(12, 10, 5);
  const std::vector<DabCase> dabs = { { Eigen::Vector3d(5e5 + 6.2, 5e5 + 4.9, 5e5 + 1.1), 3.0 },
    { Eigen::Vector3d(5e5 + 1.0, 5e5 + 1.0, 5e5), 20.0 } };
  for (int n = 1; n <= 4; ++n)
  {
    std::vector<int> choices(static_cast<std::size_t>(n));
    std::iota(choices.begin(), choices.end(), 0);
    expect_same_reach(
      s, random_owner(s, choices, 9 + unsigned(n)), n, dabs, "slab random " + std::to_string(n));
  }
}

TEST(PartitionedGeodesic, EmptyPieceAndPieceOfGhostsOnly)
{
  const Scene s = painted_grid(30, 20);
  std::vector<std::vector<index_t>> extra(4);
  for (index_t v = 9 * 30 + 10; v < 9 * 30 + 20; ++v)
    extra[2].push_back(v);
  const std::vector<DabCase> dabs = { { Eigen::Vector3d(14.6, 9.2, 0.1), 5.0 } };
  expect_same_reach(s, random_owner(s, { 0, 1, 3 }, 3), 4, dabs, "empty piece");
  expect_same_reach(s, random_owner(s, { 0, 1, 3 }, 3), 4, dabs, "ghost-only piece", extra);
}
