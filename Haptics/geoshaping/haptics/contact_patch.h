#pragma once
// Preparing the contact triangles of a SceneSnapshot on the graphics side: a surface of
// the scene is a two-sided sheet, but penalty contact (force_model.h) pushes toward one
// side of each triangle, its "free side". The graphics thread orients every triangle
// toward the side the stylus was last seen on while not in contact (a god-object-like
// memory at frame rate), and keeps only the triangles nearest to the stylus, since the
// servo thread tests every triangle every tick.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace geoshaping::haptics
{

// Reverses the triangles of the soup (3 vertices each) that do not have `free_point` on
// their counter-clockwise side. Degenerate triangles and triangles whose plane holds
// the point are left as they are. A trailing incomplete triangle is dropped.
void orient_toward(std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& free_point);

// Keeps the `max_triangles` triangles nearest to p (distance from p to the triangle),
// nearest first; the others are dropped. O(n) selection plus O(k log k) ordering.
void keep_nearest(
  std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& p, std::size_t max_triangles);

// The free-side memory of one stylus: its last position out of contact with the patch
// sent before (nearest_contact of force_model.h with the same shell). While in contact
// it stays where the stylus entered, so the triangles keep their orientation and the
// stylus is pushed back out, not through the sheet. Decided on the graphics side from
// the patch itself, so a late or stale servo snapshot cannot flip a sheet.
class FreeSide
{
public:
  // Feeds the stylus position (device frame) and the oriented patch sent last frame;
  // non-finite positions are ignored.
  void update(const Eigen::Vector3d& stylus, const std::vector<Eigen::Vector3d>& previous_patch,
    double shell);
  const Eigen::Vector3d& point() const { return this->point_; }
  bool known() const { return this->known_; }

private:
  Eigen::Vector3d point_ = Eigen::Vector3d::Zero();
  bool known_ = false;
};

} // namespace geoshaping::haptics
