#include "naive_chainmail.h"

#include <algorithm>

namespace geoshaping::bench
{

NaiveChainMail::NaiveChainMail(const double* xyz, const Adjacency& adjacency,
  const float* malleability, const TransferFunction& tf)
  : xyz_(xyz)
  , adj_(adjacency)
  , malleability_(malleability, malleability + adjacency.size())
{
  const std::size_t n = std::size_t(adjacency.size());
  std::vector<float> values(malleability, malleability + n);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  params_.resize(n);
  band_.resize(n);
  for (std::size_t v = 0; v < n; ++v)
  {
    params_[v] = region_params(tf(malleability[v]));
    band_[v] = std::uint32_t(
      std::lower_bound(values.begin(), values.end(), malleability[v]) - values.begin());
  }
  queues_.resize(std::max<std::size_t>(values.size(), 1));
  stamp_.assign(n, 0);
  disp_.assign(n, Eigen::Vector3d::Zero());
  sponsor_.assign(n, -1);
}

void NaiveChainMail::move(index_t v, const Eigen::Vector3d& u, index_t sponsor, Order order)
{
  stamp_[std::size_t(v)] = frame_;
  disp_[std::size_t(v)] = u;
  sponsor_[std::size_t(v)] = sponsor;
  moved_.push_back(v);
  for (const index_t* c = adj_.begin(v); c != adj_.end(v); ++c)
  {
    if (stamp_[std::size_t(*c)] == frame_)
      continue;
    if (order == Order::textbook)
    {
      heap_.push({ malleability_[std::size_t(*c)], counter_++, { *c, v } });
      continue;
    }
    const std::size_t q = order == Order::banded ? band_[std::size_t(*c)] : 0;
    queues_[q].push_back({ *c, v });
    lowest_ = std::min(lowest_, q);
  }
}

void NaiveChainMail::examine(const Entry& e, Order order)
{
  if (stamp_[std::size_t(e.candidate)] == frame_)
    return;
  const Eigen::Vector3d o =
    Eigen::Vector3d(xyz_ + 3 * e.candidate) - Eigen::Vector3d(xyz_ + 3 * e.sponsor);
  const Eigen::Vector3d u = required_displacement<ValidRegionFrame::axes>(
    o, params_[std::size_t(e.candidate)], disp_[std::size_t(e.sponsor)]);
  if (!u.isZero(0.0))
    move(e.candidate, u, e.sponsor, order);
}

std::size_t NaiveChainMail::deform(index_t grasp, const Eigen::Vector3d& d, bool banded)
{
  ++frame_;
  moved_.clear();
  lowest_ = 0;
  const Order order = banded ? Order::banded : Order::fifo;
  move(grasp, d, -1, order);
  for (;;)
  {
    while (lowest_ < queues_.size() && queues_[lowest_].empty())
      ++lowest_;
    if (lowest_ == queues_.size())
      break;
    const Entry e = queues_[lowest_].front();
    queues_[lowest_].pop_front();
    examine(e, order);
  }
  return moved_.size();
}

std::size_t NaiveChainMail::deform_textbook(index_t grasp, const Eigen::Vector3d& d)
{
  ++frame_;
  moved_.clear();
  counter_ = 0;
  move(grasp, d, -1, Order::textbook);
  while (!heap_.empty())
  {
    const Entry e = heap_.top().entry;
    heap_.pop();
    examine(e, Order::textbook);
  }
  return moved_.size();
}

} // namespace geoshaping::bench
