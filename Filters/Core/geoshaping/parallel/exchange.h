#pragma once
// The transport between the pieces of a partitioned mesh (one per MPI rank), as an
// interface: the partitioned deformer, the global numbering, the labels, the envelope and
// the edit history talk through it; vtkGeoShapingControllerExchange implements it over a
// vtkMultiProcessController and InProcessExchange over threads of one process
// (in_process_exchange.h: the tests).
// The messages it carries are the moved frontier (MovedVertex) and the round states.
#include "geoshaping/deform/candidate_queue.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace geoshaping
{

// A vertex moved by its owner, as sent to the pieces that hold it as a ghost.
struct MovedVertex
{
  std::int64_t gid;
  double displacement[3];
  SuperstepRoot root;
};

// What a piece tells the others at the start of a round of supersteps.
struct RoundState
{
  SuperstepKey pending;    // its lowest pending key (SuperstepQueue::none: nothing)
  std::uint64_t superstep; // its superstep number (ChainMailDeformer::superstep_index)
};

// Communication between the pieces of a partitioned mesh, like an MPI communicator:
// every call is collective (every piece calls it, in the same order).
class Exchange
{
public:
  virtual ~Exchange() = default;
  virtual int pieces() const = 0;
  virtual int piece() const = 0;
  // Every piece's `values`, by piece.
  virtual std::vector<std::vector<std::int64_t>> all_gather(
    const std::vector<std::int64_t>& values) = 0;
  // Sends out[i] to piece to[i] and returns what each piece in `from` sent this piece
  // (in the order of `from`). Each piece's `to` lists exactly the pieces whose `from`
  // list it.
  virtual std::vector<std::vector<MovedVertex>> exchange(const std::vector<int>& to,
    const std::vector<std::vector<MovedVertex>>& out, const std::vector<int>& from) = 0;
  // Sends out[q] to piece q (one entry per piece) and returns what every piece sent
  // this one, by piece. The default goes through all_gather (every piece receives
  // everything); a transport overrides it with messages to the pieces concerned.
  virtual std::vector<std::vector<std::int64_t>> all_to_all(
    const std::vector<std::vector<std::int64_t>>& out);
  // Every piece's `state`, by piece: one collective (the default goes through
  // all_gather; a transport overrides it with one fixed-size gather).
  virtual std::vector<RoundState> all_round_states(const RoundState& state);
  // Bytes this piece sent through exchange().
  std::size_t bytes_sent() const { return bytes_sent_; }

protected:
  std::size_t bytes_sent_ = 0;
};

} // namespace geoshaping
