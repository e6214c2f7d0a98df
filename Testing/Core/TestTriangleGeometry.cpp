#include "geoshaping/mesh/triangle_geometry.h"

#include <gtest/gtest.h>

using geoshaping::closest_point_on_triangle;

TEST(TriangleGeometry, ClosestPointCoversFaceEdgesAndVertices)
{
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_TRUE(
    closest_point_on_triangle({ 0.2, 0.3, 5 }, a, b, c).isApprox(Eigen::Vector3d(0.2, 0.3, 0)));
  EXPECT_TRUE(
    closest_point_on_triangle({ 0.5, -1, 0 }, a, b, c).isApprox(Eigen::Vector3d(0.5, 0, 0)));
  EXPECT_TRUE(
    closest_point_on_triangle({ 1, 1, 0 }, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_EQ(closest_point_on_triangle({ -1, -1, 2 }, a, b, c), a);
  EXPECT_EQ(closest_point_on_triangle({ 3, -0.5, 0 }, a, b, c), b);
  EXPECT_EQ(closest_point_on_triangle({ -0.1, 4, 0 }, a, b, c), c);
  // The other two edges, and a point on the face itself.
  EXPECT_TRUE(
    closest_point_on_triangle({ -2, 0.25, 1 }, a, b, c).isApprox(Eigen::Vector3d(0, 0.25, 0)));
  EXPECT_TRUE(
    closest_point_on_triangle({ 0.25, 0.25, 0 }, a, b, c).isApprox(Eigen::Vector3d(0.25, 0.25, 0)));
}
