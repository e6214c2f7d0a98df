#pragma once
// One scene timed three ways, frame by frame in turn (core, naive, textbook, core, ...) in
// thread CPU time, so load drifting during the run weighs on all three alike: the core's
// FIFO or FIFO Priority frame, the naive ChainMail (naive_chainmail.h: FIFO, or FIFO-PQ
// with one deque per distinct value) and, for FIFO Priority, the textbook
// FIFO-preserving priority queue (NaiveChainMail::deform_textbook). Counters: each one's
// ms per frame and displaced count, `speedup` = naive / core, `vs_textbook` = textbook /
// core per frame and `vs_textbook_per_vertex` per displaced vertex (the orders differ, so
// one pull may displace different counts).
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/parallel/thread_clock.h"
#include "naive_chainmail.h"

#include <benchmark/benchmark.h>

#include <string>

namespace geoshaping::bench
{

inline void time_against_references(benchmark::State& state, ChainMailDeformer& core,
  NaiveChainMail& naive, index_t grasp, double pull, const std::string& scene)
{
  const bool banded = core.queue() == QueueKind::fifo_priority;
  const Eigen::Vector3d d(0.0, 0.0, pull);
  double core_s = 0.0, naive_s = 0.0, textbook_s = 0.0;
  std::size_t naive_moved = 0, textbook_moved = 0;
  FrameResult r;
  for (auto _ : state)
  {
    const double t0 = thread_cpu_seconds();
    r = core.deform(grasp, d);
    const double t1 = thread_cpu_seconds();
    naive_moved = naive.deform(grasp, d, banded);
    const double t2 = thread_cpu_seconds();
    if (banded)
      textbook_moved = naive.deform_textbook(grasp, d);
    const double t3 = thread_cpu_seconds();
    core_s += t1 - t0;
    naive_s += t2 - t1;
    textbook_s += t3 - t2;
  }
  const double n = double(state.iterations());
  state.counters["displaced"] = double(r.moved);
  state.counters["examined"] = double(r.examined);
  state.counters["supersteps"] = double(r.supersteps);
  state.counters["naive_displaced"] = double(naive_moved);
  state.counters["core_ms"] = 1e3 * core_s / n;
  state.counters["naive_ms"] = 1e3 * naive_s / n;
  state.counters["speedup"] = naive_s / core_s;
  if (banded)
  {
    state.counters["textbook_ms"] = 1e3 * textbook_s / n;
    state.counters["textbook_displaced"] = double(textbook_moved);
    state.counters["vs_textbook"] = textbook_s / core_s;
    state.counters["vs_textbook_per_vertex"] =
      (textbook_s / double(textbook_moved)) / (core_s / double(r.moved));
  }
  state.SetLabel(std::string(queue_name(core.queue())) + " " + scene);
}

} // namespace geoshaping::bench
