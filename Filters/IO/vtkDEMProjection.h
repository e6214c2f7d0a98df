/**
 * @file   vtkDEMProjection.h
 * @brief  VTK-free: the map projection that takes an elevation grid to metres, from the
 *         grid's coordinate reference system (CRS), through PROJ. Used by vtkNpzDEMReader
 *         (whose archives are longitude/latitude on WGS84), by vtkDEMSurfaceFilter (the
 *         CRS a raster reader put in the field data) and by the fuzz targets.
 *
 * Contract: the constructor parses the CRS with PROJ (a PROJ string, `+type=crs` added
 * when missing, or WKT) and accepts a geographic CRS in degrees on the Greenwich meridian
 * or a projected CRS with linear axes; anything else (no CRS, a geocentric or vertical
 * one, grads) throws std::runtime_error naming what is wrong. Prepare() then fixes the
 * projection for a grid:
 * - geographic: the UTM zone of the grid's centre on the CRS's own ellipsoid
 *   (`+proj=utm +zone=Z [+south] +ellps=WGS84` for WGS84, else `+a=.. +b=..`; no PROJ
 *   database needed, no datum shift: the datum stays the raster's), zone
 *   floor((lon0 + 180) / 6) + 1 of the centre longitude lon0 taken into [-180, 180),
 *   clamped to 1 ... 60, south when the centre latitude is below 0;
 * - projected: the CRS's own coordinates, times the axis unit's length in metres (1 for
 *   metres, 0.3048006096 for US survey feet): nothing is reprojected.
 * Usable as a geoshaping::Projector once prepared.
 */
#ifndef vtkDEMProjection_h
#define vtkDEMProjection_h

#include "geoshaping/scenes/dem_surface.h"

#include <proj.h> // PROJ

#include <cstddef>
#include <string>

class vtkDEMProjection
{
public:
  /// The CRS of NumPy DEM archives: longitude/latitude degrees on the WGS84 ellipsoid.
  static const char* const LonLatWgs84;

  /// Parses and checks `crs` (throws, see the file's contract).
  explicit vtkDEMProjection(const std::string& crs);
  ~vtkDEMProjection();
  vtkDEMProjection(const vtkDEMProjection&) = delete;
  vtkDEMProjection& operator=(const vtkDEMProjection&) = delete;

  /// Longitude/latitude (true) or projected (false).
  bool IsGeographic() const { return this->Geographic; }

  /// Fixes the projection for `grid` (geographic: its centre's UTM zone); throws when the
  /// centre is not finite or PROJ cannot make the projection.
  void Prepare(const geoshaping::ElevationGrid& grid);

  /// x and y (degrees of longitude and latitude, or the CRS's units) to easting and
  /// northing in metres, in place. False when PROJ transforms fewer than `count` points
  /// or Prepare() was not called; a point PROJ cannot project comes back infinite.
  bool operator()(std::size_t count, double* x, double* y) const;

  /// The output's coordinates: "UTM zone 16N (WGS84, PROJ 9.1.1: +proj=utm +zone=16
  /// +ellps=WGS84)", or "the raster's projected CRS, kept (metre)", or with "x and y
  /// times 0.3048006096 (US survey foot) to metres".
  std::string GetDescription() const;

private:
  void Init(const std::string& crs); // the constructor's checks

  bool Geographic = false;
  double Metres = 1.0;   // projected: length of the axis unit in metres
  std::string UnitName;  // projected: the axis unit's name
  std::string Ellipsoid; // geographic: "WGS84" or PROJ's name of it
  std::string EllipsoidParameters;
  int Zone = 0;
  bool South = false;
  std::string Definition;
  PJ_CONTEXT* Context = nullptr;
  PJ* Source = nullptr;
  PJ* Projection = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkDEMProjection.h
