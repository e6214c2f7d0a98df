// coordinate_ids (coordinate_ids.h) against a direct numbering: the rank of each
// point's (x, y, z) among the distinct coordinates of the whole point set, the same for
// any split into pieces, with copies of a point on several pieces (ghosts), coincident
// points, negative coordinates, -0 and an empty piece; and the owner of each point: the
// lowest piece that claims a copy of it (none when no piece claims it).
#include "geoshaping/parallel/coordinate_ids.h"
#include "geoshaping/parallel/in_process_exchange.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <thread>
#include <tuple>

using namespace geoshaping;

namespace
{
using Point = std::tuple<double, double, double>;

// Points on a coarse lattice (so many coincide), some negative, one at -0.
std::vector<Point> lattice_points(std::size_t count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> cell(-6, 6);
  std::vector<Point> points;
  for (std::size_t i = 0; i < count; ++i)
    points.emplace_back(0.25 * cell(rng), 1e6 + 0.5 * cell(rng), -3.0 * cell(rng));
  points.emplace_back(-0.0, 1e6, 0.0);
  points.emplace_back(0.0, 1e6, -0.0);
  return points;
}

struct Split
{
  std::vector<std::vector<std::size_t>> held;     // point indices, by piece
  std::vector<std::vector<std::uint8_t>> claimed; // by piece and local point
};

// Piece p holds the points `owner` gives it, claimed except every seventh, plus every
// fourth point of the next piece (copies, as ghosts are; every eighth claimed there
// too, as a seam point is); piece `empty` holds nothing.
Split split(std::size_t count, int pieces, unsigned seed, int empty = -1)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> owner(0, pieces - 1);
  Split s{ std::vector<std::vector<std::size_t>>(std::size_t(pieces)),
    std::vector<std::vector<std::uint8_t>>(std::size_t(pieces)) };
  for (std::size_t i = 0; i < count; ++i)
  {
    int p = owner(rng);
    if (p == empty)
      p = (p + 1) % pieces;
    s.held[std::size_t(p)].push_back(i);
    s.claimed[std::size_t(p)].push_back(i % 7 != 0);
    const int next = (p + 1) % pieces;
    if (i % 4 == 0 && next != empty && next != p)
    {
      s.held[std::size_t(next)].push_back(i);
      s.claimed[std::size_t(next)].push_back(i % 8 == 0);
    }
  }
  return s;
}

// ids[piece][local] from threads exchanging in process; owned[piece][local].
std::vector<std::vector<std::int64_t>> run(
  const std::vector<Point>& points, const Split& s, std::vector<std::vector<std::uint8_t>>& owned)
{
  const auto& held = s.held;
  const int pieces = int(held.size());
  InProcessHub hub(pieces);
  std::vector<std::vector<std::int64_t>> ids(held.size());
  owned.assign(held.size(), {});
  std::vector<std::thread> threads;
  for (int p = 0; p < pieces; ++p)
    threads.emplace_back(
      [&, p]
      {
        std::vector<double> xyz;
        for (std::size_t i : held[std::size_t(p)])
          xyz.insert(
            xyz.end(), { std::get<0>(points[i]), std::get<1>(points[i]), std::get<2>(points[i]) });
        InProcessExchange ex(hub, p);
        ids[std::size_t(p)] = coordinate_ids(xyz.data(), index_t(held[std::size_t(p)].size()),
          s.claimed[std::size_t(p)].data(), owned[std::size_t(p)], ex);
      });
  for (auto& t : threads)
    t.join();
  return ids;
}
} // namespace

