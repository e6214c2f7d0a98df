#include "geoshaping/paint/dab_union.h"
#include "geoshaping/paint/brush.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geoshaping
{

namespace
{
// Relative slack on the bounds that only choose which cells and centres to look at: the
// kept distances are brush_distance's own, compared with the radius exactly.
constexpr double slack = 1e-9;

bool key_less(const Eigen::Array3i& a, const Eigen::Array3i& b)
{
  return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]);
}

// Squared least and greatest distance from p to the box [lo, hi].
void box_distances(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
  double& least, double& greatest)
{
  least = greatest = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double out = std::max({ lo[i] - p[i], 0.0, p[i] - hi[i] });
    const double far = std::max(std::abs(p[i] - lo[i]), std::abs(p[i] - hi[i]));
    least += out * out;
    greatest += far * far;
  }
}

// Squared least distance between the boxes [a, b] and [c, d].
double box_gap(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
  const Eigen::Vector3d& d)
{
  return (c - b).cwiseMax(a - d).cwiseMax(0.0).squaredNorm();
}
} // namespace

void DabUnion::Buckets::build(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double reach,
  const std::vector<Eigen::Vector3d>& centres, const std::vector<std::size_t>& candidates)
{
  corner = lo.array() - reach;
  const Eigen::Array3d extent = (hi - lo).array() + 2.0 * reach;
  const double side = std::max(reach, extent.maxCoeff() / 16.0);
  inverse = 1.0 / side;
  dims = (extent * inverse).floor().cast<int>() + 1;
  start.assign(std::size_t(dims.prod()) + 1, 0);
  cell.resize(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
  {
    cell[i] = index(at(centres[candidates[i]]));
    ++start[cell[i] + 1];
  }
  for (std::size_t b = 1; b < start.size(); ++b)
    start[b] += start[b - 1];
  items.resize(candidates.size());
  fill.assign(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < candidates.size(); ++i)
    items[fill[cell[i]]++] = candidates[i];
}

VertexGrid::VertexGrid(const double* xyz, index_t n)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (index_t v = 0; v < n; ++v)
  {
    const Eigen::Map<const Eigen::Vector3d> p(xyz + 3 * std::size_t(v));
    if (p.allFinite())
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  if (!(lo.x() <= hi.x()))
    return; // no finite vertex
  // About n / 2 cells, whether the points fill a volume, a sheet or a line.
  const Eigen::Vector3d e = hi - lo;
  const double cells = std::max(1.0, 0.5 * double(n));
  const double sheet = std::max({ e.x() * e.y(), e.y() * e.z(), e.x() * e.z() });
  size_ = std::max({ std::cbrt(e.prod() / cells), std::sqrt(sheet / cells), e.maxCoeff() / cells });
  if (!(size_ > 0.0) || !std::isfinite(size_))
    size_ = 1.0;
  inverse_ = 1.0 / size_;
  origin_ = lo;
  for (int i = 0; i < 3; ++i)
    dims_[i] = int(std::min(std::floor(e[i] / size_), cells)) + 1;

  std::vector<std::int64_t> cell_of(std::size_t(n), -1);
  start_.assign(std::size_t(dims_.cast<std::int64_t>().prod()) + 1, 0);
  for (index_t v = 0; v < n; ++v)
  {
    const Eigen::Map<const Eigen::Vector3d> p(xyz + 3 * std::size_t(v));
    if (p.allFinite())
    {
      // cell_range's expression, so that a query finds the vertex in its range.
      int ijk[3];
      for (int i = 0; i < 3; ++i)
        ijk[i] = std::min(int((p[i] - origin_[i]) * inverse_), dims_[i] - 1); // >= 0
      cell_of[std::size_t(v)] = cell(ijk[0], ijk[1], ijk[2]);
      ++start_[std::size_t(cell_of[std::size_t(v)]) + 1];
    }
  }
  for (std::size_t c = 1; c < start_.size(); ++c)
    start_[c] += start_[c - 1];
  ids_.resize(std::size_t(start_.back()));
  std::vector<index_t> fill(start_.begin(), start_.end() - 1);
  for (index_t v = 0; v < n; ++v)
    if (cell_of[std::size_t(v)] >= 0)
      ids_[std::size_t(fill[std::size_t(cell_of[std::size_t(v)])]++)] = v;
}

bool VertexGrid::cell_range(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
  Eigen::Array3i& first, Eigen::Array3i& last) const
{
  for (int i = 0; i < 3; ++i)
  {
    // Floor of a monotone expression: a point inside [lo, hi] falls in a cell of the range.
    const double a = std::floor((lo[i] - origin_[i]) * inverse_);
    const double b = std::floor((hi[i] - origin_[i]) * inverse_);
    if (!(b >= 0.0) || !(a < double(dims_[i])))
      return false;
    first[i] = int(std::max(a, 0.0));
    last[i] = int(std::min(b, double(dims_[i] - 1)));
  }
  return true;
}

void DabUnion::compute(const VertexGrid& grid, const double* xyz,
  const std::vector<Eigen::Vector3d>& centres, double radius, bool exact,
  std::vector<index_t>& vertices, std::vector<double>& distances)
{
  vertices.clear();
  distances.clear();
  if (grid.empty() || !(radius > 0.0) || !std::isfinite(radius))
    return;
  const double reach = radius * (1.0 + slack);
  const double reach2 = reach * reach;
  const double inside2 = radius * radius * (1.0 - slack);
  const Eigen::Vector3d r = Eigen::Vector3d::Constant(reach);

  // Centres grouped in cubes of side max(radius, cell), keyed on the grid's cells; a
  // centre whose sphere misses the grid is dropped (keys stay within int).
  const double side = std::max(radius, grid.cell_size());
  const double ratio = side / grid.cell_size();
  std::vector<Eigen::Array3i> keys(centres.size());
  order_.clear();
  for (std::size_t i = 0; i < centres.size(); ++i)
  {
    Eigen::Array3i first, last;
    if (!grid.cell_range(centres[i] - r, centres[i] + r, first, last))
      continue;
    const Eigen::Array3i k = (grid.position(centres[i]) / ratio).floor().cast<int>();
    keys[i] = k;
    order_.push_back(i);
  }
  std::stable_sort(order_.begin(), order_.end(),
    [&](std::size_t a, std::size_t b) { return key_less(keys[a], keys[b]); });
  groups_.clear();
  for (std::size_t i = 0; i < order_.size(); ++i)
  {
    if (groups_.empty() || (groups_.back().key != keys[order_[i]]).any())
      groups_.push_back({ keys[order_[i]], i, i });
    groups_.back().end = i + 1;
  }

  // Mark the non-empty cells within the radius of each group's bounding box.
  if (marked_.size() != std::size_t(grid.cells()))
    marked_.assign(std::size_t(grid.cells()), 0);
  cells_.clear();
  for (Group& g : groups_)
  {
    g.lo = g.hi = centres[order_[g.begin]];
    for (std::size_t i = g.begin + 1; i < g.end; ++i)
    {
      g.lo = g.lo.cwiseMin(centres[order_[i]]);
      g.hi = g.hi.cwiseMax(centres[order_[i]]);
    }
    Eigen::Array3i first, last;
    if (!grid.cell_range(g.lo - r, g.hi + r, first, last))
      continue;
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i)
        {
          const std::int64_t c = grid.cell(i, j, k);
          if (!marked_[std::size_t(c)] && grid.begin(c) != grid.end(c))
          {
            marked_[std::size_t(c)] = 1;
            cells_.push_back(c);
          }
        }
  }
  std::sort(cells_.begin(), cells_.end());

  for (std::int64_t c : cells_)
  {
    marked_[std::size_t(c)] = 0;
    Eigen::Vector3d lo = Eigen::Map<const Eigen::Vector3d>(xyz + 3 * std::size_t(*grid.begin(c)));
    Eigen::Vector3d hi = lo;
    for (const index_t* v = grid.begin(c); v != grid.end(c); ++v)
    {
      const Eigen::Map<const Eigen::Vector3d> p(xyz + 3 * std::size_t(*v));
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    // The centres that can reach the cell, and the least greatest distance among them.
    candidates_.clear();
    double bound = std::numeric_limits<double>::infinity();
    std::size_t whole = centres.size(); // a centre reaching every vertex of the cell
    // The group around the cell first: with a Constant falloff one of its centres often
    // covers the whole cell, and the search stops there.
    const auto scan = [&](const Eigen::Array3i& key)
    {
      const auto g = std::lower_bound(groups_.begin(), groups_.end(), key,
        [](const Group& a, const Eigen::Array3i& b) { return key_less(a.key, b); });
      if (g == groups_.end() || (g->key != key).any() || box_gap(g->lo, g->hi, lo, hi) > reach2)
        return false;
      for (std::size_t i = g->begin; i < g->end; ++i)
      {
        double least, greatest;
        box_distances(centres[order_[i]], lo, hi, least, greatest);
        if (least > reach2)
          continue;
        candidates_.push_back(order_[i]);
        bound = std::min(bound, greatest);
        if (!exact && greatest <= inside2)
        {
          whole = order_[i];
          return true;
        }
      }
      return false;
    };
    const Eigen::Array3i home = (grid.position(0.5 * (lo + hi)) / ratio).floor().cast<int>();
    const Eigen::Array3i kfirst = (grid.position(lo - r) / ratio).floor().cast<int>();
    const Eigen::Array3i klast = (grid.position(hi + r) / ratio).floor().cast<int>();
    bool done = scan(home);
    for (int kz = kfirst[2]; kz <= klast[2] && !done; ++kz)
      for (int ky = kfirst[1]; ky <= klast[1] && !done; ++ky)
        for (int kx = kfirst[0]; kx <= klast[0] && !done; ++kx)
          if ((Eigen::Array3i(kx, ky, kz) != home).any())
            done = scan(Eigen::Array3i(kx, ky, kz));
    if (candidates_.empty())
      continue;
    if (whole != centres.size())
    {
      for (const index_t* v = grid.begin(c); v != grid.end(c); ++v)
      {
        vertices.push_back(*v);
        distances.push_back(brush_distance(xyz, *v, centres[whole]));
      }
      continue;
    }
    if (exact)
    {
      // Only a centre as near to the box as the nearest one's farthest can be nearest.
      const double keep = std::min(bound, radius * radius) * (1.0 + slack);
      candidates_.erase(std::remove_if(candidates_.begin(), candidates_.end(),
                          [&](std::size_t i)
                          {
                            double least, greatest;
                            box_distances(centres[i], lo, hi, least, greatest);
                            return least > keep;
                          }),
        candidates_.end());
    }
    buckets_.build(lo, hi, reach, centres, candidates_);
    for (const index_t* v = grid.begin(c); v != grid.end(c); ++v)
    {
      const Eigen::Map<const Eigen::Vector3d> p(xyz + 3 * std::size_t(*v));
      const Eigen::Array3i home = buckets_.at(p);
      double best = std::numeric_limits<double>::infinity();
      // The vertex's own bucket first (a Constant falloff stops at the first centre
      // within the radius), then the 26 around it: a centre within `reach` is in one.
      for (int n = 0; n < 28 && !(!exact && best <= radius); ++n)
      {
        const Eigen::Array3i b =
          n == 0 ? home
                 : home + Eigen::Array3i((n - 1) % 3 - 1, (n - 1) / 3 % 3 - 1, (n - 1) / 9 - 1);
        if (n == 14 || (b < 0).any() || (b >= buckets_.dims).any())
          continue; // n == 14 is the home bucket again
        for (std::uint32_t k = buckets_.start[buckets_.index(b)];
             k < buckets_.start[buckets_.index(b) + 1]; ++k)
        {
          best = std::min(best, brush_distance(xyz, *v, centres[buckets_.items[k]]));
          if (!exact && best <= radius)
            break;
        }
      }
      if (best <= radius)
      {
        vertices.push_back(*v);
        distances.push_back(best);
      }
    }
  }
}

} // namespace geoshaping
