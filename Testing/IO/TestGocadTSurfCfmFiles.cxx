// Every real CRESCENT Community Fault Model file: counts checked against a plain line
// scan of the file, coordinates plausible for the Cascadia region in metres.
#include "GocadTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

namespace
{
std::vector<std::string> CfmFiles()
{
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(GEOSHAPING_CFM_DIR, ec))
    if (entry.path().extension() == ".ts")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// What the file says, counted without the reader: one point per VRTX/PVRTX line (an
// ATOM shares an earlier point), one triangle per TRGL line.
struct LineCounts
{
  vtkIdType Vertices = 0, Atoms = 0, Triangles = 0;
  std::string Name;
};

LineCounts CountLines(const std::string& path)
{
  LineCounts counts;
  std::ifstream file(path);
  std::string line, keyword;
  while (std::getline(file, line))
  {
    std::istringstream(line) >> keyword;
    counts.Vertices += (keyword == "VRTX" || keyword == "PVRTX");
    counts.Atoms += (keyword == "ATOM" || keyword == "PATOM");
    counts.Triangles += (keyword == "TRGL");
    if (line.rfind("name:", 0) == 0 && counts.Name.empty())
      counts.Name = line.substr(5);
    keyword.clear();
  }
  return counts;
}

class CfmFile : public ::testing::TestWithParam<std::string>
{
};
}

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CfmFile);

TEST_P(CfmFile, ReadsWithTheCountsOfTheFileAndPlausibleUtmCoordinates)
{
  const LineCounts expected = CountLines(GetParam());
  const auto r = gocadtest::Read(GetParam());
  ASSERT_EQ(r.Errors, "");
  vtkPolyData* out = r.Output;
  std::cout << "[ counts   ] " << std::filesystem::path(GetParam()).filename().string() << ": "
            << out->GetNumberOfPoints() << " points, " << out->GetNumberOfPolys()
            << " triangles (file: " << expected.Vertices << " VRTX/PVRTX, " << expected.Atoms
            << " ATOM, " << expected.Triangles << " TRGL)\n";
  EXPECT_GT(expected.Triangles, 0);
  EXPECT_EQ(out->GetNumberOfPoints(), expected.Vertices);
  EXPECT_EQ(out->GetNumberOfPolys(), expected.Triangles);
  EXPECT_EQ(out->GetNumberOfCells(), expected.Triangles);
  EXPECT_EQ(out->GetPolys()->IsHomogeneous(), 3);
  EXPECT_EQ(out->GetPoints()->GetDataType(), VTK_DOUBLE);

  auto* names = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("Name"));
  ASSERT_TRUE(names);
  EXPECT_EQ(names->GetValue(0), expected.Name);

  // Projected metres around Cascadia: |x| up to a few 1e5, y ~ 4.3e6..5.8e6, z from
  // -100 km (the subduction interface) to a few km above sea level.
  double b[6];
  out->GetBounds(b);
  for (double v : b)
    EXPECT_TRUE(std::isfinite(v));
  EXPECT_GE(b[0], -1e6);
  EXPECT_LE(b[1], 1e6);
  EXPECT_GE(b[2], 4e6);
  EXPECT_LE(b[3], 6e6);
  EXPECT_GE(b[4], -2e5);
  EXPECT_LE(b[5], 1e4);
  EXPECT_GT(b[1] - b[0], 1e3) << "a fault spans kilometres";
  EXPECT_GT(b[3] - b[2], 1e3);
}

INSTANTIATE_TEST_SUITE_P(Crescent, CfmFile, ::testing::ValuesIn(CfmFiles()),
  [](const ::testing::TestParamInfo<std::string>& info)
  {
    std::string name = std::filesystem::path(info.param).stem().string();
    std::replace_if(
      name.begin(), name.end(), [](unsigned char c) { return !std::isalnum(c); }, '_');
    return name;
  });

TEST_P(CfmFile, WriterRoundTripIsBitExactWithMalleability)
{
  auto original = gocadtest::Read(GetParam()).Output;
  ASSERT_GT(original->GetNumberOfPoints(), 0);
  vtkNew<vtkDoubleArray> malleability;
  malleability->SetName("Malleability");
  malleability->SetNumberOfTuples(original->GetNumberOfPoints());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
    malleability->SetValue(i, i % 97 == 5 ? std::nan("") : unit(random));
  original->GetPointData()->AddArray(malleability);

  const std::string name = "roundtrip_" + std::filesystem::path(GetParam()).filename().string();
  auto copy = gocadtest::WriteAndRead(original, name);
  gocadtest::ExpectSameSurface(original, copy, name);
  auto* names = vtkStringArray::SafeDownCast(copy->GetFieldData()->GetAbstractArray("Name"));
  ASSERT_TRUE(names);
  EXPECT_EQ(names->GetValue(0), CountLines(GetParam()).Name);
}