TEST(CoordinateIds, IdsAreTheRanksOfTheDistinctCoordinatesForAnySplit)
{
  const std::vector<Point> points = lattice_points(3000, 7);
  std::map<Point, std::int64_t> rank; // std::less on doubles: -0 == +0
  for (const Point& x : points)
    rank.emplace(x, 0);
  std::int64_t next = 0;
  for (auto& entry : rank)
    entry.second = next++;
  ASSERT_LT(rank.size(), points.size()); // coincident points exist
  for (int pieces = 1; pieces <= 4; ++pieces)
    for (unsigned seed : { 1u, 2u })
    {
      const Split s = split(points.size(), pieces, seed, pieces == 3 ? 1 : -1);
      std::vector<std::vector<std::uint8_t>> owned;
      const auto ids = run(points, s, owned);
      // Expected owner of each distinct point: the lowest piece claiming a copy.
      std::map<Point, int> expected;
      for (int p = pieces - 1; p >= 0; --p)
        for (std::size_t l = 0; l < s.held[std::size_t(p)].size(); ++l)
          if (s.claimed[std::size_t(p)][l])
            expected[points[s.held[std::size_t(p)][l]]] = p;
      std::map<Point, int> owners; // how many owned copies each point has
      for (int p = 0; p < pieces; ++p)
      {
        ASSERT_EQ(ids[std::size_t(p)].size(), s.held[std::size_t(p)].size());
        for (std::size_t l = 0; l < s.held[std::size_t(p)].size(); ++l)
        {
          const Point& x = points[s.held[std::size_t(p)][l]];
          ASSERT_EQ(ids[std::size_t(p)][l], rank.at(x))
            << pieces << " pieces, seed " << seed << ", piece " << p << ", point " << l;
          if (owned[std::size_t(p)][l])
          {
            ++owners[x];
            EXPECT_EQ(expected.at(x), p) << "the lowest claiming piece owns a point";
          }
        }
      }
      for (const auto& e : expected)
        EXPECT_EQ(owners[e.first], 1) << "each claimed point has one owned copy";
      EXPECT_LT(expected.size(), rank.size()) << "some points are claimed by no piece";
    }
}

TEST(CoordinateIds, NoPointsAnywhereGivesNoIds)
{
  std::vector<std::vector<std::uint8_t>> owned;
  const auto ids = run({}, Split{ { {}, {}, {} }, { {}, {}, {} } }, owned);
  for (const auto& piece : ids)
    EXPECT_TRUE(piece.empty());
}

TEST(CoordinateIds, OnePieceNumbersDistinctPointsAsSeveralPiecesDo)
{
  // Distinct points (the lattice's repeats dropped), in a shuffled order.
  std::vector<Point> points = lattice_points(3000, 11);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::shuffle(points.begin(), points.end(), std::mt19937(5));
  std::vector<double> xyz;
  for (const Point& x : points)
    xyz.insert(xyz.end(), { std::get<0>(x), std::get<1>(x), std::get<2>(x) });
  index_t coincident = -1;
  const std::vector<std::int64_t> one =
    coordinate_ids(xyz.data(), index_t(points.size()), &coincident);
  EXPECT_EQ(coincident, 0);
  std::vector<std::vector<std::uint8_t>> owned;
  const Split s = split(points.size(), 3, 9);
  const auto ids = run(points, s, owned);
  for (int p = 0; p < 3; ++p)
    for (std::size_t l = 0; l < s.held[std::size_t(p)].size(); ++l)
      ASSERT_EQ(ids[std::size_t(p)][l], one[s.held[std::size_t(p)][l]]) << "piece " << p;
}

TEST(CoordinateIds, OnePieceKeepsCoincidentPointsApartInPointOrder)
{
  // Point 1 and 3 coincide (a split node), -0 and +0 too (points 4 and 5).
  const std::vector<double> xyz = { 2, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, -0.0, 5, 0, 0.0, 5, 0 };
  index_t coincident = -1;
  const std::vector<std::int64_t> ids = coordinate_ids(xyz.data(), 6, &coincident);
  EXPECT_EQ(coincident, 2);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{ 5, 3, 0, 4, 1, 2 }));
}

