#include "test_pieces.h"

#include "geoshaping/in_process_exchange.h"

#include <algorithm>
#include <random>
#include <set>
#include <thread>

namespace geoshaping::testing
{

std::vector<MeshPiece> split_mesh(const std::vector<double>& xyz, const Adjacency& adj,
  const std::vector<std::int64_t>& gid, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra, unsigned seed)
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
        if (local_of[std::size_t(*it)] >= 0)
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

void run_in_pieces(int pieces, const std::function<void(int, Exchange&)>& body)
{
  InProcessHub hub(pieces);
  std::vector<std::thread> threads;
  for (int p = 0; p < pieces; ++p)
    threads.emplace_back(
      [&, p]
      {
        InProcessExchange ex(hub, p);
        body(p, ex);
      });
  for (auto& t : threads)
    t.join();
}

} // namespace geoshaping::testing
