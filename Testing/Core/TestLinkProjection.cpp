#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/passes/link_projection.h"
#include "test_meshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <set>
#include <string>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
using Mesh = geoshaping::testing::Mesh;

ChainMailDeformer make(const Mesh& m)
{
  ChainMailDeformer d;
  d.set_mesh(m.xyz.data(), m.size(), m.adjacency);
  return d;
}

// Deterministic malleability in [0, 1] with about one vertex in six rigid.
std::vector<float> scrambled_malleability(index_t n)
{
  std::vector<float> m(static_cast<std::size_t>(n));
  std::uint32_t s = 12345u;
  for (float& x : m)
  {
    s = s * 1664525u + 1013904223u;
    const float r = float(s >> 8) / float(1u << 24);
    x = r < 0.17f ? 0.0f : r;
  }
  return m;
}

struct Scene
{
  const char* name;
  Mesh mesh;
  std::vector<float> malleability;
  QueueKind queue;
  index_t grasp;
  Eigen::Vector3d drag;
};

std::vector<Scene> scenes()
{
  std::vector<Scene> s;
  const Mesh small = geoshaping::testing::triangle_grid(15, 15, 1.0);
  s.push_back({ "scrambled grid, FIFO", small, scrambled_malleability(small.size()),
    QueueKind::fifo, grid_id(15, 7, 7), { 3.0, 2.0, 8.0 } });
  s.push_back({ "scrambled grid, Priority", small, scrambled_malleability(small.size()),
    QueueKind::priority, grid_id(15, 7, 7), { -2.0, 1.0, 6.0 } });
  const index_t n = 25;
  const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
  std::vector<float> island(std::size_t(grid.size()), 1.0f);
  for (index_t j = 15; j < 21; ++j)
    for (index_t i = 9; i < 15; ++i)
      island[grid_id(n, i, j)] = 0.0f;
  s.push_back({ "rigid island, FIFO", grid, island, QueueKind::fifo, grid_id(n, 12, 10),
    { 4.0, 3.0, 12.0 } });
  const Mesh quads = geoshaping::testing::quad_grid(n, n, 2.0);
  s.push_back(
    { "uniform quads, FIFO Priority", quads, std::vector<float>(std::size_t(quads.size()), 0.5f),
      QueueKind::fifo_priority, grid_id(n, 5, 7), { 1.0, -3.0, 9.0 } });
  return s;
}

ChainMailDeformer run(const Scene& sc)
{
  ChainMailDeformer d = make(sc.mesh);
  d.set_malleability(sc.malleability.data());
  d.set_queue(sc.queue);
  EXPECT_TRUE(d.deform(sc.grasp, sc.drag).ok);
  return d;
}
} // namespace

TEST(LinkProjection, ReferenceConvergesOnEveryTestScene)
{
  for (const Scene& sc : scenes())
  {
    const ChainMailDeformer d = run(sc);
    const LinkMesh m = link_mesh(d);
    const Displacements start = displacements(d);
    ProjectionReport r;
    const Displacements ref = reference_configuration(m, sc.grasp, start, &r);
    std::printf("[ reference ] %-30s E_link %.3g -> %.3g, %d sweeps, violation %.2g, update "
                "%.2g, region %zu, links %zu\n",
      sc.name, link_error(m, start), link_error(m, ref), r.iterations, r.violation, r.update,
      r.region, r.links);
    EXPECT_TRUE(r.converged) << sc.name;
    EXPECT_LE(r.violation, 1e-9) << sc.name;
    EXPECT_LE(link_error(m, ref), 1e-9) << sc.name;
    EXPECT_EQ(ref[sc.grasp], start[sc.grasp]) << sc.name;
  }
}

TEST(LinkProjection, LinkErrorNeverIncreasesAcrossIterations)
{
  for (const Scene& sc : scenes())
  {
    const ChainMailDeformer d = run(sc);
    const LinkMesh m = link_mesh(d);
    LinkProjector p(m);
    // From the first iteration on (its start, the ChainMail result averaged over each
    // rigid set, may have a larger E_link than the raw ChainMail result).
    refine_links(p, d, sc.grasp, 1);
    double previous = link_error(m, p.displacements(), p.region());
    for (int it : { 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 256, 512 })
    {
      refine_links(p, d, sc.grasp, it);
      const double e = link_error(m, p.displacements(), p.region());
      std::printf("[ refine ] %-30s %4d sweeps: E_link %.3g\n", sc.name, it, e);
      EXPECT_LE(e, previous + 1e-9) << sc.name << " after " << it;
      previous = e;
    }
  }
}

TEST(LinkProjection, ReferenceFromRestOfStretchedChainIsTheLazyRamp)
{
  // Chain spacing 10, stretch 1.1: each link may lengthen by 1. The feasible
  // configuration nearest rest with the end pulled out by 8 is u_i = max(0, 8 - (19 - i)).
  const Mesh chain = geoshaping::testing::chain(20, 10.0);
  std::vector<Eigen::Vector3d> rest;
  for (index_t v = 0; v < chain.size(); ++v)
    rest.emplace_back(chain.xyz[3 * v], 0.0, 0.0);
  TransferFunction tf;
  tf.stretch = { 1.1, 1.1 };
  tf.compression = { 1.0, 1.0 };
  tf.shear = { 0.0, 0.0 };
  const LinkMesh m = link_mesh(rest, chain.adjacency, std::vector<double>(20, 0.5), tf);
  Displacements start(20, Eigen::Vector3d::Zero());
  start[19] = { 8.0, 0.0, 0.0 };
  ProjectionReport r;
  const Displacements ref = reference_configuration(m, 19, start, &r);
  EXPECT_TRUE(r.converged);
  // The stopping rule bounds the violation and the last update (1e-9 L), not the
  // distance to the exact projection: measured 3.7e-9 L here.
  for (index_t i = 0; i < 20; ++i)
    EXPECT_NEAR(ref[i].x(), std::max(0.0, 8.0 - (19 - i)), 1e-8 * m.mean_edge) << i;
}

TEST(LinkProjection, RefinementWithZeroIterationsIsTheIdentity)
{
  const Scene sc = scenes()[0];
  const ChainMailDeformer d = run(sc);
  const LinkMesh m = link_mesh(d);
  LinkProjector p(m);
  const ProjectionReport r = refine_links(p, d, sc.grasp, 0);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_TRUE(p.changed().empty());
  for (index_t v = 0; v < m.size(); ++v)
    EXPECT_EQ(p.displacement(v), d.displacement(v)) << v;
}

