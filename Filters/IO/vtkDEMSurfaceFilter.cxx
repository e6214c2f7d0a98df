#include "vtkDEMSurfaceFilter.h"

#include "vtkDEMProjection.h"
#include "vtkDEMSurfaceOutput.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/scenes/dem_surface.h"

#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDEMSurfaceFilter);

namespace
{
// The first value of field array `name` as text ("" when there is none).
std::string FieldText(vtkFieldData* fields, const char* name)
{
  vtkAbstractArray* array = fields ? fields->GetAbstractArray(name) : nullptr;
  if (!array || array->GetNumberOfValues() < 1)
    return "";
  return array->GetVariantValue(0).ToString();
}

// The raster's one band: its only array besides the ghost array, pixels (cell data)
// first. Throws naming the arrays when there are several or none.
vtkDataArray* TheBand(vtkImageData* image, bool* cells)
{
  for (const bool in_cells : { true, false })
  {
    vtkDataSetAttributes* data =
      in_cells ? static_cast<vtkDataSetAttributes*>(image->GetCellData()) : image->GetPointData();
    std::vector<vtkAbstractArray*> bands;
    for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* array = data->GetAbstractArray(i);
      const char* name = array->GetName();
      if (!name || std::string(name) != vtkDataSetAttributes::GhostArrayName())
        bands.push_back(array);
    }
    if (bands.empty())
      continue;
    if (bands.size() > 1)
    {
      std::string names;
      for (vtkAbstractArray* band : bands)
        names += std::string(names.empty() ? "" : ", ") + (band->GetName() ? band->GetName() : "?");
      throw std::runtime_error(
        std::to_string(bands.size()) + " bands (" + names +
        "): DEMSurface takes a single-band elevation raster (extract one, e.g. gdal_translate "
        "-b 1 in.tif dem.tif)");
    }
    vtkDataArray* band = vtkDataArray::SafeDownCast(bands[0]);
    if (!band || band->GetNumberOfComponents() != 1)
      throw std::runtime_error(
        std::string("the band '") + (bands[0]->GetName() ? bands[0]->GetName() : "?") +
        "' is not one numeric component: DEMSurface takes a single-band elevation raster");
    *cells = in_cells;
    return band;
  }
  throw std::runtime_error("the raster has no band (no cell or point array)");
}

// The image's samples, no-data marks and geometry, for geoshaping::grid_of_image.
geoshaping::ImageSamples Samples(vtkImageData* image)
{
  int extent[6];
  image->GetExtent(extent);
  if (image->GetNumberOfPoints() == 0)
    throw std::runtime_error("the raster is empty (did its reader fail?)");
  if (extent[4] != extent[5])
    throw std::runtime_error("the raster has several z slices: DEMSurface takes a 2D image");
  if (!image->GetDirectionMatrix()->IsIdentity())
    throw std::runtime_error("the raster is rotated (a direction matrix): not supported");
  geoshaping::ImageSamples s;
  vtkDataArray* band = TheBand(image, &s.cell_centred);
  const int cell = s.cell_centred ? 1 : 0;
  for (int axis = 0; axis < 2; ++axis)
  {
    s.dims[axis] = extent[2 * axis + 1] - extent[2 * axis] + 1 - cell;
    s.spacing[axis] = image->GetSpacing()[axis];
    s.origin[axis] = image->GetOrigin()[axis] + extent[2 * axis] * s.spacing[axis];
  }
  const vtkIdType n = band->GetNumberOfTuples();
  if (n != vtkIdType(s.dims[0]) * s.dims[1])
    throw std::runtime_error("the band has " + std::to_string(n) + " values for " +
                             std::to_string(s.dims[0]) + " x " + std::to_string(s.dims[1]) +
                             " samples");
  s.values.resize(std::size_t(n));
  for (vtkIdType k = 0; k < n; ++k)
    s.values[std::size_t(k)] = band->GetTuple1(k);
  vtkUnsignedCharArray* ghosts =
    s.cell_centred ? image->GetCellGhostArray() : image->GetPointGhostArray();
  const unsigned char hidden_bit =
    s.cell_centred ? static_cast<unsigned char>(vtkDataSetAttributes::HIDDENCELL)
                   : static_cast<unsigned char>(vtkDataSetAttributes::HIDDENPOINT);
  if (ghosts && ghosts->GetNumberOfTuples() == n)
  {
    s.hidden.resize(std::size_t(n));
    for (vtkIdType k = 0; k < n; ++k)
      s.hidden[std::size_t(k)] = ghosts->GetValue(k) & hidden_bit;
  }
  if (const std::string nodata = FieldText(image->GetFieldData(), "NO_DATA_VALUE"); !nodata.empty())
  {
    if (!geoshaping::parse_nodata(nodata, &s.nodata))
      throw std::runtime_error("NO_DATA_VALUE '" + nodata + "' is not a number");
    s.has_nodata = true;
  }
  return s;
}
} // namespace

int vtkDEMSurfaceFilter::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data object, so that a mesh or a table is refused with a message of ours.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

int vtkDEMSurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkImageData* image = vtkImageData::SafeDownCast(input);
  if (!image)
  {
    vtkErrorMacro("DEMSurface takes an elevation raster (vtkImageData, as GDALRasterReader "
                  "reads a GeoTIFF), not "
                  << (input ? input->GetClassName() : "nothing") << ".");
    return 0;
  }
  // Several pieces: an empty raster is this process's piece, and a failure must not stop
  // the pipeline here while the other processes go on into the collectives below.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const bool parallel =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) > 1;
  if (parallel && image->GetNumberOfPoints() == 0)
  {
    output->Initialize();
    return 1;
  }
  // Every failure, std::bad_alloc included, is an error and an empty output.
  try
  {
    const geoshaping::ImageSamples samples = Samples(image);
    const std::string crs = FieldText(image->GetFieldData(), "MAP_PROJECTION");
    if (crs.find_first_not_of(" \t\r\n") == std::string::npos)
      throw std::runtime_error("the raster has no CRS (its field data MAP_PROJECTION is missing "
                               "or empty): give the file one, e.g. gdal_edit.py -a_srs EPSG:32616");
    vtkDEMProjection projection(crs);
    const geoshaping::ElevationGrid grid =
      geoshaping::grid_of_image(samples, projection.IsGeographic());
    vtkNew<vtkPolyData> surface;
    vtkDEMSurfaceOutput(surface, grid, this->Stride, projection);
    vtkNew<vtkStringArray> source;
    source->SetName("SourceCRS");
    source->InsertNextValue(crs);
    surface->GetFieldData()->AddArray(source);
    vtkNew<vtkIdTypeArray> holes;
    holes->SetName("NoDataSamples");
    const vtkIdType kept =
      vtkIdType((grid.rows - 1) / this->Stride + 1) * vtkIdType((grid.cols - 1) / this->Stride + 1);
    holes->InsertNextValue(kept - surface->GetNumberOfPoints());
    surface->GetFieldData()->AddArray(holes);
    output->ShallowCopy(surface);
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro("DEMSurface: " << e.what() << ".");
    return parallel ? 1 : 0;
  }
  return 1;
}

void vtkDEMSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Stride: " << this->Stride << "\n";
}
