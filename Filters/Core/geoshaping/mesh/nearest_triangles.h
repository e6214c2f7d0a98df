#pragma once
// @brief Preparing the contact triangles of a SceneSnapshot on the graphics side: only the
// triangles nearest to the stylus are sent, since the servo thread tests every one each
// tick. Their winding does not matter: the proxy (proxy.h) treats them as two-sided.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace geoshaping::haptics
{

// Keeps the `max_triangles` triangles nearest to p (distance from p to the triangle),
// nearest first; the others are dropped. O(n) selection plus O(k log k) ordering.
void keep_nearest(
  std::vector<Eigen::Vector3d>& triangles, const Eigen::Vector3d& p, std::size_t max_triangles);

} // namespace geoshaping::haptics