TEST(LinkProjection, RefinementLeavesGraspAndPinnedVerticesBitIdentical)
{
  // Pins right beside the grasp make the link set infeasible: the cap ends the run.
  const index_t n = 15;
  const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
  ChainMailDeformer d = make(grid);
  d.set_malleability(scrambled_malleability(grid.size()).data());
  std::vector<std::uint8_t> pins(std::size_t(grid.size()), 0);
  const index_t g = grid_id(n, 7, 7);
  for (index_t v : { grid_id(n, 8, 7), grid_id(n, 7, 8), grid_id(n, 0, 0), grid_id(n, 3, 9) })
    pins[v] = 1;
  d.set_pinned(pins.data());
  const Eigen::Vector3d drag(0.1 / 3.0, -2.0 / 7.0, 5.0 + 1e-13);
  ASSERT_TRUE(d.deform(g, drag).ok);
  const LinkMesh m = link_mesh(d);
  LinkProjector p(m);
  const ProjectionReport r = refine_links(p, d, g, 2000);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(std::isfinite(r.violation));
  EXPECT_EQ(p.displacement(g), drag);
  for (index_t v = 0; v < m.size(); ++v)
  {
    EXPECT_TRUE(p.displacement(v).allFinite()) << v;
    if (pins[v])
      EXPECT_TRUE(p.displacement(v).isZero(0.0)) << v;
  }
  for (index_t v : p.changed())
    EXPECT_TRUE(v != g && !pins[v]) << v;
}

TEST(LinkProjection, OneSweepMakesFifoRipplesInRigidIslandTranslateAsOne)
{
  const Scene sc = scenes()[2];
  const ChainMailDeformer d = run(sc);
  const LinkMesh m = link_mesh(d);
  ASSERT_GT(rigid_error(m, displacements(d)), 0.1);
  LinkProjector p(m);
  refine_links(p, d, sc.grasp, 1);
  EXPECT_EQ(rigid_error(m, p.displacements()), 0.0);
}

TEST(LinkProjection, RefinementCostFollowsTheDisplacedRegion)
{
  // A pull on a 200 x 200 grid of smoothly varying malleability (no rigid vertex, so no
  // equality set reaches beyond): the pass touches only the displaced vertices, those it
  // moves and their one-ring, never the whole mesh.
  const index_t n = 200;
  const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
  ChainMailDeformer d = make(grid);
  std::vector<float> mall(std::size_t(grid.size()));
  for (index_t j = 0; j < n; ++j)
    for (index_t i = 0; i < n; ++i)
      mall[grid_id(n, i, j)] = float(0.5 + 0.4 * std::sin(i / 5.0) * std::cos(j / 7.0));
  d.set_malleability(mall.data());
  d.set_queue(QueueKind::fifo);
  const index_t g = grid_id(n, 100, 100);
  ASSERT_TRUE(d.deform(g, { 0.5, 0.0, 3.0 }).ok);
  const LinkMesh m = link_mesh(d);
  LinkProjector p(m);
  const ProjectionReport r = refine_links(p, d, g, 8);
  EXPECT_GT(p.changed().size(), 0u);
  std::set<index_t> near(d.moved().begin(), d.moved().end());
  near.insert(p.changed().begin(), p.changed().end());
  for (index_t v : p.region())
  {
    bool adjacent = near.count(v) > 0;
    for (const index_t* w = grid.adjacency.begin(v); !adjacent && w != grid.adjacency.end(v); ++w)
      adjacent = near.count(*w) > 0;
    EXPECT_TRUE(adjacent) << v;
  }
  EXPECT_LT(r.region, std::size_t(grid.size()) / 20);
  EXPECT_EQ(link_error(m, p.displacements(), p.region()), link_error(m, p.displacements()));
}

TEST(LinkProjection, ReusedProjectorMatchesAFreshOne)
{
  const Scene a = scenes()[0], b = scenes()[1];
  const ChainMailDeformer da = run(a), db = run(b);
  const LinkMesh m = link_mesh(db);
  LinkProjector reused(m), fresh(m);
  refine_links(reused, da, a.grasp, 5);
  refine_links(reused, db, b.grasp, 5);
  refine_links(fresh, db, b.grasp, 5);
  EXPECT_EQ(reused.changed(), fresh.changed());
  for (index_t v = 0; v < m.size(); ++v)
    EXPECT_EQ(reused.displacement(v), fresh.displacement(v)) << v;
}

TEST(LinkProjection, DegenerateInputGivesFiniteConvergedResult)
{
  // Vertices 0 and 1 coincide (a zero-length edge: an equality), 4 is isolated.
  AdjacencyBuilder builder(5);
  builder.add_edge(0, 1);
  builder.add_edge(1, 2);
  builder.add_edge(2, 3);
  const Adjacency adj = builder.build();
  const LinkMesh m = link_mesh({ { 0, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 9, 9, 9 } },
    adj, { 0.5, 0.5, 1.0, 0.0, 0.3 });
  Displacements start(5, Eigen::Vector3d::Zero());
  start[0] = { 0.0, 0.0, 3.0 };
  start[4] = { 1.0, 1.0, 1.0 };
  ProjectionReport r;
  const Displacements ref = reference_configuration(m, 0, start, &r);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(link_error(m, ref), 1e-9);
  EXPECT_NEAR((ref[1] - start[0]).norm(), 0.0, 1e-9); // the zero-length edge: an equality
  EXPECT_EQ(ref[4], start[4]);                        // no link: nothing to satisfy
  for (const auto& u : ref)
    EXPECT_TRUE(u.allFinite());
}

namespace
{
ProjectionOptions solver_options(ProjectionSolver solver, double tolerance, int cap = 1000000)
{
  ProjectionOptions o;
  o.solver = solver;
  o.tolerance = tolerance;
  o.max_iterations = cap;
  return o;
}

double max_distance(const Displacements& a, const Displacements& b)
{
  double d = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
    d = std::max(d, (a[v] - b[v]).norm());
  return d;
}
} // namespace

