#pragma once
// A representation's display transform, free of Qt, VTK and ParaView so that it is unit
// tested (Testing/GUI/TestDisplayTransform.cpp): the matrix of its Position, Orientation,
// Origin and Scale (Properties > Transforming), and the one rule by which the interactor
// carries a pick between the view (world) and the data: the view ray goes into the data's
// coordinates, meets the data's cell there, and the point and normal found come back.
// Hover, paint and pull all take their surface point through it, so a vertical
// exaggeration (Scale 1, 1, s) leaves the hand where the surface is drawn.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace geoshaping::interactor
{

class DisplayTransform
{
public:
  DisplayTransform() = default;
  explicit DisplayTransform(const Eigen::Matrix4d& matrix);
  // vtkProp3D::ComputeMatrix: x -> T(origin + position) Rz Rx Ry S T(-origin) x, the
  // angles in degrees (ParaView's Orientation).
  static DisplayTransform of_prop(const double position[3], const double orientation[3],
    const double origin[3], const double scale[3]);

  const Eigen::Matrix4d& matrix() const { return matrix_; }
  // False for a singular or non-finite matrix (a zero Scale): the data cannot be reached.
  bool invertible() const { return invertible_; }

  Eigen::Vector3d to_world(const Eigen::Vector3d& data) const;
  Eigen::Vector3d to_data(const Eigen::Vector3d& world) const;
  // A surface normal found in the data, in the world: the inverse transpose, unit length,
  // turned toward the viewer (`toward_viewer`, the camera's view-plane normal) as
  // ParaView's own pick turns it.
  Eigen::Vector3d normal_to_world(
    const Eigen::Vector3d& data_normal, const Eigen::Vector3d& toward_viewer) const;

  // A shape of data size drawn at `world`: the linear part about that point,
  // T(world) L T(-world). The brush cage is its sphere through it (an ellipsoid s times
  // taller under a vertical exaggeration), as the brush reaches in the data.
  Eigen::Matrix4d about(const Eigen::Vector3d& world) const;

  // The grasp takes the vertex drawn nearest to the picked point, which under a
  // vertical exaggeration need not be the data's nearest: it lies within stretch() times
  // the data's nearest distance (the largest over the smallest singular value of the
  // linear part; 1 for a rigid motion). nearest_drawn() is the index of the candidate
  // (data coordinates) drawn nearest to `point` (data coordinates); 0 for none.
  double stretch() const { return stretch_; }
  std::size_t nearest_drawn(
    const Eigen::Vector3d& point, const std::vector<Eigen::Vector3d>& candidates) const;

private:
  Eigen::Matrix4d matrix_ = Eigen::Matrix4d::Identity();
  Eigen::Matrix4d inverse_ = Eigen::Matrix4d::Identity();
  bool invertible_ = true;
  double stretch_ = 1.0;
};

// The vertical exaggeration the dock sets: the display Scale (1, 1, s), for s within
// [min_exaggeration, max_exaggeration] (a non-finite s: 1).
constexpr double min_exaggeration = 0.1;
constexpr double max_exaggeration = 100.0;
Eigen::Vector3d exaggeration_scale(double s);
// The exaggeration a display Scale shows: z over the horizontal scale, when x and y are
// scaled alike (else, or for a non-positive horizontal scale, NaN).
double exaggeration_of(const double scale[3]);

} // namespace geoshaping::interactor
