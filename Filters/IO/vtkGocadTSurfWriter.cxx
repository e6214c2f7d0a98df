#include "vtkGocadTSurfWriter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkGocadTSurfWriter);

namespace
{
struct Triangle
{
  int TFace;
  std::array<vtkIdType, 3> Ids;
};

struct SurfaceGroup
{
  std::vector<Triangle> Triangles; // sorted by TFace, file order within a TFace
  std::vector<vtkIdType> Points;   // ascending point ids
};

struct Property
{
  std::string Name;
  vtkDataArray* Array;
  double NoData;
};

// A space, then the shortest decimal that reads back as the same double (bit-exact
// round trip), in the C locale whatever the process locale is.
void Put(std::ostream& out, double value)
{
  char buffer[32];
  buffer[0] = ' ';
  const auto result = std::to_chars(buffer + 1, buffer + sizeof(buffer), value);
  out.write(buffer, result.ptr - buffer);
}

std::string FieldString(
  vtkFieldData* fd, const char* name, vtkIdType index, const std::string& fallback)
{
  auto* array = vtkStringArray::SafeDownCast(fd ? fd->GetAbstractArray(name) : nullptr);
  if (!array || index >= array->GetNumberOfValues() || array->GetValue(index).empty())
    return fallback;
  return array->GetValue(index);
}

int CellValue(vtkDataArray* array, vtkIdType cellId)
{
  return array ? static_cast<int>(array->GetComponent(cellId, 0)) : 0;
}

// A property name is one token in the file.
std::string TokenName(std::string name)
{
  std::replace_if(
    name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }, '_');
  return name;
}

// A no-data marker the array does not contain, so only NaN/inf read back as NaN.
double ChooseNoData(vtkDataArray* array)
{
  double candidate = -99999.0;
  for (int attempt = 0; attempt < 64; ++attempt, candidate = candidate * 10.0 - 9.0)
  {
    bool used = false;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples() && !used; ++i)
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
        used = used || array->GetComponent(i, c) == candidate;
    if (!used)
      break;
  }
  return candidate;
}

std::vector<Property> CollectProperties(vtkPointData* pd)
{
  std::vector<Property> properties;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pd->GetArray(i);
    if (array && array->GetName() && *array->GetName())
      properties.push_back({ TokenName(array->GetName()), array, ChooseNoData(array) });
  }
  return properties;
}

bool CheckPoints(vtkPolyData* input, std::string& error)
{
  if (input->GetNumberOfStrips() > 0)
  {
    error = "Triangle strips are not written: apply Triangulate first.";
    return false;
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "Point " + std::to_string(i) + " has a non-finite coordinate.";
      return false;
    }
  }
  return true;
}

// One group per value of the cell array "Surface" (ascending), triangles sorted by
// "TFace"; each group lists the points its triangles use, unused points go to the first.
bool GroupTriangles(vtkPolyData* input, std::vector<SurfaceGroup>& groups, std::string& error)
{
  vtkDataArray* surfaceArray = input->GetCellData()->GetArray("Surface");
  vtkDataArray* tfaceArray = input->GetCellData()->GetArray("TFace");
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  std::map<int, SurfaceGroup> byValue;
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    const vtkIdType cellId = firstPoly + it->GetCurrentCellId();
    if (npts != 3)
    {
      error = "Cell " + std::to_string(cellId) + " has " + std::to_string(npts) +
              " points: only triangles are written (apply Triangulate first).";
      return false;
    }
    byValue[CellValue(surfaceArray, cellId)].Triangles.push_back(
      { CellValue(tfaceArray, cellId), { pts[0], pts[1], pts[2] } });
  }
  groups.clear();
  for (auto& entry : byValue)
    groups.push_back(std::move(entry.second));
  if (groups.empty())
    groups.emplace_back();

  std::vector<int> owner(input->GetNumberOfPoints(), -1);
  for (std::size_t k = 0; k < groups.size(); ++k)
  {
    auto& g = groups[k];
    std::stable_sort(g.Triangles.begin(), g.Triangles.end(),
      [](const Triangle& a, const Triangle& b) { return a.TFace < b.TFace; });
    for (const auto& t : g.Triangles)
      for (vtkIdType id : t.Ids)
        if (owner[id] != static_cast<int>(k))
        {
          owner[id] = static_cast<int>(k);
          g.Points.push_back(id);
        }
  }
  for (vtkIdType id = 0; id < input->GetNumberOfPoints(); ++id)
    if (owner[id] == -1)
      groups[0].Points.push_back(id);
  for (auto& g : groups)
    std::sort(g.Points.begin(), g.Points.end());
  return true;
}

