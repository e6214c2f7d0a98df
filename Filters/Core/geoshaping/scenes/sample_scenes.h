#pragma once
// Sample scenes of the paper (Faeth et al., Figure 5): a horizon with a fault step, as
// triangles or as a tetrahedral slab, and its default painting. VTK-free.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/paint/brush.h"

#include <Eigen/Core>

#include <vector>

namespace geoshaping
{

// A mesh of one cell type: triangles (cell_size 3) or tetrahedra (cell_size 4).
struct SampleMesh
{
  std::vector<double> xyz;           // 3 per vertex
  std::vector<index_t> connectivity; // cell_size ids per cell
  int cell_size = 3;

  index_t num_points() const { return index_t(xyz.size() / 3); }
  std::size_t num_cells() const { return connectivity.size() / std::size_t(cell_size); }
  Adjacency adjacency() const;
};

// A horizontal horizon crossed along y by a near-vertical step. Its profile in the
// x-z plane is: upper flat at z = throw_height for x < x0, a smooth descent
// z = throw_height (1 - smoothstep((x - x0) / step_run)) for x0 <= x <= x0 + step_run,
// lower flat at z = 0 beyond, with x0 = step_position * length - step_run / 2. The
// profile is sampled uniformly in arc length, so the step gets as many rows of vertices
// as its height asks for, and extruded along y over `width`; all shifted by `origin`.
struct FaultStepParams
{
  double length = 100.0;      // x extent
  double width = 60.0;        // y extent
  double throw_height = 20.0; // vertical offset of the step
  double step_run = 6.0;      // horizontal extent of the step (steepest slope 1.5 throw/run)
  double step_position = 0.5; // centre of the step, as a fraction of length
  double spacing = 1.0;       // target edge length along the profile and along y
  double thickness = 6.0;     // slab only: vertical thickness below the horizon
  index_t layers = 3;         // slab only: vertex layers below the horizon
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

// Why the parameters cannot make a mesh ("" when they can): non-positive or
// non-finite sizes, spacing or layers, a step position outside [0, 1], or more than
// 2^31 - 1 vertices.
const char* validate(const FaultStepParams& p);

// Triangles, vertex (i, j) (i along the profile, j along y) at id j * nu + i where
// nu = fault_step_columns(p); each grid quad is split along its (i, j)-(i+1, j+1)
// diagonal. Empty when validate(p) fails.
SampleMesh fault_step_horizon(const FaultStepParams& p);
index_t fault_step_columns(const FaultStepParams& p);

// The horizon extruded down by `thickness` in `layers` layers (vertical offsets keep
// every cell valid since the profile is a function of x); each hexahedron of the
// (i, j, k) grid is split into six tetrahedra around its (0,0,0)-(1,1,1) diagonal
// (Kuhn), which is conforming across the grid. The top layer's ids and positions are
// those of fault_step_horizon(p); layer k's vertex (i, j) has id k * nu * nv + j * nu + i.
SampleMesh fault_step_slab(const FaultStepParams& p);

// The default painting of Figure 5C as a dab list to apply to `fault_step_red`: a
// white band of `border` on both sides of the step, then the step black (dabs centred
// on the step surface, Constant falloff, Euclidean distance, strength 1), each colour
// laid back and forth as one stroke (brush.h). Dab centres include p.origin.
constexpr double fault_step_red = 0.4; // red in the black-body map
std::vector<Dab> fault_step_painting(const FaultStepParams& p, double border = 6.0);

// That painting applied to the mesh (surface or slab), one value per vertex.
std::vector<float> fault_step_malleability(
  const SampleMesh& mesh, const FaultStepParams& p, double border = 6.0);

// A tight fold: two horizontal sheets `gap` apart (z = 0 and z = gap, x in
// [0, length]) joined at x = length by a half circle, extruded along y over `width`,
// triangles like fault_step_horizon. A point on one sheet is `gap` away from the other
// through the air but about 2 (length - x) + 1.6 gap along the surface.
SampleMesh tight_fold(double length, double width, double gap, double spacing);

} // namespace geoshaping
