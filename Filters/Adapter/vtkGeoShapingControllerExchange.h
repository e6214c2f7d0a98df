// geoshaping::Exchange (exchange.h) over a vtkMultiProcessController, for
// the GeoShaping filters' distributed paths (ChainMailDeformation, MalleabilityPaint):
// header-only; a filter that includes it depends on VTK::ParallelCore.
#ifndef vtkGeoShapingControllerExchange_h
#define vtkGeoShapingControllerExchange_h

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include "geoshaping/parallel/exchange.h"

#include <algorithm>
#include <vector>

// geoshaping::Exchange over a vtkMultiProcessController: collectives by AllGather, the
// moved frontier by Send/Receive to neighbour processes only (all_to_all, at setup, to
// every process), in an order every pair of processes agrees on (pairs in increasing
// (lower, higher) order, the lower sends first), so blocking sends cannot deadlock.
class vtkGeoShapingControllerExchange : public geoshaping::Exchange
{
public:
  // `tag`: the first of the two message tags this exchange uses (one per filter, so two
  // filters' messages never mix).
  vtkGeoShapingControllerExchange(vtkMultiProcessController* c, int tag)
    : Controller(c)
    , Tag(tag)
  {
  }
  int pieces() const override { return this->Controller->GetNumberOfProcesses(); }
  int piece() const override { return this->Controller->GetLocalProcessId(); }

  std::vector<geoshaping::RoundState> all_round_states(const geoshaping::RoundState& state) override
  {
    std::vector<unsigned long long> all(5 * std::size_t(this->pieces()));
    const unsigned long long mine[5] = { state.pending[0], state.pending[1], state.pending[2],
      state.pending[3], state.superstep };
    this->Controller->AllGather(mine, all.data(), 5);
    std::vector<geoshaping::RoundState> out;
    for (std::size_t p = 0; p < all.size(); p += 5)
      out.push_back({ { all[p], all[p + 1], all[p + 2], all[p + 3] }, all[p + 4] });
    return out;
  }

  std::vector<std::vector<std::int64_t>> all_gather(
    const std::vector<std::int64_t>& values) override
  {
    const int n = this->pieces();
    std::vector<vtkIdType> lengths(static_cast<std::size_t>(n)), offsets(std::size_t(n) + 1, 0);
    const vtkIdType mine = vtkIdType(values.size());
    this->Controller->AllGather(&mine, lengths.data(), 1);
    for (int p = 0; p < n; ++p)
      offsets[std::size_t(p) + 1] = offsets[std::size_t(p)] + lengths[std::size_t(p)];
    std::vector<long long> send(values.begin(), values.end()), all(std::size_t(offsets.back()));
    this->Controller->GetCommunicator()->AllGatherV(
      send.data(), all.data(), mine, lengths.data(), offsets.data());
    std::vector<std::vector<std::int64_t>> out(static_cast<std::size_t>(n));
    for (int p = 0; p < n; ++p)
      out[std::size_t(p)].assign(
        all.begin() + offsets[std::size_t(p)], all.begin() + offsets[std::size_t(p) + 1]);
    return out;
  }

  std::vector<std::vector<geoshaping::MovedVertex>> exchange(const std::vector<int>& to,
    const std::vector<std::vector<geoshaping::MovedVertex>>& out,
    const std::vector<int>& from) override
  {
    std::vector<std::vector<geoshaping::MovedVertex>> in(from.size());
    std::vector<int> peers(to);
    peers.insert(peers.end(), from.begin(), from.end());
    std::sort(peers.begin(), peers.end());
    peers.erase(std::unique(peers.begin(), peers.end()), peers.end());
    for (int q : peers)
    {
      const auto t = std::find(to.begin(), to.end(), q);
      const auto f = std::find(from.begin(), from.end(), q);
      this->Pair(q, t == to.end() ? nullptr : &out[std::size_t(t - to.begin())],
        f == from.end() ? nullptr : &in[std::size_t(f - from.begin())], Tag);
      if (t != to.end())
        this->bytes_sent_ +=
          out[std::size_t(t - to.begin())].size() * sizeof(geoshaping::MovedVertex);
    }
    return in;
  }

  std::vector<std::vector<std::int64_t>> all_to_all(
    const std::vector<std::vector<std::int64_t>>& out) override
  {
    const int me = this->piece();
    std::vector<std::vector<std::int64_t>> in(out.size());
    in[std::size_t(me)] = out[std::size_t(me)];
    for (int q = 0; q < this->pieces(); ++q)
      if (q != me)
        this->Pair(q, &out[std::size_t(q)], &in[std::size_t(q)], Tag + 2);
    return in;
  }

private:
  // Sends `send` to and receives `receive` from process q (either may be null), the lower
  // process sending first: a count (tag) then the values as bytes (tag + 1).
  template<class T>
  void Pair(int q, const std::vector<T>* send, std::vector<T>* receive, int tag)
  {
    auto put = [&]
    {
      if (!send)
        return;
      const vtkIdType count = vtkIdType(send->size());
      this->Controller->Send(&count, 1, q, tag);
      if (count > 0)
        this->Controller->Send(
          reinterpret_cast<const char*>(send->data()), count * vtkIdType(sizeof(T)), q, tag + 1);
    };
    auto get = [&]
    {
      if (!receive)
        return;
      vtkIdType count = 0;
      this->Controller->Receive(&count, 1, q, tag);
      receive->resize(std::size_t(count));
      if (count > 0)
        this->Controller->Receive(
          reinterpret_cast<char*>(receive->data()), count * vtkIdType(sizeof(T)), q, tag + 1);
    };
    if (this->piece() < q)
    {
      put();
      get();
    }
    else
    {
      get();
      put();
    }
  }

  vtkMultiProcessController* Controller;
  const int Tag;
};

#endif
