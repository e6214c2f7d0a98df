#pragma once
// Vertex normals of a polygon mesh, kept for the vertices a deformation touches.
//
// The normal of face f with vertices p_0 .. p_{m-1} is Newell's
//
//     N_f = sum_i p_i x p_{(i+1) mod m},      n_f = N_f / |N_f|   (|N_f| = 2 area),
//
// exact for planar polygons and the least-squares plane normal otherwise. The normal of
// vertex v is the normalised sum of the unit normals of the faces that use it,
//
//     n_v = S_v / |S_v|,   S_v = sum_{f ∋ v} n_f,
//
// which is vtkPolyDataNormals' point normal without splitting, consistency or
// orientation passes. Degenerate faces (|N_f| = 0) add nothing; a vertex whose S_v is
// zero gets (0, 0, 0), never NaN.
//
// Moving vertex u changes n_f for every face that uses u, hence n_v for every vertex v
// of those faces: affected() lists them. Cost: affected() O(sum of the face sizes around
// the moved vertices); normal(v) O(sum of the sizes of v's faces). Memory: the faces
// (offsets + vertex ids) and a vertex-to-face map, both O(mesh), built once.
#include "geoshaping/adjacency.h"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross

#include <cstdint>
#include <vector>

namespace geoshaping
{

class SparseNormals
{
public:
  // Faces as CSR: face f uses face_vertices[face_offsets[f] .. face_offsets[f + 1]).
  void set_mesh(
    std::vector<std::int64_t> face_offsets, std::vector<index_t> face_vertices, index_t vertices);

  bool empty() const { return this->face_offsets_.size() < 2; }

  // Appends to `out`, once each, every vertex whose normal depends on the position of
  // any of the k vertices `moved` (those sharing a face with one of them).
  void affected(const index_t* moved, std::size_t k, std::vector<index_t>& out);

  // n_v for positions given by `position(index_t) -> Eigen::Vector3d`.
  template<class Position>
  Eigen::Vector3d normal(index_t v, const Position& position) const
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::int64_t i = this->vertex_offsets_[v]; i < this->vertex_offsets_[v + 1]; ++i)
    {
      const index_t f = this->vertex_faces_[std::size_t(i)];
      const std::int64_t first = this->face_offsets_[f], last = this->face_offsets_[f + 1];
      Eigen::Vector3d newell = Eigen::Vector3d::Zero();
      for (std::int64_t j = first; j < last; ++j)
      {
        const std::int64_t next = j + 1 < last ? j + 1 : first;
        newell += position(this->face_vertices_[std::size_t(j)])
                    .cross(position(this->face_vertices_[std::size_t(next)]));
      }
      const double length = newell.norm();
      if (length > 0.0)
        sum += newell / length;
    }
    const double length = sum.norm();
    return length > 0.0 ? Eigen::Vector3d(sum / length) : Eigen::Vector3d::Zero();
  }

private:
  std::vector<std::int64_t> face_offsets_;
  std::vector<index_t> face_vertices_;
  std::vector<std::int64_t> vertex_offsets_; // vertex -> faces, CSR
  std::vector<index_t> vertex_faces_;
  std::vector<std::uint8_t> seen_; // scratch for affected()
};

} // namespace geoshaping