TEST(LinkProjection, AdmmAndDykstraFindTheSameProjection)
{
  // Two independent algorithms for the same strongly convex problem: their results agree
  // to the accuracy they are run to.
  for (const Scene& sc : scenes())
  {
    const ChainMailDeformer d = run(sc);
    const LinkMesh m = link_mesh(d);
    const Displacements start = displacements(d);
    ProjectionReport ra, rd;
    const Displacements a = reference_configuration(
      m, sc.grasp, start, &ra, solver_options(ProjectionSolver::admm, 1e-10));
    const Displacements b = reference_configuration(
      m, sc.grasp, start, &rd, solver_options(ProjectionSolver::dykstra, 1e-10));
    std::printf("[ admm/dykstra ] %-30s ADMM %d iterations (%d factorisations), Dykstra %d "
                "sweeps, |difference| %.2g L\n",
      sc.name, ra.iterations, ra.factorisations, rd.iterations, max_distance(a, b) / m.scale());
    ASSERT_TRUE(ra.converged && rd.converged) << sc.name;
    EXPECT_LE(link_error(m, a), 1e-10) << sc.name;
    EXPECT_LE(max_distance(a, b), 1e-6 * m.scale()) << sc.name;
    EXPECT_EQ(a[sc.grasp], start[sc.grasp]) << sc.name;
    EXPECT_LE(rigid_error(m, a), 1e-12) << sc.name;
  }
}

TEST(LinkProjection, AdmmGivesTheLazyRampInBothFrames)
{
  // The chain of ReferenceFromRestOfStretchedChainIsTheLazyRamp, along x: the box and the
  // cylinder (shear 0: a segment) give the same feasible set, u_i = max(0, 8 - (19 - i)).
  const Mesh chain = geoshaping::testing::chain(20, 10.0);
  std::vector<Eigen::Vector3d> rest;
  for (index_t v = 0; v < chain.size(); ++v)
    rest.emplace_back(chain.xyz[3 * v], 0.0, 0.0);
  TransferFunction tf;
  tf.stretch = { 1.1, 1.1 };
  tf.compression = { 1.0, 1.0 };
  tf.shear = { 0.0, 0.0 };
  LinkMesh m = link_mesh(rest, chain.adjacency, std::vector<double>(20, 0.5), tf);
  for (ValidRegionFrame frame : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    m.frame = frame;
    Displacements start(20, Eigen::Vector3d::Zero());
    start[19] = { 8.0, 0.0, 0.0 };
    ProjectionReport r;
    const Displacements ref =
      reference_configuration(m, 19, start, &r, solver_options(ProjectionSolver::admm, 1e-10));
    EXPECT_TRUE(r.converged) << frame_name(frame);
    for (index_t i = 0; i < 20; ++i)
    {
      EXPECT_NEAR(ref[i].x(), std::max(0.0, 8.0 - (19 - i)), 1e-7 * m.mean_edge) << i;
      EXPECT_NEAR(ref[i].y(), 0.0, 1e-9) << i;
    }
  }
}

TEST(LinkProjection, LinkFrameProjectionIsRotationInvariant)
{
  // With the Link region the feasible set of a rotated mesh is the rotated feasible set, so
  // the projection of the rotated start is the rotated projection.
  const Scene sc = scenes()[3]; // uniform quads: no axis-aligned special case
  const Mesh& mesh = sc.mesh;
  const Eigen::Matrix3d R =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  std::vector<double> turned(mesh.xyz.size());
  for (std::size_t v = 0; v < mesh.xyz.size() / 3; ++v)
  {
    Eigen::Map<Eigen::Vector3d> to(&turned[3 * v]);
    to = R * Eigen::Map<const Eigen::Vector3d>(&mesh.xyz[3 * v]);
  }
  ChainMailDeformer a, b;
  a.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  b.set_mesh(turned.data(), mesh.size(), mesh.adjacency);
  for (ChainMailDeformer* d : { &a, &b })
  {
    d->set_malleability(sc.malleability.data());
    d->set_valid_region_frame(ValidRegionFrame::link);
  }
  // The same start for both (a's FIFO result, rotated for b), so only the projection is
  // compared.
  a.set_queue(QueueKind::fifo);
  ASSERT_TRUE(a.deform(sc.grasp, sc.drag).ok);
  const LinkMesh ma = link_mesh(a), mb = link_mesh(b);
  const Displacements start = displacements(a);
  Displacements turned_start(start.size());
  for (std::size_t v = 0; v < start.size(); ++v)
    turned_start[v] = R * start[v];
  ProjectionReport ra, rb;
  const ProjectionOptions o = solver_options(ProjectionSolver::admm, 1e-10);
  const Displacements pa = reference_configuration(ma, sc.grasp, start, &ra, o);
  const Displacements pb = reference_configuration(mb, sc.grasp, turned_start, &rb, o);
  ASSERT_TRUE(ra.converged && rb.converged);
  EXPECT_GT(link_error(ma, start), 0.01);
  EXPECT_LE(link_error(ma, pa), 1e-10);
  double defect = 0.0, size = 0.0;
  for (std::size_t v = 0; v < pa.size(); ++v)
  {
    defect = std::max(defect, (R * pa[v] - pb[v]).norm());
    size = std::max(size, pa[v].norm());
  }
  std::printf("[ link frame ] rotation defect %.2g of %.3g\n", defect, size);
  EXPECT_LE(defect, 1e-7 * size);
}

TEST(LinkProjection, AdmmReusesItsFactorisationForTheSameRegion)
{
  const Scene sc = scenes()[0];
  const ChainMailDeformer d = run(sc);
  const LinkMesh m = link_mesh(d);
  LinkProjector p(m);
  const ProjectionOptions o = solver_options(ProjectionSolver::admm, 1e-8, 500);
  const ProjectionReport first = refine_links(p, d, sc.grasp, o);
  const Displacements u = p.displacements();
  const ProjectionReport second = refine_links(p, d, sc.grasp, o);
  EXPECT_GE(first.factorisations, 1);
  EXPECT_EQ(second.factorisations, 0);
  EXPECT_EQ(second.iterations, first.iterations);
  for (index_t v = 0; v < m.size(); ++v)
    EXPECT_EQ(p.displacement(v), u[v]) << v;
}

TEST(LinkProjection, RefinementToleranceStopsEarlier)
{
  const Scene sc = scenes()[2];
  const ChainMailDeformer d = run(sc);
  const LinkMesh m = link_mesh(d);
  LinkProjector p(m);
  for (ProjectionSolver solver : { ProjectionSolver::admm, ProjectionSolver::dykstra })
  {
    const ProjectionReport loose = refine_links(p, d, sc.grasp, solver_options(solver, 1e-3));
    const double loose_error = link_error(m, p.displacements());
    const ProjectionReport tight = refine_links(p, d, sc.grasp, solver_options(solver, 1e-9));
    EXPECT_TRUE(loose.converged && tight.converged);
    EXPECT_LT(loose.iterations, tight.iterations);
    EXPECT_LE(loose_error, 1e-3);
    EXPECT_LE(link_error(m, p.displacements()), 1e-9);
  }
}

