#include "geoshaping/parallel/coordinate_ids.h"

#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/mesh/huge_pages.h"
#include "geoshaping/mesh/radix_sort.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace geoshaping
{

namespace
{
using Key = std::array<std::int64_t, 3>;

// An integer whose signed order is the numeric order of the finite double x (-0 = +0).
std::int64_t ordered_bits(double x)
{
  const std::int64_t b = bit_cast<std::int64_t>(x == 0.0 ? 0.0 : x);
  return b < 0 ? b ^ std::numeric_limits<std::int64_t>::max() : b;
}

void append(std::vector<std::int64_t>& out, const Key& k)
{
  out.insert(out.end(), k.begin(), k.end());
}

void append_keys(std::vector<Key>& out, const std::vector<std::int64_t>& flat)
{
  for (std::size_t i = 0; i + 2 < flat.size(); i += 3)
    out.push_back({ flat[i], flat[i + 1], flat[i + 2] });
}

void sort_unique(std::vector<Key>& keys)
{
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

std::size_t position(const std::vector<Key>& sorted, const Key& k)
{
  return std::size_t(std::lower_bound(sorted.begin(), sorted.end(), k) - sorted.begin());
}

std::vector<Key> keys_of(const double* xyz, index_t n)
{
  std::vector<Key> keys(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k)
      keys[std::size_t(v)][std::size_t(k)] = ordered_bits(xyz[3 * std::size_t(v) + std::size_t(k)]);
  return keys;
}
} // namespace

std::vector<std::int64_t> coordinate_ids(const double* xyz, index_t n, index_t* coincident)
{
  // The order of (x, y, z, v): a stable sort by x from the order of v, then each run of
  // equal x put in (y, z) order, stably. A run already in order stays; one in strictly
  // decreasing order is reversed (a DEM's columns, whose rows run north to south); any
  // other is sorted stably by z, then by y. The key of a coordinate as unsigned:
  // ordered_bits with its sign bit flipped.
  struct Record
  {
    std::uint64_t key;
    index_t v;
  };
  const auto key = [xyz](index_t v, int axis)
  {
    return std::uint64_t(ordered_bits(xyz[3 * std::size_t(v) + std::size_t(axis)])) ^
           (std::uint64_t(1) << 63);
  };
  const auto by_key = [](const Record& r) { return r.key; };
  std::vector<Record> order, scratch;
  fresh_huge(order, std::size_t(n));
  order.resize(std::size_t(n));
  for (index_t v = 0; v < n; ++v)
    order[std::size_t(v)] = { key(v, 0), v };
  radix_sort(order, scratch, by_key);
  std::vector<Record>().swap(scratch);
  std::vector<Record> run;
  const auto yz = [&key](index_t v) { return std::make_pair(key(v, 1), key(v, 2)); };
  for (std::size_t first = 0, last = 0; first < order.size(); first = last)
  {
    bool ascending = true, descending = true;
    auto previous = yz(order[first].v);
    for (last = first + 1; last < order.size() && order[last].key == order[first].key; ++last)
    {
      const auto next = yz(order[last].v);
      ascending = ascending && !(next < previous);
      descending = descending && next < previous;
      previous = next;
    }
    if (ascending)
      continue;
    if (descending)
    {
      std::reverse(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(last));
      continue;
    }
    run.assign(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(last));
    for (int axis = 2; axis >= 1; --axis)
    {
      for (Record& r : run)
        r.key = key(r.v, axis);
      radix_sort(run, scratch, by_key);
    }
    for (std::size_t i = first; i < last; ++i)
      order[i].v = run[i - first].v;
  }
  std::vector<std::int64_t> ids;
  fresh_huge(ids, std::size_t(n));
  ids.resize(std::size_t(n));
  index_t repeated = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    const index_t v = order[i].v;
    ids[std::size_t(v)] = std::int64_t(i);
    if (i > 0 && order[i - 1].key == order[i].key)
      repeated += yz(order[i - 1].v) == yz(v);
  }
  if (coincident)
    *coincident = repeated;
  return ids;
}

std::vector<std::int64_t> coordinate_ids(const double* xyz, index_t n, const std::uint8_t* claimed,
  std::vector<std::uint8_t>& owned, Exchange& exchange, index_t* coincident)
{
  const int pieces = exchange.pieces(), me = exchange.piece();
  const std::vector<Key> keys = keys_of(xyz, n);
  std::vector<Key> distinct(keys);
  sort_unique(distinct);

  // The same P - 1 splitters on every piece, from P regular samples of each piece.
  std::vector<std::int64_t> samples;
  for (int i = 0; i < pieces && !distinct.empty(); ++i)
    append(samples, distinct[std::size_t(i) * distinct.size() / std::size_t(pieces)]);
  std::vector<Key> pooled;
  for (const auto& s : exchange.all_gather(samples))
    append_keys(pooled, s);
  std::sort(pooled.begin(), pooled.end());
  std::vector<Key> splitters;
  for (int i = 1; i < pieces && !pooled.empty(); ++i)
    splitters.push_back(pooled[std::size_t(i) * pooled.size() / std::size_t(pieces)]);

  // Whether this piece claims each distinct key (any of its copies not a ghost).
  // And how many of its points are claimed at a position it already claims: ghosts are
  // left out (a ghost may be a copy of a point held here, see coordinate_ids.h).
  std::vector<std::uint8_t> claims(distinct.size(), 0);
  index_t repeated = 0;
  for (index_t v = 0; v < n; ++v)
    if (claimed[v])
    {
      std::uint8_t& c = claims[position(distinct, keys[std::size_t(v)])];
      repeated += c;
      c = 1;
    }
  if (coincident)
    *coincident = repeated;

  // Each key to the piece of its interval (contiguous runs of `distinct`, in order),
  // as (x, y, z, claimed).
  std::vector<std::vector<std::int64_t>> out(static_cast<std::size_t>(pieces));
  for (std::size_t d = 0; d < distinct.size(); ++d)
  {
    auto& box = out[std::size_t(
      std::upper_bound(splitters.begin(), splitters.end(), distinct[d]) - splitters.begin())];
    append(box, distinct[d]);
    box.push_back(claims[d]);
  }
  const auto received = exchange.all_to_all(out);
  std::vector<std::vector<Key>> asked(static_cast<std::size_t>(pieces));
  std::vector<Key> interval;
  for (int q = 0; q < pieces; ++q)
  {
    const auto& r = received[std::size_t(q)];
    for (std::size_t i = 0; i + 3 < r.size(); i += 4)
      asked[std::size_t(q)].push_back({ r[i], r[i + 1], r[i + 2] });
    interval.insert(interval.end(), asked[std::size_t(q)].begin(), asked[std::size_t(q)].end());
  }
  sort_unique(interval);
  // The lowest claiming piece owns a key (pieces are visited in increasing order).
  std::vector<int> owner(interval.size(), -1);
  for (int q = 0; q < pieces; ++q)
    for (std::size_t i = 0; i < asked[std::size_t(q)].size(); ++i)
    {
      int& o = owner[position(interval, asked[std::size_t(q)][i])];
      if (o < 0 && received[std::size_t(q)][4 * i + 3])
        o = q;
    }
  std::int64_t offset = 0;
  const auto counts = exchange.all_gather({ std::int64_t(interval.size()) });
  for (int q = 0; q < me; ++q)
    offset += counts[std::size_t(q)][0];

  // Number the interval, answer each sender in its order with (id, yours), read the
  // answers back.
  std::vector<std::vector<std::int64_t>> reply(static_cast<std::size_t>(pieces));
  for (int q = 0; q < pieces; ++q)
    for (const Key& k : asked[std::size_t(q)])
    {
      const std::size_t i = position(interval, k);
      reply[std::size_t(q)].push_back(offset + std::int64_t(i));
      reply[std::size_t(q)].push_back(owner[i] == q);
    }
  std::vector<std::int64_t> answers;
  for (const auto& answer : exchange.all_to_all(reply))
    answers.insert(answers.end(), answer.begin(), answer.end());

  // One owned copy per point this piece owns: the first copy it claims.
  std::vector<std::int64_t> ids(static_cast<std::size_t>(n));
  owned.assign(std::size_t(n), 0);
  std::vector<std::uint8_t> given(distinct.size(), 0);
  for (index_t v = 0; v < n; ++v)
  {
    const std::size_t d = position(distinct, keys[std::size_t(v)]);
    ids[std::size_t(v)] = answers[2 * d];
    if (answers[2 * d + 1] && claimed[v] && !given[d])
      owned[std::size_t(v)] = given[d] = 1;
  }
  return ids;
}

std::string coincident_points_refusal(index_t coincident, Exchange& exchange)
{
  std::int64_t total = 0;
  for (const auto& v : exchange.all_gather({ coincident }))
    total += v[0];
  if (total == 0)
    return {};
  return std::to_string(total) +
         " points share their coordinates with another point of their process (split nodes, "
         "e.g. the two sides of a fault): without point GlobalIds, processes cannot tell them "
         "from the copies of one point. Give the data point GlobalIds before distributing it "
         "(its point ids, docs/mpi.md \"Identity\")";
}

} // namespace geoshaping
