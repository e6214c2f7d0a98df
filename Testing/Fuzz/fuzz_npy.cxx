// libFuzzer target: the .npy parser of vtkNpzDEMReader (Filters/IO) on any bytes, the
// header and the data of one array without the zip around it.
#include "vtkNpzDEMParser.h"

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkNpyArray array;
  try
  {
    array = vtkNpyParse(std::vector<char>(data, data + size), "fuzz.npy");
  }
  catch (const std::exception&)
  {
    return 0;
  }
  // Accepted: the values are exactly the shape's product, and fit in the input.
  std::size_t count = 1;
  for (const std::size_t n : array.Shape)
    count *= n;
  if (array.Values.size() != count || count > size)
    std::abort();
  return 0;
}
