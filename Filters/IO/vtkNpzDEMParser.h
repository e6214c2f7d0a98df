/**
 * @file   vtkNpzDEMParser.h
 * @brief  VTK-free reading of NumPy `.npz` archives (libzip + `.npy`), used by
 *         vtkNpzDEMReader and by the fuzz targets (Testing/Fuzz).
 *
 * Everything here throws std::runtime_error naming what is wrong (and std::bad_alloc when
 * memory runs out); the reader turns every exception into an error and an empty output.
 * Sizes read from the file are checked against what its bytes can hold before anything is
 * allocated: see docs/readers.md for the memory and time bounds.
 */
#ifndef vtkNpzDEMParser_h
#define vtkNpzDEMParser_h

#include "geoshaping/scenes/dem_surface.h"

#include <zip.h> // libzip

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

/// The entries of a .npz (a zip archive of .npy files), read with libzip from the bytes in
/// memory (central directory checked for consistency, CRC-32 checked on every read);
/// stored and deflated entries.
class vtkNpzArchive
{
public:
  /// Opens the archive `bytes` (the whole file); throws when libzip cannot.
  explicit vtkNpzArchive(std::vector<char> bytes);
  ~vtkNpzArchive();
  vtkNpzArchive(const vtkNpzArchive&) = delete;
  vtkNpzArchive& operator=(const vtkNpzArchive&) = delete;

  /// The uncompressed bytes of entry `name`. A stored entry is as long as its data, a
  /// deflated one at most 1032 times as long plus 64 bytes (deflate's largest ratio):
  /// larger claims are refused before any allocation.
  std::vector<char> Read(const std::string& name) const;

private:
  std::vector<char> Bytes; // libzip reads them in place
  zip_t* Zip = nullptr;
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
geoshaping::ElevationGrid vtkNpzDEMParse(const vtkNpzArchive& npz);

#endif
// VTK-HeaderTest-Exclude: vtkNpzDEMParser.h
