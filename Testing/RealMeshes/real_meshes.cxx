#include "real_meshes.h"

#include "vtkGocadTSurfParser.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace geoshaping::testing
{
namespace
{

double mean_edge(const RealMesh& m)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (index_t v = 0; v < m.adjacency.size(); ++v)
    for (const index_t* w = m.adjacency.begin(v); w != m.adjacency.end(v); ++w)
    {
      sum += (m.point(v) - m.point(*w)).norm();
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
  m.triangles = data.Triangles;
  AdjacencyBuilder builder(index_t(data.GetNumberOfPoints()));
  for (std::size_t t = 0; t + 2 < m.triangles.size(); t += 3)
    builder.add_cell(CellKind::triangle, &m.triangles[t], 3);
  m.adjacency = builder.build();
  m.edge = mean_edge(m);
  return true;
}

// A tetrahedral slab under a surface: `layers` more copies of it, each 0.8 mean edge
// lengths below the last (along -z), each triangle's prism cut into three tetrahedra by
// the order of its vertex ids (a split both neighbours of a face agree on).
RealMesh slab_under(const RealMesh& s, int layers)
{
  RealMesh m;
  m.name = s.name + " (tetrahedral slab)";
  const index_t n = s.size();
  for (int l = 0; l <= layers; ++l)
    for (index_t v = 0; v < n; ++v)
    {
      Eigen::Vector3d p = s.point(v);
      p.z() -= 0.8 * s.edge * l;
      m.xyz.insert(m.xyz.end(), { p.x(), p.y(), p.z() });
    }
  AdjacencyBuilder builder(n * index_t(layers + 1));
  for (int l = 0; l < layers; ++l)
    for (std::size_t t = 0; t + 2 < s.triangles.size(); t += 3)
    {
      std::int64_t a[3] = { s.triangles[t], s.triangles[t + 1], s.triangles[t + 2] };
      std::sort(a, a + 3);
      const std::int64_t top = std::int64_t(n) * l, bottom = top + n;
      const std::int64_t tets[3][4] = { { a[0] + top, a[1] + top, a[2] + top, a[2] + bottom },
        { a[0] + top, a[1] + top, a[1] + bottom, a[2] + bottom },
        { a[0] + top, a[0] + bottom, a[1] + bottom, a[2] + bottom } };
      for (const auto& tet : tets)
        builder.add_cell(CellKind::tetra, tet, 4);
    }
  m.adjacency = builder.build();
  m.edge = mean_edge(m);
  return m;
}

std::vector<RealMesh> read_real_meshes()
{
  std::vector<RealMesh> out;
  for (const char* file : { "mccrory_2012_cascadia_interface.ts", "Almanor.ts",
         "Uhtanum_Ridge_-_Gable_Mountain.ts", "Southern_Whidbey_Island_north.ts", "Yaquina.ts" })
  {
    RealMesh m;
    if (read_tsurf(std::string(GEOSHAPING_CFM_DIR) + "/" + file, m))
      out.push_back(std::move(m));
  }
  RealMesh s;
  if (read_tsurf(std::string(GEOSHAPING_CFM_DIR) + "/Devils_Mountain.ts", s))
    out.push_back(slab_under(s, 3));
  return out;
}

} // namespace

const std::vector<RealMesh>& real_meshes()
{
  static const std::vector<RealMesh> m = read_real_meshes();
  return m;
}

RealScene real_scene(const RealMesh& m, bool uniform)
{
  RealScene s;
  const index_t n = m.size();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (index_t v = 0; v < n; ++v)
    c += m.point(v);
  c /= double(n);
  double best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if ((m.point(v) - c).norm() < best)
    {
      best = (m.point(v) - c).norm();
      s.grasp = v;
    }
  const Eigen::Vector3d g = m.point(s.grasp);
  // The rigid disc's centre: the vertex nearest 6 edges from the grasp.
  index_t disc = s.grasp;
  best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if (std::abs((m.point(v) - g).norm() - 6.0 * m.edge) < best)
    {
      best = std::abs((m.point(v) - g).norm() - 6.0 * m.edge);
      disc = v;
    }
  s.malleability.assign(std::size_t(n), 0.5f);
  if (!uniform)
    for (index_t v = 0; v < n; ++v)
    {
      const double r = (m.point(v) - g).norm() / m.edge;
      float& a = s.malleability[std::size_t(v)];
      a = r < 4.0 ? 0.8f : (r < 9.0 ? 0.35f : 0.6f);
      if ((m.point(v) - m.point(disc)).norm() < 2.5 * m.edge)
        a = 0.0f;
    }
  s.malleability[std::size_t(s.grasp)] = uniform ? 0.5f : 0.8f;
  s.pull = 12.0 * m.edge * Eigen::Vector3d(0.3, -0.5, 0.81).normalized();
  const Eigen::Vector3d behind = g - 5.0 * m.edge * s.pull.normalized();
  best = INFINITY;
  for (index_t v = 0; v < n; ++v)
    if (v != s.grasp && (m.point(v) - behind).norm() < best)
    {
      best = (m.point(v) - behind).norm();
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

} // namespace geoshaping::testing
