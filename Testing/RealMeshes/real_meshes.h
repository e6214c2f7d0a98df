// The real meshes the promises are checked on (issue 36): the CRESCENT CFM faults and the
// Cascadia interface, GOCAD TSurf files read in place from GEOSHAPING_CFM_DIR (never
// copied into the repository), and a tetrahedral slab extruded from one of them; and the
// scene every test paints on them, in terms that turn with the mesh.
#pragma once

#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace geoshaping::testing
{

struct RealMesh
{
  std::string name;
  std::vector<double> xyz; // local coordinates: the first point subtracted
  Adjacency adjacency;
  std::vector<std::int64_t> triangles; // surfaces only (empty for the slab)
  double edge = 0.0;                   // mean edge length
  index_t size() const { return index_t(xyz.size() / 3); }
  Eigen::Vector3d point(index_t v) const
  {
    return { xyz[3 * std::size_t(v)], xyz[3 * std::size_t(v) + 1], xyz[3 * std::size_t(v) + 2] };
  }
};

// The Cascadia interface, four CRESCENT faults and the slab under Devils Mountain (369
// points, 3 layers of tetrahedra); empty when GEOSHAPING_CFM_DIR holds none. Read once.
const std::vector<RealMesh>& real_meshes();

#define SKIP_WITHOUT_REAL_MESHES()                                                                 \
  if (geoshaping::testing::real_meshes().empty())                                                  \
  GTEST_SKIP() << "no CRESCENT CFM files in '" GEOSHAPING_CFM_DIR                                  \
                  "' (set GEOSHAPING_CFM_DIR to the folder of the *.ts files)"

// The scene on a mesh, in terms that turn with it: the grasp is the vertex nearest the
// centroid; malleability is painted by distance r from the grasp in three bands (0.8 for
// r < 4 mean edge lengths, 0.35 for r < 9, 0.6 beyond) with a rigid disc (0) of radius
// 2.5 around the vertex nearest 6 from the grasp; `uniform`: 0.5 everywhere. Distances
// only, so a rotation or translation paints the same values on the same ids.
struct RealScene
{
  index_t grasp = 0;
  index_t second = 0; // pulled after the commit: the vertex nearest 5 edges behind the grasp
  std::vector<float> malleability;
  Eigen::Vector3d pull; // 12 mean edge lengths, a fixed random direction
};
RealScene real_scene(const RealMesh& m, bool uniform);

Eigen::Matrix3d random_rotation(std::mt19937& rng);
// x -> R x + t on every point.
std::vector<double> moved(
  const std::vector<double>& xyz, const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

} // namespace geoshaping::testing
