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

} // namespace geoshaping
