#pragma once
// Small analytic meshes shared by the core tests and benchmarks.
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/mesh/adjacency.h"

#include <vector>

namespace geoshaping::testing
{

struct Mesh
{
  std::vector<double> xyz; // n * 3
  Adjacency adjacency;
  index_t size() const { return index_t(xyz.size() / 3); }
};

// A chain of `n` vertices along x with the given spacing, joined by lines.
Mesh chain(index_t n, double spacing);
// An nx-by-ny grid of quads in the z = 0 plane, vertex (i, j) at (i h, j h, 0),
// id = j * nx + i.
Mesh quad_grid(index_t nx, index_t ny, double h);
// The same grid split into triangles.
Mesh triangle_grid(index_t nx, index_t ny, double h);

inline index_t grid_id(index_t nx, index_t i, index_t j)
{
  return j * nx + i;
}

// The paper's Figure 6 scene: a soft (malleability 1) 31 x 31 triangle grid with a
// rigid (0) 7 x 7 island, grasped at (15, 12) and pulled by (4, 3, 12).
struct IslandScene
{
  Mesh mesh;
  std::vector<float> malleability;
  index_t grasp;
  double pull[3];
};
IslandScene rigid_island();

// The same stretch t, compression k and shear h at every malleability.
inline TransferFunction constant(double t, double k, double h)
{
  TransferFunction tf;
  tf.stretch = { t, t };
  tf.compression = { k, k };
  tf.shear = { h, h };
  return tf;
}

} // namespace geoshaping::testing
