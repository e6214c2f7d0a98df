#pragma once
// ChainMail on a mesh split into pieces (one per MPI rank), with the same result as on
// the whole mesh, bit for bit, whatever the partition (docs/deformer.md, "Order", and
// docs/mpi.md).
//
// A piece holds the vertices it owns and a ghost layer: every neighbour of an owned
// vertex, owned by another piece (one ring; ParaView's ghost level 1 of cells gives it).
// Every vertex has a global id (the same on every piece that holds it) and exactly one
// owner. The frame runs ChainMailDeformer's supersteps on every piece in lockstep:
//
//   superstep 0: the grasp's owner moves it;
//   each superstep: key = min over pieces of the lowest pending (band, root, generation);
//     stop when none is pending anywhere (quiescence); every piece examines its entries
//     of `key` (entries for the candidates it owns); then each piece sends the owned
//     vertices it moved (global id, displacement) to the pieces holding them as ghosts
//     (the moved frontier, to neighbour pieces only, with their roots), marks the
//     ghosts it receives as moved, and queues the owned neighbours of all of them.
//
// Why this equals the whole mesh: an entry (c, s) is examined on c's owner, which holds
// s (one ring) and s's displacement (its own, or received in the superstep s moved);
// the entries of a superstep are the same set as on the whole mesh (each owner queues
// its own candidates after the superstep, from the same moved set), examined in the
// same (candidate id, sponsor id) order per candidate, with the same arithmetic (the
// pieces share the whole mesh's local origin). So every piece computes exactly the
// whole mesh's displacement for each vertex it owns, and each vertex moves at most
// once, on its owner. Pins and rigid regions need nothing more.
//
// Rounds: the supersteps run in rounds, one synchronisation each (a gather of every
// piece's lowest pending key and superstep number, then the frontier exchange). A piece
// whose lowest key is below every other piece's runs ahead alone: it goes on to its
// next key while the superstep it just ran moved nothing another piece holds (nothing to
// send) and that next key is still below the others'. This is the same sequence of
// supersteps as one per round: the others' keys cannot change while nothing reaches them,
// so each key run ahead is the global minimum when it runs. A superstep's generation is
// its number in the frame, so a piece that sat out supersteps skips to the number the
// others reached (ChainMailDeformer::skip_to_superstep): from the gathered numbers at the
// start of a round, or, for a piece that receives the frontier of a run-ahead superstep,
// from a marker record at the front of that message (global id INT64_MIN, reserved; its
// root.generation is the superstep's number).
//
// Cost of a frame: the supersteps' work is O(displaced on this piece), plus per round
// one gather of 32 bytes per piece and one message to and from each neighbour piece
// carrying the moved frontier (sizeof(MovedVertex) = 48 bytes per moved vertex and piece
// holding it as a ghost, plus one marker after a run-ahead). Rounds <= supersteps; on
// one piece a frame is one round.
// Setting up a piece gathers every piece's ghost ids on every piece (once per mesh).
//
// Obstacles (obstacles.h): every piece's deformer holds the same obstacle triangles
// (set_obstacles after set_piece, the whole obstacle on every piece, given in the same
// order). An owned vertex passes the gate on its owner, with the same arithmetic as on
// the whole mesh (the same local origin and tree); a ghost takes its owner's gated
// displacement unchanged. A rigid component stops as one at the smallest fraction over
// its members: exact when each component lies on one piece (its members owned by one
// piece); a component that continues on another piece (a rigid ghost joined to it) is
// refused, with obstacles, on every piece (it would need a collective per component
// entered). The grasp's owner reports the grasp's fraction; blocked counts this piece's
// owned vertices held back.
//
// Only FIFO and FIFO Priority are partitioned: Priority (heap order) and Max Violation
// are sequential, and a partitioned frame refuses them on every piece.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/parallel/exchange.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace geoshaping
{

// Drives a ChainMailDeformer that holds one piece (set up by set_piece).
class PartitionedChainMail
{
public:
  explicit PartitionedChainMail(ChainMailDeformer& deformer)
    : deformer_(deformer)
  {
  }

  // Collective. `n` local points (xyz), their adjacency (local ids), global ids and
  // ownership (non-zero = owned). A global id held twice by a piece is one point (its
  // copies move together). Returns "" or why the partition is refused (a ghost owned by
  // no piece or by several); the same answer on every piece.
  std::string set_piece(const double* xyz, index_t n, Adjacency adjacency, const std::int64_t* gid,
    const std::uint8_t* owned, Exchange& exchange);
  // Malleability, pins, transfer function, queue and frame are set here, the same on
  // every piece (pins and malleability of the piece's points).
  ChainMailDeformer& deformer() { return deformer_; }
  const ChainMailDeformer& deformer() const { return deformer_; }

  // Collective: one frame, grasping the vertex of global id `grasp`. ok and message are
  // the same on every piece; moved, examined and blocked count this piece's owned
  // vertices and examined entries; grasp_fraction is the grasp owner's (1 elsewhere). The piece's
  // ghosts hold their owners' displacements afterwards.
  FrameResult deform(std::int64_t grasp, const Eigen::Vector3d& displacement, Exchange& exchange);
  // Supersteps of the last frame (the same on every piece).
  std::size_t supersteps() const { return supersteps_; }
  // Rounds (synchronisations) of the last frame, after the grasp's (the same on every
  // piece): what a frame's latency grows with.
  std::size_t rounds() const { return rounds_; }
  // Appends the local vertices holding global id `gid` (none when this piece does not
  // hold it; a point held twice, all its copies): EditPlace::holders for edits.
  void holders(std::int64_t gid, std::vector<index_t>& out) const;

private:
  // Fills the outboxes with this superstep's owned moved vertices that other pieces hold;
  // true if any are sent.
  bool fill_outbox();
  // Sends the outboxes (with a marker of this superstep's number first when `marked`)
  // and moves the ghosts received.
  void trade(Exchange& exchange, bool marked);
  // Moves the other copies of the points moved in this superstep.
  void move_aliases();

  ChainMailDeformer& deformer_;
  std::unordered_map<std::int64_t, index_t> local_of_; // global id -> local id
  std::unordered_multimap<index_t, index_t> aliases_;  // local id -> its other copies
  std::vector<int> send_to_, receive_from_;
  // By local id: the indices into send_to_ of the pieces holding it as a ghost (CSR).
  std::vector<std::uint32_t> subscriber_offsets_;
  std::vector<std::uint32_t> subscribers_;
  std::vector<std::vector<MovedVertex>> outbox_;
  std::size_t supersteps_ = 0;
  std::size_t rounds_ = 0;
};

} // namespace geoshaping
