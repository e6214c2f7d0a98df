#pragma once
// A hint to start loading the cache line of p because it is needed soon (no effect on
// results; a no-op where the compiler has no prefetch built-in).

namespace geoshaping
{

inline void prefetch(const void* p)
{
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

} // namespace geoshaping
