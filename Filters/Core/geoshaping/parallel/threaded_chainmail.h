#pragma once
// A large frame on several threads of one process, bit for bit the one-thread frame.
//
// The whole mesh's ChainMailDeformer stays the one the caller sets up and reads (moved(),
// displacement(), sponsor(), commit() ...). A frame predicted large runs instead on
// pieces of it, one thread each: the partitioned core (partitioned_chainmail.h) that MPI
// ranks run, its exchange in memory (in_process_exchange.h). The moves are then written
// back into the whole deformer (ChainMailDeformer::adopt_move) in the order its own frame
// makes them: by superstep, inside one by global id. The partitioned core promises the
// whole mesh's result for any partition, so the whole deformer ends the frame in the same
// state as after deform(): the same moved set and order, displacements, roots, sponsors
// and FrameResult.
//
// Pieces: the vertices in Morton order (mesh/morton.h) of their rest positions, cut into
// blocks of `block` vertices, block b owned by piece b mod P (compact patches dealt in
// turn, so a grasp's region falls on every piece in about equal parts wherever it lies),
// each piece with its one ring of ghosts. They are built (O(mesh log mesh), in parallel)
// on the first threaded frame after the whole deformer's revision() or the thread count
// changed (a commit or an edit changes it too); each frame copies the transfer function,
// queue and region shape. They hold about the whole deformer's memory again.
//
// The switch: a frame runs threaded when the previous frame (one thread or several)
// displaced at least threshold() vertices and at least per_superstep() per superstep
// (a round of the partitioned frame costs two collectives, which only a wide enough
// front repays; FIFO Priority on a finely painted mesh enters many small regions
// downhill and runs few vertices a superstep), the queue is FIFO or FIFO Priority (the
// only partitioned ones) and there are no obstacles (a rigid region crossing pieces
// would need a collective per component). Everything else, and the first frame, runs on
// one thread. Which way a frame runs never changes its result.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/parallel/partitioned_chainmail.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace geoshaping
{

class ThreadedChainMail
{
public:
  ThreadedChainMail();
  ~ThreadedChainMail();

  // Threads a large frame runs on: 1 (the default) turns threading off; 0 is the
  // hardware's concurrency.
  void set_threads(int threads);
  int threads() const;
  // The previous frame's displaced count from which a frame runs threaded.
  void set_threshold(std::size_t displaced) { threshold_ = displaced; }
  std::size_t threshold() const { return threshold_; }
  // The previous frame's displaced vertices per superstep from which a frame runs threaded.
  void set_per_superstep(double v) { per_superstep_ = v; }
  double per_superstep() const { return per_superstep_; }
  // Vertices per block of the partition (>= 1).
  void set_block(index_t vertices);

  // One frame of `whole`: whole.deform(grasp, displacement), on one thread or several.
  FrameResult deform(ChainMailDeformer& whole, index_t grasp, const Eigen::Vector3d& displacement);
  // Forgets the previous frame: the next frame runs on one thread.
  void forget() { last_moved_ = 0; }

  // The last frame: whether it ran threaded, its supersteps (both ways) and its rounds
  // (synchronisations, threaded only; 0 otherwise).
  bool last_threaded() const { return last_threaded_; }
  std::size_t supersteps() const { return last_supersteps_; }
  std::size_t rounds() const { return last_rounds_; }
  // The CPU seconds each thread spent on the last threaded frame (its piece's frame, its
  // share of the write-back; not the time it slept at a barrier): the frame's length on
  // cores of its own is about the largest, plus the barriers' latency.
  const std::vector<double>& thread_seconds() const { return thread_seconds_; }

private:
  struct Piece;
  bool predicts_threaded(
    const ChainMailDeformer& whole, index_t grasp, const Eigen::Vector3d& displacement) const;
  void build(const ChainMailDeformer& whole, int pieces);
  // A thread's share of the write-back: the supersteps [from_step, to_step), which are
  // the whole deformer's slots [begin, end) of `total`.
  struct Share
  {
    std::uint32_t from_step = ~0u, to_step = ~0u;
    std::size_t begin = 0, end = 0, total = 0;
  };
  Share share_of(int thread, int threads) const;
  // Writes the pieces' owned moves of a share into the whole deformer in its order (by
  // superstep, inside one by global id), and order_ for them.
  void merge(ChainMailDeformer& whole, const Share& share);

  int threads_ = 1;
  std::size_t threshold_;
  double per_superstep_;
  index_t block_;
  std::vector<std::unique_ptr<Piece>> pieces_;
  std::uint64_t built_revision_ = 0;
  const ChainMailDeformer* built_for_ = nullptr;
  int built_pieces_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order_; // (piece, slot)
  std::size_t last_moved_ = 0;
  std::size_t last_supersteps_ = 0;
  std::size_t last_rounds_ = 0;
  bool last_threaded_ = false;
  std::vector<double> thread_seconds_;
};

} // namespace geoshaping
