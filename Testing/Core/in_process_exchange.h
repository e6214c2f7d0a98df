#pragma once
// Exchange (exchange.h) between pieces run by threads of one process: the
// tests' stand-in for MPI. One InProcessHub is shared; each piece's thread uses its own
// InProcessExchange. Collectives meet at a barrier, so the calls must be made in the
// same order on every piece, as with MPI.
#include "geoshaping/parallel/exchange.h"

#include <condition_variable>
#include <mutex>

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
  std::mutex mutex_;
  std::condition_variable cv_;
  int waiting_ = 0;
  std::uint64_t generation_ = 0;
  std::vector<std::vector<std::int64_t>> gathered_;
  std::vector<std::vector<std::vector<MovedVertex>>> mail_; // [from][to]
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
};

} // namespace geoshaping
