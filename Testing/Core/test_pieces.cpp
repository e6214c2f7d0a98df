#include "test_pieces.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>

namespace geoshaping::testing
{

std::vector<MeshPiece> split_mesh(const std::vector<double>& xyz, const Adjacency& adj,
  const std::vector<std::int64_t>& gid, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra, unsigned seed, GhostLinks links)
{
  const index_t n = index_t(xyz.size() / 3);
  std::mt19937 rng(seed);
  std::vector<MeshPiece> out(static_cast<std::size_t>(pieces));
  std::vector<index_t> local_of(static_cast<std::size_t>(n), -1);
  for (int p = 0; p < pieces; ++p)
  {
    std::set<index_t> local;
    for (index_t v = 0; v < n; ++v)
      if (owner[std::size_t(v)] == p)
      {
        local.insert(v);
        local.insert(adj.begin(v), adj.end(v));
      }
    if (std::size_t(p) < extra.size())
      local.insert(extra[std::size_t(p)].begin(), extra[std::size_t(p)].end());
    MeshPiece& piece = out[std::size_t(p)];
    piece.global.assign(local.begin(), local.end());
    std::shuffle(piece.global.begin(), piece.global.end(), rng);
    for (std::size_t i = 0; i < piece.global.size(); ++i)
      local_of[std::size_t(piece.global[i])] = index_t(i);
    piece.adjacency.offsets.push_back(0);
    std::vector<index_t> row;
    for (index_t v : piece.global)
    {
      piece.xyz.insert(piece.xyz.end(), &xyz[3 * std::size_t(v)], &xyz[3 * std::size_t(v)] + 3);
      row.clear();
      for (const index_t* it = adj.begin(v); it != adj.end(v); ++it)
        if (local_of[std::size_t(*it)] >= 0 &&
            (links == GhostLinks::all || owner[std::size_t(v)] == p ||
              owner[std::size_t(*it)] == p))
          row.push_back(local_of[std::size_t(*it)]);
      std::sort(row.begin(), row.end());
      piece.adjacency.neighbors.insert(piece.adjacency.neighbors.end(), row.begin(), row.end());
      piece.adjacency.offsets.push_back(std::int64_t(piece.adjacency.neighbors.size()));
      piece.gid.push_back(gid[std::size_t(v)]);
      piece.owned.push_back(owner[std::size_t(v)] == p);
    }
    for (index_t v : piece.global)
      local_of[std::size_t(v)] = -1;
  }
  return out;
}

std::vector<int> striped_owner(const std::vector<double>& xyz, int pieces)
{
  const std::size_t n = xyz.size() / 3;
  double lo = 1e300, hi = -1e300;
  for (std::size_t v = 0; v < n; ++v)
  {
    lo = std::min(lo, xyz[3 * v]);
    hi = std::max(hi, xyz[3 * v]);
  }
  std::vector<int> owner(n, 0);
  if (hi > lo)
    for (std::size_t v = 0; v < n; ++v)
      owner[v] = std::min(pieces - 1, int(double(pieces) * (xyz[3 * v] - lo) / (hi - lo)));
  return owner;
}

std::vector<int> random_owner(index_t n, const std::vector<int>& choices, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, choices.size() - 1);
  std::vector<int> owner(static_cast<std::size_t>(n));
  for (int& o : owner)
    o = choices[pick(rng)];
  return owner;
}

std::vector<std::int64_t> shuffled_ids(index_t n, unsigned seed)
{
  std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
  std::iota(gid.begin(), gid.end(), std::int64_t(0));
  std::shuffle(gid.begin(), gid.end(), std::mt19937(seed));
  for (auto& g : gid)
    g = 3 * g + 1000000007LL;
  return gid;
}

PaintedMesh painted_grid(index_t nx, index_t ny)
{
  PaintedMesh s;
  s.mesh = triangle_grid(nx, ny, 1.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (double& x : s.mesh.xyz)
    x += jitter(rng);
  s.malleability.resize(std::size_t(s.mesh.size()));
  s.pins.assign(s.malleability.size(), 0);
  for (index_t j = 0; j < ny; ++j)
    for (index_t i = 0; i < nx; ++i)
    {
      const double b = 0.5 + 0.5 * std::sin(0.3 * i) * std::cos(0.25 * j);
      float m = float(0.2 + 0.1 * std::floor(b * 7.999));
      if (i >= nx / 3 && i < nx / 3 + 6 && j >= ny / 2 && j < ny / 2 + 5)
        m = 0.0f;
      s.malleability[std::size_t(j * nx + i)] = m;
      if (j == ny / 4 && i > 3 && i < nx - 4)
        s.pins[std::size_t(j * nx + i)] = 1;
    }
  s.gid = shuffled_ids(s.mesh.size(), 17);
  return s;
}

PaintedMesh tet_slab(index_t nx, index_t ny, index_t nz)
{
  PaintedMesh s;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (index_t k = 0; k < nz; ++k)
    for (index_t j = 0; j < ny; ++j)
      for (index_t i = 0; i < nx; ++i)
        for (double c : { double(i), double(j), 0.5 * double(k) })
          s.mesh.xyz.push_back(5e5 + c + jitter(rng));
  const index_t n = nx * ny * nz;
  AdjacencyBuilder builder(n);
  auto id = [&](index_t i, index_t j, index_t k) { return std::int64_t((k * ny + j) * nx + i); };
  for (index_t k = 0; k + 1 < nz; ++k)
    for (index_t j = 0; j + 1 < ny; ++j)
      for (index_t i = 0; i + 1 < nx; ++i)
      {
        // The six tetrahedra of a cube around its main diagonal.
        const std::int64_t c[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        const int tets[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
          { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
        for (const auto& t : tets)
        {
          const std::int64_t ids[4] = { c[t[0]], c[t[1]], c[t[2]], c[t[3]] };
          builder.add_cell(CellKind::tetra, ids, 4);
        }
      }
  s.mesh.adjacency = builder.build();
  s.malleability.resize(std::size_t(n));
  std::uniform_int_distribution<int> band(0, 4);
  for (float& m : s.malleability)
    m = 0.25f * float(band(rng));
  s.pins.assign(std::size_t(n), 0);
  s.pins[std::size_t(id(nx / 2, 1, 0))] = 1;
  s.gid = shuffled_ids(n, 23);
  return s;
}

std::vector<PaintedPiece> split(const PaintedMesh& m, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra, unsigned seed, GhostLinks links)
{
  std::vector<PaintedPiece> out;
  for (MeshPiece& piece :
    split_mesh(m.mesh.xyz, m.mesh.adjacency, m.gid, owner, pieces, extra, seed, links))
  {
    PaintedPiece painted{ std::move(piece), {}, {} };
    painted.pins = painted.gather(m.pins);
    painted.malleability = painted.gather(m.malleability);
    out.push_back(std::move(painted));
  }
  return out;
}

} // namespace geoshaping::testing
