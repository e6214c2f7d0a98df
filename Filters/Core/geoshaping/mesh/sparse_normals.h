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
// of those faces. The unit face normals are kept (3 floats per face, computed once by
// set_positions), so moved() recomputes each affected face once and each affected vertex
// from its faces' kept normals. Cost of moved(): O(sum of the sizes of the faces around
// the moved vertices + the face counts of the affected vertices); memory O(mesh): the
// faces, a vertex-to-face map and the face normals, built once.
#include "geoshaping/mesh/adjacency.h"

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

  // Every face's unit normal from the positions `position(index_t) -> Eigen::Vector3d`.
  template<class Position>
  void set_positions(const Position& position)
  {
    const index_t faces = index_t(this->face_offsets_.size() - 1);
    this->face_normals_.resize(std::size_t(faces));
    for (index_t f = 0; f < faces; ++f)
      this->face_normals_[std::size_t(f)] = this->face_normal(f, position);
  }

  // The k vertices `moved` moved to `position`: refreshes the normals of the faces that
  // use them and appends to `affected`, once each, the vertices of those faces (whose
  // normal() changed).
  template<class Position>
  void moved(
    const index_t* moved, std::size_t k, const Position& position, std::vector<index_t>& affected)
  {
    this->faces_.clear();
    for (std::size_t i = 0; i < k; ++i)
      for (std::int64_t a = this->vertex_offsets_[moved[i]];
           a < this->vertex_offsets_[moved[i] + 1]; ++a)
      {
        const index_t f = this->vertex_faces_[std::size_t(a)];
        if (!this->face_seen_[std::size_t(f)])
        {
          this->face_seen_[std::size_t(f)] = 1;
          this->faces_.push_back(f);
        }
      }
    const std::size_t start = affected.size();
    for (index_t f : this->faces_)
    {
      this->face_seen_[std::size_t(f)] = 0;
      this->face_normals_[std::size_t(f)] = this->face_normal(f, position);
      for (std::int64_t j = this->face_offsets_[f]; j < this->face_offsets_[f + 1]; ++j)
      {
        const index_t v = this->face_vertices_[std::size_t(j)];
        if (!this->seen_[std::size_t(v)])
        {
          this->seen_[std::size_t(v)] = 1;
          affected.push_back(v);
        }
      }
    }
    for (std::size_t i = start; i < affected.size(); ++i)
      this->seen_[std::size_t(affected[i])] = 0;
  }

  // n_v from the kept face normals.
  Eigen::Vector3d normal(index_t v) const
  {
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    for (std::int64_t i = this->vertex_offsets_[v]; i < this->vertex_offsets_[v + 1]; ++i)
      sum += this->face_normals_[std::size_t(this->vertex_faces_[std::size_t(i)])];
    const float length = sum.norm();
    return length > 0.0f ? Eigen::Vector3d((sum / length).cast<double>()) : Eigen::Vector3d::Zero();
  }

  // n_f (zero for a degenerate face).
  template<class Position>
  Eigen::Vector3f face_normal(index_t f, const Position& position) const
  {
    const std::int64_t first = this->face_offsets_[f], last = this->face_offsets_[f + 1];
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    Eigen::Vector3d p = position(this->face_vertices_[std::size_t(last - 1)]);
    for (std::int64_t j = first; j < last; ++j)
    {
      const Eigen::Vector3d q = position(this->face_vertices_[std::size_t(j)]);
      newell += p.cross(q);
      p = q;
    }
    const double length = newell.norm();
    return length > 0.0 ? Eigen::Vector3f((newell / length).cast<float>())
                        : Eigen::Vector3f::Zero();
  }

private:
  std::vector<std::int64_t> face_offsets_;
  std::vector<index_t> face_vertices_;
  std::vector<std::int64_t> vertex_offsets_; // vertex -> faces, CSR
  std::vector<index_t> vertex_faces_;
  std::vector<Eigen::Vector3f> face_normals_;
  std::vector<std::uint8_t> seen_, face_seen_; // scratch for moved()
  std::vector<index_t> faces_;
};

} // namespace geoshaping
