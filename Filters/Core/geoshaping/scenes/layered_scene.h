#pragma once
// The paper's Figure 1: horizons cut by a fault. VTK-free.
#include "geoshaping/scenes/sample_scenes.h"

namespace geoshaping
{

// Two horizontal horizons cut by a planar fault that strikes along y and dips toward +x.
// The fault trace at elevation z is x_f(z) = fault_x + (top - z) / tan(dip); the
// hanging wall (x > x_f) is dropped by `throw_height`. Each horizon is two triangle
// grids, one per fault block, ending on the fault; the fault is a triangle grid from
// `bottom` to `top` elevation. All vertices about `spacing` apart, shifted by `origin`.
struct LayeredSceneParams
{
  double length = 200.0;        // x extent
  double width = 100.0;         // y extent
  double fault_x = 90.0;        // fault trace at z = top
  double dip_degrees = 70.0;    // fault dip, in (0, 90]
  double top = 0.0;             // top of the fault surface
  double bottom = -120.0;       // bottom of the fault surface
  double horizon_upper = -30.0; // footwall elevations of the two horizons
  double horizon_lower = -80.0;
  double throw_height = 15.0; // hanging-wall drop
  double spacing = 2.0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

// Why the parameters cannot make the scene ("" when they can).
const char* validate(const LayeredSceneParams& p);

enum class ScenePart : int
{
  upper_horizon = 0,
  lower_horizon = 1,
  fault = 2
};

// Triangles of all parts in one mesh (separate components: the parts share no vertex),
// and the part of each vertex.
struct LayeredScene
{
  SampleMesh mesh;
  std::vector<int> part; // ScenePart per vertex
};

LayeredScene layered_fault_scene(const LayeredSceneParams& p);

} // namespace geoshaping
