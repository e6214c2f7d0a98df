#include "geoshaping/mesh/nearest_triangles.h"
#include "geoshaping/mesh/triangle_geometry.h"

#include <gtest/gtest.h>

#include <random>

using namespace geoshaping;

namespace
{
std::vector<Eigen::Vector3d> square()
{
  const Eigen::Vector3d a(-0.1, -0.1, 0), b(0.1, -0.1, 0), c(0.1, 0.1, 0), d(-0.1, 0.1, 0);
  return { a, c, b, a, d, c };
}
} // namespace

TEST(NearestTriangles, KeepNearestMatchesABruteForceSortAndDropsIncompleteTriangles)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> soup;
  for (int i = 0; i < 3 * 300; ++i)
  {
    soup.emplace_back(u(rng), u(rng), u(rng));
  }
  const Eigen::Vector3d p(0.1, -0.2, 0.3);
  std::vector<std::pair<double, std::size_t>> brute;
  for (std::size_t t = 0; t < 300; ++t)
  {
    const Eigen::Vector3d q =
      geoshaping::closest_point_on_triangle(p, soup[3 * t], soup[3 * t + 1], soup[3 * t + 2]);
    brute.emplace_back((q - p).squaredNorm(), t);
  }
  std::sort(brute.begin(), brute.end());
  auto kept = soup;
  keep_nearest(kept, p, 40);
  ASSERT_EQ(kept.size(), 120u);
  for (std::size_t k = 0; k < 40; ++k)
  {
    const std::size_t t = brute[k].second;
    EXPECT_EQ(kept[3 * k], soup[3 * t]) << k;
    EXPECT_EQ(kept[3 * k + 2], soup[3 * t + 2]) << k;
  }
  auto all = soup;
  keep_nearest(all, p, 1000); // fewer than asked: all kept (reordered)
  EXPECT_EQ(all.size(), soup.size());

  std::vector<Eigen::Vector3d> ragged = square();
  ragged.push_back(Eigen::Vector3d::Zero());
  keep_nearest(ragged, p, 10);
  EXPECT_EQ(ragged.size(), 6u);
}