namespace
{
// The envelope computed independently of the projector (link_projection.h, "Envelope"):
// all-pairs shortest paths (Floyd-Warshall) per axis on the weights w(b -> a) = hi_ab of
// the slab u_a - u_b in [lo_ab, hi_ab], both directions' displacement_bounds intersected
// by hand, then D = min_b (z'_b + d(b, a)) with z' = max(z, max_f (v_f - d(a, f))), U the
// same on -z, and (D + U) / 2 on the free vertices.
Displacements envelope_by_floyd_warshall(const LinkMesh& m, index_t grasp, const Displacements& z)
{
  const index_t n = m.size();
  const double inf = std::numeric_limits<double>::infinity();
  const auto fixed = [&](index_t v) { return v == grasp || m.is_pinned(v); };
  Displacements out = z;
  for (int axis = 0; axis < 3; ++axis)
  {
    // d_hi(b, a): shortest path under w(b -> a) = hi_ab; the weights of -u are -lo_ab.
    std::vector<double> dh(std::size_t(n) * n, inf), dl(std::size_t(n) * n, inf);
    for (index_t v = 0; v < n; ++v)
    {
      dh[std::size_t(v) * n + v] = dl[std::size_t(v) * n + v] = 0.0;
      for (const index_t* s = m.adjacency->begin(v); s != m.adjacency->end(v); ++s)
      {
        const Eigen::Vector3d o = m.rest[v] - m.rest[*s];
        const Box cs = displacement_bounds(o, m.params[v]);
        const Box sc = displacement_bounds(-o, m.params[*s]);
        const double lo = std::max(cs.lo[axis], -sc.hi[axis]);
        const double hi = std::min(cs.hi[axis], -sc.lo[axis]);
        dh[std::size_t(*s) * n + v] = hi;  // u_v <= u_s + hi
        dl[std::size_t(*s) * n + v] = -lo; // -u_v <= -u_s - lo
      }
    }
    for (std::vector<double>* d : { &dh, &dl })
      for (index_t k = 0; k < n; ++k)
        for (index_t i = 0; i < n; ++i)
          for (index_t j = 0; j < n; ++j)
            (*d)[std::size_t(i) * n + j] = std::min((*d)[std::size_t(i) * n + j],
              (*d)[std::size_t(i) * n + k] + (*d)[std::size_t(k) * n + j]);
    // Greatest feasible below y (values y = sign u, distances d), fixed vertices kept.
    const auto greatest_below = [&](const std::vector<double>& y, const std::vector<double>& d,
                                  const std::vector<double>& d_reverse)
    {
      std::vector<double> raised(y);
      for (index_t a = 0; a < n; ++a)
        for (index_t f = 0; f < n; ++f)
          if (fixed(f) && !fixed(a))
            raised[a] = std::max(raised[a], y[f] - d_reverse[std::size_t(f) * n + a]);
      std::vector<double> r(raised);
      for (index_t a = 0; a < n; ++a)
        if (!fixed(a))
          for (index_t b = 0; b < n; ++b)
            r[a] = std::min(r[a], raised[b] + d[std::size_t(b) * n + a]);
      return r;
    };
    std::vector<double> y(static_cast<std::size_t>(n)), ny(static_cast<std::size_t>(n));
    for (index_t v = 0; v < n; ++v)
    {
      y[v] = z[v][axis];
      ny[v] = -z[v][axis];
    }
    // The lower cone of f at a: y_f - (shortest path from a to f under -u's weights, i.e.
    // from f to a reversed): y_a >= y_f + lo-path = y_f - dl(f, a).
    const std::vector<double> down = greatest_below(y, dh, dl);
    const std::vector<double> up = greatest_below(ny, dl, dh);
    for (index_t v = 0; v < n; ++v)
      if (!fixed(v))
        out[v][axis] = down[v] == -up[v] ? down[v] : 0.5 * (down[v] - up[v]);
  }
  return out;
}
} // namespace

TEST(LinkProjection, EnvelopeMatchesAnIndependentShortestPathComputation)
{
  // Every test scene, shrunk to 9x9 so that Floyd-Warshall is cheap, plus pins far from
  // the grasp (consistent: rest is feasible around them).
  for (const bool pinned : { false, true })
  {
    const index_t n = 9;
    const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
    ChainMailDeformer d = make(grid);
    std::vector<float> malleability = scrambled_malleability(grid.size());
    std::vector<std::uint8_t> pins(std::size_t(grid.size()), 0);
    if (pinned) // soft around the pins, so that rest beside them stays feasible
    {
      for (index_t j = 0; j < n; ++j)
        for (index_t i = 0; i < n; ++i)
          if (j < 4)
            malleability[grid_id(n, i, j)] = 1.0f;
      pins[grid_id(n, 0, 0)] = pins[grid_id(n, 8, 0)] = 1;
      d.set_pinned(pins.data());
    }
    d.set_malleability(malleability.data());
    const QueueKind q = pinned ? QueueKind::priority : QueueKind::fifo;
    d.set_queue(q);
    const index_t g = grid_id(n, 4, 4);
    ASSERT_TRUE(d.deform(g, { 0.6, -0.4, 1.5 }).ok);
    const LinkMesh m = link_mesh(d);
    const Displacements start = displacements(d);
    ASSERT_GT(link_error(m, start), 1e-3) << "the start must violate links";
    const Displacements expected = envelope_by_floyd_warshall(m, g, start);
    LinkProjector p(m);
    ProjectionOptions o;
    o.solver = ProjectionSolver::envelope;
    o.max_iterations = 1;
    o.tolerance = 1e-9;
    const ProjectionReport r = refine_links(p, d, g, o);
    EXPECT_TRUE(r.converged) << (pinned ? "pinned" : "free");
    EXPECT_LE(r.violation, 1e-12);
    EXPECT_LE(link_error(m, p.displacements()), 1e-12);
    EXPECT_LE(link_error(m, expected), 1e-12); // the formula itself is feasible
    EXPECT_EQ(rigid_error(m, p.displacements()), 0.0);
    double worst = 0.0;
    for (index_t v = 0; v < m.size(); ++v)
      worst = std::max(worst, (p.displacement(v) - expected[v]).cwiseAbs().maxCoeff());
    EXPECT_LE(worst, 1e-12);
    EXPECT_EQ(p.displacement(g), d.displacement(g));
    for (index_t v : p.changed())
      EXPECT_TRUE(v != g && !pins[v]) << v;
  }
}

