// ChainMail's order promises on real irregular meshes (issue 36): the CRESCENT CFM faults
// and the Cascadia interface, GOCAD TSurf files read in place from GEOSHAPING_CFM_DIR
// (never copied into the repository; every test here is skipped, saying so, when the
// folder holds none), and a tetrahedral slab extruded from one of them. Global ids are
// the filter's without GlobalIds: coordinate_ids() (coordinate_ids.h).
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
#include "test_pieces.h"

#include "vtkGocadTSurfParser.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace geoshaping;

namespace
{

struct RealMesh
{
  std::string name;
  std::vector<double> xyz;
  Adjacency adjacency;
  double edge = 0.0; // mean edge length
};

Eigen::Vector3d point(const std::vector<double>& xyz, index_t v)
{
  return { xyz[3 * std::size_t(v)], xyz[3 * std::size_t(v) + 1], xyz[3 * std::size_t(v) + 2] };
}

double mean_edge(const std::vector<double>& xyz, const Adjacency& adj)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (index_t v = 0; v < adj.size(); ++v)
    for (const index_t* w = adj.begin(v); w != adj.end(v); ++w)
    {
      sum += (point(xyz, v) - point(xyz, *w)).norm();
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

// A TSurf file's points (local coordinates: the first point subtracted, so the tests'
// rotations do not stretch rounding over UTM-sized values) and its triangles' edges.
bool read_tsurf(const std::string& path, RealMesh& m)
{
  std::ifstream in(path);
  vtkGocadTSurfData data;
  std::string error;
  if (!in || !vtkGocadTSurfParse(in, data, error) || data.GetNumberOfPoints() < 3)
    return false;
  m.name = path.substr(path.find_last_of('/') + 1);
  m.xyz = data.Points;
  for (std::size_t i = 3; i < m.xyz.size(); ++i)
    m.xyz[i] -= m.xyz[i % 3];
  m.xyz[0] = m.xyz[1] = m.xyz[2] = 0.0;
  AdjacencyBuilder builder(index_t(data.GetNumberOfPoints()));
  for (std::size_t t = 0; t + 2 < data.Triangles.size(); t += 3)
    builder.add_cell(CellKind::triangle, &data.Triangles[t], 3);
  m.adjacency = builder.build();
  m.edge = mean_edge(m.xyz, m.adjacency);
  return true;
}

// A tetrahedral slab under a surface: `layers` more copies of it, each 0.8 mean edge
// lengths below the last (along -z), each triangle's prism cut into three tetrahedra by
// the order of its vertex ids (a split both neighbours of a face agree on).
RealMesh slab_under(const RealMesh& s, const std::vector<std::int64_t>& triangles, int layers)
{
  RealMesh m;
  m.name = s.name + " (tetrahedral slab)";
  const index_t n = index_t(s.xyz.size() / 3);
  for (int l = 0; l <= layers; ++l)
    for (index_t v = 0; v < n; ++v)
    {
      Eigen::Vector3d p = point(s.xyz, v);
      p.z() -= 0.8 * s.edge * l;
      m.xyz.insert(m.xyz.end(), { p.x(), p.y(), p.z() });
    }
  AdjacencyBuilder builder(n * index_t(layers + 1));
  for (int l = 0; l < layers; ++l)
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
    {
      std::int64_t a[3] = { triangles[t], triangles[t + 1], triangles[t + 2] };
      std::sort(a, a + 3);
      const std::int64_t top = std::int64_t(n) * l, bottom = top + n;
      const std::int64_t tets[3][4] = { { a[0] + top, a[1] + top, a[2] + top, a[2] + bottom },
        { a[0] + top, a[1] + top, a[1] + bottom, a[2] + bottom },
        { a[0] + top, a[0] + bottom, a[1] + bottom, a[2] + bottom } };
      for (const auto& tet : tets)
        builder.add_cell(CellKind::tetra, tet, 4);
    }
  m.adjacency = builder.build();
  m.edge = mean_edge(m.xyz, m.adjacency);
  return m;
}

std::vector<RealMesh> real_meshes()
{
  std::vector<RealMesh> out;
  for (const char* file : { "mccrory_2012_cascadia_interface.ts", "Almanor.ts",
         "Uhtanum_Ridge_-_Gable_Mountain.ts", "Southern_Whidbey_Island_north.ts", "Yaquina.ts" })
  {
    RealMesh m;
    if (read_tsurf(std::string(GEOSHAPING_CFM_DIR) + "/" + file, m))
      out.push_back(std::move(m));
  }
  // The slab under Devils Mountain (369 points, 3 layers).
  {
    std::ifstream in(std::string(GEOSHAPING_CFM_DIR) + "/Devils_Mountain.ts");
    vtkGocadTSurfData data;
    std::string error;
    RealMesh s;
    if (in && vtkGocadTSurfParse(in, data, error) &&
        read_tsurf(std::string(GEOSHAPING_CFM_DIR) + "/Devils_Mountain.ts", s))
      out.push_back(slab_under(s, data.Triangles, 3));
  }
  return out;
}

const std::vector<RealMesh>& meshes()
{
  static const std::vector<RealMesh> m = real_meshes();
  return m;
}

#define SKIP_WITHOUT_DATA()                                                                        \
  if (meshes().empty())                                                                            \
  GTEST_SKIP() << "no CRESCENT CFM files in '" GEOSHAPING_CFM_DIR                                  \
                  "' (set GEOSHAPING_CFM_DIR to the folder of the *.ts files)"

// The scene on a mesh, in terms that turn with it: the grasp is the vertex nearest the
// centroid; malleability is painted by distance r from the grasp in three bands (0.8 for
// r < 4 mean edge lengths, 0.35 for r < 9, 0.6 beyond) with a rigid disc (0) of radius
// 2.5 around the vertex nearest 6 from the grasp; `uniform`: 0.5 everywhere. Distances
// only, so a rotation or translation paints the same values on the same ids.
struct Scene
{
  index_t grasp = 0;
  index_t second = 0; // pulled after the commit: the vertex nearest 5 edges behind the grasp
  std::vector<float> malleability;
  Eigen::Vector3d pull; // 12 mean edge lengths, a fixed random direction
};

Scene scene(const RealMesh& m, bool uniform)
{
  Scene s;
  const index_t n = index_t(m.xyz.size() / 3);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (index_t v = 0; v < n; ++v)
    c += point(m.xyz, v);
  c /= double(n);
  double best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if ((point(m.xyz, v) - c).norm() < best)
    {
      best = (point(m.xyz, v) - c).norm();
      s.grasp = v;
    }
  const Eigen::Vector3d g = point(m.xyz, s.grasp);
  // The rigid disc's centre: the vertex nearest 6 edges from the grasp.
  index_t disc = s.grasp;
  best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if (std::abs((point(m.xyz, v) - g).norm() - 6.0 * m.edge) < best)
    {
      best = std::abs((point(m.xyz, v) - g).norm() - 6.0 * m.edge);
      disc = v;
    }
  s.malleability.assign(std::size_t(n), 0.5f);
  if (!uniform)
    for (index_t v = 0; v < n; ++v)
    {
      const double r = (point(m.xyz, v) - g).norm() / m.edge;
      float& a = s.malleability[std::size_t(v)];
      a = r < 4.0 ? 0.8f : (r < 9.0 ? 0.35f : 0.6f);
      if ((point(m.xyz, v) - point(m.xyz, disc)).norm() < 2.5 * m.edge)
        a = 0.0f;
    }
  s.malleability[std::size_t(s.grasp)] = uniform ? 0.5f : 0.8f;
  s.pull = 12.0 * m.edge * Eigen::Vector3d(0.3, -0.5, 0.81).normalized();
  const Eigen::Vector3d behind = g - 5.0 * m.edge * s.pull.normalized();
  best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if (v != s.grasp && (point(m.xyz, v) - behind).norm() < best)
    {
      best = (point(m.xyz, v) - behind).norm();
      s.second = v;
    }
  return s;
}

Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

// x -> R x + t on every point.
std::vector<double> moved(
  const std::vector<double>& xyz, const Eigen::Matrix3d& R, const Eigen::Vector3d& t)
{
  std::vector<double> out(xyz.size());
  for (std::size_t i = 0; i < xyz.size(); i += 3)
  {
    const Eigen::Vector3d p = R * Eigen::Vector3d(xyz[i], xyz[i + 1], xyz[i + 2]) + t;
    out[i] = p.x();
    out[i + 1] = p.y();
    out[i + 2] = p.z();
  }
  return out;
}

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

const char* frame_label(ValidRegionFrame f)
{
  return frame_name(f);
}

} // namespace

// Rotating the mesh and the pull rotates every frame of the session (Link region).
TEST(Promises, LinkResultTurnsWithTheMeshAndThePull)
{
  SKIP_WITHOUT_DATA();
  std::mt19937 rng(36);
  for (const RealMesh& m : meshes())
    for (bool uniform : { false, true })
    {
      const Scene s = scene(m, uniform);
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
  SKIP_WITHOUT_DATA();
  for (const RealMesh& m : meshes())
  {
    const Scene s = scene(m, false);
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
          << m.name << " " << frame_label(f) << " " << queue_name(q) << " translated";
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
          << m.name << " " << frame_label(f) << " " << queue_name(q) << " renumbered";
      }
  }
}

// A partition into 2 or 3 pieces (slabs along x, or random owners) gives every owned
// vertex the whole mesh's displacement bit for bit (FIFO, FIFO Priority; Link), the
// global ids being the coordinates' (coordinate_ids.h), as the filter's without GlobalIds.
TEST(Promises, PiecesGiveTheWholeMeshsBits)
{
  SKIP_WITHOUT_DATA();
  for (const RealMesh& m : meshes())
  {
    const Scene s = scene(m, false);
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
