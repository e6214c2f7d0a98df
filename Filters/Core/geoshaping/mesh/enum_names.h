#pragma once
// The printed name of an enumeration's value (a queue, a refinement solver, a region
// frame, a falloff, a distance mode): each enum keeps one table of names beside it, and
// every *_name function reads its table here. The names are the texts of the plugin's
// EnumerationDomain entries (Testing/Filters/TestEnumerations.cxx checks them).
#include <cstddef>

namespace geoshaping
{

struct EnumName
{
  int value;
  const char* text;
};

// The text of `value` in `names`, "" when it has none.
template<std::size_t N>
constexpr const char* name_of(const EnumName (&names)[N], int value)
{
  for (const EnumName& n : names)
    if (n.value == value)
      return n.text;
  return "";
}

} // namespace geoshaping
