#pragma once
// The vertices within a radius of any of many centres, each found once: what a stroke of
// Euclidean dabs paints, in time that follows the area it covers, not the number of dabs.
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace geoshaping
{

// A uniform grid of cubic cells over the vertices' bounding box, each cell listing its
// vertices (CSR): about two vertices per cell on a solid, more on a surface. Built once
// per geometry in O(n).
class VertexGrid
{
public:
  VertexGrid() = default;
  VertexGrid(const double* xyz, index_t n);

  bool empty() const { return ids_.empty(); }
  double cell_size() const { return size_; }
  // The cells along each axis that a coordinate interval [lo, hi] overlaps, clamped to
  // the grid; false when it misses the grid.
  bool cell_range(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Eigen::Array3i& first,
    Eigen::Array3i& last) const;
  // A position in cell units from the grid's corner (not clamped).
  Eigen::Array3d position(const Eigen::Vector3d& p) const
  {
    return ((p - origin_) * inverse_).array();
  }
  std::int64_t cell(int i, int j, int k) const
  {
    return (std::int64_t(k) * dims_[1] + j) * dims_[0] + i;
  }
  std::int64_t cells() const { return std::int64_t(start_.size()) - 1; }
  const index_t* begin(std::int64_t c) const { return ids_.data() + start_[std::size_t(c)]; }
  const index_t* end(std::int64_t c) const { return ids_.data() + start_[std::size_t(c) + 1]; }

private:
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double size_ = 1.0;
  double inverse_ = 1.0; // cells per unit length: every cell index is computed with it
  Eigen::Array3i dims_ = Eigen::Array3i::Zero();
  std::vector<index_t> start_{ 0 }; // cells + 1 offsets into ids_
  std::vector<index_t> ids_;
};

// For every vertex within `radius` of at least one of `centres` (brush_distance, the
// rim included), its distance to the nearest centre: the union of the dabs' spheres. Each
// such vertex is reported once, in an order fixed by the grid. With `exact` false the
// distance reported is only guaranteed to be <= radius (enough for a Constant falloff,
// and cheaper: a cell of vertices all within the radius of one centre is taken whole).
//
// Cost: the cells within the radius of a centre are marked once each (centres grouped in
// cubes of side max(radius, cell)); each marked cell's vertices are compared only with
// the centres that can be the nearest to some point of the cell's bounding box (those
// whose least distance to it is at most the least, over centres, of the greatest), so a
// vertex costs about the centres around its own nearest one, not every dab reaching it.
class DabUnion
{
public:
  void compute(const VertexGrid& grid, const double* xyz,
    const std::vector<Eigen::Vector3d>& centres, double radius, bool exact,
    std::vector<index_t>& vertices, std::vector<double>& distances);

private:
  std::vector<std::uint8_t> marked_; // per grid cell, cleared after each call
  std::vector<std::int64_t> cells_;
  struct Group
  {
    Eigen::Array3i key;
    std::size_t begin, end; // into order_
    Eigen::Vector3d lo, hi; // the centres' bounding box
  };
  std::vector<Group> groups_;
  std::vector<std::size_t> order_;
  std::vector<std::size_t> candidates_;
  // One cell's candidate centres in a small grid (at most 17 buckets a side, each at
  // least the radius wide) over the cell's box grown by the radius.
  struct Buckets
  {
    Eigen::Array3d corner;
    double inverse = 1.0;
    Eigen::Array3i dims;
    std::vector<std::uint32_t> start, fill;
    std::vector<std::size_t> items, cell;
    void build(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double reach,
      const std::vector<Eigen::Vector3d>& centres, const std::vector<std::size_t>& candidates);
    Eigen::Array3i at(const Eigen::Vector3d& p) const
    {
      return ((p.array() - corner) * inverse).floor().cast<int>().max(0).min(dims - 1);
    }
    std::size_t index(const Eigen::Array3i& b) const
    {
      return std::size_t((b[2] * dims[1] + b[1]) * dims[0] + b[0]);
    }
  };
  Buckets buckets_;
};

} // namespace geoshaping
