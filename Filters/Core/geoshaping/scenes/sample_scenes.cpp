#include "geoshaping/scenes/sample_scenes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping
{

namespace
{
using Profile = std::vector<Eigen::Vector2d>; // (x, z) polyline

double smoothstep(double t)
{
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double step_start(const FaultStepParams& p)
{
  return p.step_position * p.length - 0.5 * p.step_run;
}

// Dense polyline of the fault-step profile, exact on the flats.
Profile fault_step_profile(const FaultStepParams& p)
{
  const double x0 = step_start(p);
  Profile dense;
  dense.emplace_back(0.0, p.throw_height);
  const int samples = 4096;
  for (int i = 0; i <= samples; ++i)
  {
    const double x = x0 + p.step_run * i / samples;
    if (x > 0.0 && x < p.length)
      dense.emplace_back(x, p.throw_height * (1.0 - smoothstep((x - x0) / p.step_run)));
  }
  dense.emplace_back(p.length, 0.0);
  return dense;
}

std::vector<double> cumulative_length(const Profile& dense)
{
  std::vector<double> s(dense.size(), 0.0);
  for (std::size_t i = 1; i < dense.size(); ++i)
    s[i] = s[i - 1] + (dense[i] - dense[i - 1]).norm();
  return s;
}

// Points every `spacing` (rounded so both ends are hit) in arc length along `dense`.
Profile resample(const Profile& dense, double spacing)
{
  const std::vector<double> s = cumulative_length(dense);
  const index_t n = std::max<index_t>(2, index_t(std::lround(s.back() / spacing)) + 1);
  Profile out;
  std::size_t seg = 0;
  for (index_t i = 0; i < n; ++i)
  {
    const double target = s.back() * i / (n - 1);
    while (seg + 2 < dense.size() && s[seg + 1] < target)
      ++seg;
    const double len = s[seg + 1] - s[seg];
    const double t = len > 0.0 ? std::clamp((target - s[seg]) / len, 0.0, 1.0) : 0.0;
    out.push_back(dense[seg] + t * (dense[seg + 1] - dense[seg]));
  }
  return out;
}

index_t rows(double width, double spacing)
{
  return std::max<index_t>(2, index_t(std::lround(width / spacing)) + 1);
}

// Profile columns x rows along y, `layers` + 1 vertex layers `dz` apart downward.
SampleMesh extrude(const Profile& columns, double width, double spacing, index_t layers, double dz,
  const Eigen::Vector3d& origin)
{
  const index_t nu = index_t(columns.size()), nv = rows(width, spacing), nk = layers + 1;
  SampleMesh m;
  m.xyz.reserve(std::size_t(3) * nu * nv * nk);
  for (index_t k = 0; k < nk; ++k)
    for (index_t j = 0; j < nv; ++j)
      for (index_t i = 0; i < nu; ++i)
        m.xyz.insert(m.xyz.end(), { origin.x() + columns[i].x(), origin.y() + width * j / (nv - 1),
                                    origin.z() + columns[i].y() - dz * k });
  auto id = [&](index_t i, index_t j, index_t k) { return (k * nv + j) * nu + i; };
  if (layers == 0)
  {
    for (index_t j = 0; j + 1 < nv; ++j)
      for (index_t i = 0; i + 1 < nu; ++i)
        m.connectivity.insert(
          m.connectivity.end(), { id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j, 0),
                                  id(i + 1, j + 1, 0), id(i, j + 1, 0) });
    return m;
  }
  m.cell_size = 4;
  const int axes[6][2] = { { 0, 1 }, { 0, 2 }, { 1, 0 }, { 1, 2 }, { 2, 0 }, { 2, 1 } };
  auto point = [&](index_t v) { return Eigen::Map<const Eigen::Vector3d>(&m.xyz[3 * v]); };
  for (index_t k = 0; k < layers; ++k)
    for (index_t j = 0; j + 1 < nv; ++j)
      for (index_t i = 0; i + 1 < nu; ++i)
        for (const auto& ax : axes)
        {
          // Path 000 -> e_a -> e_a + e_b -> 111 through the hexahedron (Kuhn).
          index_t c[3] = { i, j, k };
          index_t t[4];
          t[0] = id(c[0], c[1], c[2]);
          ++c[ax[0]];
          t[1] = id(c[0], c[1], c[2]);
          ++c[ax[1]];
          t[2] = id(c[0], c[1], c[2]);
          t[3] = id(i + 1, j + 1, k + 1);
          const Eigen::Vector3d a = point(t[1]) - point(t[0]), b = point(t[2]) - point(t[0]),
                                d = point(t[3]) - point(t[0]);
          if (a.cross(b).dot(d) < 0.0) // VTK orders a tetra with positive volume
            std::swap(t[1], t[2]);
          m.connectivity.insert(m.connectivity.end(), t, t + 4);
        }
  return m;
}

bool positive(double v)
{
  return std::isfinite(v) && v > 0.0;
}
} // namespace

Adjacency SampleMesh::adjacency() const
{
  AdjacencyBuilder builder(num_points());
  const CellKind kind = cell_size == 4 ? CellKind::tetra : CellKind::triangle;
  std::vector<std::int64_t> ids(static_cast<std::size_t>(cell_size));
  for (std::size_t c = 0; c < num_cells(); ++c)
  {
    std::copy_n(&connectivity[c * cell_size], cell_size, ids.begin());
    builder.add_cell(kind, ids.data(), cell_size);
  }
  return builder.build();
}

const char* validate(const FaultStepParams& p)
{
  if (!positive(p.length) || !positive(p.width) || !positive(p.spacing))
    return "length, width and spacing must be positive";
  if (!std::isfinite(p.throw_height) || !positive(p.step_run))
    return "the throw must be finite and the step run positive";
  if (!(p.step_position >= 0.0 && p.step_position <= 1.0))
    return "the step position must lie in [0, 1]";
  if (!positive(p.thickness) || p.layers < 1)
    return "the slab needs a positive thickness and at least one layer";
  if (!p.origin.allFinite())
    return "the origin must be finite";
  const double arc = p.length + std::abs(p.throw_height) + p.step_run;
  const double points = (arc / p.spacing + 2.0) * (p.width / p.spacing + 2.0) * (p.layers + 1);
  if (points > double(std::numeric_limits<index_t>::max()))
    return "the mesh would have more than 2^31 - 1 vertices";
  return "";
}

index_t fault_step_columns(const FaultStepParams& p)
{
  return *validate(p) ? 0 : index_t(resample(fault_step_profile(p), p.spacing).size());
}

SampleMesh fault_step_horizon(const FaultStepParams& p)
{
  if (*validate(p))
    return {};
  return extrude(resample(fault_step_profile(p), p.spacing), p.width, p.spacing, 0, 0.0, p.origin);
}

SampleMesh fault_step_slab(const FaultStepParams& p)
{
  if (*validate(p))
    return {};
  return extrude(resample(fault_step_profile(p), p.spacing), p.width, p.spacing, p.layers,
    p.thickness / p.layers, p.origin);
}

std::vector<Dab> fault_step_painting(const FaultStepParams& p, double border)
{
  if (*validate(p))
    return {};
  // Dab centres on the step surface, a grid `pitch` apart in arc length and along y.
  const double x0 = step_start(p);
  Profile step;
  for (const Eigen::Vector2d& q : fault_step_profile(p))
    if (q.x() >= x0 && q.x() <= x0 + p.step_run)
      step.push_back(q);
  auto dabs_on_step = [&](double radius, double pitch, double value, std::vector<Dab>& out)
  {
    const Profile across = resample(step, pitch);
    const index_t nv = rows(p.width, pitch);
    // Back and forth along y, so that each colour is one stroke (brush.h): every centre
    // within a pitch (less than the radius) of the previous one.
    for (std::size_t a = 0; a < across.size(); ++a)
      for (index_t k = 0; k < nv; ++k)
      {
        const Eigen::Vector2d& q = across[a];
        const index_t j = a % 2 ? nv - 1 - k : k;
        Dab d;
        d.center = p.origin + Eigen::Vector3d(q.x(), p.width * j / (nv - 1), q.y());
        d.radius = radius;
        d.value = value;
        d.strength = 1.0;
        out.push_back(d);
      }
  };
  // Pitches well under the radii keep the scallops between neighbouring spheres
  // (their sagitta) below a tenth of the spacing.
  const double black = 2.0 * p.spacing; // reaches past the rows next to the step
  std::vector<Dab> dabs;
  if (border > 0.0)
    dabs_on_step(black + border, 3.0 * p.spacing, 1.0, dabs);
  dabs_on_step(black, p.spacing, 0.0, dabs);
  return dabs;
}

std::vector<float> fault_step_malleability(
  const SampleMesh& mesh, const FaultStepParams& p, double border)
{
  std::vector<float> m(std::size_t(mesh.num_points()), float(fault_step_red));
  Painter painter(mesh.xyz.data(), mesh.num_points(), nullptr,
    brute_force_queries(mesh.xyz.data(), mesh.num_points()));
  painter.paint(
    fault_step_painting(p, border), Falloff::constant, DistanceMode::euclidean, m.data());
  return m;
}

SampleMesh tight_fold(double length, double width, double gap, double spacing)
{
  if (!positive(length) || !positive(width) || !positive(gap) || !positive(spacing))
    return {};
  Profile dense{ { 0.0, gap } };
  const int samples = 512;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= samples; ++i)
  {
    const double a = pi * i / samples; // from the top of the hinge round to its bottom
    dense.emplace_back(length + 0.5 * gap * std::sin(a), 0.5 * gap * (1.0 + std::cos(a)));
  }
  dense.emplace_back(0.0, 0.0);
  return extrude(resample(dense, spacing), width, spacing, 0, 0.0, Eigen::Vector3d::Zero());
}

} // namespace geoshaping
