#pragma once
// "Snap to markers" (docs/markers.md, "Snap to markers"): the surface moved onto the
// markers through ChainMail, as one edit. O(markers x a ChainMail frame).
//
// The rule. The markers are taken in the map's order (MarkerCrossingMap: the inside
// markers, each with the triangles its vertical line crossed). For marker m:
//
//   1. its crossing on the current shape: the triangle nearest_crossed_triangle picks
//      among its mapped triangles (the plane of each at the shape's positions), at
//      c = (m_x, m_y, z);
//   2. the grasp g: the corner of that triangle nearest to c (3D distance; the first of
//      equally near ones) that is not pinned;
//   3. one ChainMail frame grasps g and moves it by m - x_g onto the marker, with the
//      caller's pins and every vertex already snapped pinned; the frame is committed into
//      the deformer's rest shape (ChainMailDeformer::commit), and g joins the pins.
//
// A marker is skipped (counted, nothing moved for it) when it has no crossing, when its
// triangle's three corners are pinned, or when the frame fails or does not bring the
// grasp all the way (an obstacle stopped it). What it guarantees: after the snap each
// snapped marker m is the position of its vertex g, within the rounding of x_g + (m - x_g)
// (a few ulps of the coordinates), and stays there through the later markers' frames
// (g is pinned), so the surface passes through it; the pulls move the surface around it
// as ChainMail moves it around a grasp.
//
// The deformer is left as it was (rest shape, pins); the result is the net displacement
// of every vertex the frames moved, for the caller to commit as one edit
// (EditSession::commit).
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/metrics/marker_pins.h"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace geoshaping
{

struct MarkerSnap
{
  std::vector<index_t> vertices;              // moved, in the order first moved
  std::vector<Eigen::Vector3d> displacements; // net, from the rest shape before the snap
  std::vector<index_t> grasps;                // the snapped markers' vertices
  std::size_t snapped = 0;                    // markers brought onto the surface
  std::size_t skipped = 0;                    // markers left as they were (above)
};

// `pins`: the vertices to keep during the snap (non-zero; empty or shorter: none beyond).
MarkerSnap snap_to_markers(
  ChainMailDeformer& deformer, const MarkerCrossingMap& map, const std::vector<std::uint8_t>& pins);

} // namespace geoshaping
