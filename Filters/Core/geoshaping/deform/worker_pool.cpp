#include "geoshaping/deform/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace geoshaping
{

namespace
{
// How long a waiting thread spins before it blocks: longer than the one-thread part
// between two large supersteps (tens of microseconds), short against the pause between
// frames. Blocking sooner costs a wake-up per barrier, several per superstep, which on idle
// cores made two threads slower than one (docs/benchmarks.md, "Threaded frame").
constexpr std::chrono::microseconds spin_before_blocking{ 2000 };

inline void pause()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

// When this thread last left a barrier (or started a run): its work since is the time
// from there to its next barrier.
thread_local std::chrono::steady_clock::time_point left_barrier;
} // namespace

WorkerPool::WorkerPool(int threads)
  : threads_(threads < 1 ? 1 : threads)
{
  for (int t = 1; t < threads_; ++t)
    workers_.emplace_back([this, t] { work(t); });
}

WorkerPool::~WorkerPool()
{
  stop_ = true;
  if (!workers_.empty())
    barrier(); // the workers' start of a run: they see stop_ and return
  for (std::thread& w : workers_)
    w.join();
}

void WorkerPool::work(int t)
{
  for (;;)
  {
    barrier(false);
    if (stop_)
      return;
    call_(job_, t);
    barrier(true);
  }
}

void WorkerPool::run_erased(void (*call)(void*, int), void* job)
{
  call_ = call;
  job_ = job;
  stalled_.store(false, std::memory_order_relaxed);
  if (workers_.empty())
  {
    call(job, 0);
    return;
  }
  barrier(false);
  call(job, 0);
  barrier(true);
}

void WorkerPool::barrier(bool in_job)
{
  // Sense by generation: the last of threads_ arrivals resets the count and starts the
  // next generation. seq_cst on generation_ and sleepers_: a waiter that found the old
  // generation after announcing itself is seen by the last arrival, which then notifies
  // under the mutex the waiter holds until it waits.
  const std::uint32_t gen = generation_.load();
  if (arrived_.fetch_add(1) + 1 == threads_)
  {
    arrived_.store(0, std::memory_order_relaxed);
    generation_.store(gen + 1);
    if (sleepers_.load() > 0)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      wake_.notify_all();
    }
    left_barrier = std::chrono::steady_clock::now();
    return;
  }
  using clock = std::chrono::steady_clock;
  const clock::time_point arrived = clock::now();
  // Longer than this, and the thread waited for ran at under half this one's speed.
  const clock::duration stall = std::max<clock::duration>(stall_floor, arrived - left_barrier);
  bool waited_long = false;
  for (clock::time_point now = arrived; now - arrived < spin_before_blocking; now = clock::now())
  {
    for (int i = 0; i < 64; ++i)
    {
      if (generation_.load(std::memory_order_acquire) != gen)
      {
        left_barrier = clock::now();
        return;
      }
      pause();
    }
    if (in_job && !waited_long && now - arrived > stall)
    {
      waited_long = true;
      stalled_.store(true, std::memory_order_relaxed);
    }
    if (now - arrived > yield_after)
      std::this_thread::yield();
  }
  if (in_job)
    stalled_.store(true, std::memory_order_relaxed);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    sleepers_.fetch_add(1);
    wake_.wait(lock, [&] { return generation_.load() != gen; });
    sleepers_.fetch_sub(1);
  }
  left_barrier = clock::now();
}

int WorkerPool::runnable_in_loadavg(const char* line)
{
  // Fields: three load averages, then "runnable/total", then the last pid.
  int runnable = -1, total = 0;
  return std::sscanf(line, "%*s %*s %*s %d/%d", &runnable, &total) == 2 && runnable >= 0 ? runnable
                                                                                         : -1;
}

int WorkerPool::others_running(const WorkerPool* pool)
{
  std::FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f)
    return -1;
  char line[128] = {};
  const bool read = std::fgets(line, sizeof line, f) != nullptr;
  std::fclose(f);
  const int runnable = read ? runnable_in_loadavg(line) : -1;
  if (runnable < 0)
    return -1;
  const int spinning = pool ? int(pool->workers_.size()) - pool->sleepers_.load() : 0;
  return std::max(0, runnable - 1 - spinning);
}

} // namespace geoshaping