// The pieces of a surface gathered from several processes (vtkParallelSerialWriter
// appends them) as one surface: ghost cells (DUPLICATECELL) are left out, the copies of
// a point (the same point GlobalIds) become one point, ghost points (DUPLICATEPOINT) no
// kept triangle uses are left out, and the vtkGhostType arrays are not written. Only the
// polygons are kept. Data without ghost arrays is returned as it is.
vtkSmartPointer<vtkPolyData> MergePieces(vtkPolyData* input)
{
  vtkUnsignedCharArray* cellGhosts = input->GetCellGhostArray();
  vtkUnsignedCharArray* pointGhosts = input->GetPointGhostArray();
  if (!cellGhosts && !pointGhosts)
    return input;
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const auto kept = [&](vtkIdType cellId)
  { return !cellGhosts || !(cellGhosts->GetValue(cellId) & vtkDataSetAttributes::DUPLICATECELL); };
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (kept(firstPoly + it->GetCurrentCellId()))
      for (vtkIdType k = 0; k < npts; ++k)
        used[std::size_t(pts[k])] = 1;
  }

  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->GetFieldData()->ShallowCopy(input->GetFieldData());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = out->GetPointData();
  outPD->CopyFieldOff(vtkDataSetAttributes::GhostArrayName());
  outPD->CopyGlobalIdsOn(); // written as the serial writer writes them: a property
  outPD->CopyAllocate(inPD, n);
  vtkDataArray* gids = inPD->GetGlobalIds();
  std::unordered_map<long long, vtkIdType> byGlobalId;
  std::vector<vtkIdType> newId(static_cast<std::size_t>(n), -1);
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (!used[std::size_t(p)] && pointGhosts &&
        (pointGhosts->GetValue(p) & vtkDataSetAttributes::DUPLICATEPOINT))
      continue;
    if (gids)
    {
      const auto found =
        byGlobalId.emplace((long long)gids->GetTuple1(p), points->GetNumberOfPoints());
      if (!found.second)
      {
        newId[std::size_t(p)] = found.first->second;
        continue;
      }
    }
    newId[std::size_t(p)] = points->InsertNextPoint(input->GetPoint(p));
    outPD->CopyData(inPD, p, newId[std::size_t(p)]);
  }
  out->SetPoints(points);

  vtkNew<vtkCellArray> polys;
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = out->GetCellData();
  outCD->CopyFieldOff(vtkDataSetAttributes::GhostArrayName());
  outCD->CopyAllocate(inCD, input->GetNumberOfPolys());
  std::vector<vtkIdType> ids;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    const vtkIdType cellId = firstPoly + it->GetCurrentCellId();
    if (!kept(cellId))
      continue;
    ids.assign(pts, pts + npts);
    for (vtkIdType& id : ids)
      id = newId[std::size_t(id)];
    outCD->CopyData(inCD, cellId, polys->InsertNextCell(npts, ids.data()));
  }
  out->SetPolys(polys);
  return out;
}

struct SurfaceWriter
{
  std::ostream& Out;
  vtkPolyData* Input;
  std::vector<Property> Properties;
  std::vector<vtkIdType> LocalId; // file id of each point in the current surface

  void Write(const SurfaceGroup& g, const std::string& name)
  {
    this->Out << "GOCAD TSurf 1\nHEADER {\nname:" << name << "\n}\n";
    this->WriteCoordinateSystem();
    this->WritePropertyHeader();
    this->Out << "TFACE\n";
    vtkIdType next = 1;
    for (vtkIdType id : g.Points)
    {
      this->LocalId[id] = next;
      this->WriteVertex(id, next++);
    }
    for (std::size_t t = 0; t < g.Triangles.size(); ++t)
    {
      if (t > 0 && g.Triangles[t].TFace != g.Triangles[t - 1].TFace)
        this->Out << "TFACE\n";
      const auto& ids = g.Triangles[t].Ids;
      this->Out << "TRGL " << this->LocalId[ids[0]] << ' ' << this->LocalId[ids[1]] << ' '
                << this->LocalId[ids[2]] << '\n';
    }
    this->Out << "END\n";
  }