namespace
{
// The envelope as first written (binary-heap Dijkstra recomputing each link's slab at every
// relaxation, dense scratch per call), kept verbatim as the reference the cached fast path
// in LinkProjector must reproduce bit for bit.
bool old_axis_slab(const LinkMesh& m, index_t c, index_t s, int i, double& lo, double& hi)
{
  const Eigen::Vector3d o = m.rest[std::size_t(c)] - m.rest[std::size_t(s)];
  if (!o.allFinite())
    return false;
  const Eigen::Vector3d a = o.cwiseAbs();
  const double side = a.sum() - a[i];
  const ChainMailParams& pc = m.params[std::size_t(c)];
  const ChainMailParams& ps = m.params[std::size_t(s)];
  const double oi = o[i];
  const double c_near = (pc.compression - 1.0) * oi, c_far = (pc.stretch - 1.0) * oi;
  const double s_near = (ps.compression - 1.0) * -oi, s_far = (ps.stretch - 1.0) * -oi;
  const double c_lo = (oi >= 0.0 ? c_near : c_far) - pc.shear * side;
  const double c_hi = (oi >= 0.0 ? c_far : c_near) + pc.shear * side;
  const double s_lo = (-oi >= 0.0 ? s_near : s_far) - ps.shear * side;
  const double s_hi = (-oi >= 0.0 ? s_far : s_near) + ps.shear * side;
  lo = std::max(c_lo, -s_hi);
  hi = std::min(c_hi, -s_lo);
  return true;
}

struct OldEnvelope
{
  const LinkMesh& m;
  index_t grasp;
  Displacements u;
  std::vector<std::uint8_t> expanded;
  std::vector<index_t> region, changed;
  std::vector<double> value, down, cone_value;
  std::vector<std::uint32_t> stamp, cone_stamp;
  std::uint32_t pass = 0, cone_pass = 0;
  std::vector<index_t> touched, cone_touched;
  double violation = 0.0;

  OldEnvelope(const LinkMesh& mesh, index_t g, const std::vector<index_t>& vertices,
    const Displacements& values)
    : m(mesh)
    , grasp(g >= 0 && g < mesh.size() ? g : -1)
    , u(std::size_t(mesh.size()), Eigen::Vector3d::Zero())
    , expanded(std::size_t(mesh.size()), 0)
    , value(std::size_t(mesh.size()), 0.0)
    , down(std::size_t(mesh.size()), std::numeric_limits<double>::quiet_NaN())
    , cone_value(std::size_t(mesh.size()), 0.0)
    , stamp(std::size_t(mesh.size()), 0)
    , cone_stamp(std::size_t(mesh.size()), 0)
  {
    std::vector<index_t> start;
    for (std::size_t i = 0; i < vertices.size(); ++i)
    {
      u[vertices[i]] = values[i];
      start.push_back(vertices[i]);
    }
    if (grasp >= 0)
      start.push_back(grasp);
    run(start);
  }
  bool is_fixed(index_t v) const { return v == grasp || m.is_pinned(v); }
  double val(index_t v, int axis, double sign) const
  {
    return sign * (stamp[v] == pass ? value[v] : u[v][axis]);
  }
  void touch(index_t v, double x)
  {
    if (stamp[v] != pass)
    {
      stamp[v] = pass;
      touched.push_back(v);
    }
    value[v] = x;
  }
  void min_pass(int axis, double sign, std::vector<index_t>& seeds)
  {
    using Item = std::pair<double, index_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    for (index_t s : seeds)
      heap.emplace(val(s, axis, sign), s);
    const Adjacency& adj = *m.adjacency;
    double lo, hi;
    while (!heap.empty())
    {
      const auto [y, b] = heap.top();
      heap.pop();
      if (y != val(b, axis, sign))
        continue;
      for (const index_t* n = adj.begin(b); n != adj.end(b); ++n)
      {
        const index_t a = *n;
        if (is_fixed(a) || !old_axis_slab(m, a, b, axis, lo, hi))
          continue;
        const double cap = y + (sign > 0.0 ? hi : -lo);
        if (cap < val(a, axis, sign))
        {
          touch(a, sign * cap);
          heap.emplace(cap, a);
        }
      }
    }
  }
  void cone(int axis, double sign, const std::vector<index_t>& fixed)
  {
    if (fixed.empty())
      return;
    double top = 0.0;
    for (index_t v : region)
      top = std::max(top, sign * u[v][axis]);
    ++cone_pass;
    cone_touched.clear();
    using Item = std::pair<double, index_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
    const auto get = [&](index_t v) {
      return cone_stamp[v] == cone_pass ? cone_value[v] : std::numeric_limits<double>::infinity();
    };
    const auto set = [&](index_t v, double c)
    {
      if (cone_stamp[v] != cone_pass)
      {
        cone_stamp[v] = cone_pass;
        cone_touched.push_back(v);
      }
      cone_value[v] = c;
      heap.emplace(c, v);
    };
    for (index_t f : fixed)
      set(f, val(f, axis, sign));
    const Adjacency& adj = *m.adjacency;
    double lo, hi;
    while (!heap.empty())
    {
      const auto [c, b] = heap.top();
      heap.pop();
      if (c != get(b))
        continue;
      for (const index_t* n = adj.begin(b); n != adj.end(b); ++n)
      {
        const index_t a = *n;
        if (is_fixed(a) || !old_axis_slab(m, a, b, axis, lo, hi))
          continue;
        const double cap = c + (sign > 0.0 ? hi : -lo);
        if (cap < get(a) && cap < top)
          set(a, cap);
      }
    }
    for (index_t a : cone_touched)
      if (!is_fixed(a) && cone_value[a] < val(a, axis, sign))
        touch(a, sign * cone_value[a]);
  }
  void run(const std::vector<index_t>& start)
  {
    const Adjacency& adj = *m.adjacency;
    for (index_t v : start)
      if (!expanded[v])
      {
        expanded[v] = 1;
        region.push_back(v);
      }
    std::vector<index_t> fixed, seeds, seeds_up, down_list;
    if (grasp >= 0)
      fixed.push_back(grasp);
    if (!m.pinned.empty())
      for (index_t v : region)
      {
        if (v != grasp && m.is_pinned(v))
          fixed.push_back(v);
        for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
          if (!expanded[*n] && m.is_pinned(*n))
            fixed.push_back(*n);
      }
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
    double lo, hi;
    const auto prescan = [&](int axis)
    {
      seeds.clear();
      seeds_up.clear();
      for (index_t v : region)
        for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
        {
          if ((expanded[*n] && *n < v) || !old_axis_slab(m, v, *n, axis, lo, hi))
            continue;
          const double w = u[v][axis] - u[*n][axis];
          const index_t high = w > hi ? v : (w < lo ? *n : -1);
          if (high < 0)
            continue;
          const index_t low = high == v ? *n : v;
          if (!is_fixed(high))
            seeds.push_back(low);
          if (!is_fixed(low))
            seeds_up.push_back(high);
        }
    };
    const auto envelope = [&](int axis, double sign, std::vector<index_t>& from)
    {
      ++pass;
      touched.clear();
      cone(axis, -sign, fixed);
      for (std::size_t k = 0; k < touched.size(); ++k)
      {
        const index_t v = touched[k];
        for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
        {
          if (!old_axis_slab(m, v, *n, axis, lo, hi))
            continue;
          const double yv = val(v, axis, sign), ym = val(*n, axis, sign);
          const double ub_vm = sign > 0.0 ? hi : -lo;
          const double ub_mv = sign > 0.0 ? -lo : hi;
          if (yv > ym + ub_vm && !is_fixed(v))
            from.push_back(*n);
          if (ym > yv + ub_mv && !is_fixed(*n))
            from.push_back(v);
        }
      }
      min_pass(axis, sign, from);
    };
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      bool zero = true;
      for (index_t v : region)
        zero = zero && u[v][axis] == 0.0;
      if (zero)
        continue;
      prescan(axis);
      envelope(axis, 1.0, seeds);
      down_list = touched;
      for (index_t v : down_list)
        down[v] = value[v];
      envelope(axis, -1.0, seeds_up);
      const auto combine = [&](index_t v)
      {
        const double old = u[v][axis];
        const double d = std::isnan(down[v]) ? old : down[v];
        const double up = stamp[v] == pass ? value[v] : old;
        const double mid = d == up ? d : 0.5 * (d + up);
        if (is_fixed(v) || mid == old || !std::isfinite(mid))
          return;
        u[v][axis] = mid;
        if (!expanded[v])
          region.push_back(v);
        if (expanded[v] != 2)
          changed.push_back(v);
        expanded[v] = 2;
      };
      for (index_t v : down_list)
        combine(v);
      for (index_t v : touched)
        combine(v);
      for (index_t v : down_list)
        down[v] = std::numeric_limits<double>::quiet_NaN();
      double worst = 0.0;
      for (index_t v : region)
        for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
          if (!(expanded[*n] && *n < v) && old_axis_slab(m, v, *n, axis, lo, hi) &&
              !(is_fixed(v) && is_fixed(*n)))
          {
            const double w = u[v][axis] - u[*n][axis];
            worst = std::max(worst, std::max(lo - w, w - hi));
          }
      squared += worst * worst;
    }
    violation = std::sqrt(squared) / m.scale();
  }
};

