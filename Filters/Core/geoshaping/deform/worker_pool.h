#pragma once
// A fixed set of threads that run one job together, for the deformer's large supersteps
// (chainmail_deformer.h, "Threads"). The caller is thread 0 of every run; the others wait
// between runs, first spinning for up to 2 ms (a frame's supersteps follow one another within
// microseconds), then blocked on a condition variable (between frames).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace geoshaping
{

class WorkerPool
{
public:
  // `threads` >= 1, the caller included (threads - 1 are started).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  int size() const { return threads_; }

  // Runs job(t) for t = 0 .. size() - 1, t = 0 on the calling thread, and returns when
  // every thread has returned. A job must not throw. Not reentrant.
  template<class Job>
  void run(Job& job)
  {
    run_erased([](void* j, int t) { (*static_cast<Job*>(j))(t); }, &job);
  }
  // Inside a job: returns once every thread of the run has called it; what a thread wrote
  // before it is visible to all after it.
  void barrier();

private:
  void run_erased(void (*call)(void*, int), void* job);
  void work(int t);

  int threads_;
  std::vector<std::thread> workers_;
  void (*call_)(void*, int) = nullptr;
  void* job_ = nullptr;
  bool stop_ = false;
  // The barrier: arrivals in this generation; the generation, bumped by the last arrival.
  std::atomic<int> arrived_{ 0 };
  std::atomic<std::uint32_t> generation_{ 0 };
  std::atomic<int> sleepers_{ 0 };
  std::mutex mutex_;
  std::condition_variable wake_;
};

} // namespace geoshaping
