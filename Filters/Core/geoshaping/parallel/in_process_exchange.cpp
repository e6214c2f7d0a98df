#include "geoshaping/parallel/in_process_exchange.h"

#include <thread>

namespace geoshaping
{

InProcessHub::InProcessHub(int pieces)
  : pieces_(pieces)
{
  for (unsigned s = 0; s < 2; ++s)
  {
    gathered_[s].resize(std::size_t(pieces));
    mail_[s].assign(
      std::size_t(pieces), std::vector<std::vector<MovedVertex>>(std::size_t(pieces)));
  }
}

void InProcessHub::barrier()
{
  const std::uint64_t generation = generation_.load(std::memory_order_acquire);
  if (waiting_.fetch_add(1, std::memory_order_acq_rel) + 1 == pieces_)
  {
    waiting_.store(0, std::memory_order_relaxed);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      generation_.store(generation + 1, std::memory_order_release);
    }
    cv_.notify_all();
    return;
  }
  for (int spin = 0; spin < 2000; ++spin)
    if (generation_.load(std::memory_order_acquire) != generation)
      return;
  std::unique_lock<std::mutex> lock(mutex_);
  cv_.wait(lock, [&] { return generation_.load(std::memory_order_acquire) != generation; });
}

// Each collective: write this piece's slot of the current set, meet, read every slot.
std::vector<std::vector<std::int64_t>> InProcessExchange::all_gather(
  const std::vector<std::int64_t>& values)
{
  auto& gathered = hub_.gathered_[set_];
  set_ ^= 1u;
  gathered[std::size_t(piece_)] = values;
  hub_.barrier();
  return gathered;
}

std::vector<std::vector<MovedVertex>> InProcessExchange::exchange(const std::vector<int>& to,
  const std::vector<std::vector<MovedVertex>>& out, const std::vector<int>& from)
{
  auto& mail = hub_.mail_[set_];
  set_ ^= 1u;
  for (std::size_t i = 0; i < to.size(); ++i)
  {
    mail[std::size_t(piece_)][std::size_t(to[i])] = out[i];
    bytes_sent_ += out[i].size() * sizeof(MovedVertex);
  }
  hub_.barrier();
  std::vector<std::vector<MovedVertex>> in;
  in.reserve(from.size());
  for (int q : from)
    in.push_back(mail[std::size_t(q)][std::size_t(piece_)]);
  return in;
}

void run_in_pieces(int pieces, const std::function<void(int piece, Exchange& exchange)>& body)
{
  InProcessHub hub(pieces);
  std::vector<std::thread> threads;
  for (int p = 1; p < pieces; ++p)
    threads.emplace_back(
      [&, p]
      {
        InProcessExchange ex(hub, p);
        body(p, ex);
      });
  {
    InProcessExchange ex(hub, 0);
    body(0, ex);
  }
  for (auto& t : threads)
    t.join();
}

} // namespace geoshaping