// A random mesh: a jittered triangle grid with random extra chords (so vertex degrees and
// link directions vary), random malleability (some rigid), random pins and start values.
struct RandomScene
{
  std::vector<Eigen::Vector3d> rest;
  Adjacency adjacency;
  LinkMesh mesh;
  index_t grasp = -1;
  std::vector<index_t> vertices;
  Displacements values;
};

// Fills `r` in place (its mesh points at its own adjacency, so it must not move).
void random_scene(std::uint32_t seed, RandomScene& r)
{
  std::uint32_t s = seed * 2654435761u + 1u;
  const auto next = [&s]()
  {
    s = s * 1664525u + 1013904223u;
    return double(s >> 8) / double(1u << 24);
  };
  const index_t nx = 12 + index_t(next() * 10), ny = 10 + index_t(next() * 10);
  const Mesh grid = geoshaping::testing::triangle_grid(nx, ny, 1.0);
  AdjacencyBuilder b(grid.size());
  for (index_t v = 0; v < grid.size(); ++v)
    for (const index_t* n = grid.adjacency.begin(v); n != grid.adjacency.end(v); ++n)
      b.add_edge(v, *n);
  for (int k = 0; k < grid.size() / 10; ++k)
  {
    const index_t a = index_t(next() * grid.size()), c = index_t(next() * grid.size());
    if (a != c && std::abs(a % nx - c % nx) < 3 && std::abs(a / nx - c / nx) < 3)
      b.add_edge(a, c);
  }
  r.adjacency = b.build();
  std::vector<double> malleability(std::size_t(grid.size()));
  for (index_t v = 0; v < grid.size(); ++v)
  {
    r.rest.emplace_back(grid.xyz[3 * v] + 0.3 * (next() - 0.5),
      grid.xyz[3 * v + 1] + 0.3 * (next() - 0.5), 0.5 * (next() - 0.5));
    malleability[v] = next() < 0.1 ? 0.0 : next();
  }
  r.mesh = link_mesh(r.rest, r.adjacency, malleability);
  r.grasp = index_t(next() * grid.size());
  if (seed % 3 == 1) // pins (possibly inconsistent with the grasp: F may be empty)
  {
    r.mesh.pinned.assign(std::size_t(grid.size()), 0);
    for (index_t v = 0; v < grid.size(); ++v)
      r.mesh.pinned[v] = v != r.grasp && next() < 0.03 ? 1 : 0;
  }
  if (seed % 4 == 2) // no grasp: the start's own violations only
    r.grasp = -1;
  // Start: a random blob of displaced vertices around a centre, values of a random pull
  // decaying with distance plus noise (violating many links), some axes left at 0.
  const Eigen::Vector3d pull(seed % 5 == 0 ? 0.0 : 4.0 * (next() - 0.5),
    seed % 7 == 0 ? 0.0 : 4.0 * (next() - 0.5), 6.0 * next());
  const index_t centre = r.grasp >= 0 ? r.grasp : index_t(next() * grid.size());
  const double radius = 2.0 + 5.0 * next();
  for (index_t v = 0; v < grid.size(); ++v)
  {
    const double d = (r.rest[v] - r.rest[centre]).head<2>().norm();
    if (d > radius && v != r.grasp)
      continue;
    if (r.mesh.is_pinned(v))
      continue;
    Eigen::Vector3d x = pull * std::max(0.0, 1.0 - d / (radius + 1.0));
    for (int i = 0; i < 3; ++i)
      if (pull[i] != 0.0)
        x[i] += 0.8 * (next() - 0.5);
    r.vertices.push_back(v);
    r.values.push_back(x);
  }
}
ProjectionOptions envelope_options()
{
  ProjectionOptions o;
  o.solver = ProjectionSolver::envelope;
  o.tolerance = 1e-9;
  return o;
}

