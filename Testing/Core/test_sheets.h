#pragma once
// Triangle sheets (obstacles) for the core tests, and crossings and distances computed
// with the tests' own code (Cramer's rule, brute force), independent of obstacles.h.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace geoshaping::testing
{

struct Sheet
{
  std::vector<double> xyz;
  std::vector<std::int64_t> tri;
  Eigen::Vector3d point(std::size_t i) const
  {
    return Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  }
  std::size_t points() const { return xyz.size() / 3; }
  std::size_t triangles() const { return tri.size() / 3; }
  void add(const Sheet& other);
};

// An n x n grid of triangles: corner o, sides du, dv.
Sheet sheet(int n, const Eigen::Vector3d& o, const Eigen::Vector3d& du, const Eigen::Vector3d& dv);

// Whether p -> q crosses triangle abc: its ends strictly on opposite sides of the plane
// and p + t (q - p) = a + u (b - a) + v (c - a) with u, v >= -slack, u + v <= 1 + slack
// (Cramer's rule); slack > 0 widens the triangle, so the check is stricter than the rule.
bool crosses(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c);
bool crosses_any(const Sheet& s, const Eigen::Vector3d& p, const Eigen::Vector3d& q);

// Distance from p to triangle t of the sheet: to the plane when p projects inside the
// triangle, else to the nearest of its three edges.
double triangle_distance(const Sheet& s, std::size_t t, const Eigen::Vector3d& p);
double distance_to(const Sheet& s, const Eigen::Vector3d& p);
// Nearest approach of the segment p -> p + w to the sheet: per triangle the distance
// along the segment is convex, so a ternary search finds its minimum.
double segment_distance(const Sheet& s, const Eigen::Vector3d& p, const Eigen::Vector3d& w);

} // namespace geoshaping::testing
