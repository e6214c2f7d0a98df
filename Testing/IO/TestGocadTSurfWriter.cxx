// The writer writes what the reader reads, bit for bit.
#include "GocadTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <sstream>

namespace
{
// A gently curved grid at UTM-sized coordinates with awkward (non-decimal) doubles.
vtkSmartPointer<vtkPolyData> UtmSurface(int n)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> malleability;
  malleability->SetName("Malleability");
  vtkNew<vtkFloatArray> temperature;
  temperature->SetName("Temperature");
  vtkNew<vtkDoubleArray> normal;
  normal->SetName("Normal");
  normal->SetNumberOfComponents(3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const double x = 512345.678901234 + i * 12.345678901 + unit(random) / 3.0;
      const double y = 4412345.6789012 + j * 9.87654321 - unit(random) / 7.0;
      points->InsertNextPoint(x, y, -1234.5678 + std::sin(x / 50.0) * 33.3 + unit(random));
      malleability->InsertNextValue(unit(random));
      temperature->InsertNextValue(static_cast<float>(10.0 + unit(random) / 3.0));
      normal->InsertNextTuple3(unit(random), -unit(random), 1.0 / 3.0);
    }
  malleability->SetValue(3, std::nan(""));
  malleability->SetValue(4, -99999.0); // the writer's first no-data choice: must survive
  vtkNew<vtkCellArray> polys;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      const vtkIdType t1[3] = { a, b, d }, t2[3] = { a, d, c };
      polys->InsertNextCell(3, t1);
      polys->InsertNextCell(3, t2);
    }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->AddArray(malleability);
  surface->GetPointData()->AddArray(temperature);
  surface->GetPointData()->AddArray(normal);
  return surface;
}

void ExpectRefused(vtkPolyData* surface, const std::string& name, const std::string& message)
{
  std::string errors;
  const std::string path = gocadtest::Write(surface, name, &errors);
  EXPECT_NE(errors.find(message), std::string::npos) << errors;
  EXPECT_FALSE(std::filesystem::exists(path)) << "nothing is written";
}

std::string ReadAll(const std::string& path)
{
  std::ostringstream text;
  text << std::ifstream(path, std::ios::binary).rdbuf();
  return text.str();
}
}

TEST(GocadTSurfWriter, SyntheticUtmSurfaceRoundTripIsBitExact)
{
  auto surface = UtmSurface(25);
  auto copy = gocadtest::WriteAndRead(surface, "utm.ts");
  gocadtest::ExpectSameSurface(surface, copy, "utm.ts");
  EXPECT_EQ(copy->GetPointData()->GetArray("Normal")->GetNumberOfComponents(), 3);
  EXPECT_TRUE(std::isnan(copy->GetPointData()->GetArray("Malleability")->GetComponent(3, 0)));
  EXPECT_EQ(copy->GetPointData()->GetArray("Malleability")->GetComponent(4, 0), -99999.0);
}

TEST(GocadTSurfWriter, WritesPropertiesHeaderAndCoordinateSystem)
{
  auto surface = UtmSurface(3);
  vtkNew<vtkStringArray> name;
  name->SetName("Name");
  name->InsertNextValue("Sample horizon");
  surface->GetFieldData()->AddArray(name);
  const std::string text = ReadAll(gocadtest::Write(surface, "header.ts"));
  EXPECT_EQ(text.rfind("GOCAD TSurf 1\nHEADER {\nname:Sample horizon\n}\n", 0), 0u) << text;
  EXPECT_NE(text.find("PROPERTIES Malleability Temperature Normal\nESIZES 1 1 3\n"
                      "NO_DATA_VALUES -999999 -99999 -99999\n"),
    std::string::npos)
    << text;
  EXPECT_NE(text.find("ZPOSITIVE Elevation\n"), std::string::npos);
  EXPECT_NE(text.find("AXIS_UNIT \"m\" \"m\" \"m\"\n"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 4), "END\n");
}

