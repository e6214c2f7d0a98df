// One small hand-written file per TSurf keyword the reader understands.
#include "GocadTestUtilities.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <cmath>

using gocadtest::Read;
using gocadtest::WriteText;

namespace
{
const char* const Triangle = "GOCAD TSurf 1\n"
                             "HEADER {\n"
                             "name:one triangle\n"
                             "}\n"
                             "TFACE\n"
                             "VRTX 1 500000.5 4400000.25 100\n"
                             "VRTX 2 500010.5 4400000.25 110\n"
                             "VRTX 3 500000.5 4400010.25 120\n"
                             "TRGL 1 2 3\n"
                             "END\n";

std::string FieldString(vtkPolyData* data, const char* name, vtkIdType index = 0)
{
  auto* array = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array && index < array->GetNumberOfValues() ? array->GetValue(index) : "(missing)";
}

std::vector<vtkIdType> CellPoints(vtkPolyData* data, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  data->GetCellPoints(cell, ids);
  return { ids->begin(), ids->end() };
}

std::vector<int> CellInts(vtkPolyData* data, const char* name)
{
  std::vector<int> values;
  vtkDataArray* array = data->GetCellData()->GetArray(name);
  for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
    values.push_back(static_cast<int>(array->GetComponent(i, 0)));
  return values;
}
}

TEST(GocadTSurfReader, ReadsVerticesTrianglesInDoublePrecision)
{
  const auto r = Read(WriteText("triangle.ts", Triangle));
  ASSERT_EQ(r.Errors, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 3);
  ASSERT_EQ(r.Output->GetNumberOfPolys(), 1);
  EXPECT_EQ(r.Output->GetPoints()->GetDataType(), VTK_DOUBLE);
  double p[3];
  r.Output->GetPoint(1, p);
  EXPECT_EQ(p[0], 500010.5);
  EXPECT_EQ(p[1], 4400000.25);
  EXPECT_EQ(p[2], 110.0);
  EXPECT_EQ(CellPoints(r.Output, 0), (std::vector<vtkIdType>{ 0, 1, 2 }));
}

TEST(GocadTSurfReader, KeepsTheHeaderNameAsFieldData)
{
  EXPECT_EQ(FieldString(Read(WriteText("header.ts", Triangle)).Output, "Name"), "one triangle");
  const std::string block = "HEADER {\nname:one triangle\n}";
  std::string oneLine = Triangle;
  oneLine.replace(oneLine.find(block), block.size(), "HEADER {name:inline}");
  EXPECT_EQ(FieldString(Read(WriteText("header1.ts", oneLine)).Output, "Name"), "inline");
}

