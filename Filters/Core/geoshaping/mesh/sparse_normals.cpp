#include "geoshaping/mesh/sparse_normals.h"

namespace geoshaping
{

void SparseNormals::set_mesh(
  std::vector<std::int64_t> face_offsets, std::vector<index_t> face_vertices, index_t vertices)
{
  this->face_offsets_ = std::move(face_offsets);
  this->face_vertices_ = std::move(face_vertices);
  this->vertex_offsets_.assign(std::size_t(vertices) + 1, 0);
  for (index_t v : this->face_vertices_)
    ++this->vertex_offsets_[std::size_t(v) + 1];
  for (std::size_t v = 0; v < std::size_t(vertices); ++v)
    this->vertex_offsets_[v + 1] += this->vertex_offsets_[v];
  this->vertex_faces_.assign(this->face_vertices_.size(), 0);
  std::vector<std::int64_t> fill(this->vertex_offsets_.begin(), this->vertex_offsets_.end() - 1);
  const index_t faces = index_t(this->face_offsets_.empty() ? 0 : this->face_offsets_.size() - 1);
  for (index_t f = 0; f < faces; ++f)
    for (std::int64_t j = this->face_offsets_[f]; j < this->face_offsets_[f + 1]; ++j)
      this->vertex_faces_[std::size_t(fill[std::size_t(this->face_vertices_[std::size_t(j)])]++)] =
        f;
  this->seen_.assign(std::size_t(vertices), 0);
  this->face_seen_.assign(std::size_t(faces), 0);
  this->face_normals_.assign(std::size_t(faces), Eigen::Vector3f::Zero());
}

} // namespace geoshaping
