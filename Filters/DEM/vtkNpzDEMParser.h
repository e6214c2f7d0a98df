/**
 * @file   vtkNpzDEMParser.h
 * @brief  VTK-free reading of NumPy `.npz` archives (zip + zlib + `.npy`), used by
 *         vtkNpzDEMReader and by the fuzz targets (Testing/Fuzz).
 *
 * Everything here throws std::runtime_error naming what is wrong (and std::bad_alloc when
 * memory runs out); the reader turns every exception into an error and an empty output.
 * Sizes read from the file are checked against what its bytes can hold before anything is
 * allocated: see docs/readers.md for the memory and time bounds.
 */
#ifndef vtkNpzDEMParser_h
#define vtkNpzDEMParser_h

#include "geoshaping/dem_surface.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

/// The entries of a .npz (a zip archive of .npy files), read through its central
/// directory; stored and deflated entries, no ZIP64.
class vtkNpzArchive
{
public:
  /// Parses the central directory of the archive `bytes` (the whole file).
  explicit vtkNpzArchive(std::vector<char> bytes);

  /// The uncompressed bytes of entry `name`. A stored entry is as long as its data, a
  /// deflated one at most 1032 times as long plus 64 bytes (deflate's largest ratio):
  /// larger claims are refused before any allocation.
  std::vector<char> Read(const std::string& name) const;

private:
  struct Entry
  {
    std::uint16_t Method = 0;
    std::uint32_t Compressed = 0, Size = 0, Local = 0;
  };
  void Need(std::size_t at, std::size_t count) const;
  std::uint16_t U16(std::size_t at) const;
  std::uint32_t U32(std::size_t at) const;
  std::vector<char> Bytes;
  std::map<std::string, Entry> Entries;
};

/// A .npy array as doubles (little-endian or byte-sized integers and floats, C order).
struct vtkNpyArray
{
  std::vector<std::size_t> Shape;
  std::vector<double> Values;
};

/// The whole file at `path` (throws when it cannot be opened).
std::vector<char> vtkNpzReadFile(const std::string& path);

/// Parses the .npy bytes of entry `name` (used in messages). The header must be exact
/// (shape tuple, True/False, supported dtype) and the data exactly shape x item size.
vtkNpyArray vtkNpyParse(const std::vector<char>& bytes, const std::string& name);

/// The DEM of an archive: the 2D `elevation` (rows and columns at most INT_MAX) and the
/// scalars `xmin xmax ymin ymax` (matplotlib's layout). Not yet validated: see
/// geoshaping::validate.
geoshaping::GeographicGrid vtkNpzDEMParse(const vtkNpzArchive& npz);

#endif
// VTK-HeaderTest-Exclude: vtkNpzDEMParser.h
