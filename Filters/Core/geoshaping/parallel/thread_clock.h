#pragma once
// The calling thread's CPU time: what the benchmarks time with, since on a loaded machine
// it leaves out the time other threads and processes ran.
#include <ctime>

namespace geoshaping
{

// Seconds of CPU this thread has used (0 where POSIX does not give a thread clock).
inline double thread_cpu_seconds()
{
#if defined(CLOCK_THREAD_CPUTIME_ID)
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
#else
  return 0.0;
#endif
}

} // namespace geoshaping
