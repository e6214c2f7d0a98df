#include "geoshaping/mesh/huge_pages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace geoshaping
{

void advise_huge_pages(void* data, std::size_t bytes)
{
#if defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(1) << 21, page = 4096;
  if (!data || bytes < huge)
    return;
  const std::uintptr_t first = (std::uintptr_t(data) + page - 1) & ~(page - 1);
  const std::uintptr_t last = (std::uintptr_t(data) + bytes) & ~(page - 1);
  if (last > first)
    madvise(
      reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE); // a hint: failure is harmless
#else
  (void)data;
  (void)bytes;
#endif
}

} // namespace geoshaping