// Every coordinate of the projector's result equals the first implementation's, bit for
// bit, the sign of a zero included.
void expect_same_bits(
  const LinkProjector& p, const OldEnvelope& old, index_t n, const std::string& what)
{
  for (index_t v = 0; v < n; ++v)
    for (int i = 0; i < 3; ++i)
    {
      const double a = p.displacement(v)[i], b = old.u[v][i];
      ASSERT_TRUE(a == b && std::signbit(a) == std::signbit(b))
        << what << " vertex " << v << " axis " << i << ": " << a << " vs " << b;
    }
}
} // namespace

TEST(LinkProjection, EnvelopeFastPathEqualsTheFirstImplementationBitForBit)
{
  // 60 random meshes (jittered grids with chords, random malleability with rigid vertices,
  // pins, with and without a grasp, some axes at rest). One projector per mesh runs three
  // calls: the grasp, another grasp (the link cache kept across calls must not remember
  // which vertex was grasped), the first grasp again (a warm cache).
  int compared = 0, changed_total = 0;
  for (std::uint32_t seed = 0; seed < 60; ++seed)
  {
    RandomScene sc;
    random_scene(seed, sc);
    LinkProjector p(sc.mesh);
    const ProjectionOptions o = envelope_options();
    const index_t other = sc.vertices.empty() ? -1 : sc.vertices[sc.vertices.size() / 2];
    for (const index_t grasp : { sc.grasp, other, sc.grasp })
    {
      const OldEnvelope old(sc.mesh, grasp, sc.vertices, sc.values);
      const ProjectionReport r = p.project(grasp, sc.vertices, sc.values, o);
      EXPECT_EQ(r.violation, old.violation) << "seed " << seed;
      expect_same_bits(
        p, old, sc.mesh.size(), "seed " + std::to_string(seed) + " grasp " + std::to_string(grasp));
      if (HasFatalFailure())
        return;
      std::set<index_t> mine(p.changed().begin(), p.changed().end());
      std::set<index_t> theirs(old.changed.begin(), old.changed.end());
      EXPECT_EQ(mine, theirs) << "seed " << seed;
      std::set<index_t> region(p.region().begin(), p.region().end());
      EXPECT_EQ(region, std::set<index_t>(old.region.begin(), old.region.end()));
      ++compared;
      changed_total += int(old.changed.size());
    }
  }
  EXPECT_EQ(compared, 180);
  EXPECT_GT(changed_total, 180 * 10); // the scenes do move vertices
}

