#pragma once
// Exchange (exchange.h) between pieces run by threads of one process: the tests' (and the
// report's) stand-in for MPI. One InProcessHub is shared; each
// piece's thread uses its own InProcessExchange. Collectives meet at a barrier, so the
// calls must be made in the same order on every piece, as with MPI.
//
// Cost: one barrier per collective. The slots a collective writes alternate between two
// sets, so a piece may write the next collective's slot while another still reads this
// one's (a piece reaches collective k + 2 only after every piece has left collective k).
// The barrier spins briefly, then sleeps: a frame runs a few hundred to tens of thousands
// of rounds (two collectives each), too many for a sleep and a wake-up each when the cores
// are free, and a waiting thread must not take the core from the one it waits for when
// they are not.
#include "geoshaping/parallel/exchange.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

namespace geoshaping
{

class InProcessHub
{
public:
  explicit InProcessHub(int pieces);
  int pieces() const { return pieces_; }

private:
  friend class InProcessExchange;
  void barrier();
  int pieces_;
  alignas(64) std::atomic<int> waiting_{ 0 };
  alignas(64) std::atomic<std::uint64_t> generation_{ 0 };
  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<std::vector<std::int64_t>> gathered_[2];         // [set][piece]
  std::vector<std::vector<std::vector<MovedVertex>>> mail_[2]; // [set][from][to]
};

class InProcessExchange : public Exchange
{
public:
  InProcessExchange(InProcessHub& hub, int piece)
    : hub_(hub)
    , piece_(piece)
  {
  }
  int pieces() const override { return hub_.pieces(); }
  int piece() const override { return piece_; }
  std::vector<std::vector<std::int64_t>> all_gather(
    const std::vector<std::int64_t>& values) override;
  std::vector<std::vector<MovedVertex>> exchange(const std::vector<int>& to,
    const std::vector<std::vector<MovedVertex>>& out, const std::vector<int>& from) override;

private:
  InProcessHub& hub_;
  int piece_;
  unsigned set_ = 0; // the slot set of the next collective
};

// Runs body(piece, exchange) for pieces 0 .. pieces - 1, piece 0 on the calling thread and
// each other piece on a thread of its own, with an InProcessExchange of one shared hub.
void run_in_pieces(int pieces, const std::function<void(int piece, Exchange& exchange)>& body);

} // namespace geoshaping
