#include "geoshaping/edit/marker_snap.h"

#include <limits>

namespace geoshaping
{

MarkerSnap snap_to_markers(
  ChainMailDeformer& deformer, const MarkerCrossingMap& map, const std::vector<std::uint8_t>& pins)
{
  MarkerSnap snap;
  const std::size_t n = std::size_t(deformer.size());
  std::vector<std::uint8_t> before(n), mask(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    before[v] = deformer.pinned(index_t(v)) ? 1 : 0;
    mask[v] = v < pins.size() && pins[v] ? 1 : 0;
  }
  std::vector<std::uint8_t> touched(n);
  std::vector<Eigen::Vector3d> oldRest, oldOffset;
  deformer.reset();
  const auto position = [&deformer](index_t v) { return deformer.position(v); };
  for (std::size_t i = 0; i < map.size(); ++i)
  {
    const Eigen::Vector3d m(map.xyz.data() + 3 * i);
    const index_t* corners = map.corners.data() + map.first[i];
    double z = 0.0;
    const std::ptrdiff_t t =
      nearest_crossed_triangle(m, corners, map.first[i + 1] - map.first[i], position, z);
    index_t grasp = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; t >= 0 && k < 3; ++k)
    {
      const index_t v = corners[t + k];
      const double d = (position(v) - Eigen::Vector3d(m.x(), m.y(), z)).squaredNorm();
      if (!mask[std::size_t(v)] && d < nearest)
      {
        nearest = d;
        grasp = v;
      }
    }
    if (grasp < 0)
    {
      ++snap.skipped;
      continue;
    }
    deformer.set_pinned(mask.data());
    const FrameResult frame = deformer.deform(grasp, m - position(grasp));
    if (!frame.ok || frame.grasp_fraction < 1.0)
    {
      deformer.reset();
      ++snap.skipped;
      continue;
    }
    for (const index_t v : deformer.moved())
      if (!touched[std::size_t(v)])
      {
        touched[std::size_t(v)] = 1;
        snap.vertices.push_back(v);
        oldRest.push_back(deformer.rest_local(v));
        oldOffset.push_back(deformer.committed_offset(v));
      }
    deformer.commit();
    mask[std::size_t(grasp)] = 1;
    snap.grasps.push_back(grasp);
    ++snap.snapped;
  }
  // The net displacements, and the deformer back to its rest shape and pins.
  deformer.reset();
  for (std::size_t k = 0; k < snap.vertices.size(); ++k)
  {
    const index_t v = snap.vertices[k];
    snap.displacements.push_back(deformer.rest_local(v) - oldRest[k]);
    deformer.set_rest(v, oldRest[k], oldOffset[k]);
  }
  deformer.set_pinned(before.data());
  return snap;
}

} // namespace geoshaping
