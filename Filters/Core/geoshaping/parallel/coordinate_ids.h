#pragma once
// Global point ids from coordinates alone, for a mesh split into pieces that carries
// none (docs/mpi.md, "Identity"): the same ids for any number of pieces and any
// partition, so ChainMail's order (which the global ids decide) and its result are too.
//
//   id(x) = #{ distinct keys k in the union of all pieces : k < key(x) },
//   key(x) = (x, y, z) compared lexicographically as numbers (-0 = +0).
//
// So every copy of a point (owned or ghost, on any piece) gets the same id, and the ids
// are 0 .. distinct - 1 in coordinate order whatever the partition, because the set of
// distinct keys is the whole mesh's. Coincident points would get one id: a split node's
// two sides (two vertices at one position, e.g. across a fault) would become one vertex.
// Where both are on one piece the caller learns it (`coincident`) and refuses; where a
// partition puts them on different pieces with nothing else between them, they cannot be
// told from the copies of one seam point: such meshes need their own GlobalIds.
//
// One process uses the same numbering (the second overload), so it orders ChainMail as
// several do: for points with distinct coordinates the ids are equal; coincident points
// there keep their own ids, consecutive in point order (one process can keep them apart).
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
#include "geoshaping/parallel/exchange.h"

#include <cstdint>
#include <string>
#include <vector>

namespace geoshaping
{

// Collective. The ids of the `n` points xyz of this piece (see above); `claimed[v]`
// non-zero when this piece's data does not mark v as a ghost, `owned[v]` set to whether
// this piece owns v (for one of the copies of each point claimed here). `coincident`,
// when given: how many claimed points of this piece share their coordinates with an
// earlier claimed point of this piece (0 unless the mesh has split nodes or repeated
// points). Ghosts are left out: VTK's vtkGhostCellsGenerator, matching by coordinates,
// can send a piece a ghost copy of a point the piece holds, where three pieces meet.
std::vector<std::int64_t> coordinate_ids(const double* xyz, index_t n, const std::uint8_t* claimed,
  std::vector<std::uint8_t>& owned, Exchange& exchange, index_t* coincident = nullptr);

// The whole mesh in one piece, every point its own vertex: id(v) = the rank of
// (key(v), v), which is the collective overload's id for every point whose coordinates
// no other point shares. O(n log n), once per mesh. `coincident` as above.
std::vector<std::int64_t> coordinate_ids(
  const double* xyz, index_t n, index_t* coincident = nullptr);

// Collective. Why several pieces refuse a mesh without GlobalIds, from each piece's
// `coincident` count (the collective overload's): the same text on every piece, or ""
// when no piece holds coincident points.
std::string coincident_points_refusal(index_t coincident, Exchange& exchange);

} // namespace geoshaping