  void WriteCoordinateSystem()
  {
    vtkFieldData* fd = this->Input->GetFieldData();
    this->Out << "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME "
              << FieldString(fd, "CoordinateSystemName", 0, "Default") << "\nAXIS_NAME";
    const char* axisNames[3] = { "X", "Y", "Z" };
    for (int c = 0; c < 3; ++c)
      this->Out << " \"" << FieldString(fd, "AxisName", c, axisNames[c]) << '"';
    this->Out << "\nAXIS_UNIT";
    for (int c = 0; c < 3; ++c)
      this->Out << " \"" << FieldString(fd, "AxisUnit", c, "m") << '"';
    this->Out << "\nZPOSITIVE Elevation\nEND_ORIGINAL_COORDINATE_SYSTEM\n";
  }

  void WritePropertyHeader()
  {
    if (this->Properties.empty())
      return;
    this->Out << "PROPERTIES";
    for (const auto& p : this->Properties)
      this->Out << ' ' << p.Name;
    this->Out << "\nESIZES";
    for (const auto& p : this->Properties)
      this->Out << ' ' << p.Array->GetNumberOfComponents();
    this->Out << "\nNO_DATA_VALUES";
    for (const auto& p : this->Properties)
      Put(this->Out, p.NoData);
    this->Out << '\n';
  }

  void WriteVertex(vtkIdType id, vtkIdType fileId)
  {
    double x[3];
    this->Input->GetPoint(id, x);
    this->Out << (this->Properties.empty() ? "VRTX " : "PVRTX ") << fileId;
    for (double c : x)
      Put(this->Out, c);
    for (const auto& p : this->Properties)
      for (int c = 0; c < p.Array->GetNumberOfComponents(); ++c)
      {
        const double v = p.Array->GetComponent(id, c);
        Put(this->Out, std::isfinite(v) ? v : p.NoData);
      }
    this->Out << '\n';
  }
};
}

vtkGocadTSurfWriter::~vtkGocadTSurfWriter()
{
  this->SetFileName(nullptr);
}

vtkPolyData* vtkGocadTSurfWriter::GetInput()
{
  return vtkPolyData::SafeDownCast(this->Superclass::GetInput());
}

int vtkGocadTSurfWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkGocadTSurfWriter::WriteData()
{
  if (!this->GetInput() || !this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< (this->GetInput() ? "No FileName set." : "No vtkPolyData input."));
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  const vtkSmartPointer<vtkPolyData> pieces = MergePieces(this->GetInput());
  vtkPolyData* input = pieces;
  std::string error;
  std::vector<SurfaceGroup> groups;
  if (!CheckPoints(input, error) || !GroupTriangles(input, groups, error))
  {
    vtkErrorMacro(<< error << " Nothing written to '" << this->FileName << "'.");
    return;
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
    vtkWarningMacro("Vertex and line cells are not written to a TSurf.");

  std::ofstream out(this->FileName, std::ios::binary);
  if (!out)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "' for writing.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  std::string stem = this->FileName;
  stem = stem.substr(stem.find_last_of("/\\") + 1);
  stem = stem.substr(0, stem.find_last_of('.'));
  SurfaceWriter writer{ out, input, CollectProperties(input->GetPointData()),
    std::vector<vtkIdType>(input->GetNumberOfPoints(), 0) };
  for (std::size_t k = 0; k < groups.size(); ++k)
  {
    const std::string fallback = groups.size() > 1 ? stem + "_" + std::to_string(k) : stem;
    writer.Write(groups[k], FieldString(input->GetFieldData(), "Name", k, fallback));
  }
  if (!out.flush())
  {
    vtkErrorMacro("Could not write '" << this->FileName << "'.");
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
  }
}

void vtkGocadTSurfWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
