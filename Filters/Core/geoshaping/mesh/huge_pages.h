#pragma once
// Fresh storage for the big per-vertex arrays of a set-up (adjacency, renumbering, coordinate
// ids, the deformer's layout), backed by transparent huge pages where the kernel gives them
// on request (Linux THP in "madvise" mode): the first touch of a 4 KiB page is a page fault,
// and on a virtual machine 128 MiB of them cost some 0.4 s of CPU against 0.02 s in 2 MiB
// pages. No effect on any value; a no-op elsewhere and below 2 MiB.
#include <cstddef>
#include <vector>

namespace geoshaping
{

// Asks for huge pages on the whole pages inside [data, data + bytes) (not yet touched).
void advise_huge_pages(void* data, std::size_t bytes);

// Empties v and gives it room for n elements, fresh (untouched) storage advised for huge
// pages when it must grow; the capacity is exactly n then, as a first resize(n) gives.
template<class T, class A>
void fresh_huge(std::vector<T, A>& v, std::size_t n)
{
  v.clear();
  if (v.capacity() >= n)
    return;
  std::vector<T, A>().swap(v);
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
}

} // namespace geoshaping
