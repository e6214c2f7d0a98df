#pragma once
// The envelope refinement (link_projection.h, ProjectionSolver::envelope, Axes frame) on
// a mesh split into pieces (one per MPI rank), with the same result as LinkProjector on
// the whole mesh, bit for bit, whatever the partition (docs/mpi.md, "Refinement").
//
// Pieces as in partitioned_chainmail.h: owned vertices plus one ghost ring, global ids,
// exactly one owner per vertex; the start is given on every copy of a vertex (as
// PartitionedChainMail leaves the frame: ghosts hold their owners' displacements).
//
// What is computed (per axis i and direction sign, y = sign u_i): two label-correcting
// runs, exactly those of LinkProjector's envelope: both run the one per-axis step,
// EnvelopeAxis (envelope_axis.h).
//   cone:  c_a = min_f fl(c_f + ub'(a, f) ...) from the fixed vertices f (grasp, and pins in
//          or next to S = start + grasp) on y' = -y, labels kept only below
//          top = max(0, max_{v in S} y'_v); then z'_a = max(z_a, -c_a) for free a;
//   min:   d_a = min(z'_a, min_b fl(d_b + ub(a, b))) for free a (fixed ones keep z),
// with ub(a, b) = hi_ab (sign +1) or -lo_ab (sign -1) from the same axis_slab numbers
// (link_axis_slab). The result of each axis is (D + U) / 2 per vertex, as there.
//
// Why the pieces get the same bits: both runs compute the greatest fixed point below
// their start of the monotone map y_a -> min(y_a, min_b fl(y_b + w_ab)) (w >= 0, so a
// label only falls and fl(y + w) >= y: no cycle lowers a label for ever). Any fair order
// of updates from the same start reaches that same fixed point: every label ever set is
// >= the fixed point (induction: fl is monotone), and the final labels satisfy every
// constraint (each lowered label is relaxed). The cone's pruning at `top` keeps exactly
// the labels < top (a path's partial sums never decrease). So it is enough that
//   - the start, the fixed set, `top` and "this axis is all zero" are the same as on the
//     whole mesh: start and fixedness are per vertex (the grasp by global id; a pin is
//     fixed when it or a neighbour is in S, decided by its owner, who holds its ring);
//     top and zero are reduced over the pieces (max and and are exact);
//   - every constraint b -> a of the whole mesh is relaxed somewhere: a's owner holds a's
//     whole ring (one ghost level), and every label it lowers reaches the other copies;
//   - the seeds cover every violated link (a piece scans the links of its copies of S
//     and of the cone's labels; seeding more than needed changes nothing).
// The distributed runs are PartitionedLabels::correct (partitioned_labels.h).
//
// Cost of a call: O(touched log touched) work per piece for the vertices whose labels
// change and their rings (never O(piece)), 12 runs (3 axes x D, U x cone, min; axes whose
// start is all zero are skipped) of a few supersteps each, each superstep one message to
// and from each neighbour piece carrying the lowered border labels, plus one all_gather
// of a flag; two small all_gathers per call (the reductions). set_piece is O(piece) and
// gathers every piece's ghost ids (once per partition).
#include "geoshaping/parallel/partitioned_labels.h"
#include "geoshaping/passes/envelope_axis.h"
#include "geoshaping/passes/link_projection.h"

#include <cstdint>
#include <vector>

namespace geoshaping
{

class PartitionedEnvelope
{
public:
  // Collective, once per partition: the piece as `deformer` holds it after
  // PartitionedChainMail::set_piece (global ids, ownership; copies of one global id: the
  // owned one, else the first, is the vertex, the others follow it), and its link data
  // (for the mean edge length over the whole mesh, which only scales the report).
  void set_piece(const ChainMailDeformer& deformer, const LinkMesh& mesh, Exchange& exchange);

  // Collective: the envelope of the start (`vertices` at `values`, every other vertex at
  // rest; given on every copy) with the grasp (global id; -1: none) and the pins fixed,
  // on the piece's link data `mesh` (Axes frame; same adjacency and rest as at
  // set_piece). The report is the same on every piece: violation (E_link bound, as
  // LinkProjector's) and region are over the whole mesh.
  ProjectionReport project(const LinkMesh& mesh, std::int64_t grasp,
    const std::vector<index_t>& vertices, const Displacements& values,
    const ProjectionOptions& options, Exchange& exchange);

  // The result on this piece (dense; at rest outside region()), owned vertices and
  // ghosts alike.
  const Displacements& displacements() const { return u_; }
  // This piece's vertices the last call touched (start, grasp and changed).
  const std::vector<index_t>& region() const { return region_; }
  // This piece's vertices whose result differs from the start (fixed ones never).
  const std::vector<index_t>& changed() const { return changed_; }
  // Of the last call, the same on every piece: supersteps of all its runs; changed
  // vertices over the whole mesh (each counted once, by its owner).
  std::size_t supersteps() const { return supersteps_; }
  std::size_t changed_total() const { return changed_total_; }

private:
  // The piece as EnvelopeAxis's Net (envelope_axis.h).
  struct Net;
  bool is_fixed(index_t v) const;
  double start_y(index_t v, int axis, double sign) const { return sign * u_[std::size_t(v)][axis]; }

  PartitionedLabels pieces_;
  const LinkMesh* mesh_ = nullptr;
  index_t n_ = 0;
  double scale_ = 1.0;

  index_t grasp_ = -1;
  Displacements u_;
  std::vector<std::uint8_t> in_region_; // 1: start or grasp, 2: changed
  std::vector<index_t> region_, changed_;
  SparseLabels cone_, env_;
  EnvelopeAxis axis_; // the per-axis step, shared with LinkProjector
  std::size_t supersteps_ = 0, changed_total_ = 0;
};

} // namespace geoshaping
