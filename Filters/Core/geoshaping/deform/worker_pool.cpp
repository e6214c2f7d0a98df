#include "geoshaping/deform/worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace geoshaping
{

namespace
{
// Spins of about 10-40 ns before a waiting thread blocks: some tens of microseconds, longer
// than the one-thread part between two large supersteps, far shorter than a frame.
constexpr int spins_before_blocking = 256;

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
  for (int i = 0; i < spins_before_blocking; ++i)
  {
    if (generation_.load(std::memory_order_acquire) != gen)
      return;
    pause();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  sleepers_.fetch_add(1);
  wake_.wait(lock, [&] { return generation_.load() != gen; });
  sleepers_.fetch_sub(1);
}

} // namespace geoshaping
