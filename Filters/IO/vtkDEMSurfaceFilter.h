/**
 * @class   vtkDEMSurfaceFilter
 * @brief   A single-band elevation raster (vtkImageData, as ParaView's GDALRasterReader
 *          reads a GeoTIFF) as the triangulated surface in metres GeoShaping deforms.
 *
 * Input: vtkImageData with one array (one band: GDALRasterReader puts the pixels in a
 * cell array, other image sources may give a point array), one component, any numeric
 * type, a single z slice, axis-aligned, and its CRS in the field data: `MAP_PROJECTION`
 * (a PROJ string or WKT, as GDALRasterReader writes it); the optional field
 * `NO_DATA_VALUE` (text) names the band's no-data value.
 *
 * Output: one vertex per sample (pixel centres for cell data), triangulated as the .npz
 * DEMs are (geoshaping::dem_surface, through vtkDEMSurfaceOutput: one code path), rows in
 * the raster's file order (north first), in double-precision metres:
 * - a projected CRS is kept (x and y converted to metres when its unit is another);
 * - a geographic CRS is projected with PROJ to the UTM zone of the raster's centre on the
 *   CRS's own ellipsoid, as vtkNpzDEMReader does;
 * z and the point array `Elevation` are the values. Samples that are no data (equal to
 * NO_DATA_VALUE, NaN, or hidden by the reader's ghost array) are left out with every
 * triangle that uses them: holes, not spikes. Field data: `Projection` (the output's
 * coordinates and any reprojection), `SourceCRS` (MAP_PROJECTION as read) and
 * `NoDataSamples` (samples of the strided grid left out). Every Stride-th row and column
 * is kept, starting from the first (northern) row.
 *
 * Bad input (not image data, several arrays or components, no CRS, a CRS PROJ cannot
 * use, an unreadable NO_DATA_VALUE, an empty image as a failed reader leaves, fewer than
 * 2 x 2 samples, out of memory): one vtkErrorMacro naming the problem, an empty output.
 * In parallel (several pieces requested: an MPI server or pvbatch) an empty image is a
 * piece like any other (GDALRasterReader gives the raster to one process): an empty
 * output, no error. There a bad raster is an error and an empty output too, but not a
 * failed request, so that the filters below it run on every process and none waits for
 * ever in a collective the others never reach (docs/mpi.md, "Empty pieces").
 * Memory and time: docs/readers.md, "Elevation rasters".
 */
#ifndef vtkDEMSurfaceFilter_h
#define vtkDEMSurfaceFilter_h

#include "GeoShapingIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGIO_EXPORT vtkDEMSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkDEMSurfaceFilter* New();
  vtkTypeMacro(vtkDEMSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Keep every Stride-th row and column (default 1: all).
  vtkSetClampMacro(Stride, int, 1, VTK_INT_MAX);
  vtkGetMacro(Stride, int);

protected:
  vtkDEMSurfaceFilter() = default;
  ~vtkDEMSurfaceFilter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Stride = 1;

private:
  vtkDEMSurfaceFilter(const vtkDEMSurfaceFilter&) = delete;
  void operator=(const vtkDEMSurfaceFilter&) = delete;
};

#endif
