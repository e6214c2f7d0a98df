#include "vtkGocadTSurfReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include "vtkGocadTSurfParser.h"

#include <exception>
#include <fstream>

vtkStandardNewMacro(vtkGocadTSurfReader);

namespace
{
template<typename ArrayT, typename ValueT>
vtkNew<ArrayT> MakeArray(const char* name, const std::vector<ValueT>& values, int components)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  return array;
}

void AddStrings(vtkFieldData* fd, const char* name, const std::vector<std::string>& values)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  for (const auto& v : values)
    array->InsertNextValue(v);
  fd->AddArray(array);
}

void AddCoordinateSystem(vtkFieldData* fd, const std::vector<vtkGocadTSurfSurfaceInfo>& surfaces)
{
  std::vector<std::string> names, zpositive;
  for (const auto& s : surfaces)
  {
    names.push_back(s.Name);
    zpositive.push_back(s.ZPositive);
  }
  AddStrings(fd, "Name", names);
  AddStrings(fd, "ZPositive", zpositive);
  for (const auto& s : surfaces)
  {
    if (s.AxisNames[0].empty() && s.AxisUnits[0].empty() && s.CoordinateSystemName.empty())
      continue;
    AddStrings(fd, "AxisName", { s.AxisNames.begin(), s.AxisNames.end() });
    AddStrings(fd, "AxisUnit", { s.AxisUnits.begin(), s.AxisUnits.end() });
    AddStrings(fd, "CoordinateSystemName", { s.CoordinateSystemName });
    return;
  }
}

void Fill(vtkPolyData* output, const vtkGocadTSurfData& data)
{
  vtkNew<vtkPoints> points;
  points->SetData(MakeArray<vtkDoubleArray>("Points", data.Points, 3));
  output->SetPoints(points);

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(data.TFace.size() + 1));
  for (vtkIdType i = 0; i < offsets->GetNumberOfValues(); ++i)
    offsets->SetValue(i, 3 * i);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, MakeArray<vtkIdTypeArray>("Connectivity", data.Triangles, 1));
  output->SetPolys(polys);

  // A VSet's points are vertex cells, which a vtkPolyData numbers before its polygons.
  if (!data.Vertices.empty())
  {
    vtkNew<vtkCellArray> verts;
    verts->AllocateExact(
      static_cast<vtkIdType>(data.Vertices.size()), static_cast<vtkIdType>(data.Vertices.size()));
    for (const std::int64_t v : data.Vertices)
    {
      const vtkIdType id = static_cast<vtkIdType>(v);
      verts->InsertNextCell(1, &id);
    }
    output->SetVerts(verts);
  }
  std::vector<int> surface = data.VertexSurface, tface(data.Vertices.size(), 0);
  surface.insert(surface.end(), data.Surface.begin(), data.Surface.end());
  tface.insert(tface.end(), data.TFace.begin(), data.TFace.end());
  output->GetCellData()->AddArray(MakeArray<vtkIntArray>("Surface", surface, 1));
  output->GetCellData()->AddArray(MakeArray<vtkIntArray>("TFace", tface, 1));
  for (const auto& p : data.Properties)
    output->GetPointData()->AddArray(
      MakeArray<vtkDoubleArray>(p.Name.c_str(), p.Values, p.NumberOfComponents));

  vtkNew<vtkFieldData> fd;
  AddCoordinateSystem(fd, data.Surfaces);
  output->SetFieldData(fd);
}
}

vtkGocadTSurfReader::vtkGocadTSurfReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkGocadTSurfReader::~vtkGocadTSurfReader()
{
  this->SetFileName(nullptr);
}

int vtkGocadTSurfReader::CanReadFile(const char* fileName)
{
  std::ifstream file(fileName ? fileName : "", std::ios::binary);
  return file && vtkGocadTSurfLooksLikeTSurf(file) ? 1 : 0;
}

int vtkGocadTSurfReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set (line 0).");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 0;
  }
  std::ifstream file(this->FileName, std::ios::binary);
  if (!file)
  {
    vtkErrorMacro("Cannot open GOCAD TSurf file '" << this->FileName << "' (line 0).");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return 0;
  }
  // No exception may escape into ParaView: the parser turns its own into errors, and an
  // allocation failing here (std::bad_alloc) is an error too.
  try
  {
    vtkGocadTSurfData data;
    std::string error;
    file.seekg(0, std::ios::end);
    const auto size = static_cast<std::uint64_t>(std::max<std::streamoff>(0, file.tellg()));
    file.seekg(0, std::ios::beg);
    const auto progress = [this](double done)
    {
      this->UpdateProgress(done);
      return !this->CheckAbort();
    };
    if (!vtkGocadTSurfParse(file, data, error, progress, size))
    {
      vtkErrorMacro("GOCAD TSurf file '" << this->FileName << "', " << error);
      this->SetErrorCode(vtkErrorCode::FileFormatError);
      return 0;
    }
    for (const auto& warning : data.Warnings)
      vtkWarningMacro("GOCAD TSurf file '" << this->FileName << "', " << warning);
    Fill(output, data);
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro("GOCAD TSurf file '" << this->FileName << "': " << e.what());
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return 0;
  }
  return 1;
}

void vtkGocadTSurfReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
