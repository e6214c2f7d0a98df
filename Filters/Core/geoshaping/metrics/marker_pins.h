#pragma once
// Well markers honoured while shaping (docs/markers.md, "Honoured while shaping"): the
// vertices to pin so that every marker keeps its place against the surface. O(crossed
// triangles) per marker, O(P log P) to sort the P pinned vertices.
//
// The rule. A marker m = (x, y, z_m) reads the surface where its vertical line crosses it
// (marker_misfit.h): among the triangles the caller's locator found the line to cross, the
// crossing nearest to z_m (nearest_crossing), at the elevation plane_elevation gives from
// the triangle's first corner. The three corners of that triangle are pinned. A pinned
// vertex never moves and never sponsors (chainmail_deformer.h), so the triangle, its plane
// and hence its elevation at (x, y) stay bit for bit those of the shape the pins were made
// from, in every frame and after every commit made while they hold (a commit makes the
// frame's shape the rest shape, and the frame did not move them):
//
//   - a marker on that surface (|z_s - z_m| <= tolerance) stays on it;
//   - a marker off it keeps its vertical misfit z_s - z_m: the deformer holds a pin where
//     it is, not at a given position, so nothing brings the surface to the marker. It is
//     counted in `off_surface`.
//
// A marker whose vertical line crosses no triangle is outside the footprint: not honoured,
// counted in `outside`. A marker with a non-finite coordinate is skipped, counted in
// `non_finite`. Neither is an error.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/metrics/marker_misfit.h"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <vector>

namespace geoshaping
{

struct MarkerPins
{
  std::vector<index_t> vertices; // the pinned vertices, sorted, unique
  std::size_t honoured = 0;      // markers whose triangle is pinned
  std::size_t outside = 0;       // markers whose vertical line crosses no triangle
  std::size_t non_finite = 0;    // markers skipped for a NaN or infinite coordinate
  std::size_t off_surface = 0;   // honoured markers with |vertical misfit| > tolerance
};

// `markers`: count x 3 coordinates. `crossed(m, corners)`: the corners (3 vertex ids per
// triangle, appended to the cleared `corners`) of the triangles the caller's locator found
// the vertical line through marker m to cross. `position(v)`: vertex v's position (the
// shape the pins hold). `tolerance`: how far from the surface a marker counts as on it.
MarkerPins pin_markers(const double* markers, std::size_t count,
  const std::function<void(const Eigen::Vector3d&, std::vector<index_t>&)>& crossed,
  const std::function<Eigen::Vector3d(index_t)>& position, double tolerance);

// The crossing a marker m reads among the `count` / 3 triangles `corners` (3 vertex ids each) its
// vertical line was found to cross: the offset in `corners` (a multiple of 3) of the
// triangle whose plane_elevation at (m_x, m_y), with the corners at `position`, is the
// nearest to m_z (nearest_crossing; vertical triangles skipped), `z` set to that
// elevation; -1 (z untouched) when there is none. pin_markers pins that triangle.
std::ptrdiff_t nearest_crossed_triangle(const Eigen::Vector3d& m, const index_t* corners,
  std::size_t count, const std::function<Eigen::Vector3d(index_t)>& position, double& z);

// The markers mapped to the triangles their vertical lines cross (made once per change
// of the shape or the markers, by the caller's locator), to read their vertical misfit
// in a frame without a locator: marker i is xyz[3i .. 3i + 2], its triangles'
// corners are corners[first[i] .. first[i + 1]). Only the markers with a crossing.
struct MarkerCrossingMap
{
  std::vector<double> xyz;
  std::vector<std::size_t> first{ 0 };
  std::vector<index_t> corners;
  std::size_t size() const { return this->first.size() - 1; }
};

// The vertical misfit of the mapped markers in a frame whose vertex positions are
// `position`: per marker z_s - z_m with z_s from nearest_crossed_triangle over its
// mapped triangles at the frame's positions, summarized as summarize_misfit does
// (rms, max |.|, inside = the markers with a crossing). O(mapped triangles). This is
// Marker Misfit's VerticalMisfit exactly while each marker's (x, y) stays over the
// triangles mapped for it (always for an honoured marker, whose triangle is pinned, and
// for any pull that moves vertices along z only); when a frame moves a mapped triangle
// sideways off the marker, its plane is read extended.
MisfitSummary mapped_vertical_misfit(
  const MarkerCrossingMap& map, const std::function<Eigen::Vector3d(index_t)>& position);

} // namespace geoshaping
