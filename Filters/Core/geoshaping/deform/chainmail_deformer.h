#pragma once
// Generalized ChainMail extended to inhomogeneous meshes (Faeth, Oren, Harding).
#include "geoshaping/deform/candidate_queue.h"
#include "geoshaping/deform/obstacles.h"
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/mesh/prefetch.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace geoshaping
{

struct FrameResult
{
  bool ok = false;
  std::string message;         // why the frame did nothing (when !ok)
  std::size_t moved = 0;       // vertices displaced this frame, grasp included
  std::size_t examined = 0;    // candidates popped from the queue
  std::size_t blocked = 0;     // vertices an obstacle held back short of their target
  double grasp_fraction = 1.0; // the part of the displacement the grasp moved (< 1: stopped)
  std::size_t supersteps = 0;  // groups examined (FIFO, FIFO Priority; 0 for the others)
  std::size_t threaded_supersteps = 0; // of which on several threads (set_threads)
};

// Builds adjacency and rest state once; each frame starts from the rest state, moves
// the grasped vertex to x0[g] + d and propagates (the deformation contract, docs/design.md):
//
//   pop (c, s); skip c if it moved already this frame;
//   box = valid region of c w.r.t. s from c's own (t, k, h);
//   if x0[c] lies outside the box, move c to the nearest point of the box and queue
//   its neighbours that have not moved and are not pinned, with c as sponsor.
//
// Order. FIFO and FIFO Priority run in supersteps (SuperstepQueue, candidate_queue.h):
// a superstep takes every pending entry of the lowest (band, root, generation), band =
// the candidate's malleability (FIFO: one band), root = where propagation entered the
// band's region (a region entered downhill is filled from its first entry alone, so
// rigid regions move as one; roots entered in one superstep come longest move first),
// generation = 1 + the superstep in which the sponsor moved. A candidate with several
// entries in a superstep takes the longest of the moves they ask (sponsor_wins(); the
// first in sponsor global id order among exactly equal lengths). Entries for different
// candidates in one superstep are independent: a box depends on the candidate's rest
// position and malleability and on the sponsor, which moved in an earlier superstep.
// The neighbours of the vertices a superstep moved are queued after it, skipping those
// moved by then, so the entries (and the supersteps) do not depend on the order inside
// a superstep. Hence the result depends only on the mesh and the pull (the global ids
// only at exact ties of length), never on the vertex numbering, a rotation or
// translation of mesh and pull together, or a partition into pieces
// (partitioned_chainmail.h; docs/deformer.md, "Order"). Global ids are the caller's ids
// unless set_global_ids() gives others. (How: the sponsors are taken in id order, a
// group is examined in push order and its moves are then put in id order, see
// SuperstepQueue::open.) Priority (heap order) and Max Violation pop one candidate at a
// time and push its neighbours at once.
//
// The region is the paper's axis-aligned box (ValidRegionFrame::axes, the default) or
// the cylinder in the frame of the rest link (ValidRegionFrame::link, rotation
// invariant); both in valid_region.h.
//
// Decisions the design leaves open, fixed here:
// - A candidate found inside its box is NOT marked: when another neighbour moves later
//   it is queued and examined again against that sponsor. Each vertex still moves at
//   most once; the pushes of a frame are bounded by the sum of the degrees of the
//   moved vertices, so the frame stays proportional to the displaced region.
// - A pinned vertex never moves and never sponsors: propagation stops at it as at the
//   border of the mesh and flows around it. Grasping a pinned vertex is refused.
// - The grasped vertex moves to x0[g] + d whatever its malleability.
// - Obstacles (set_obstacles, obstacles.h). Every move, the grasp's included, goes
//   through one gate: a vertex whose target u would take it across an obstacle (or
//   within the clearance) moves by f u instead, f = Obstacles::admissible_fraction of
//   its segment x0 -> x0 + u, and still counts as moved: its neighbours are examined
//   against where it stopped. Rigid regions stop as one: when the first vertex of a
//   rigid component (rigid vertices joined by edges, pins left out) moves by u in a
//   frame, f is the smallest admissible fraction of u over the whole component, and the
//   component's displacement f u is admissible for each member (the admissible part of
//   a segment is a prefix); its other members, sponsored inside the component, receive
//   f u bit for bit and pass the gate unchanged. (A member reached with another
//   displacement, under a queue that does not keep rigid regions whole, is gated alone.)
//   Sliding vertices (set_sliding: on an obstacle, a horizon's cut-off line on its
//   fault) pass the gate by Obstacles::slide instead: a sliding vertex whose target is
//   x0 + u lands on the obstacle point nearest to it, so it stays on the surface and
//   moves along it; it is left out of the rigid components, as pins are. On a piece
//   (set_owned) a ghost passes the gate unchanged: it moves by its owner's word, which
//   the owner's gate gave.
//   Cost: O(log T) per move for T obstacle triangles, O(component) once per frame for
//   a rigid component it enters; the components are found once per malleability, pins,
//   sliding mask and transfer function (O(mesh)). Without obstacles the gate is one
//   pointer test.
//
// Threads. With set_threads(n > 1), a superstep whose group holds at least
// threaded_threshold() entries is examined by n threads of a pool the deformer keeps
// (worker_pool.h; deform/threaded_superstep.cpp): entries are independent within a
// superstep, and thread t owns the candidates whose global ids lie in a range [lo_t, hi_t)
// (ranges in id order, from samples of the group), so it alone examines their entries, in
// push order, keeping for each candidate "the longest move, the first in push order among
// equal lengths" with no atomics. Each thread sorts its winners by global id and, after one
// barrier, writes them into the slots the one-thread superstep gives them (its range's
// slots follow the lower ranges'); under FIFO it then pushes the neighbours of its moves,
// and the threads' pushes in range order are the one-thread push order. Everything else runs on the
// caller's thread as before: small supersteps, FIFO Priority's pushes (their groups depend on the
// bands), Priority and Max Violation, frames with obstacles, pieces (set_owned). The result is bit
// for bit the one-thread frame's whatever the threads or their scheduling.
//
// On a busy machine threads would lose (another process on a core stops one thread for
// milliseconds at each barrier). Unless told ThreadUse::always, a frame reads the
// machine's runnable threads before its first large superstep and stays on the caller's
// thread when others hold the cores (WorkerPool::cores_short); and when the pool reports
// a stall (WorkerPool::stalled()) the rest of the frame and the next b frames run on the
// caller's thread, b doubling from 1 to 64 while stalls recur and going back to 0 after a
// threaded frame without one: a frame costs at most one stall more than the one-thread
// frame.
//
// Arithmetic is double, on displacements u = x - x0 of rest positions stored relative
// to a local origin, so UTM-sized coordinates lose nothing and a rigid region's
// displacement is bit-identical to its sponsor's.
//
// A frame costs time proportional to the vertices it reaches, never to the mesh size
// (the reset is a frame counter). Internally the vertices are renumbered once, in
// set_mesh, for memory locality (docs/deformer.md, "Data layout and speed"); every
// public method takes and returns the caller's ids. Before the first frame no vertex
// counts as moved.
class ChainMailDeformer
{
public:
  // Rest positions, `n` xyz triples in any frame; the centre of their bounding box
  // becomes the local origin. Resets malleability to `default_malleability`, clears pins.
  void set_mesh(const double* xyz, index_t n, Adjacency adjacency);
  // The same with a given local origin (pieces of one mesh share the whole mesh's, so
  // their arithmetic is bit-identical to the whole mesh's).
  void set_mesh(const double* xyz, index_t n, Adjacency adjacency, const Eigen::Vector3d& origin);
  // The local origin set_mesh chooses: the centre of the bounding box of the finite
  // points given as lo/hi (bounds() below), zero when there is none.
  static Eigen::Vector3d origin_of(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
  {
    return 0.5 * (lo + hi);
  }
  // Bounding box of the finite points; false (and lo = hi = 0) when there is none.
  static bool bounds(const double* xyz, index_t n, Eigen::Vector3d& lo, Eigen::Vector3d& hi);
  index_t size() const { return index_t(nodes_.size()); }
  // The adjacency given to set_mesh. The deformer keeps only its own renumbered copy;
  // this one is rebuilt from it on first use and cached until the next set_mesh.
  const Adjacency& adjacency() const;

  // Per-vertex malleability. Values are clamped to [0, 1]; NaN is treated as 0 (rigid:
  // the vertex keeps its shape rather than producing a NaN). Returns the number of
  // values that were clamped or NaN so callers can warn.
  std::size_t set_malleability(const float* m);
  std::size_t set_malleability(const double* m);
  void set_uniform_malleability(double m);
  float malleability(index_t v) const { return distinct_[std::size_t(nodes_[inner(v)].rank)]; }

  // Optional mask: non-zero = pinned. Pass nullptr to clear.
  void set_pinned(const std::uint8_t* mask);
  bool pinned(index_t v) const { return !pinned_.empty() && pinned_[std::size_t(v)] != 0; }

  // Global ids (any distinct 64-bit values) decide the order inside a superstep; nullptr
  // restores the default, the caller's ids.
  void set_global_ids(const std::int64_t* gid);
  std::int64_t global_id(index_t v) const
  {
    return gid_.empty() ? std::int64_t(v) : gid_[inner(v)];
  }
  // Ownership mask for a piece of a partitioned mesh: non-zero = owned. A vertex not
  // owned (a ghost) is never examined here; its owner moves it and move_vertex() tells
  // this piece. nullptr: every vertex is owned (the default).
  void set_owned(const std::uint8_t* mask);
  bool owned(index_t v) const { return ghost_.empty() || !ghost_[inner(v)]; }

  void set_transfer_function(const TransferFunction& tf);
  const TransferFunction& transfer_function() const { return transfer_; }
  void set_queue(QueueKind q) { queue_kind_ = q; }
  QueueKind queue() const { return queue_kind_; }
  // Threads (see "Threads" below): a superstep of at least threaded_threshold() entries
  // runs on `threads` threads; 1 (the default) runs every frame on the caller's thread;
  // 0 is the hardware's concurrency. With ThreadUse::when_cores_free (the default) a frame
  // runs on one thread when other programs hold the cores its threads need, and for a
  // while after a stall; ThreadUse::always uses them whatever the load (tests,
  // benchmarks). Nothing changes any result. Setting what is already set keeps the
  // busy-machine state (the filter sets it every frame).
  enum class ThreadUse
  {
    when_cores_free,
    always
  };
  void set_threads(int threads, ThreadUse use = ThreadUse::when_cores_free);
  int threads() const { return threads_; }
  ThreadUse thread_use() const { return thread_use_; }
  void set_threaded_threshold(std::size_t entries) { threaded_threshold_ = entries; }
  std::size_t threaded_threshold() const { return threaded_threshold_; }
  // Shape of the valid region (valid_region.h): axes (default) or link.
  void set_valid_region_frame(ValidRegionFrame f) { frame_kind_ = f; }
  ValidRegionFrame valid_region_frame() const { return frame_kind_; }

  // Obstacle triangles (obstacles.h) in the caller's frame, as set_mesh's points; stored
  // relative to origin(). Cleared by set_mesh. Returns "" or why they are refused (then
  // there are none).
  std::string set_obstacles(
    const double* xyz, std::size_t n, const std::int64_t* triangles, std::size_t num_triangles);
  void clear_obstacles() { obstacles_.reset(); }
  // Clearance (scene units, >= 0; false and unchanged otherwise); kept across
  // set_obstacles.
  bool set_obstacle_clearance(double c);
  double obstacle_clearance() const { return clearance_; }
  const Obstacles* obstacles() const { return obstacles_.get(); }
  // The fraction of the last gated move (1 without obstacles) and the vertices held back
  // so far this frame: FrameResult's grasp_fraction and blocked, for a driver that moves
  // vertices itself (PartitionedChainMail).
  double last_fraction() const { return last_fraction_; }
  std::size_t blocked() const { return blocked_; }
  // On a piece (set_owned): whether a rigid component of the gate (pins and sliding
  // vertices left out) holds a ghost, i.e. continues on another piece. Builds the
  // components when they are stale (O(mesh)); false without ghosts.
  bool rigid_component_split()
  {
    if (rigid_of_.empty())
      build_rigid_components();
    return rigid_split_;
  }
  // Optional mask: non-zero = sliding (the vertex lies on an obstacle and stays on it,
  // see the class comment); nullptr clears. Cleared by set_mesh; without obstacles it
  // has no effect.
  void set_sliding(const std::uint8_t* mask);
  bool sliding(index_t v) const { return !sliding_.empty() && sliding_[inner(v)] != 0; }

  // One frame. Invalid grasp, non-finite displacement or pinned grasp: ok == false,
  // the shape returns to rest.
  FrameResult deform(index_t grasp, const Eigen::Vector3d& displacement);
  // Back to the rest state (sparse).
  void reset();

  // The frame in supersteps, for a partitioned driver (FIFO and FIFO Priority only):
  //   begin_frame(); move_vertex(grasp, d) on the grasp's owner; end_superstep();
  //   while ((key = lowest pending over all pieces) != SuperstepQueue::none)
  //     superstep(key); move_vertex() for ghosts moved by their owners; end_superstep();
  // deform() is this loop on one piece. moved()[superstep_begin(), end) are the
  // vertices moved in the current superstep.
  void begin_frame();
  // Moves v by d with no sponsor (the grasp, or a ghost moved by its owner, with the
  // root its owner gave it); v must not have moved this frame.
  void move_vertex(index_t v, const Eigen::Vector3d& d, const SuperstepRoot& root = {});
  // The root of a vertex moved in the current frame (FIFO, FIFO Priority).
  SuperstepRoot root(index_t v) const { return moved_root_[std::size_t(slot_[inner(v)])].get(); }
  SuperstepKey pending() const { return supersteps_.top(); }
  // Examines this piece's entries of `key` (if it is its lowest); returns how many.
  std::size_t superstep(const SuperstepKey& key);
  // Queues the unmoved, unpinned, owned neighbours of the vertices moved in this
  // superstep, and starts the next.
  void end_superstep();
  std::size_t superstep_begin() const { return superstep_begin_; }
  // The current superstep's number (0: the grasp's; an entry's generation is 1 + the
  // number of the superstep its sponsor moved in). A partitioned driver whose piece sat
  // out supersteps that another piece ran alone brings it to the others' number:
  // skip_to_superstep(n), n >= superstep_index(), is n - superstep_index() supersteps in
  // which this piece moved nothing (what it moved since the last end_superstep(),
  // ghosts received, belongs to superstep n).
  std::uint32_t superstep_index() const { return superstep_; }
  void skip_to_superstep(std::uint32_t n);

  // Editing (edit_history.h). The rest shape can change: `commit()` makes the last
  // frame's shape the rest shape of the vertices it moved (x0 += u, u = 0), in
  // O(moved). Besides its rest position each vertex keeps its offset from the mesh
  // given to set_mesh (zero until an edit moves it), accumulated by the same additions,
  // so a caller writes `input + committed_offset(v) + displacement(v)`: never-edited
  // vertices stay bit-identical to the input, and restoring both values undoes an edit
  // exactly.
  void commit();
  // Sets v's rest position (local) and its offset from the input; u[v] must be zero
  // (call between frames or after reset()).
  void set_rest(index_t v, const Eigen::Vector3d& rest_local, const Eigen::Vector3d& offset);
  const Eigen::Vector3d& committed_offset(index_t v) const
  {
    return committed_.empty() ? zero_ : committed_[std::size_t(v)];
  }

  // Vertices displaced by the last frame, in the order they moved (grasp first).
  const std::vector<index_t>& moved() const { return moved_; }
  // Vertices displaced by the frame before it (already reset to rest), so a caller
  // mirroring positions can restore them too.
  const std::vector<index_t>& previously_moved() const { return previously_moved_; }
  // Sponsor of a vertex moved in the last frame (-1 for the grasp); undefined otherwise.
  index_t sponsor(index_t v) const
  {
    const std::size_t i = inner(v);
    const index_t s =
      nodes_[i].stamp == frame_ ? moved_rec_[std::size_t(slot_[i])].sponsor_slot : -1;
    return s < 0 ? -1 : moved_[std::size_t(s)];
  }
  bool moved_this_frame(index_t v) const { return nodes_[inner(v)].stamp == frame_; }

  const Eigen::Vector3d& origin() const { return origin_; }
  const Eigen::Vector3d& rest_local(index_t v) const { return nodes_[inner(v)].rest; }
  const Eigen::Vector3d& displacement(index_t v) const
  {
    const std::size_t i = inner(v);
    return nodes_[i].stamp == frame_ ? moved_rec_[std::size_t(slot_[i])].disp : zero_;
  }
  Eigen::Vector3d position(index_t v) const { return origin_ + rest_local(v) + displacement(v); }
  ChainMailParams params(index_t v) const { return transfer_(malleability(v)); }

  // Bytes held beyond the input mesh (rest copy, state, adjacency, queue pool).
  std::size_t memory_bytes() const;

private:
  // Resizing leaves new elements uninitialised (a threaded superstep fills them in).
  template<class T>
  struct UninitializedAllocator : std::allocator<T>
  {
    template<class U>
    struct rebind
    {
      using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template<class U>
    UninitializedAllocator(const UninitializedAllocator<U>&)
    {
    }
    template<class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
    {
      ::new (static_cast<void*>(p)) U;
    }
    template<class U, class... A>
    void construct(U* p, A&&... a)
    {
      ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
  };
  // The pool and the scratch of threaded supersteps (threaded_superstep.cpp), made on the
  // first; a copy of the deformer starts without and makes its own.
  struct Threaded;
  struct ThreadedHandle
  {
    std::unique_ptr<Threaded> state;
    ThreadedHandle();
    ThreadedHandle(const ThreadedHandle&);
    ThreadedHandle& operator=(const ThreadedHandle&);
    ~ThreadedHandle();
  };

  template<ValidRegionFrame Frame, class Queue>
  void propagate(Queue& queue, index_t grasp, FrameResult& result);
  template<class Queue>
  void propagate(Queue& queue, index_t grasp, FrameResult& result);
  void rebuild_ranks(const std::vector<float>& values);
  void finish_ranks();
  std::size_t caller_adjacency_bytes() const;
  static std::mutex& caller_adjacency_mutex();
  void rebuild_rank_params();
  template<class T>
  std::size_t assign_malleability(const T* m);
  std::size_t inner(index_t v) const { return std::size_t(inner_of_[std::size_t(v)]); }

  // Internally vertices are renumbered once, in set_mesh, along a space-filling (Morton)
  // curve of their rest positions, so the vertices a frame touches lie close together
  // in memory; every public method takes and returns the caller's ids. The propagation
  // reads per candidate one 32-byte record (rest position, frame stamp, malleability
  // rank); what only moved vertices have (displacement, sponsor) lives in `moved_rec_`,
  // indexed by the order of moving (the "slot"), which a frame fills sequentially.
  struct alignas(32) Node
  {
    Eigen::Vector3d rest; // relative to origin_
    std::uint32_t stamp;  // == frame_ when moved this frame
    index_t rank;         // index of the malleability among the sorted distinct values
  };
  // A SuperstepRoot without default values, so that resizing leaves it uninitialised.
  // Built in place from a root (move()): a copy made on the stack first, two narrow
  // stores read back by one 16-byte load, stalled store forwarding on every move
  // (docs/benchmarks.md, "Threaded frame").
  struct StoredRoot
  {
    std::uint32_t generation;
    std::uint64_t order;
    std::int64_t gid;
    StoredRoot() = default;
    explicit StoredRoot(const SuperstepRoot& r)
      : generation(r.generation)
      , order(r.order)
      , gid(r.gid)
    {
    }
    SuperstepRoot get() const { return { generation, order, gid }; }
  };
  struct MovedRecord
  {
    Eigen::Vector3d disp; // this frame's displacement (zeroed by commit())
    index_t vertex;       // internal id
    index_t sponsor_slot; // slot of the sponsor, -1 for the grasp
  };

  template<ValidRegionFrame Frame>
  std::size_t examine(std::size_t begin, std::size_t end, const SuperstepRoot& root);
  // examine() on threads (see "Threads"); under FIFO it pushes the neighbours too, which
  // end_superstep() then files.
  template<ValidRegionFrame Frame>
  std::size_t examine_threaded(std::size_t begin, std::size_t end, const SuperstepRoot& root);
  // Whether the current superstep, `entries` long, runs on threads.
  bool threaded_superstep(std::size_t entries) const
  {
    return threads_ > 1 && entries >= threaded_threshold_ && !threads_paused_ && !obstacles_ &&
           ghost_.empty() && moved_rec_.size() == superstep_begin_;
  }
  // With automatic threads, whether the cores are free for them this frame: read once per
  // frame, at its first superstep large enough for threads (WorkerPool::others_running).
  bool cores_free();
  // Files the pushes examine_threaded() made, if they are this superstep's; false if not.
  bool file_threaded_pushes();
  std::size_t threaded_bytes() const;
  // Where candidate c must move given sponsor s moved by sponsor_u (see propagate()).
  template<ValidRegionFrame Frame>
#if defined(__GNUC__)
  __attribute__((always_inline)) // once per examined entry: not worth a call
#endif
  Eigen::Vector3d
  required_displacement(const Node& c, index_t sponsor_slot) const
  {
    // The nearest point of c's valid region w.r.t. the sponsor moved in `sponsor_slot` to
    // c's rest position (required_displacement() in valid_region.h, on the per-rank
    // parameters): zero when c may stay at rest.
    const MovedRecord& s = moved_rec_[std::size_t(sponsor_slot)];
    const Eigen::Vector3d o = c.rest - nodes_[std::size_t(s.vertex)].rest;
    if (!o.allFinite())
      return Eigen::Vector3d::Zero();
    return geoshaping::required_displacement<Frame>(o, rank_params_[std::size_t(c.rank)], s.disp);
  }
  // Starts loading the records of internal vertex i's neighbours, which the push after
  // its move tests.
  void prefetch_neighbour_records(std::size_t i) const
  {
    for (std::uint32_t e = offsets_[i]; e < offsets_[i + 1]; ++e)
      prefetch(&nodes_[std::size_t(neighbors_[e])]);
  }
  // The rule of a superstep for a candidate several of its sponsors would move
  // (docs/deformer.md, "Order"): whether the target `u` of a later entry (in push order)
  // replaces `best`, the target the candidate holds: when it is longer, |u|^2 > |best|^2
  // as computed. So the longest target wins, the first in push order (sponsor global id
  // order) among exactly equal lengths.
  static bool sponsor_wins(const Eigen::Vector3d& u, const Eigen::Vector3d& best)
  {
    return u.squaredNorm() > best.squaredNorm();
  }
  // gate false: d passes the obstacle gate later (sort_moves()).
  void move(index_t inner_vertex, const Eigen::Vector3d& d, index_t sponsor_slot,
    const SuperstepRoot& root = {}, bool gate = true);
  std::int64_t global_id_inner(index_t i) const
  {
    return gid_.empty() ? std::int64_t(outer_of_[std::size_t(i)]) : gid_[std::size_t(i)];
  }
  // Whether the moves in slots [begin, end) are in global id order; their order by id
  // (by_id_, offsets from begin).
  bool ids_sorted(std::size_t begin, std::size_t end) const;
  // end_superstep()'s pushes (Banded: FIFO Priority's bands and roots).
  template<bool Banded>
  void push_neighbours();
  // by_id_: the slots [begin, end) in global id order, [begin, sorted) already in it.
  void sort_by_id(std::size_t begin, std::size_t end, std::size_t sorted);
  // Puts the moves a superstep made from `begin` on into global id order (slots,
  // moved()) and passes them through the obstacle gate in that order.
  void sort_moves(std::size_t begin);
  // The obstacle gate of move() (see the class comment): d or the admissible part of it.
  Eigen::Vector3d admissible(index_t inner_vertex, const Eigen::Vector3d& d);
  void build_rigid_components();

  mutable std::shared_ptr<const Adjacency> caller_adjacency_; // built by adjacency()
  std::vector<std::uint32_t> offsets_; // internal CSR: rows in internal order, each row's
  std::vector<index_t> neighbors_;     // neighbours in the caller's order, internal ids
  std::vector<index_t> inner_of_;      // caller id -> internal id
  std::vector<index_t> outer_of_;      // internal id -> caller id
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  std::vector<Node> nodes_;               // by internal id
  std::vector<index_t> slot_;             // by internal id: slot when moved this frame
  std::vector<float> distinct_;           // the sorted distinct malleability values (rank -> value)
  std::vector<RegionParams> rank_params_; // per rank: (t - 1, k - 1, h), evaluated once
  std::vector<std::uint32_t> rank_band_;  // per rank: the band (SuperstepQueue) of its value
  std::vector<std::int64_t> gid_;         // by internal id; empty: the caller's ids
  std::vector<std::uint8_t> ghost_;       // by internal id; empty: all owned
  index_t num_ranks_ = 1;
  std::vector<std::uint8_t> pinned_;       // by caller id; empty when none
  std::vector<std::uint8_t> pinned_inner_; // by internal id; empty when none
  std::vector<Eigen::Vector3d> committed_; // by caller id; empty until the first edit
  Eigen::Vector3d zero_ = Eigen::Vector3d::Zero();
  std::uint32_t frame_ = 0;
  std::vector<index_t> moved_, previously_moved_;                           // caller ids
  std::vector<MovedRecord, UninitializedAllocator<MovedRecord>> moved_rec_; // by slot
  std::vector<StoredRoot, UninitializedAllocator<StoredRoot>> moved_root_;  // by slot
  std::vector<std::pair<std::int64_t, std::uint32_t>> by_id_key_;           // sort_by_id() scratch
  std::vector<std::uint32_t> by_id_;
  std::vector<MovedRecord> moved_scratch_;

  TransferFunction transfer_;
  QueueKind queue_kind_ = QueueKind::fifo_priority;
  ValidRegionFrame frame_kind_ = ValidRegionFrame::axes;
  HeapPriorityQueue heap_;
  MaxViolationQueue violation_;
  SuperstepQueue supersteps_;
  // Obstacles and the rigid components their gate moves as one (empty rigid_of_: not
  // built yet; built on the first gated move).
  std::shared_ptr<const Obstacles> obstacles_; // immutable: copies of the deformer share it
  double clearance_ = 0.0;
  std::vector<index_t> rigid_of_;          // by internal id: component, -1 soft or pinned
  std::vector<std::uint32_t> rigid_first_; // CSR of the components' members (internal)
  std::vector<index_t> rigid_members_;
  std::vector<std::uint32_t> rigid_stamp_;  // == frame_: the component moved this frame
  std::vector<Eigen::Vector3d> rigid_disp_; // by rigid_disp_[component]
  std::vector<std::uint8_t> rank_rigid_;    // rigid per rank when the components were built
  std::vector<std::uint8_t> sliding_;       // by internal id; empty when none
  double last_fraction_ = 1.0;              // of the last gated move
  std::size_t blocked_ = 0;
  bool rigid_split_ = false;        // a component holds a ghost (build_rigid_components)
  std::uint32_t superstep_ = 0;     // the current superstep of the frame
  std::size_t superstep_begin_ = 0; // slot of its first move
  std::size_t sorted_begin_ = 0, sorted_end_ = 0; // slots sort_moves() left in id order
  int threads_ = 1;
  std::size_t threaded_threshold_ = 512; // docs/benchmarks.md, "Threaded frame"
  std::size_t threaded_supersteps_ = 0;  // this frame's
  // The back-off after a stall ("Threads"): this frame runs on one thread from here on;
  // frames still to run on one thread; the length of the last back-off.
  ThreadUse thread_use_ = ThreadUse::when_cores_free;
  bool threads_paused_ = false;
  std::uint32_t paused_frames_ = 0, backoff_ = 0;
  std::uint32_t load_frame_ = 0; // the frame cores_free() last read the machine in
  bool cores_taken_ = false;
  ThreadedHandle threaded_;
};

} // namespace geoshaping
