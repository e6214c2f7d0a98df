#pragma once
// C++20's std::bit_cast for this C++17 core: the exact bits of a double as an integer and
// back, to carry doubles losslessly through integer buffers (the edit records' payload,
// the partitioned driver's exchange). Same-size trivially copyable types only.
#include <cstring>
#include <type_traits>

namespace geoshaping
{

template<class To, class From>
To bit_cast(const From& from)
{
  static_assert(sizeof(To) == sizeof(From), "bit_cast needs types of the same size");
  static_assert(std::is_trivially_copyable<To>::value && std::is_trivially_copyable<From>::value,
    "bit_cast needs trivially copyable types");
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

} // namespace geoshaping
