// ChainMail's order promises on real irregular meshes (issue 36; the meshes and the scene:
// real_meshes.h; every test here is skipped, saying so, when the data folder holds none).
// Global ids are the filter's without GlobalIds: coordinate_ids() (coordinate_ids.h).
//
// Guarded promises (docs/deformer.md, "Order"):
// - With the Link region, rotating the surface and the pull rotates the result, over
//   several frames and a commit, under FIFO, FIFO Priority and Max Violation;
// - translating the mesh and permuting its point ids change nothing (Axes and Link);
// - a partition into pieces gives the whole mesh's result bit for bit (FIFO, FIFO
//   Priority).
// Tolerance: 1e-9 of the mean edge length (rounding only; an order that turns with the
// coordinates differs by whole edge lengths).
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/parallel/coordinate_ids.h"
#include "real_meshes.h"
#include "test_pieces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace geoshaping;

namespace
{
using geoshaping::testing::moved;
using geoshaping::testing::random_rotation;
using geoshaping::testing::real_meshes;
using geoshaping::testing::RealMesh;

// An edit session as the filter drives it: global ids from coordinates, three frames of
// a growing pull, commit, then two frames pulling `second` back. Returns every vertex's position
// after each frame.
std::vector<std::vector<Eigen::Vector3d>> session(const std::vector<double>& xyz,
  const Adjacency& adj, const std::vector<float>& malleability, index_t grasp, index_t second,
  const Eigen::Vector3d& pull, QueueKind q, ValidRegionFrame f)
{
  const index_t n = index_t(xyz.size() / 3);
  ChainMailDeformer d;
  d.set_mesh(xyz.data(), n, adj);
  d.set_global_ids(coordinate_ids(xyz.data(), n).data());
  d.set_malleability(malleability.data());
  d.set_queue(q);
  d.set_valid_region_frame(f);
  std::vector<std::vector<Eigen::Vector3d>> out;
  auto record = [&]
  {
    std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(n));
    for (index_t v = 0; v < n; ++v)
      p[std::size_t(v)] = d.origin() + d.rest_local(v) + d.displacement(v);
    out.push_back(std::move(p));
  };
  for (double s : { 0.4, 0.8, 1.2 })
  {
    EXPECT_TRUE(d.deform(grasp, s * pull).ok);
    record();
  }
  d.commit();
  for (double s : { -0.3, -0.6 })
  {
    EXPECT_TRUE(d.deform(second, s * pull).ok);
    record();
  }
  return out;
}

} // namespace

// Rotating the mesh and the pull rotates every frame of the session (Link region).
TEST(Promises, LinkResultTurnsWithTheMeshAndThePull)
{
  SKIP_WITHOUT_REAL_MESHES();
  std::mt19937 rng(36);
  for (const RealMesh& m : real_meshes())
    for (bool uniform : { false, true })
    {
      const auto s = geoshaping::testing::real_scene(m, uniform);
      for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority, QueueKind::max_violation })
      {
        const auto base = session(
          m.xyz, m.adjacency, s.malleability, s.grasp, s.second, s.pull, q, ValidRegionFrame::link);
        for (int turn = 0; turn < 3; ++turn)
        {
          const Eigen::Matrix3d R = random_rotation(rng);
          const auto turned = session(moved(m.xyz, R, Eigen::Vector3d::Zero()), m.adjacency,
            s.malleability, s.grasp, s.second, R * s.pull, q, ValidRegionFrame::link);
          double worst = 0.0;
          for (std::size_t k = 0; k < base.size(); ++k)
            for (std::size_t v = 0; v < base[k].size(); ++v)
              worst = std::max(worst, (R * base[k][v] - turned[k][v]).norm());
          EXPECT_LE(worst, 1e-9 * m.edge)
            << m.name << (uniform ? " uniform " : " bands ") << queue_name(q) << " turn " << turn
            << ": off by " << worst / m.edge << " mean edge lengths";
        }
      }
    }
}