TEST(GocadTSurfWriter, SurfacesTFacesNamesAndAxesRoundTrip)
{
  const auto original = gocadtest::Read(gocadtest::WriteText("multi.ts",
    "GOCAD TSurf 1\nHEADER {\nname:upper\n}\nGOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME utm10\n"
    "AXIS_NAME \"E\" \"N\" \"Z\"\nAXIS_UNIT \"m\" \"m\" \"ft\"\nZPOSITIVE Depth\n"
    "END_ORIGINAL_COORDINATE_SYSTEM\nTFACE\nVRTX 1 0 0 10\nVRTX 2 1 0 10\nVRTX 3 0 1 10\n"
    "VRTX 4 1 1 10\nTRGL 1 2 3\nTFACE\nTRGL 2 4 3\nEND\n"
    "GOCAD TSurf 1\nHEADER {\nname:lower\n}\nVRTX 1 0 0 -5\nVRTX 2 1 0 -5\nVRTX 3 0 1 -5\n"
    "TRGL 1 2 3\nEND\n"));
  ASSERT_EQ(original.Errors, "");
  auto copy = gocadtest::WriteAndRead(original.Output, "multi_copy.ts");
  gocadtest::ExpectSameSurface(original.Output, copy, "multi");
  for (const char* array : { "Surface", "TFace" })
    for (vtkIdType c = 0; c < 3; ++c)
      EXPECT_EQ(copy->GetCellData()->GetArray(array)->GetComponent(c, 0),
        original.Output->GetCellData()->GetArray(array)->GetComponent(c, 0))
        << array << " of cell " << c;
  auto* names = vtkStringArray::SafeDownCast(copy->GetFieldData()->GetAbstractArray("Name"));
  ASSERT_TRUE(names && names->GetNumberOfValues() == 2);
  EXPECT_EQ(names->GetValue(1), "lower");
  auto* units = vtkStringArray::SafeDownCast(copy->GetFieldData()->GetAbstractArray("AxisUnit"));
  ASSERT_TRUE(units);
  EXPECT_EQ(units->GetValue(2), "ft");
  double p[3];
  copy->GetPoint(0, p);
  EXPECT_EQ(p[2], -10.0) << "depth became elevation once, and stays elevation";
}

TEST(GocadTSurfWriter, RefusesPolygonsThatAreNotTriangles)
{
  auto surface = UtmSurface(3);
  const vtkIdType quad[4] = { 0, 1, 4, 3 };
  surface->GetPolys()->InsertNextCell(4, quad);
  ExpectRefused(surface, "quad.ts", "Cell 8 has 4 points");
}

TEST(GocadTSurfWriter, RefusesNonFiniteCoordinates)
{
  auto surface = UtmSurface(3);
  surface->GetPoints()->SetPoint(2, 0.0, std::nan(""), 0.0);
  ExpectRefused(surface, "nanpoint.ts", "Point 2 has a non-finite coordinate");
}

TEST(GocadTSurfWriter, ReportsAnUnwritableFile)
{
  auto surface = UtmSurface(3);
  vtkNew<vtkGocadTSurfWriter> writer;
  vtkNew<gocadtest::MessageCapture> capture;
  capture->Watch(writer);
  writer->SetInputData(surface);
  writer->SetFileName(gocadtest::WorkPath("no/such/folder/x.ts").c_str());
  writer->Write();
  EXPECT_NE(capture->Errors.find("Cannot open"), std::string::npos) << capture->Errors;
}

