#include "geoshaping/parallel/partitioned_geodesic.h"

#include "geoshaping/mesh/bit_cast.h"

#include <limits>

namespace geoshaping
{

namespace
{
constexpr auto distance = brush_distance; // brush.h: the same bits as the brush
constexpr auto edge_length = brush_edge_length;
} // namespace

void PartitionedGeodesic::set_piece(const double* xyz, index_t n, const Adjacency* adjacency,
  const std::int64_t* gid, const std::uint8_t* owned, Exchange& exchange)
{
  xyz_ = xyz;
  adjacency_ = adjacency;
  pieces_.set_piece(n, gid, owned, exchange);
  distance_.begin(std::size_t(n));
}

void PartitionedGeodesic::compute(
  const Eigen::Vector3d& center, double radius, index_t candidate, Reach& out, Exchange& exchange)
{
  out.clear();
  supersteps_ = 0;
  source_ = -1;
  // The source: the least (distance, global id) of the pieces' candidates.
  const bool any = candidate >= 0 && candidate < pieces_.size();
  const double mine = any ? distance(xyz_, candidate, center) : 0.0;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : exchange.all_gather(
         { any ? 1 : 0, bit_cast<std::int64_t>(mine), any ? pieces_.gid(candidate) : 0 }))
  {
    const double d = bit_cast<double>(c[1]);
    if (c[0] && (source_ < 0 || d < best || (d == best && c[2] < source_)))
    {
      best = d;
      source_ = c[2];
    }
  }
  distance_.begin(std::size_t(pieces_.size()));
  if (source_ < 0 || !(radius > 0.0) || !(best <= radius))
    return; // the same decision on every piece: no superstep
  std::vector<index_t> seeds, dirty;
  const index_t s = pieces_.local(source_);
  if (s >= 0)
  {
    distance_.set(s, distance(xyz_, s, center));
    seeds.push_back(s);
    if (pieces_.owned(s))
      dirty.push_back(s);
  }
  const auto label = [&](index_t v)
  {
    return distance_.has(v) ? distance_.value[std::size_t(v)]
                            : std::numeric_limits<double>::infinity();
  };
  const Adjacency& adj = *adjacency_;
  supersteps_ = pieces_.correct(
    distance_, label,
    [&](index_t b, double d, const auto& lower)
    {
      if (b >= adj.size())
        return;
      for (const index_t* a = adj.begin(b); a != adj.end(b); ++a)
        lower(*a, d + edge_length(xyz_, b, *a));
    },
    [radius](index_t, double d) { return d <= radius; }, seeds, dirty, exchange);
  for (index_t v : distance_.touched)
  {
    out.vertices.push_back(v);
    out.distances.push_back(distance_.value[std::size_t(v)]);
  }
  // Copies of a vertex follow it.
  for (const auto& [copy, rep] : pieces_.aliases())
    if (distance_.has(rep))
    {
      out.vertices.push_back(copy);
      out.distances.push_back(distance_.value[std::size_t(rep)]);
    }
}

} // namespace geoshaping
