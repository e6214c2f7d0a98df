#include "DisplayTransform.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping::interactor
{

DisplayTransform::DisplayTransform(const Eigen::Matrix4d& matrix)
  : matrix_(matrix)
{
  const Eigen::Matrix3d linear = matrix.topLeftCorner<3, 3>();
  const double det = linear.determinant();
  invertible_ = matrix.allFinite() && std::isfinite(det) && std::abs(det) > 0.0;
  inverse_ = invertible_ ? Eigen::Matrix4d(matrix.inverse()) : Eigen::Matrix4d::Identity();
  invertible_ = invertible_ && inverse_.allFinite();
  if (invertible_)
  {
    const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(linear).singularValues();
    stretch_ = sigma(0) / sigma(2);
  }
}

Eigen::Matrix4d DisplayTransform::about(const Eigen::Vector3d& world) const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  const Eigen::Matrix3d linear = matrix_.topLeftCorner<3, 3>();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = world - linear * world;
  return m;
}

std::size_t DisplayTransform::nearest_drawn(
  const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& candidates) const
{
  const Eigen::Matrix3d linear = matrix_.topLeftCorner<3, 3>();
  std::size_t best = 0;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates.size(); ++i)
  {
    const double d = (linear * (candidates[i] - point)).squaredNorm();
    if (d < least)
    {
      least = d;
      best = i;
    }
  }
  return best;
}

DisplayTransform DisplayTransform::of_prop(const double position[3], const double orientation[3],
  const double origin[3], const double scale[3])
{
  const double degree = 3.14159265358979323846 / 180.0;
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  const Eigen::Matrix3d rotation = (AngleAxisd(orientation[2] * degree, Vector3d::UnitZ()) *
                                    AngleAxisd(orientation[0] * degree, Vector3d::UnitX()) *
                                    AngleAxisd(orientation[1] * degree, Vector3d::UnitY()))
                                     .toRotationMatrix();
  const Vector3d o(origin[0], origin[1], origin[2]);
  const Vector3d p(position[0], position[1], position[2]);
  const Eigen::Matrix3d linear = rotation * Vector3d(scale[0], scale[1], scale[2]).asDiagonal();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = o + p - linear * o;
  return DisplayTransform(m);
}

Eigen::Vector3d DisplayTransform::to_world(const Eigen::Vector3d& data) const
{
  return (matrix_ * data.homogeneous()).hnormalized();
}

Eigen::Vector3d DisplayTransform::to_data(const Eigen::Vector3d& world) const
{
  return (inverse_ * world.homogeneous()).hnormalized();
}

Eigen::Vector3d DisplayTransform::normal_to_world(
  const Eigen::Vector3d& data_normal, const Eigen::Vector3d& toward_viewer) const
{
  const Eigen::Vector3d n = (inverse_.topLeftCorner<3, 3>().transpose() * data_normal).normalized();
  return n.dot(toward_viewer) < 0.0 ? Eigen::Vector3d(-n) : n;
}

Eigen::Vector3d exaggeration_scale(double s)
{
  const double z = std::isfinite(s) ? std::clamp(s, min_exaggeration, max_exaggeration) : 1.0;
  return Eigen::Vector3d(1.0, 1.0, z);
}

double exaggeration_of(const double scale[3])
{
  return scale[0] == scale[1] && scale[0] > 0.0 ? scale[2] / scale[0]
                                                : std::numeric_limits<double>::quiet_NaN();
}

} // namespace geoshaping::interactor
