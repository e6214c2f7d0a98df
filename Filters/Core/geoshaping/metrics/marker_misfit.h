#pragma once
// How far a surface is from well markers (docs/markers.md): the rules, given the nearest
// point and the vertical crossings the caller's locator found. O(1) per marker, plus
// O(hits) to pick the vertical crossing and O(markers) for the summary.
//
// Signs are "surface minus marker", so a marker above the surface has a negative misfit:
//
//   VerticalMisfit = z_s - z_m, with z_s the elevation, among the surface's crossings of
//                    the vertical line through the marker, nearest to the marker's z_m
//                    (a fold or an overturned fault crosses the line several times; the
//                    nearest crossing is the one a geologist reads the marker against).
//                    No crossing: the marker is outside the surface's footprint
//                    (Inside = 0) and VerticalMisfit is 0, not NaN.
//   Misfit         = s |c - m|, with c the surface point nearest to the marker m and
//                    s = sign((c - m) . n), n the normal of the triangle holding c, turned
//                    so that n_z >= 0 (a horizon's normal points up; a vertical triangle
//                    keeps the orientation its vertex order gives; s = +1 where
//                    (c - m) . n = 0). Where c is inside a
//                    triangle, c - m is parallel to n and Misfit is the signed distance
//                    along the normal exactly; on an edge or a vertex it is the distance,
//                    signed by that triangle's side. Misfit = 0 exactly when m lies on
//                    the surface.
//
// The summary is over the inside markers only: MisfitRMS = sqrt(mean(Misfit^2)) and
// MisfitMax = max |Misfit| (both 0 when no marker is inside).
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace geoshaping
{

// The elevation at (x, y) of the plane of triangle (a, b, c), by barycentric coordinates
// in xy taken from a (so UTM-sized coordinates keep their digits):
//
//   p = (x - a_x, y - a_y), e1 = b - a, e2 = c - a, det = e1_x e2_y - e1_y e2_x,
//   u = (p_x e2_y - p_y e2_x) / det, v = (e1_x p_y - e1_y p_x) / det,
//   z = a_z + u e1_z + v e2_z.
//
// False (z untouched) for a triangle standing vertical (det = 0): the line runs in its
// plane, and its neighbours give the crossing. The caller has found the triangle the
// line crosses; (u, v) may lie outside [0, 1] by that search's tolerance.
bool plane_elevation(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
  double x, double y, double& z);

// The index in `crossings` of the elevation nearest to marker_z (the first of equally near
// ones), -1 when there is none: the crossing VerticalMisfit reads, and the one whose
// triangle HonourMarkers pins (marker_pins.h).
std::ptrdiff_t nearest_crossing(double marker_z, const std::vector<double>& crossings);

// The surface minus the marker along z (above): `crossings` are the elevations where the
// vertical line through the marker meets the surface. `inside` is set to whether there is
// one; the result is 0 when there is none.
double vertical_misfit(double marker_z, const std::vector<double>& crossings, bool& inside);

// The signed distance above from the marker m to triangle (a, b, c), the one holding its
// nearest surface point (found by the caller's locator): c = the triangle's point nearest
// m (closest_point_on_triangle, taken from a), n = (b - a) x (c - a) turned up.
double normal_misfit(const Eigen::Vector3d& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c);

struct MisfitSummary
{
  double rms = 0.0;       // sqrt(mean Misfit^2) over the inside markers
  double max = 0.0;       // max |Misfit| over the inside markers
  std::size_t inside = 0; // how many markers are inside the footprint
};

// `misfit[i]` and `inside[i]` (non-zero: inside) per marker.
MisfitSummary summarize_misfit(
  const std::vector<double>& misfit, const std::vector<unsigned char>& inside);

} // namespace geoshaping
