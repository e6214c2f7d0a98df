#pragma once
// A naive Generalized ChainMail, the yardstick of the core's speed (docs/benchmarks.md):
// insertion-order queues (one std::deque per malleability band for FIFO-PQ, one for
// FIFO), the caller's CSR adjacency and ids, per-vertex state in plain vectors, the
// transfer function evaluated once per vertex. No renumbering, no supersteps: its order
// is the sequential one, which no partition into pieces can reproduce, so it moves the
// same vertices as the core only where the order does not matter (one sponsor per
// vertex, rigid regions). The valid region is valid_region.h's, the one definition.
// deform_textbook() is the textbook FIFO-preserving priority queue: one std::priority_queue
// keyed by (malleability, insertion counter), so equal values come out first in, first out
// and any number of distinct values costs O(log P) per entry.
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/deform/valid_region.h"
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <cstdint>
#include <deque>
#include <functional>
#include <queue>
#include <vector>

namespace geoshaping::bench
{

class NaiveChainMail
{
public:
  // `xyz` and `adjacency` are kept by reference (they must outlive the object).
  NaiveChainMail(const double* xyz, const Adjacency& adjacency, const float* malleability,
    const TransferFunction& tf = {});
  // One frame from rest: the grasp moves by d, the others by propagation. `banded`:
  // FIFO-PQ (lowest malleability band first), else plain FIFO. Returns moved vertices.
  std::size_t deform(index_t grasp, const Eigen::Vector3d& d, bool banded);
  // The same frame in the textbook priority queue's order (exact malleability, then
  // insertion). Returns moved vertices.
  std::size_t deform_textbook(index_t grasp, const Eigen::Vector3d& d);
  const std::vector<index_t>& moved() const { return moved_; }
  bool moved(index_t v) const { return stamp_[std::size_t(v)] == frame_; }
  const Eigen::Vector3d& displacement(index_t v) const { return disp_[std::size_t(v)]; }
  index_t sponsor(index_t v) const { return sponsor_[std::size_t(v)]; }

private:
  struct Entry
  {
    index_t candidate, sponsor;
  };
  struct Keyed
  {
    float malleability;
    std::uint64_t counter;
    Entry entry;
    bool operator>(const Keyed& o) const
    {
      return malleability != o.malleability ? malleability > o.malleability : counter > o.counter;
    }
  };
  enum class Order
  {
    fifo,    // one deque
    banded,  // a deque per distinct value, the lowest first
    textbook // heap_ on (malleability, insertion counter)
  };
  void move(index_t v, const Eigen::Vector3d& u, index_t sponsor, Order order);
  void examine(const Entry& e, Order order);
  const double* xyz_;
  const Adjacency& adj_;
  std::vector<RegionParams> params_; // per vertex
  std::vector<std::uint32_t> band_;  // per vertex: rank of its malleability
  std::vector<std::deque<Entry>> queues_;
  std::vector<float> malleability_; // per vertex, as given
  std::priority_queue<Keyed, std::vector<Keyed>, std::greater<Keyed>> heap_;
  std::uint64_t counter_ = 0;
  std::size_t lowest_ = 0; // no queue below it holds an entry
  std::vector<std::uint32_t> stamp_;
  std::vector<Eigen::Vector3d> disp_;
  std::vector<index_t> sponsor_, moved_;
  std::uint32_t frame_ = 0;
};

} // namespace geoshaping::bench