TEST(CoordinateIds, PiecesCountTheirOwnCoincidentPoints)
{
  // Piece 0 holds a split node (two claimed points at one position) and a copy of piece
  // 1's point; piece 1 holds nothing twice but ghost copies of piece 0's point 4 and of
  // its own point 3, which are copies, not split nodes.
  const std::vector<Point> points = { { 0, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 },
    { 3, 0, 0 } };
  const Split s{ { { 0, 1, 2, 4 }, { 2, 3, 3, 4, 4 } }, { { 1, 1, 0, 1 }, { 1, 1, 0, 0, 0 } } };
  InProcessHub hub(2);
  index_t counted[2] = { -1, -1 };
  std::vector<std::thread> threads;
  for (int p = 0; p < 2; ++p)
    threads.emplace_back(
      [&, p]
      {
        std::vector<double> xyz;
        for (std::size_t i : s.held[std::size_t(p)])
          xyz.insert(
            xyz.end(), { std::get<0>(points[i]), std::get<1>(points[i]), std::get<2>(points[i]) });
        std::vector<std::uint8_t> owned;
        InProcessExchange ex(hub, p);
        coordinate_ids(xyz.data(), index_t(s.held[std::size_t(p)].size()),
          s.claimed[std::size_t(p)].data(), owned, ex, &counted[p]);
      });
  for (auto& t : threads)
    t.join();
  EXPECT_EQ(counted[0], 1);
  EXPECT_EQ(counted[1], 0);
}

namespace
{
// coordinate_ids on one piece against std::sort of (x, y, z, point id), and its count of
// points coincident with an earlier one.
void expect_ranks_of_coordinates_then_point_ids(const std::vector<double>& xyz)
{
  const index_t n = index_t(xyz.size() / 3);
  std::vector<index_t> order(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    order[std::size_t(v)] = v;
  const auto point = [&xyz](index_t v)
  {
    // -0 == +0 as numbers: both compare as +0.
    const auto c = [&](int k) { return xyz[3 * std::size_t(v) + std::size_t(k)] + 0.0; };
    return std::make_tuple(c(0), c(1), c(2), v);
  };
  std::sort(order.begin(), order.end(), [&](index_t a, index_t b) { return point(a) < point(b); });
  index_t coincident = -1;
  const std::vector<std::int64_t> ids = coordinate_ids(xyz.data(), n, &coincident);
  index_t repeated = 0;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    ASSERT_EQ(ids[std::size_t(order[i])], std::int64_t(i));
    if (i > 0)
    {
      const auto a = point(order[i - 1]), b = point(order[i]);
      repeated += std::get<0>(a) == std::get<0>(b) && std::get<1>(a) == std::get<1>(b) &&
                  std::get<2>(a) == std::get<2>(b);
    }
  }
  EXPECT_EQ(coincident, repeated);
}
} // namespace

TEST(CoordinateIds, OnePieceIdsAreTheRanksOfCoordinatesThenPointIds)
{
  // Magnitudes from 1e-300 to 1e300 of both signs, zeros of both signs, repeats.
  std::mt19937 rng(21);
  std::uniform_int_distribution<int> pick(0, 40), exponent(-300, 300);
  std::vector<double> values;
  for (int i = 0; i < 40; ++i)
    values.push_back((i % 2 ? -1.0 : 1.0) * std::ldexp(1.0 + i / 64.0, exponent(rng)));
  values.insert(values.end(), { 0.0, -0.0 });
  std::vector<double> xyz;
  for (int i = 0; i < 3 * 5000; ++i)
    xyz.push_back(values[std::size_t(pick(rng))]);
  expect_ranks_of_coordinates_then_point_ids(xyz);
}

TEST(CoordinateIds, OnePieceNumbersGridColumnsInEitherRowOrder)
{
  // A DEM's grid (equal x down each column): rows north to south (each column's run in
  // decreasing y, reversed), south to north (already in order), and with a column that
  // is neither (a repeated point, a point out of place, -0 against +0).
  for (const bool north_first : { true, false })
  {
    std::vector<double> xyz;
    for (int r = 0; r < 30; ++r)
      for (int c = 0; c < 20; ++c)
        xyz.insert(xyz.end(), { 500000.0 + 10.0 * c, 4000000.0 + 10.0 * (north_first ? 29 - r : r),
                                300.0 + std::sin(0.7 * r + 0.3 * c) });
    expect_ranks_of_coordinates_then_point_ids(xyz);
    xyz.insert(
      xyz.end(), { 500000.0, 4000100.0, 300.0, 500000.0, 4000100.0, 300.0, 500000.0, 4000100.0,
                   299.0, 500000.0, 3999000.0, 0.0, 500000.0, 3999000.0, -0.0 });
    expect_ranks_of_coordinates_then_point_ids(xyz);
  }
}