TEST(LinkProjection, EnvelopeCacheOfSomeAxesServesCallsOnOtherAxesBitForBit)
{
  // The link cache holds the bounds of the axes its calls ran: one projector pulls along
  // z only, then along every axis, then along x only, then along z again; each call equals
  // the first implementation on a fresh start, bit for bit.
  int compared = 0;
  for (std::uint32_t seed = 0; seed < 20; ++seed)
  {
    RandomScene sc;
    random_scene(seed, sc);
    LinkProjector p(sc.mesh);
    const ProjectionOptions o = envelope_options();
    for (const int axes : { 4, 7, 1, 4 })
    {
      Displacements values = sc.values;
      for (Eigen::Vector3d& u : values)
        for (int i = 0; i < 3; ++i)
          if (!(axes & (1 << i)))
            u[i] = 0.0;
      const OldEnvelope old(sc.mesh, sc.grasp, sc.vertices, values);
      const ProjectionReport r = p.project(sc.grasp, sc.vertices, values, o);
      EXPECT_EQ(r.violation, old.violation) << "seed " << seed << " axes " << axes;
      expect_same_bits(
        p, old, sc.mesh.size(), "seed " + std::to_string(seed) + " axes " + std::to_string(axes));
      if (HasFatalFailure())
        return;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 80);
}

TEST(LinkProjection, EnvelopeOfADragEqualsTheFirstImplementationAcrossCommitAndRepaint)
{
  // ChainMail frames on a scrambled 31 x 31 grid refined as the filter does: one
  // projector kept across a drag (its link cache and labels reused, the cone's links
  // filled ahead only on the first frame), a new one after a commit (new rest shape) and
  // after a repaint (new malleability). Each call equals the first implementation, which
  // computes every slab where it reads it, bit for bit; a grasp elsewhere mid-drag too.
  const index_t n = 31;
  const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
  ChainMailDeformer d = make(grid);
  std::vector<float> m = scrambled_malleability(grid.size());
  d.set_malleability(m.data());
  d.set_queue(QueueKind::fifo_priority);
  const ProjectionOptions o = envelope_options();
  int compared = 0;
  std::size_t moved = 0;
  for (int phase = 0; phase < 3; ++phase)
  {
    if (phase == 1)
      d.commit();
    if (phase == 2)
    {
      for (float& x : m)
        x = 1.0f - x;
      d.set_malleability(m.data());
    }
    const LinkMesh links = link_mesh(d);
    LinkProjector p(links);
    const index_t grasps[] = { grid_id(n, 15, 15), grid_id(n, 15, 15), grid_id(n, 9, 20),
      grid_id(n, 15, 15) };
    for (int frame = 0; frame < 4; ++frame)
    {
      const index_t g = grasps[frame];
      const Eigen::Vector3d pull(0.3 * frame, -0.2 * phase, 2.0 + 1.5 * frame);
      d.deform(g, pull);
      Displacements values;
      for (index_t v : d.moved())
        values.push_back(d.displacement(v));
      const OldEnvelope old(links, g, d.moved(), values);
      const ProjectionReport r = refine_links(p, d, g, o);
      EXPECT_EQ(r.violation, old.violation) << "phase " << phase << " frame " << frame;
      expect_same_bits(
        p, old, links.size(), "phase " + std::to_string(phase) + " frame " + std::to_string(frame));
      if (HasFatalFailure())
        return;
      moved += d.moved().size();
      ++compared;
    }
  }
  EXPECT_EQ(compared, 12);
  EXPECT_GT(moved, std::size_t(12 * 50)); // the frames do move vertices
}

TEST(LinkProjection, EnvelopeKeepsAFeasibleStartAndReportsAnEmptyFeasibleSet)
{
  // A feasible start (the projection of the ramp) comes back unchanged.
  const index_t n = 15;
  const Mesh grid = geoshaping::testing::triangle_grid(n, n, 1.0);
  ChainMailDeformer d = make(grid);
  d.set_malleability(scrambled_malleability(grid.size()).data());
  const index_t g = grid_id(n, 7, 7);
  ASSERT_TRUE(d.deform(g, { 0.5, 0.5, 3.0 }).ok);
  const LinkMesh m = link_mesh(d);
  const Displacements feasible = reference_configuration(m, g, displacements(d));
  ASSERT_LE(link_error(m, feasible), 1e-8);
  std::vector<index_t> vertices;
  Displacements values;
  for (index_t v = 0; v < m.size(); ++v)
    if (!feasible[v].isZero(0.0))
    {
      vertices.push_back(v);
      values.push_back(feasible[v]);
    }
  LinkProjector p(m);
  ProjectionOptions o;
  o.solver = ProjectionSolver::envelope;
  o.tolerance = 1e-6;
  p.project(g, vertices, values, o);
  double moved = 0.0;
  for (index_t v = 0; v < m.size(); ++v)
    moved = std::max(moved, (p.displacement(v) - feasible[v]).cwiseAbs().maxCoeff());
  EXPECT_LE(moved, 1e-7 * m.scale()); // only links within the reference's own residual move

  // Pins beside the grasp: no feasible configuration; finite, fixed exact, not converged.
  std::vector<std::uint8_t> pins(std::size_t(grid.size()), 0);
  pins[grid_id(n, 8, 7)] = pins[grid_id(n, 7, 8)] = 1;
  d.set_pinned(pins.data());
  ASSERT_TRUE(d.deform(g, { 0.0, 0.0, 5.0 }).ok);
  const LinkMesh pm = link_mesh(d);
  LinkProjector q(pm);
  const ProjectionReport r = refine_links(q, d, g, o);
  EXPECT_FALSE(r.converged);
  EXPECT_TRUE(std::isfinite(r.violation));
  EXPECT_EQ(q.displacement(g), d.displacement(g));
  for (index_t v = 0; v < pm.size(); ++v)
  {
    EXPECT_TRUE(q.displacement(v).allFinite());
    if (pins[v])
      EXPECT_TRUE(q.displacement(v).isZero(0.0));
  }
}

TEST(LinkProjection, EnvelopeInTheLinkFrameRunsDykstra)
{
  const Scene sc = scenes()[0];
  ChainMailDeformer d = run(sc);
  d.set_valid_region_frame(ValidRegionFrame::link);
  ASSERT_TRUE(d.deform(sc.grasp, sc.drag).ok);
  const LinkMesh m = link_mesh(d);
  LinkProjector a(m), b(m);
  ProjectionOptions o;
  o.max_iterations = 8;
  o.solver = ProjectionSolver::envelope;
  const ProjectionReport ra = refine_links(a, d, sc.grasp, o);
  o.solver = ProjectionSolver::dykstra;
  const ProjectionReport rb = refine_links(b, d, sc.grasp, o);
  EXPECT_EQ(ra.iterations, rb.iterations);
  for (index_t v = 0; v < m.size(); ++v)
    EXPECT_EQ(a.displacement(v), b.displacement(v)) << v;
}

TEST(LinkProjection, CappedReferenceIsFinishedToTheTolerance)
{
  // The rigid-island scene needs ~6,000 ADMM iterations; capped at 300 the finish projects
  // ADMM's result (envelope in Axes: exactly feasible; in Link ADMM at 100x rho, then
  // Dykstra: both converge to the tolerance).
  const Scene sc = scenes()[2];
  for (const ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    ChainMailDeformer d = run(sc);
    d.set_valid_region_frame(f);
    ASSERT_TRUE(d.deform(sc.grasp, sc.drag).ok);
    const LinkMesh m = link_mesh(d);
    const Displacements start = displacements(d);
    ProjectionOptions exact;
    exact.tolerance = 1e-10;
    const Displacements reference = reference_configuration(m, sc.grasp, start, nullptr, exact);
    ProjectionOptions capped;
    capped.tolerance = 1e-6;
    capped.max_iterations = 300;
    capped.finish = false;
    ProjectionReport raw;
    const Displacements x = reference_configuration(m, sc.grasp, start, &raw, capped);
    ASSERT_FALSE(raw.converged) << frame_name(f);
    capped.finish = true;
    ProjectionReport r;
    const Displacements finished = reference_configuration(m, sc.grasp, start, &r, capped);
    EXPECT_GT(r.finish_iterations, 0);
    EXPECT_LE(link_error(m, finished), raw.violation) << frame_name(f);
    if (f == ValidRegionFrame::axes) // the envelope: exact in one pass
    {
      EXPECT_TRUE(r.converged);
      EXPECT_EQ(r.finish_iterations, 1);
      EXPECT_LE(link_error(m, finished), 1e-12);
    }
    else
    {
      EXPECT_TRUE(r.converged) << r.violation;
      EXPECT_LE(link_error(m, finished), capped.tolerance);
    }
    EXPECT_EQ(rigid_error(m, finished), 0.0);
    double moved = 0.0, off = 0.0, raw_off = 0.0;
    for (index_t v = 0; v < m.size(); ++v)
    {
      moved = std::max(moved, (finished[v] - x[v]).norm());
      off = std::max(off, (finished[v] - reference[v]).norm());
      raw_off = std::max(raw_off, (x[v] - reference[v]).norm());
    }
    std::printf("[ finish ] %s: ADMM 300 violation %.2e L, %.2e L from the reference; finish "
                "(%d iterations) moves %.2e L, result %.2e L from it, violation %.2e L\n",
      frame_name(f), raw.violation, raw_off / m.scale(), r.finish_iterations, moved / m.scale(),
      off / m.scale(), r.violation);
    // The finish moves by about the violation it removes; the distance to the projection
    // stays ADMM's, which the violation does not bound (measured: 1.3e-3 L of violation,
    // 0.22 L from the projection, Axes).
    EXPECT_LE(moved / m.scale(), 10.0 * raw.violation);
    EXPECT_LE(off, raw_off + moved + 1e-12);
  }
}
