/**
 * @file   vtkGocadTSurfParser.h
 * @brief  VTK-free line parser of GOCAD TSurf (`.ts`) and VSet (`.vs`) text, used by
 *         vtkGocadTSurfReader.
 *
 * The parser fills plain arrays (points, triangles, per-triangle TFACE and surface
 * index, point properties) for all `GOCAD TSurf` objects of a stream, and for its
 * `GOCAD VSet` (or `PointSet`) objects points with their properties, listed as vertices
 * (point sets such as well markers). It stops at the
 * first problem and reports it as "line N: ..."; it never loops without consuming a
 * line, so a damaged or binary file ends in an error, not a hang. Memory is bounded by
 * the input's size (the NaN padding of properties is refused beyond one value per byte
 * read plus 64 per point) and no exception escapes. See docs/tsurf.md and docs/readers.md.
 */
#ifndef vtkGocadTSurfParser_h
#define vtkGocadTSurfParser_h

#include <array>
#include <cstdint>
#include <functional>
#include <istream>
#include <string>
#include <vector>

struct vtkGocadTSurfSurfaceInfo
{
  std::string Name;                     // HEADER name:
  std::string CoordinateSystemName;     // NAME inside GOCAD_ORIGINAL_COORDINATE_SYSTEM
  std::array<std::string, 3> AxisNames; // empty when the file gives none
  std::array<std::string, 3> AxisUnits;
  std::string ZPositive; // as written in the file ("" when absent)
};

struct vtkGocadTSurfProperty
{
  std::string Name;
  int NumberOfComponents = 1;
  std::vector<double> Values; // NumberOfComponents per point; NaN where no data
};

struct vtkGocadTSurfData
{
  std::vector<double> Points;          // x y z per point, z = elevation
  std::vector<std::int64_t> Triangles; // 3 point indices per triangle
  std::vector<int> TFace;              // per triangle: TFACE index within its surface
  std::vector<int> Surface;            // per triangle: index into Surfaces
  std::vector<std::int64_t> Vertices;  // the points of VSet objects, one vertex each
  std::vector<int> VertexSurface;      // per vertex: index into Surfaces
  std::vector<vtkGocadTSurfSurfaceInfo> Surfaces;
  std::vector<vtkGocadTSurfProperty> Properties; // union over all surfaces
  std::vector<std::string> Warnings;

  std::size_t GetNumberOfPoints() const { return this->Points.size() / 3; }
};

/**
 * Parse every `GOCAD TSurf ... END` and `GOCAD VSet ... END` object of `input` into `data`. Returns
 * false and sets `error` (starting with "line N:") on the first problem; `data` is then partial and
 * must be discarded.
 *
 * `progress` (optional) is told the fraction of `totalBytes` read, every 1 % of them, and
 * stops the parse (an error "stopped at the user's request") when it returns false.
 */
bool vtkGocadTSurfParse(std::istream& input, vtkGocadTSurfData& data, std::string& error,
  const std::function<bool(double)>& progress = {}, std::uint64_t totalBytes = 0);

/** True when the first non-blank, non-comment line of `input` starts a TSurf or a VSet. */
bool vtkGocadTSurfLooksLikeTSurf(std::istream& input);

#endif
// VTK-HeaderTest-Exclude: vtkGocadTSurfParser.h
