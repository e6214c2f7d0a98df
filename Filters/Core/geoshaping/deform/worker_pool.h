#pragma once
// A fixed set of threads that run one job together, for the deformer's large supersteps
// (chainmail_deformer.h, "Threads"). The caller is thread 0 of every run; the others wait
// between runs, first spinning for up to 2 ms (a frame's supersteps follow one another within
// microseconds), then blocked on a condition variable (between frames).
//
// A busy machine: when another process holds the core of one of the threads, the others
// wait for it at each barrier for as long as the scheduler keeps it off (milliseconds),
// and a run takes longer than on one thread. The pool notices it and says so (stalled()):
// a thread that waits at a barrier inside a job for longer than it worked since the last
// one (and longer than `stall_floor`) means another ran at less than half its speed,
// where T threads cannot beat one. A wait past `yield_after` yields the core instead of
// spinning on it, so the thread waited for can run there.
//
// Before a run the caller may ask whether other threads hold the cores (others_running(),
// cores_short()): Linux counts the runnable threads of the whole machine at this instant
// (/proc/loadavg), so a process spinning beside the pool is seen before a run stalls on it.
#include <atomic>
#include <chrono>
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
  void barrier() { barrier(true); }
  // Whether a thread of the last run waited at a barrier inside the job for longer than it
  // had worked since its previous barrier, and longer than stall_floor (see above).
  bool stalled() const { return stalled_.load(std::memory_order_relaxed); }

  // The threads of the machine runnable now other than the caller and this pool's workers
  // still spinning between runs; -1 where that cannot be read (no /proc/loadavg). A pool
  // not yet made counts none of its own: others_running(nullptr).
  static int others_running(const WorkerPool* pool);
  // The runnable count of a /proc/loadavg line ("0.52 0.58 0.59 3/467 1234": 3), -1 if the
  // line has none.
  static int runnable_in_loadavg(const char* line);
  // Whether `threads` threads would share a core with one of `others` runnable threads on a
  // machine of `cores` (others > cores - threads); an unknown count (-1) is not short.
  static bool cores_short(int others, int cores, int threads)
  {
    return others >= 0 && others > cores - threads;
  }

private:
  void run_erased(void (*call)(void*, int), void* job);
  void work(int t);
  // in_job: a barrier inside a run (a long wait there is a stall), not the one that starts
  // a run (workers wait there between runs).
  void barrier(bool in_job);
  static constexpr std::chrono::microseconds stall_floor{ 1000 };
  static constexpr std::chrono::microseconds yield_after{ 50 };

  int threads_;
  std::vector<std::thread> workers_;
  void (*call_)(void*, int) = nullptr;
  void* job_ = nullptr;
  bool stop_ = false;
  // The barrier: arrivals in this generation; the generation, bumped by the last arrival.
  std::atomic<int> arrived_{ 0 };
  std::atomic<std::uint32_t> generation_{ 0 };
  std::atomic<int> sleepers_{ 0 };
  std::atomic<bool> stalled_{ false };
  std::mutex mutex_;
  std::condition_variable wake_;
};

} // namespace geoshaping