// Translating the mesh and permuting its point ids change nothing (Axes and Link).
TEST(Promises, TranslationAndRenumberingChangeNothing)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    const auto s = geoshaping::testing::real_scene(m, false);
    const index_t n = index_t(m.xyz.size() / 3);
    // Renumbering: new id perm[v] for old v, rows rebuilt (so their order changes too).
    std::vector<index_t> perm(static_cast<std::size_t>(n));
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(7));
    std::vector<double> xyz_p(m.xyz.size());
    std::vector<float> mall_p(s.malleability.size());
    AdjacencyBuilder builder(n);
    for (index_t v = 0; v < n; ++v)
    {
      const std::size_t p = std::size_t(perm[std::size_t(v)]);
      std::copy_n(&m.xyz[3 * std::size_t(v)], 3, &xyz_p[3 * p]);
      mall_p[p] = s.malleability[std::size_t(v)];
      for (const index_t* w = m.adjacency.begin(v); w != m.adjacency.end(v); ++w)
        builder.add_edge(perm[std::size_t(v)], perm[std::size_t(*w)]);
    }
    const Adjacency adj_p = builder.build();
    const Eigen::Vector3d shift = 1e3 * m.edge * Eigen::Vector3d(3.1, -7.7, 2.3);
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
      for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority, QueueKind::max_violation,
             QueueKind::priority })
      {
        const auto base =
          session(m.xyz, m.adjacency, s.malleability, s.grasp, s.second, s.pull, q, f);
        const auto shifted = session(moved(m.xyz, Eigen::Matrix3d::Identity(), shift), m.adjacency,
          s.malleability, s.grasp, s.second, s.pull, q, f);
        double worst_shift = 0.0;
        for (std::size_t k = 0; k < base.size(); ++k)
          for (std::size_t v = 0; v < base[k].size(); ++v)
            worst_shift = std::max(worst_shift, (base[k][v] + shift - shifted[k][v]).norm());
        EXPECT_LE(worst_shift, 1e-9 * m.edge)
          << m.name << " " << frame_name(f) << " " << queue_name(q) << " translated";
        if (q == QueueKind::priority || q == QueueKind::max_violation)
          continue; // heap ties follow the rows' order, which renumbering changes
        const auto renumbered = session(xyz_p, adj_p, mall_p, perm[std::size_t(s.grasp)],
          perm[std::size_t(s.second)], s.pull, q, f);
        double worst_perm = 0.0;
        for (std::size_t k = 0; k < base.size(); ++k)
          for (index_t v = 0; v < n; ++v)
            worst_perm = std::max(worst_perm,
              (base[k][std::size_t(v)] - renumbered[k][std::size_t(perm[std::size_t(v)])]).norm());
        EXPECT_LE(worst_perm, 1e-9 * m.edge)
          << m.name << " " << frame_name(f) << " " << queue_name(q) << " renumbered";
      }
  }
}

// A partition into 2 or 3 pieces (slabs along x, or random owners) gives every owned
// vertex the whole mesh's displacement bit for bit (FIFO, FIFO Priority; Link), the
// global ids being the coordinates' (coordinate_ids.h), as the filter's without GlobalIds.
TEST(Promises, PiecesGiveTheWholeMeshsBits)
{
  SKIP_WITHOUT_REAL_MESHES();
  for (const RealMesh& m : real_meshes())
  {
    const auto s = geoshaping::testing::real_scene(m, false);
    const index_t n = index_t(m.xyz.size() / 3);
    const std::vector<std::int64_t> gid = coordinate_ids(m.xyz.data(), n);
    const std::vector<double> steps = { 0.4, 0.8, 1.2 };
    for (QueueKind q : { QueueKind::fifo, QueueKind::fifo_priority })
    {
      ChainMailDeformer whole;
      whole.set_mesh(m.xyz.data(), n, m.adjacency);
      whole.set_global_ids(gid.data());
      whole.set_malleability(s.malleability.data());
      whole.set_queue(q);
      whole.set_valid_region_frame(ValidRegionFrame::link);
      std::vector<std::vector<Eigen::Vector3d>> expected;
      for (double f : steps)
      {
        ASSERT_TRUE(whole.deform(s.grasp, f * s.pull).ok);
        expected.emplace_back();
        for (index_t v = 0; v < n; ++v)
          expected.back().push_back(whole.displacement(v));
      }
      for (int pieces : { 2, 3 })
        for (bool striped : { true, false })
        {
          const std::vector<int> owner =
            striped ? geoshaping::testing::striped_owner(m.xyz, pieces)
                    : geoshaping::testing::random_owner(n, { 0, 1, 2 }, 5 + pieces);
          std::vector<int> clamped = owner;
          for (int& o : clamped)
            o %= pieces;
          const auto parts =
            geoshaping::testing::split_mesh(m.xyz, m.adjacency, gid, clamped, pieces);
          std::vector<std::string> errors(std::size_t(pieces), "");
          std::vector<double> worst(std::size_t(pieces), 0.0);
          geoshaping::testing::run_in_pieces(pieces,
            [&](int p, Exchange& ex)
            {
              const geoshaping::testing::MeshPiece& piece = parts[std::size_t(p)];
              ChainMailDeformer d;
              PartitionedChainMail pc(d);
              errors[std::size_t(p)] = pc.set_piece(piece.xyz.data(), piece.size(), piece.adjacency,
                piece.gid.data(), piece.owned.data(), ex);
              if (!errors[std::size_t(p)].empty())
                return;
              const std::vector<float> mall = piece.gather(s.malleability);
              d.set_malleability(mall.data());
              d.set_queue(q);
              d.set_valid_region_frame(ValidRegionFrame::link);
              for (std::size_t k = 0; k < steps.size(); ++k)
              {
                pc.deform(gid[std::size_t(s.grasp)], steps[k] * s.pull, ex);
                for (index_t v = 0; v < piece.size(); ++v)
                  if (piece.owned[std::size_t(v)])
                    worst[std::size_t(p)] = std::max(worst[std::size_t(p)],
                      (d.displacement(v) - expected[k][std::size_t(piece.global[std::size_t(v)])])
                        .cwiseAbs()
                        .maxCoeff());
              }
            });
          for (int p = 0; p < pieces; ++p)
          {
            EXPECT_EQ(errors[std::size_t(p)], "") << m.name;
            EXPECT_EQ(worst[std::size_t(p)], 0.0)
              << m.name << " " << queue_name(q) << " " << pieces
              << (striped ? " slabs" : " random owners") << ", piece " << p;
          }
        }
    }
  }
}
