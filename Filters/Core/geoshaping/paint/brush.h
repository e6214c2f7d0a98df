#pragma once
// Malleability painting: a brush dab moves the values under it toward its value.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/paint/progress.h"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace geoshaping
{

// The brush's distances, one definition (the partitioned geodesic, partitioned_geodesic.h,
// must compute the same bits): from vertex v to p, and the length of the edge (a, b).
inline double brush_distance(const double* xyz, index_t v, const Eigen::Vector3d& p)
{
  const double* q = xyz + 3 * std::size_t(v);
  return (Eigen::Vector3d(q[0], q[1], q[2]) - p).norm();
}

inline double brush_edge_length(const double* xyz, index_t a, index_t b)
{
  const double* p = xyz + 3 * std::size_t(a);
  return brush_distance(xyz, b, Eigen::Vector3d(p[0], p[1], p[2]));
}

// Weight of a dab at normalised distance r = distance / radius, 1 at the centre and 0
// at and beyond r = 1 (except `constant`, which is 1 up to and including r = 1):
//
//   constant  1
//   linear    1 - r
//   smooth    1 - (3 r^2 - 2 r^3)                   (smoothstep, flat at both ends)
//   gaussian  (exp(-r^2 / 2s^2) - exp(-1 / 2s^2)) / (1 - exp(-1 / 2s^2)),  s = 1/3
//             (a Gaussian of sigma radius/3, shifted and rescaled so it reaches 0 at
//             the rim instead of being cut off there)
enum class Falloff
{
  constant,
  linear,
  smooth,
  gaussian
};

enum class DistanceMode
{
  euclidean, // straight-line distance: the brush is a sphere
  geodesic   // shortest path along mesh edges: the brush follows the surface
};

const char* falloff_name(Falloff f);
const char* distance_mode_name(DistanceMode m);

double falloff_weight(Falloff f, double r);

// The black-body heat map's colour at malleability m (RGB in [0, 1]): linear in RGB
// between the preset's control points (geoshaping/paint/malleability_preset.h), as ParaView maps
// it; m is clamped to [0, 1] and NaN reads as 0 (rigid, black).
Eigen::Vector3d malleability_color(double m);

struct Dab
{
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 1.0;
  double value = 1.0;    // target malleability, in [0, 1]
  double strength = 1.0; // fraction of the way to `value` at the centre, in [0, 1]
};

// Why a dab cannot be applied ("" when it can): a non-finite number, a negative
// radius, a value or strength outside [0, 1]. A radius of 0 is valid and paints nothing.
const char* validate_dab(const Dab& dab);

// The vertices a dab reaches and their distances from its centre.
struct Reach
{
  std::vector<index_t> vertices;
  std::vector<double> distances;
  void clear()
  {
    vertices.clear();
    distances.clear();
  }
};

// For every reached vertex v with d = distance / radius:
//   m[v] += strength * falloff(d) * (value - m[v])
// computed in double and stored as float, clamped to [0, 1]. Touches only `reach`.
void apply_dab(const Dab& dab, Falloff falloff, const Reach& reach, float* malleability);

// Graph distance along mesh edges (each edge weighted by its rest length) from a source
// vertex that lies `start_distance` from the dab centre, bounded by `radius`: Dijkstra
// that never records a vertex farther than `radius`, so its cost is proportional to the
// vertices within the radius (and their edges), not to the mesh. The path along edges
// is an upper bound on the true distance over the surface: exact along mesh lines, up
// to sqrt(2) longer across the diagonals of a regular triangle grid, so a geodesic
// brush on such a grid is a rounded diamond rather than a disc. It never crosses a gap
// between unconnected parts, which is the point: a brush on one side of a fault or a
// tight fold leaves the other side alone.
// Scratch arrays are kept between calls and reset sparsely.
class GeodesicReach
{
public:
  void compute(const Adjacency& adjacency, const double* xyz, index_t source, double start_distance,
    double radius, Reach& out);

private:
  std::vector<double> distance_; // +inf except for the vertices of the last call
  std::vector<index_t> touched_;
  struct Item
  {
    double distance;
    index_t vertex;
    bool operator>(const Item& o) const
    {
      return distance > o.distance || (distance == o.distance && vertex > o.vertex);
    }
  };
  std::vector<Item> heap_;
};

// Spatial queries a painter needs; the VTK filter answers them with a point locator.
struct PointQueries
{
  // The vertex nearest to a position (-1 when the mesh is empty).
  std::function<index_t(const Eigen::Vector3d&)> nearest;
  // The vertices within a distance of a position (inclusive), any order.
  std::function<void(const Eigen::Vector3d&, double, std::vector<index_t>&)> within;
};

// Brute-force queries scanning every vertex: for small meshes and tests.
PointQueries brute_force_queries(const double* xyz, index_t n);

struct PaintReport
{
  bool aborted = false; // the Progress asked to stop: dabs from `applied` on were not applied
  std::size_t applied = 0;
  std::size_t painted = 0; // vertex values written (a vertex under two dabs counts twice)
  std::vector<std::pair<std::size_t, std::string>> rejected; // (dab index, reason)
};

// Applies `dabs` in order to `malleability` (n floats). A rejected dab changes nothing;
// the others are applied as if it were absent. Euclidean distance is measured from the
// dab centre; geodesic distance is the centre-to-nearest-vertex distance plus the
// GeodesicReach path from that vertex. Deterministic: the same input gives a
// bit-identical result.
class Painter
{
public:
  Painter(const double* xyz, index_t n, const Adjacency* adjacency, PointQueries queries);

  // `progress` (optional) is told the fraction of dabs done and can stop the painting
  // between dabs (geoshaping/paint/progress.h).
  PaintReport paint(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode,
    float* malleability, const Progress& progress = {});
  // The vertices one dab reaches, with distances (also used by paint()).
  void reach(const Dab& dab, DistanceMode mode, Reach& out);

private:
  const double* xyz_;
  index_t n_;
  const Adjacency* adjacency_;
  PointQueries queries_;
  GeodesicReach geodesic_;
  std::vector<index_t> ids_;
  Reach reach_;
};

} // namespace geoshaping
