#include "test_sheets.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping::testing
{

using Vec = Eigen::Vector3d;

void Sheet::add(const Sheet& other)
{
  const auto base = std::int64_t(xyz.size() / 3);
  xyz.insert(xyz.end(), other.xyz.begin(), other.xyz.end());
  for (std::int64_t t : other.tri)
    tri.push_back(base + t);
}

Sheet sheet(int n, const Vec& o, const Vec& du, const Vec& dv)
{
  Sheet s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      const Vec x = o + (double(i) / n) * du + (double(j) / n) * dv;
      s.xyz.insert(s.xyz.end(), { x.x(), x.y(), x.z() });
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const std::int64_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      s.tri.insert(s.tri.end(), { a, b, d, a, d, c });
    }
  return s;
}

bool crosses(const Vec& p, const Vec& q, const Vec& a, const Vec& b, const Vec& c)
{
  const Vec n = (b - a).cross(c - a);
  const double sp = n.dot(p - a), sq = n.dot(q - a);
  if (!((sp > 0 && sq < 0) || (sp < 0 && sq > 0)))
    return false;
  Eigen::Matrix3d m;
  m.col(0) = b - a;
  m.col(1) = c - a;
  m.col(2) = p - q;
  const Vec rhs = p - a;
  const double det = m.determinant();
  Eigen::Matrix3d mu = m, mv = m;
  mu.col(0) = rhs;
  mv.col(1) = rhs;
  const double u = mu.determinant() / det, v = mv.determinant() / det, slack = 1e-9;
  return u >= -slack && v >= -slack && u + v <= 1 + slack;
}

bool crosses_any(const Sheet& s, const Vec& p, const Vec& q)
{
  for (std::size_t t = 0; t < s.triangles(); ++t)
    if (crosses(p, q, s.point(std::size_t(s.tri[3 * t])), s.point(std::size_t(s.tri[3 * t + 1])),
          s.point(std::size_t(s.tri[3 * t + 2]))))
      return true;
  return false;
}

double triangle_distance(const Sheet& s, std::size_t t, const Vec& p)
{
  auto segment = [&p](const Vec& a, const Vec& b)
  {
    const double f = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (p - (a + f * (b - a))).norm();
  };
  const Vec a = s.point(std::size_t(s.tri[3 * t])), b = s.point(std::size_t(s.tri[3 * t + 1])),
            c = s.point(std::size_t(s.tri[3 * t + 2]));
  const Vec n = (b - a).cross(c - a).normalized();
  const Vec x = p - n.dot(p - a) * n; // projection onto the plane
  const bool inside = (b - a).cross(x - a).dot(n) >= 0 && (c - b).cross(x - b).dot(n) >= 0 &&
                      (a - c).cross(x - c).dot(n) >= 0;
  return inside ? std::abs(n.dot(p - a))
                : std::min({ segment(a, b), segment(b, c), segment(c, a) });
}

double distance_to(const Sheet& s, const Vec& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < s.triangles(); ++t)
    best = std::min(best, triangle_distance(s, t, p));
  return best;
}

double segment_distance(const Sheet& s, const Vec& p, const Vec& w)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < s.triangles(); ++t)
  {
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 100; ++k)
    {
      const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
      if (triangle_distance(s, t, p + a * w) < triangle_distance(s, t, p + b * w))
        hi = b;
      else
        lo = a;
    }
    best = std::min(best, triangle_distance(s, t, p + lo * w));
  }
  return best;
}

} // namespace geoshaping::testing
