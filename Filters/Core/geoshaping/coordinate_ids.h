#pragma once
// Global point ids from coordinates alone, for a mesh split into pieces that carries
// none (docs/mpi.md, "Identity"): the same ids for any number of pieces and any
// partition, so ChainMail's order (which the global ids decide) and its result are too.
//
//   id(x) = #{ distinct keys k in the union of all pieces : k < key(x) },
//   key(x) = (x, y, z) compared lexicographically as numbers (-0 = +0).
//
// So every copy of a point (owned or ghost, on any piece) gets the same id, coincident
// points get one id (a split node's two sides become one vertex: give such meshes their
// own GlobalIds), and the ids are 0 .. distinct - 1 in coordinate order whatever the
// partition, because the set of distinct keys is the whole mesh's.
//
// Distributed as a sample sort over the pieces (P of them, n points here, N in all):
//   1. each piece sorts its distinct keys (O(n log n));
//   2. each gathers P regular samples of every piece's keys and takes the same P - 1
//      splitters (O(P^2) data);
//   3. all_to_all sends each key to the piece owning its splitter interval; that piece
//      merges and deduplicates them (its distinct count c_p) and, with the offsets
//      sum_{q < p} c_q from one all_gather, numbers them;
//   4. all_to_all returns the ids in the order the keys came, so a piece reads its
//      keys' ids back in its own sorted order.
// Cost: O(n log n) per piece and O(n) bytes sent, once per mesh (setup, not per frame).
// Coordinates must be finite (the caller refuses others).
//
// Ownership comes with the ids: without global ids a partition may leave a point on a
// seam between pieces claimed (not a ghost) by every piece whose cells use it; the
// piece that numbers its key gives it to the lowest piece that claims it (none: owned
// by no piece, which set_piece refuses). A claiming piece holds the point's whole ring
// (one ghost level around its own cells), so any claimant computes it alike.
#include "geoshaping/partitioned_chainmail.h"

#include <cstdint>
#include <vector>

namespace geoshaping
{

// Collective. The ids of the `n` points xyz of this piece (see above); `claimed[v]`
// non-zero when this piece's data does not mark v as a ghost, `owned[v]` set to whether
// this piece owns v (for one of the copies of each point claimed here).
std::vector<std::int64_t> coordinate_ids(const double* xyz, index_t n, const std::uint8_t* claimed,
  std::vector<std::uint8_t>& owned, Exchange& exchange);

} // namespace geoshaping
