#include "geoshaping/deform/worker_pool.h"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace geoshaping
{

namespace
{
// How long a waiting thread spins before it blocks: longer than the one-thread part
// between two large supersteps (tens of microseconds), short against the pause between
// frames. Blocking sooner costs a wake-up per barrier: with 256 spins (~10 us) two threads
// ran a 1,000,000-vertex FIFO frame at 0.47-0.61x one thread on two idle cores (five
// barriers in each of 633 supersteps), with spinning up to 1-10 ms at 1.13-1.48x.
constexpr std::chrono::microseconds spin_before_blocking{ 2000 };

inline void pause()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}
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
    barrier();
    if (stop_)
      return;
    call_(job_, t);
    barrier();
  }
}

void WorkerPool::run_erased(void (*call)(void*, int), void* job)
{
  call_ = call;
  job_ = job;
  if (workers_.empty())
  {
    call(job, 0);
    return;
  }
  barrier();
  call(job, 0);
  barrier();
}

void WorkerPool::barrier()
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
    return;
  }
  const auto until = std::chrono::steady_clock::now() + spin_before_blocking;
  do
  {
    for (int i = 0; i < 64; ++i)
    {
      if (generation_.load(std::memory_order_acquire) != gen)
        return;
      pause();
    }
  } while (std::chrono::steady_clock::now() < until);
  std::unique_lock<std::mutex> lock(mutex_);
  sleepers_.fetch_add(1);
  wake_.wait(lock, [&] { return generation_.load() != gen; });
  sleepers_.fetch_sub(1);
}

} // namespace geoshaping
