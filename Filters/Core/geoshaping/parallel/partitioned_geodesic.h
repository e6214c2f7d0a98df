#pragma once
// The geodesic reach of a brush dab (brush.h: GeodesicReach from the vertex nearest the
// dab's centre) on a mesh split into pieces (one per MPI rank), with the same distances
// as on the whole mesh, bit for bit, whatever the partition (docs/painting.md,
// "Distributed data").
//
// Pieces as in partitioned_chainmail.h (owned vertices, one ghost ring, global ids). The
// distance of v is
//
//   d(v) = min over edge paths source = v_0, ..., v_k = v of
//          fl(... fl(fl(|x_s - c| + |x_v1 - x_v0|) + |x_v2 - x_v1|) ... )
//
// kept only where d <= radius: the greatest fixed point below +inf of the monotone map
// d_a -> min(d_a, d_b + |x_a - x_b|) with the label allowed when <= radius, which any
// fair order of updates reaches (partitioned_labels.h): so the pieces' run
// (PartitionedLabels::correct) gives the whole mesh's Dijkstra labels on every copy.
// What must be agreed on first is the source: the vertex nearest the centre over all
// pieces, ties to the lowest global id (one all_gather of each piece's candidate).
// On one process the same rule applies (Painter with nearest ties to the lowest id).
//
// Cost of a dab: O(r log r) for the r vertices of the piece within the radius and their
// rings (never O(piece)), one all_gather for the source, and a few supersteps (each one
// message to and from each neighbour piece carrying the border distances, and one
// all_gather of a flag).
#include "geoshaping/paint/brush.h"
#include "geoshaping/parallel/partitioned_labels.h"

namespace geoshaping
{

class PartitionedGeodesic
{
public:
  // Collective, once per partition: the piece's n points (xyz, 3 per point, kept by the
  // caller), its adjacency (kept by the caller), global ids and ownership (non-zero =
  // owned).
  void set_piece(const double* xyz, index_t n, const Adjacency* adjacency, const std::int64_t* gid,
    const std::uint8_t* owned, Exchange& exchange);

  // Collective: the piece's vertices (owned and ghosts) within `radius` of the dab's
  // source along edges, with their distances from `center` (the source's straight-line
  // distance plus the path), in no particular order. `candidate` is this piece's vertex
  // nearest `center` (ties to the lowest global id; -1 when the piece is empty). A
  // radius that is not > 0 reaches nothing.
  void compute(const Eigen::Vector3d& center, double radius, index_t candidate, Reach& out,
    Exchange& exchange);

  // Global id of the last dab's source (-1: none); supersteps of the last dab.
  std::int64_t source() const { return source_; }
  std::size_t supersteps() const { return supersteps_; }
  const PartitionedLabels& pieces() const { return pieces_; }

private:
  PartitionedLabels pieces_;
  const double* xyz_ = nullptr;
  const Adjacency* adjacency_ = nullptr;
  SparseLabels distance_;
  std::int64_t source_ = -1;
  std::size_t supersteps_ = 0;
};

} // namespace geoshaping
