#pragma once
// Malleability painting: a brush dab moves the values under it toward its value.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/paint/dab_union.h"
#include "geoshaping/paint/progress.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
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

// Weight of a dab at normalised distance r = distance / radius: 1 within the brush's
// core, r <= brush_core, so that a dab of strength 1 paints its value itself there (a
// black stroke makes what its core covers rigid, 0, whatever the falloff); from the core
// to the rim the falloff's shape over t = (r - brush_core) / (1 - brush_core), 0 at and
// beyond r = 1 (except `constant`, which is 1 up to and including r = 1):
//
//   constant  1
//   linear    1 - t
//   smooth    1 - (3 t^2 - 2 t^3)                   (smoothstep, flat at both ends)
//   gaussian  (exp(-t^2 / 2s^2) - exp(-1 / 2s^2)) / (1 - exp(-1 / 2s^2)),  s = 1/3
//             (a Gaussian of sigma (rim - core)/3, shifted and rescaled so it reaches 0
//             at the rim instead of being cut off there)
constexpr double brush_core = 0.5;
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

// A stroke: consecutive dabs of one brush (equal radius, value and strength) whose
// centres follow a path, each at most one radius from the previous and not on it, as
// BrushStroke places them (geoshaping/paint/brush_stroke.h). A stroke paints each vertex once,
// with its strongest weight: for the distance d of the stroke's nearest centre (the
// distances of GeodesicReach in geodesic mode),
//
//   m = b + strength * falloff(d / radius) * (value - b),   b the value before the stroke,
//
// which is the weight of the strongest dab (every falloff is non-increasing). Where the
// dabs do not overlap this is apply_dab's value bit for bit; where they overlap, dabs
// applied one after the other would compound to 1 - prod(1 - w_i) instead of max(w_i).
// A dab that repeats the previous centre or jumps farther than its radius starts a new
// stroke, so a second click on the same spot paints again.
//
// The accumulator keeps the open stroke's distances and base values (sparse, reset
// sparsely), so dabs appended later continue it as if painted in one go.
class StrokeAccumulator
{
public:
  bool open() const { return open_; }
  const Dab& brush() const { return brush_; }                      // centre: the last dab's
  const std::vector<index_t>& members() const { return members_; } // in first-reach order
  // Whether `dab` continues the open stroke (then move() to its centre).
  bool continues(const Dab& dab) const;
  void move(const Eigen::Vector3d& centre) { brush_.center = centre; }
  // Closes the open stroke and opens one with `dab`'s brush (and this falloff).
  void begin(const Dab& dab, Falloff falloff);
  void end() { open_ = false; }
  // Lowers the stroke's distance of each vertex of `reach` (distances from a centre of
  // the stroke) and writes its value to m, appending the vertices written to `written`
  // when given. Returns the number of vertices the stroke reaches for the first time.
  std::size_t add(const Reach& reach, float* m, std::vector<index_t>* written = nullptr);

private:
  bool open_ = false;
  Dab brush_;
  Falloff falloff_ = Falloff::constant;
  std::vector<double> distance_; // +inf off the open stroke
  std::vector<float> base_;
  std::vector<index_t> members_;
};

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
  std::size_t painted = 0; // vertices painted (once per stroke reaching them)
  std::vector<std::pair<std::size_t, std::string>> rejected; // (dab index, reason)
};

// Paints `dabs` in order on `malleability` (n floats), stroke by stroke (see
// StrokeAccumulator). A rejected dab changes nothing; the others are painted as if it were
// absent (it does not break a stroke). Euclidean distance is measured from the
// dab centre; geodesic distance is the centre-to-nearest-vertex distance plus the
// GeodesicReach path from that vertex. Deterministic: the same input gives a
// bit-identical result. A Euclidean stroke costs the vertices it covers (DabUnion over a
// VertexGrid built on the first Euclidean paint), however many dabs it has.
class Painter
{
public:
  Painter(const double* xyz, index_t n, const Adjacency* adjacency, PointQueries queries);

  // `progress` (optional) is told the fraction of dabs done and can stop the painting
  // between strokes, and between the dabs of a geodesic stroke (geoshaping/paint/progress.h).
  PaintReport paint(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode,
    float* malleability, const Progress& progress = {});
  // Paints dabs appended to those of the last paint() or append() on the same array with
  // the same falloff and mode: their first stroke continues the last one when its dab
  // continues it, so the array is bit for bit what paint() of the whole list gives. The
  // vertices painted are appended to `touched`.
  PaintReport append(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode,
    float* malleability, std::vector<index_t>& touched);
  // The vertices one dab reaches, with distances (also used by paint()).
  void reach(const Dab& dab, DistanceMode mode, Reach& out);

private:
  PaintReport run(const std::vector<Dab>& dabs, Falloff falloff, DistanceMode mode, float* m,
    const Progress& progress, std::vector<index_t>* touched);

  const double* xyz_;
  index_t n_;
  const Adjacency* adjacency_;
  PointQueries queries_;
  GeodesicReach geodesic_;
  std::vector<index_t> ids_;
  Reach reach_;
  StrokeAccumulator stroke_;
  std::unique_ptr<VertexGrid> grid_;
  DabUnion union_;
  std::vector<Eigen::Vector3d> centres_;
};

} // namespace geoshaping
