#include "in_process_exchange.h"

#include <algorithm>

namespace geoshaping
{

InProcessHub::InProcessHub(int pieces)
  : pieces_(pieces)
  , gathered_(std::size_t(pieces))
  , mail_(std::size_t(pieces), std::vector<std::vector<MovedVertex>>(std::size_t(pieces)))
{
}

void InProcessHub::barrier()
{
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t generation = generation_;
  if (++waiting_ == pieces_)
  {
    waiting_ = 0;
    ++generation_;
    cv_.notify_all();
    return;
  }
  cv_.wait(lock, [&] { return generation_ != generation; });
}

// Each collective: write this piece's slot, meet, read every slot, meet again (so no
// piece overwrites a slot before all have read it).
std::vector<std::vector<std::int64_t>> InProcessExchange::all_gather(
  const std::vector<std::int64_t>& values)
{
  hub_.gathered_[std::size_t(piece_)] = values;
  hub_.barrier();
  std::vector<std::vector<std::int64_t>> all = hub_.gathered_;
  hub_.barrier();
  return all;
}

std::vector<std::vector<MovedVertex>> InProcessExchange::exchange(const std::vector<int>& to,
  const std::vector<std::vector<MovedVertex>>& out, const std::vector<int>& from)
{
  for (std::size_t i = 0; i < to.size(); ++i)
  {
    hub_.mail_[std::size_t(piece_)][std::size_t(to[i])] = out[i];
    bytes_sent_ += out[i].size() * sizeof(MovedVertex);
  }
  hub_.barrier();
  std::vector<std::vector<MovedVertex>> in;
  in.reserve(from.size());
  for (int q : from)
    in.push_back(hub_.mail_[std::size_t(q)][std::size_t(piece_)]);
  hub_.barrier();
  return in;
}

} // namespace geoshaping