namespace
{
// Rows [lo, hi) of the n x n UtmSurface's points as one process's piece would hold them
// after ParaView distributes it (one ghost ring, ghost arrays, point GlobalIds): the
// quads of rows lo - 1 .. hi (those outside [lo, hi) ghost cells), the points they use
// (those outside [lo, hi) ghost points).
void AppendPiece(vtkPolyData* surface, int n, int lo, int hi, vtkPolyData* pieces)
{
  vtkPoints* points = pieces->GetPoints();
  auto* pointGhosts = vtkUnsignedCharArray::SafeDownCast(
    pieces->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  auto* cellGhosts = vtkUnsignedCharArray::SafeDownCast(
    pieces->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  std::map<vtkIdType, vtkIdType> local;
  const auto add = [&](vtkIdType id)
  {
    const auto found = local.emplace(id, points->GetNumberOfPoints());
    if (!found.second)
      return found.first->second;
    points->InsertNextPoint(surface->GetPoint(id));
    for (int a = 0; a < surface->GetPointData()->GetNumberOfArrays(); ++a)
      pieces->GetPointData()
        ->GetArray(surface->GetPointData()->GetArrayName(a))
        ->InsertNextTuple(id, surface->GetPointData()->GetArray(a));
    const int row = int(id / n);
    pointGhosts->InsertNextValue(row >= lo && row < hi ? 0 : vtkDataSetAttributes::DUPLICATEPOINT);
    return found.first->second;
  };
  // The points in ascending id order (so the merged surface has the whole one's order).
  for (int pass = 0; pass < 2; ++pass)
  {
    std::set<vtkIdType> used;
    for (int qj = std::max(lo - 1, 0); qj <= std::min(hi, n - 2); ++qj)
      for (vtkIdType c = 2 * qj * (n - 1); c < 2 * (qj + 1) * (n - 1); ++c)
      {
        vtkNew<vtkIdList> ids;
        surface->GetCellPoints(c, ids);
        vtkIdType tri[3];
        for (int k = 0; k < 3; ++k)
          used.insert(tri[k] = pass ? add(ids->GetId(k)) : ids->GetId(k));
        if (pass)
        {
          pieces->GetPolys()->InsertNextCell(3, tri);
          cellGhosts->InsertNextValue(
            qj >= lo && qj < hi ? 0 : vtkDataSetAttributes::DUPLICATECELL);
        }
      }
    if (!pass)
      for (vtkIdType id : used)
        add(id);
  }
}
}

TEST(GocadTSurfWriter, PiecesFromSeveralProcessesAreWrittenAsTheWholeSurface)
{
  const int n = 6;
  auto surface = UtmSurface(n);
  vtkNew<vtkIdTypeArray> gids;
  gids->SetName("GlobalIds");
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    gids->InsertNextValue(i);
  surface->GetPointData()->SetGlobalIds(gids);

  // What vtkParallelSerialWriter's AppendPolyData gives on the first process.
  vtkNew<vtkPolyData> pieces;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  pieces->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  pieces->SetPolys(polys);
  for (int a = 0; a < surface->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* from = surface->GetPointData()->GetArray(a);
    auto to = vtk::TakeSmartPointer(from->NewInstance());
    to->SetName(from->GetName());
    to->SetNumberOfComponents(from->GetNumberOfComponents());
    pieces->GetPointData()->AddArray(to);
  }
  pieces->GetPointData()->SetActiveGlobalIds("GlobalIds");
  vtkNew<vtkUnsignedCharArray> pointGhosts, cellGhosts;
  pointGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  cellGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  pieces->GetPointData()->AddArray(pointGhosts);
  pieces->GetCellData()->AddArray(cellGhosts);
  AppendPiece(surface, n, 0, 3, pieces);
  AppendPiece(surface, n, 3, n, pieces);
  ASSERT_GT(pieces->GetNumberOfPoints(), surface->GetNumberOfPoints());
  ASSERT_GT(pieces->GetNumberOfPolys(), surface->GetNumberOfPolys());

  const std::string path = gocadtest::Write(pieces, "pieces.ts");
  EXPECT_EQ(ReadAll(path).find("vtkGhostType"), std::string::npos);
  gocadtest::ExpectSameSurface(surface, gocadtest::Read(path).Output, "pieces.ts");
}
