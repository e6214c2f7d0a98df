// VTK-free map projection of elevation grids (vtkNpzDEMReader, vtkDEMSurfaceFilter).
#include "vtkDEMProjection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace
{
constexpr double Wgs84A = 6378137.0;
constexpr double Wgs84InverseFlattening = 298.257223563;
constexpr double Degree = 3.14159265358979323846 / 180.0;

// A PJ owned here (PROJ objects are released with proj_destroy).
using PjPointer = std::unique_ptr<PJ, decltype(&proj_destroy)>;
PjPointer Own(PJ* pj)
{
  return PjPointer(pj, &proj_destroy);
}

// "%.17g": the double's exact decimal round trip, for PROJ strings.
std::string Exact(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", v);
  return text;
}

// `crs` as PROJ reads it: a PROJ string gets +type=crs, which makes it a CRS, not an
// operation; WKT and "EPSG:4326" are passed as they are.
std::string AsCrs(const std::string& crs)
{
  if (crs.find("+proj=") != std::string::npos && crs.find("+type=crs") == std::string::npos)
    return crs + " +type=crs";
  return crs;
}
} // namespace

const char* const vtkDEMProjection::LonLatWgs84 = "+proj=longlat +ellps=WGS84 +no_defs";

vtkDEMProjection::vtkDEMProjection(const std::string& crs)
{
  if (crs.find_first_not_of(" \t\r\n") == std::string::npos)
    throw std::runtime_error("no coordinate reference system (CRS)");
  this->Context = proj_context_create();
  if (!this->Context)
    throw std::runtime_error("PROJ cannot make a context");
  proj_log_level(this->Context, PJ_LOG_NONE); // errors are thrown, not printed
  // The destructor does not run when the constructor throws: release PROJ's objects
  // here, after Init's own have gone.
  try
  {
    this->Init(crs);
  }
  catch (...)
  {
    proj_destroy(this->Source);
    proj_context_destroy(this->Context);
    throw;
  }
}

void vtkDEMProjection::Init(const std::string& crs)
{
  this->Source = proj_create(this->Context, AsCrs(crs).c_str());
  if (!this->Source)
    throw std::runtime_error(
      "PROJ cannot read the CRS '" + crs +
      "': " + proj_context_errno_string(this->Context, proj_context_errno(this->Context)));
  const PJ_TYPE type = proj_get_type(this->Source);
  this->Geographic = type == PJ_TYPE_GEOGRAPHIC_2D_CRS || type == PJ_TYPE_GEOGRAPHIC_3D_CRS;
  if (!this->Geographic && type != PJ_TYPE_PROJECTED_CRS)
    throw std::runtime_error("the CRS '" + crs + "' is neither geographic nor projected");
  const PjPointer cs = Own(proj_crs_get_coordinate_system(this->Context, this->Source));
  double factor[2] = { 0.0, 0.0 };
  const char* unit = nullptr;
  for (int axis = 0; axis < 2; ++axis)
    if (!cs || !proj_cs_get_axis_info(this->Context, cs.get(), axis, nullptr, nullptr, nullptr,
                 &factor[axis], &unit, nullptr, nullptr))
      throw std::runtime_error("PROJ gives no axes for the CRS '" + crs + "'");
  if (this->Geographic)
  {
    // Longitudes and latitudes in degrees from Greenwich: what UTM zones are made of.
    double meridian = 0.0;
    const PjPointer pm = Own(proj_get_prime_meridian(this->Context, this->Source));
    if (!pm ||
        !proj_prime_meridian_get_parameters(this->Context, pm.get(), &meridian, nullptr, nullptr) ||
        meridian != 0.0)
      throw std::runtime_error("the geographic CRS '" + crs + "' is not on the Greenwich meridian");
    if (std::abs(factor[0] - Degree) > 1e-12 || std::abs(factor[1] - Degree) > 1e-12)
      throw std::runtime_error("the geographic CRS '" + crs + "' is not in degrees");
    double a = 0.0, b = 0.0, inverse_flattening = 0.0;
    const PjPointer ellipsoid = Own(proj_get_ellipsoid(this->Context, this->Source));
    if (!ellipsoid ||
        !proj_ellipsoid_get_parameters(
          this->Context, ellipsoid.get(), &a, &b, nullptr, &inverse_flattening) ||
        !(a > 0.0) || !(b > 0.0))
      throw std::runtime_error("the geographic CRS '" + crs + "' has no ellipsoid");
    const bool wgs84 = a == Wgs84A && inverse_flattening == Wgs84InverseFlattening;
    this->Ellipsoid = wgs84 ? "WGS84" : proj_get_name(ellipsoid.get());
    this->EllipsoidParameters = wgs84 ? "+ellps=WGS84" : "+a=" + Exact(a) + " +b=" + Exact(b);
  }
  else
  {
    if (!(factor[0] > 0.0) || factor[0] != factor[1] || !std::isfinite(factor[0]))
      throw std::runtime_error(
        "the projected CRS '" + crs + "' has no common linear unit for x and y");
    this->Metres = factor[0];
    this->UnitName = unit ? unit : "unnamed unit";
  }
}

vtkDEMProjection::~vtkDEMProjection()
{
  proj_destroy(this->Projection);
  proj_destroy(this->Source);
  proj_context_destroy(this->Context);
}

void vtkDEMProjection::Prepare(const geoshaping::ElevationGrid& grid)
{
  if (!this->Geographic)
    return;
  double lon0 = 0.5 * (grid.x_first + grid.x_last);
  const double lat0 = 0.5 * (grid.y_first + grid.y_last);
  if (!std::isfinite(lon0) || !std::isfinite(lat0))
    throw std::runtime_error("the grid's centre is not finite: no UTM zone");
  lon0 -= 360.0 * std::floor((lon0 + 180.0) / 360.0);
  const double zone = std::floor((lon0 + 180.0) / 6.0) + 1.0;
  this->Zone = int(std::min(60.0, std::max(1.0, zone)));
  this->South = lat0 < 0.0;
  this->Definition = "+proj=utm +zone=" + std::to_string(this->Zone) +
                     (this->South ? " +south " : " ") + this->EllipsoidParameters;
  proj_destroy(this->Projection);
  this->Projection = proj_create(this->Context, this->Definition.c_str());
  if (!this->Projection)
    throw std::runtime_error(
      "PROJ cannot make " + this->Definition + ": " +
      proj_context_errno_string(this->Context, proj_context_errno(this->Context)));
}

bool vtkDEMProjection::operator()(std::size_t count, double* x, double* y) const
{
  if (!this->Geographic)
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      x[i] *= this->Metres;
      y[i] *= this->Metres;
    }
    return true;
  }
  if (!this->Projection)
    return false;
  for (std::size_t i = 0; i < count; ++i)
  {
    x[i] = proj_torad(x[i]);
    y[i] = proj_torad(y[i]);
  }
  return proj_trans_generic(this->Projection, PJ_FWD, x, sizeof(double), count, y, sizeof(double),
           count, nullptr, 0, 0, nullptr, 0, 0) == count;
}

std::string vtkDEMProjection::GetDescription() const
{
  if (!this->Geographic)
    return "the raster's projected CRS, kept" +
           (this->Metres == 1.0
               ? std::string(" (metre)")
               : ": x and y times " + Exact(this->Metres) + " (" + this->UnitName + ") to metres");
  const PJ_INFO info = proj_info();
  return "UTM zone " + std::to_string(this->Zone) + (this->South ? "S" : "N") + " (" +
         this->Ellipsoid + ", PROJ " + info.version + ": " + this->Definition + ")";
}
