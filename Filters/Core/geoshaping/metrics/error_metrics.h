#pragma once
// Error metrics of a deformed configuration (docs/design.md, Error against run time).
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace geoshaping
{

class ChainMailDeformer;

// A configuration is given as per-vertex displacements u = x - x0 from the rest
// positions, which is what the deformer stores: the metrics then need only rest offsets
// and displacement differences, so UTM-sized coordinates lose nothing and a rigid
// translation has exactly zero rigid error.
using Displacements = std::vector<Eigen::Vector3d>;

// What the metrics and the link projection read about a mesh, as plain per-vertex arrays.
struct LinkMesh
{
  const Adjacency* adjacency = nullptr; // not owned: must outlive the LinkMesh
  std::vector<Eigen::Vector3d> rest;    // x0, relative to any local origin
  std::vector<ChainMailParams> params;  // each vertex's own (t, k, h)
  std::vector<std::uint8_t> rigid;      // non-zero where malleability == 0 (for E_rigid)
  std::vector<std::uint8_t> pinned;     // non-zero = never moves; empty = none pinned
  double mean_edge = 0.0;               // mean_edge_length(rest, *adjacency)
  // Shape of the valid regions link_distance() and link_error() measure against (the
  // deformer's, from link_mesh(deformer)), and that the link projection (refinement,
  // link_projection.h) projects onto.
  ValidRegionFrame frame = ValidRegionFrame::axes;

  index_t size() const { return index_t(rest.size()); }
  bool is_pinned(index_t v) const { return !pinned.empty() && pinned[std::size_t(v)] != 0; }
  // Lengths are divided by the mean edge length; by 1 when it is 0 (no edges, or all of
  // zero length), so a degenerate mesh reports raw lengths rather than NaN or Inf.
  double scale() const { return mean_edge > 0.0 ? mean_edge : 1.0; }
};

// Snapshot of a deformer's mesh: rest (local origin), params from its transfer function,
// rigid = malleability 0, pins. O(n); rebuild when malleability or pins change.
LinkMesh link_mesh(const ChainMailDeformer& deformer);
// Builds a LinkMesh from plain arrays; `malleability` gives both params (through `tf`)
// and the rigid mask.
LinkMesh link_mesh(const std::vector<Eigen::Vector3d>& rest, const Adjacency& adjacency,
  const std::vector<double>& malleability, const TransferFunction& tf = {});
// The deformer's current displacements as a dense array (O(n)).
Displacements displacements(const ChainMailDeformer& deformer);

// Mean over undirected edges (each counted once) of |x0_i - x0_j|; edges with a
// non-finite end are skipped; 0 when there is no edge.
double mean_edge_length(const std::vector<Eigen::Vector3d>& rest, const Adjacency& adjacency);

// E_rigid = max over edges (i, j) with both ends rigid of
//   |(x_i - x_j) - (x0_i - x0_j)| = |u_i - u_j|   (Euclidean),
// divided by the mean edge length. 0 for a rigid translation, bit for bit.
double rigid_error(const LinkMesh& mesh, const Displacements& u);

// Distance (in mesh units, not normalised) from vertex c to its valid region w.r.t. its
// neighbour s, with c's own params (valid_region.h): for o = x0_c - x0_s and the
// displacement bounds [lo, hi] of (o, params_c), the box is x_s + o + [lo, hi], so
//   dist = | (u_c - u_s) - clamp(u_c - u_s, lo, hi) |;
// with the Link region the distance to the cylinder, | w - link_displacement_projection(o, w) |
// with w = u_c - u_s.
// 0 when o is not finite (the deformer places no constraint there either).
double link_distance(const LinkMesh& mesh, const Displacements& u, index_t c, index_t s);

// E_link = max over every edge, in both directions, of link_distance, divided by the
// mean edge length. ChainMail guarantees 0 only on the sponsor links.
double link_error(const LinkMesh& mesh, const Displacements& u);

// Sparse variants: only the edges with at least one end in `vertices` (duplicates
// allowed). Edges with both ends at rest contribute 0 to both metrics, so when
// `vertices` holds every vertex with u != 0 (the displaced region: its one-ring is
// reached through the edges) the result equals the dense metric, at O(edges of the
// region) cost.
double rigid_error(
  const LinkMesh& mesh, const Displacements& u, const std::vector<index_t>& vertices);
double link_error(
  const LinkMesh& mesh, const Displacements& u, const std::vector<index_t>& vertices);

// E_ref: per-vertex distance d_v = |u_v - r_v| to a reference configuration r,
//   max = max_v d_v / L,   rms = sqrt(sum_v d_v^2 / m) / L,
// L the mean edge length, m the number of vertices displaced in u or r (u_v != 0 or
// r_v != 0), so padding the mesh with untouched vertices changes neither; both 0 when
// m == 0.
struct ReferenceError
{
  double max = 0.0;
  double rms = 0.0;
};
ReferenceError reference_error(
  const LinkMesh& mesh, const Displacements& u, const Displacements& reference);
// Over `vertices` (no duplicates) only; equal to the dense value when it holds every
// vertex displaced in u or r.
ReferenceError reference_error(const LinkMesh& mesh, const Displacements& u,
  const Displacements& reference, const std::vector<index_t>& vertices);

// Smoothness of a deformed triangle surface (the facets and saw-tooth "teeth" ChainMail
// leaves): for an interior edge e shared by exactly two triangles, theta_e(x) is
// the angle between their normals, atan2(|n_1 x n_2|, n_1 . n_2) in [0, pi] (0 where the
// two are coplanar: the jump of the surface normal across e), and
//   bend_e = | theta_e(x0 + u) - theta_e(x0) |,
// the change of that jump the deformation made (so the rest shape's own relief counts 0;
// a rigid motion gives 0 up to rounding). Over the edges whose two triangles have all
// their vertices in `vertices` (e.g. the displaced soft region: the intended crease
// where it meets a rigid part is left out):
//   max = max_e bend_e,   rms = sqrt(mean_e bend_e^2),   in radians.
// Folding a flat sheet by phi along a line of edges gives max = phi. Triangles must be
// consistently oriented; border and non-manifold edges (not exactly two triangles) and
// edges of a degenerate triangle (zero normal at rest or deformed) are skipped. Surfaces
// only: a tetrahedral mesh has no such measure here. Cost O(n + triangles) (a metric of
// the report and tests, not of the frame).
struct BendingError
{
  double max = 0.0;
  double rms = 0.0;
  std::size_t edges = 0; // edges measured
};
BendingError bending_error(const std::vector<Eigen::Vector3d>& rest,
  const std::vector<index_t>& triangles, const Displacements& u,
  const std::vector<index_t>& vertices);

// E_temporal over a drag d_0, d_1, ... with configurations X(d_k):
//   max_k max_v |X_v(d_{k+1}) - X_v(d_k)| / |d_{k+1} - d_k|
// (infinity norm over vertices of the Euclidean per-vertex difference). It is a ratio of
// two lengths: dividing both by the mean edge length changes nothing, so it is reported
// as is (1 for a rigid translation). Steps with d_{k+1} == d_k are skipped.
double temporal_error(
  const std::vector<Eigen::Vector3d>& drags, const std::vector<Displacements>& frames);

// The same metric fed one sparse frame at a time: `vertices` are those displaced in this
// frame and `values` their displacements (every other vertex at rest). Each frame costs
// O(vertices displaced now + vertices displaced in the previous frame).
class TemporalError
{
public:
  explicit TemporalError(index_t num_vertices);
  void add_frame(
    const Eigen::Vector3d& drag, const std::vector<index_t>& vertices, const Displacements& values);
  double value() const { return worst_; }

private:
  Displacements previous_; // dense, zero outside previous_vertices_
  std::vector<index_t> previous_vertices_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t frame_ = 0;
  bool started_ = false;
  Eigen::Vector3d previous_drag_ = Eigen::Vector3d::Zero();
  double worst_ = 0.0;
};

// Drives `deformer` through the drag with grasp `grasp` and returns E_temporal.
double temporal_error(
  ChainMailDeformer& deformer, index_t grasp, const std::vector<Eigen::Vector3d>& drags);

} // namespace geoshaping
