#pragma once
// @brief The triangles nearest a point: the contact patch the graphics side sends the
// haptic servo (only the triangles nearest the stylus, since the servo tests every one
// each tick) and each rank's part of it on a server (vtkGeoShapingContactPatch). Their
// winding does not matter: the haptic proxy treats them as two-sided.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace geoshaping
{

// Keeps the `max_triangles` triangles nearest to p (distance from p to the triangle),
// nearest first; the others are dropped. O(n) selection plus O(k log k) ordering.
void keep_nearest(
  std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& p, std::size_t max_triangles);

} // namespace geoshaping
