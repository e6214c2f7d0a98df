// libFuzzer target: the GOCAD TSurf parser of vtkGocadTSurfReader (Filters/IO), on any
// bytes. Besides "no crash, no sanitizer report", a file the parser accepts must be a
// consistent mesh (every check below aborts, which the fuzzer reports as a crash).
#include "fuzz_require.h"
#include "vtkGocadTSurfParser.h"

#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  {
    std::istringstream probe(text);
    (void)vtkGocadTSurfLooksLikeTSurf(probe);
  }
  std::istringstream input(text);
  vtkGocadTSurfData mesh;
  std::string error;
  if (!vtkGocadTSurfParse(input, mesh, error))
  {
    Require(error.compare(0, 5, "line ") == 0);
    return 0;
  }
  const std::size_t points = mesh.GetNumberOfPoints();
  Require(mesh.Points.size() == 3 * points);
  Require(mesh.Triangles.size() % 3 == 0);
  Require(mesh.TFace.size() * 3 == mesh.Triangles.size());
  Require(mesh.Surface.size() * 3 == mesh.Triangles.size());
  Require(!mesh.Surfaces.empty());
  for (const std::int64_t id : mesh.Triangles)
    Require(id >= 0 && static_cast<std::size_t>(id) < points);
  for (const int s : mesh.Surface)
    Require(s >= 0 && static_cast<std::size_t>(s) < mesh.Surfaces.size());
  for (const auto& property : mesh.Properties)
  {
    Require(!property.Name.empty());
    Require(property.NumberOfComponents >= 1);
    Require(property.Values.size() == points * property.NumberOfComponents);
  }
  // The padding bound (docs/tsurf.md): values stored <= bytes + 64 per point.
  std::size_t values = 0;
  for (const auto& property : mesh.Properties)
    values += property.Values.size();
  Require(values <= size + 1 + 64 * points);
  return 0;
}