TEST(GocadTSurfReader, PvrtxPropertiesBecomePointArraysAndNoDataBecomesNaN)
{
  const auto r = Read(WriteText("pvrtx.ts",
    "GOCAD TSurf 1\nPROPERTIES Malleability Age\nNO_DATA_VALUES -99999 -1\nTFACE\n"
    "PVRTX 1 0 0 0 0.25 100\nPVRTX 2 1 0 0 -99999 200\nPVRTX 3 0 1 0 1 -1\n"
    "TRGL 1 2 3\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  vtkDataArray* m = r.Output->GetPointData()->GetArray("Malleability");
  vtkDataArray* age = r.Output->GetPointData()->GetArray("Age");
  ASSERT_TRUE(m && age);
  EXPECT_EQ(m->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(m->GetComponent(0, 0), 0.25);
  EXPECT_TRUE(std::isnan(m->GetComponent(1, 0)));
  EXPECT_EQ(m->GetComponent(2, 0), 1.0);
  EXPECT_EQ(age->GetComponent(1, 0), 200.0);
  EXPECT_TRUE(std::isnan(age->GetComponent(2, 0)));
}

TEST(GocadTSurfReader, EsizesGiveMultiComponentArrays)
{
  const auto r = Read(WriteText("esizes.ts",
    "GOCAD TSurf 1\nPROPERTIES Vector Scalar\nESIZES 3 1\n"
    "PVRTX 1 0 0 0 1 2 3 4\nPVRTX 2 1 0 0 5 6 7 8\nPVRTX 3 0 1 0 9 10 11 12\n"
    "TRGL 1 2 3\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  vtkDataArray* v = r.Output->GetPointData()->GetArray("Vector");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  EXPECT_EQ(v->GetComponent(1, 2), 7.0);
  EXPECT_EQ(r.Output->GetPointData()->GetArray("Scalar")->GetComponent(2, 0), 12.0);
}

// An empty name ("") was read as an unnamed array, which the writer leaves out: lost on
// write then read. It is named after its position, with a warning.
TEST(GocadTSurfReader, APropertyWithAnEmptyNameIsNamedWithAWarning)
{
  const auto r = Read(WriteText("empty_name.ts",
    "GOCAD TSurf 1\nPROPERTIES \"\" b unnamed_1\n"
    "PVRTX 1 0 0 0 1 2 3\nPVRTX 2 1 0 0 4 5 6\nPVRTX 3 0 1 0 7 8 9\nTRGL 1 2 3\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_NE(r.Warnings.find("line 2: property 1 has an empty name, read as 'unnamed_1_'"),
    std::string::npos)
    << r.Warnings;
  vtkDataArray* a = r.Output->GetPointData()->GetArray("unnamed_1_");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->GetComponent(2, 0), 7.0);
  EXPECT_EQ(r.Output->GetPointData()->GetArray("unnamed_1")->GetComponent(2, 0), 9.0);
  const auto back = gocadtest::WriteAndRead(r.Output, "empty_name_back.ts");
  EXPECT_EQ(back->GetPointData()->GetNumberOfArrays(), 3);
  gocadtest::ExpectSameSurface(r.Output, back, "empty name, written and read back");
}

TEST(GocadTSurfReader, AtomSharesThePointItRefersTo)
{
  const auto r = Read(WriteText("atom.ts",
    "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\n"
    "TFACE\nATOM 4 2\nPATOM 5 3\nVRTX 6 1 1 0\nTRGL 4 6 5\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 4);
  EXPECT_EQ(CellPoints(r.Output, 1), (std::vector<vtkIdType>{ 1, 3, 2 }));
}

TEST(GocadTSurfReader, TwoTFacesAreNumberedInTheTFaceArray)
{
  const auto r = Read(WriteText("tface.ts",
    "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nVRTX 4 1 1 0\n"
    "TRGL 1 2 3\nTRGL 2 4 3\nTFACE\nVRTX 5 2 0 0\nTRGL 2 5 4\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(CellInts(r.Output, "TFace"), (std::vector<int>{ 0, 0, 1 }));
  EXPECT_EQ(CellInts(r.Output, "Surface"), (std::vector<int>{ 0, 0, 0 }));
}

TEST(GocadTSurfReader, TwoSurfacesInOneFileAreConcatenatedWithTheirNames)
{
  const auto r =
    Read(WriteText("two.ts", "GOCAD TSurf 1\nHEADER {\nname:first\n}\nPROPERTIES A\n"
                             "PVRTX 1 0 0 0 5\nPVRTX 2 1 0 0 6\nPVRTX 3 0 1 0 7\nTRGL 1 2 3\nEND\n"
                             "# a comment between objects\n\n"
                             "GOCAD TSurf 1\nHEADER {\nname:second\n}\n"
                             "VRTX 1 0 0 1\nVRTX 2 1 0 1\nVRTX 3 0 1 1\nTRGL 3 2 1\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 6);
  EXPECT_EQ(CellPoints(r.Output, 1), (std::vector<vtkIdType>{ 5, 4, 3 }));
  EXPECT_EQ(CellInts(r.Output, "Surface"), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(FieldString(r.Output, "Name", 0), "first");
  EXPECT_EQ(FieldString(r.Output, "Name", 1), "second");
  vtkDataArray* a = r.Output->GetPointData()->GetArray("A");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->GetComponent(2, 0), 7.0);
  EXPECT_TRUE(std::isnan(a->GetComponent(3, 0))) << "the second surface has no property A";
}

TEST(GocadTSurfReader, ZPositiveDepthIsTurnedIntoElevationAndAxesAreKept)
{
  const auto r = Read(WriteText("depth.ts",
    "GOCAD TSurf 1\nGOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME Default\n"
    "AXIS_NAME \"X\" \"Y\" \"Depth\"\nAXIS_UNIT \"m\" \"m\" \"ft\"\nZPOSITIVE Depth\n"
    "END_ORIGINAL_COORDINATE_SYSTEM\n"
    "VRTX 1 0 0 100\nVRTX 2 1 0 -5\nVRTX 3 0 1 0\nTRGL 1 2 3\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  double p[3];
  r.Output->GetPoint(0, p);
  EXPECT_EQ(p[2], -100.0);
  r.Output->GetPoint(1, p);
  EXPECT_EQ(p[2], 5.0);
  EXPECT_EQ(FieldString(r.Output, "ZPositive"), "Depth");
  EXPECT_EQ(FieldString(r.Output, "AxisName", 2), "Depth");
  EXPECT_EQ(FieldString(r.Output, "AxisUnit", 2), "ft");
  EXPECT_EQ(FieldString(r.Output, "CoordinateSystemName"), "Default");
}

TEST(GocadTSurfReader, CrlfLineEndsReadLikeLf)
{
  std::string crlf;
  for (const char c : std::string(Triangle))
    crlf += (c == '\n') ? std::string("\r\n") : std::string(1, c);
  const auto r = Read(WriteText("crlf.ts", crlf));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 3);
  EXPECT_EQ(r.Output->GetNumberOfPolys(), 1);
  EXPECT_EQ(FieldString(r.Output, "Name"), "one triangle");
}

TEST(GocadTSurfReader, IgnoresCommentsBordersStonesAndPropertyClassHeaders)
{
  const auto r = Read(WriteText("extras.ts",
    "# exported by hand\nGOCAD TSurf 1\nHEADER {\nname:extras\n*solid*color:1 0 0 1\n}\n"
    "PROPERTY_CLASSES m\nPROPERTY_CLASS_HEADER m {\nkind:Real Number\n}\nPROPERTIES m\n"
    "TFACE\n# a vertex follows\nPVRTX 1 0 0 0 0.5\nPVRTX 2 1 0 0 0.5\nPVRTX 3 0 1 0 0.5\n"
    "TRGL 1 2 3\nBSTONE 1\nBORDER 4 1 2\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPolys(), 1);
  EXPECT_EQ(FieldString(r.Output, "Name"), "extras");
  EXPECT_TRUE(r.Output->GetPointData()->GetArray("m"));
}

TEST(GocadTSurfReader, SkipsOtherGocadObjectsWithAWarning)
{
  const auto r = Read(
    WriteText("pline.ts", std::string("GOCAD PLine 1\nILINE\nVRTX 1 0 0 0\nEND\n") + Triangle));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 3);
  EXPECT_NE(r.Warnings.find("PLine"), std::string::npos);
}

TEST(GocadTSurfReader, CanReadFileRecognisesTSurfOnly)
{
  vtkNew<vtkGocadTSurfReader> reader;
  EXPECT_EQ(reader->CanReadFile(WriteText("can.ts", Triangle).c_str()), 1);
  EXPECT_EQ(reader->CanReadFile(WriteText("cannot.ts", "hello\n").c_str()), 0);
  EXPECT_EQ(reader->CanReadFile(gocadtest::WorkPath("absent.ts").c_str()), 0);
}

// Well markers: a GOCAD VSet's points (with their properties) become vertex cells.
TEST(GocadTSurfReader, ReadsVSetPointsAsVerticesWithTheirProperties)
{
  const auto r = Read(WriteText("markers.vs",
    "GOCAD VSet 1\nHEADER {\nname:tops\n}\nPROPERTIES well depth\n"
    "PVRTX 1 10 20 -30 7 30\nPVRTX 2 11 21 -31.5 8 31.5\nVRTX 3 12 22 -32\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 3);
  EXPECT_EQ(r.Output->GetNumberOfVerts(), 3);
  EXPECT_EQ(r.Output->GetNumberOfPolys(), 0);
  EXPECT_EQ(r.Output->GetPoint(1)[2], -31.5);
  vtkDataArray* depth = r.Output->GetPointData()->GetArray("depth");
  ASSERT_TRUE(depth);
  EXPECT_EQ(depth->GetTuple1(0), 30);
  EXPECT_TRUE(std::isnan(depth->GetTuple1(2))); // a VRTX gives no value
  EXPECT_EQ(FieldString(r.Output, "Name"), "tops");
  vtkNew<vtkGocadTSurfReader> reader;
  EXPECT_EQ(
    reader->CanReadFile(WriteText("can.vs", "GOCAD VSet 1\nVRTX 1 0 0 0\nEND\n").c_str()), 1);
}

// A file with both: vertices first (vtkPolyData's cell order), the cell arrays in step.
TEST(GocadTSurfReader, VSetAndTSurfInOneFileKeepTheirCellArraysInStep)
{
  const auto r = Read(WriteText(
    "both.ts", std::string(Triangle) + "GOCAD VSet 1\nVRTX 1 5 5 5\nVRTX 2 6 6 6\nEND\n"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 5);
  ASSERT_EQ(r.Output->GetNumberOfCells(), 3);
  EXPECT_EQ(r.Output->GetCellType(0), VTK_VERTEX);
  EXPECT_EQ(r.Output->GetCellType(2), VTK_TRIANGLE);
  vtkDataArray* surface = r.Output->GetCellData()->GetArray("Surface");
  ASSERT_TRUE(surface);
  EXPECT_EQ(surface->GetNumberOfTuples(), 3);
  EXPECT_EQ(surface->GetTuple1(0), 1); // the VSet is the file's second object
  EXPECT_EQ(surface->GetTuple1(2), 0);
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  r.Output->GetCellPoints(0, npts, pts);
  EXPECT_EQ(pts[0], 3);
}

TEST(GocadTSurfReader, RefusesATriangleInsideAVSet)
{
  const auto r =
    Read(WriteText("vset_trgl.vs", "GOCAD VSet 1\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\n"
                                   "TRGL 1 2 3\nEND\n"));
  EXPECT_NE(r.Errors.find("line 5: TRGL in a GOCAD VSet"), std::string::npos) << r.Errors;
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
}
