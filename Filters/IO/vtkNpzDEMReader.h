/**
 * @class   vtkNpzDEMReader
 * @brief   Reads a geographic DEM stored as a NumPy .npz archive into a surface in metres.
 *
 * The archive holds `elevation` (a 2D array, rows = latitudes from `ymin` to `ymax`,
 * columns = longitudes from `xmin` to `xmax` — matplotlib's names for the first and last
 * row and column, in either order — any little-endian integer or float type, C order)
 * and the scalars `xmin xmax ymin ymax` (degrees), the layout of matplotlib's
 * sample DEM `jacksboro_fault_dem.npz` (Debian: python-matplotlib-data). The output is a
 * triangulated vtkPolyData in double precision, in the UTM zone of the grid's centre
 * (WGS84, projected with PROJ: the Jacksboro fault zone lands in zone 16N at about
 * 745,000 E, 4,055,000 N), with the elevation in metres as z and as the point array
 * `Elevation`; the field data keeps the bounds (`LonLatBounds`) and the projection
 * (`Projection`). Every Stride-th row and column is kept. docs/painting.md.
 *
 * The archive is read with libzip (stored and deflated entries, CRC checked); a damaged or
 * unsupported file gives an error naming the entry and an empty output. Sizes read from
 * the file are checked against what it can hold before any allocation (a deflated entry
 * at most 1032 x its compressed size), .npy headers must be exact, and no exception
 * escapes; docs/readers.md gives the memory and time bounds.
 */
#ifndef vtkNpzDEMReader_h
#define vtkNpzDEMReader_h

#include "GeoShapingIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGIO_EXPORT vtkNpzDEMReader : public vtkPolyDataAlgorithm
{
public:
  static vtkNpzDEMReader* New();
  vtkTypeMacro(vtkNpzDEMReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /// Keep every Stride-th row and column (default 1: all).
  vtkSetClampMacro(Stride, int, 1, VTK_INT_MAX);
  vtkGetMacro(Stride, int);

protected:
  vtkNpzDEMReader();
  ~vtkNpzDEMReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int Stride = 1;

private:
  vtkNpzDEMReader(const vtkNpzDEMReader&) = delete;
  void operator=(const vtkNpzDEMReader&) = delete;
};

#endif
