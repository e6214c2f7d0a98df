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

#include "geoshaping/dem_surface.h"

#include <proj.h> // PROJ
#include <zip.h>  // libzip

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

/// The map projection of a DEM: the UTM zone (WGS84 ellipsoid) of the grid's centre,
/// through PROJ (`+proj=utm +zone=Z [+south] +ellps=WGS84`: no database needed). Zone
/// floor((lon0 + 180) / 6) + 1 of the centre longitude lon0, clamped to 1 ... 60; south
/// when the centre latitude is below 0. Usable as a geoshaping::Projector.
class vtkNpzUtmProjection
{
public:
  /// Throws when PROJ cannot make the projection.
  explicit vtkNpzUtmProjection(const geoshaping::GeographicGrid& grid);
  ~vtkNpzUtmProjection();
  vtkNpzUtmProjection(const vtkNpzUtmProjection&) = delete;
  vtkNpzUtmProjection& operator=(const vtkNpzUtmProjection&) = delete;

  /// Longitudes in x and latitudes in y (degrees) to easting and northing (m), in place.
  /// False when PROJ transforms fewer than `count` points; a point PROJ cannot project
  /// comes back infinite (HUGE_VAL).
  bool operator()(std::size_t count, double* x, double* y) const;

  int GetZone() const { return this->Zone; }
  bool GetSouth() const { return this->South; }
  /// "UTM zone 16N (WGS84, PROJ 9.1.1: +proj=utm +zone=16 +ellps=WGS84)".
  std::string GetDescription() const;

private:
  int Zone = 0;
  bool South = false;
  std::string Definition;
  PJ_CONTEXT* Context = nullptr;
  PJ* Projection = nullptr;
};

/// The DEM of an archive: the 2D `elevation` (rows and columns at most INT_MAX) and the
/// scalars `xmin xmax ymin ymax` (matplotlib's layout). Not yet validated: see
/// geoshaping::validate.
geoshaping::GeographicGrid vtkNpzDEMParse(const vtkNpzArchive& npz);

#endif
// VTK-HeaderTest-Exclude: vtkNpzDEMParser.h
