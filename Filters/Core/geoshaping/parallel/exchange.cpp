#include "geoshaping/parallel/exchange.h"

namespace geoshaping
{

std::vector<std::vector<std::int64_t>> Exchange::all_to_all(
  const std::vector<std::vector<std::int64_t>>& out)
{
  // [length for piece 0, ..., length for piece P - 1, the data for 0, 1, ...]
  std::vector<std::int64_t> flat;
  for (const auto& o : out)
    flat.push_back(std::int64_t(o.size()));
  for (const auto& o : out)
    flat.insert(flat.end(), o.begin(), o.end());
  const std::size_t me = std::size_t(piece());
  std::vector<std::vector<std::int64_t>> in;
  for (const auto& f : all_gather(flat))
  {
    const std::size_t pieces = out.size();
    std::size_t begin = pieces;
    for (std::size_t q = 0; q < me; ++q)
      begin += std::size_t(f[q]);
    in.emplace_back(
      f.begin() + std::ptrdiff_t(begin), f.begin() + std::ptrdiff_t(begin + std::size_t(f[me])));
  }
  return in;
}

std::vector<RoundState> Exchange::all_round_states(const RoundState& state)
{
  std::vector<RoundState> out;
  for (const auto& w : all_gather({ std::int64_t(state.pending[0]), std::int64_t(state.pending[1]),
         std::int64_t(state.pending[2]), std::int64_t(state.pending[3]),
         std::int64_t(state.superstep) }))
    out.push_back(
      { { std::uint64_t(w[0]), std::uint64_t(w[1]), std::uint64_t(w[2]), std::uint64_t(w[3]) },
        std::uint64_t(w[4]) });
  return out;
}

} // namespace geoshaping
