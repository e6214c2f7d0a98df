// Every damaged file gives an error naming its line and an empty output.
#include "GocadTestUtilities.h"
#include "vtkGocadTSurfParser.h"
#include "vtkGocadTSurfText.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <random>
#include <sstream>
#include <streambuf>
#include <unordered_map>
#include <vector>

using gocadtest::Read;
using gocadtest::WriteText;

namespace
{
struct BadFile
{
  const char* Name;
  std::string Content;
  const char* Expected; // must appear in the error message
};

// Names the case in test names and messages instead of dumping the struct's bytes.
void PrintTo(const BadFile& bad, std::ostream* os)
{
  *os << bad.Name;
}

std::string WithVertex(const std::string& vertexLine)
{
  return "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\n" + vertexLine + "\nTRGL 1 2 3\nEND\n";
}

std::string BinaryJunk()
{
  std::mt19937 random(42);
  std::string junk;
  for (int i = 0; i < 4096; ++i)
    junk += static_cast<char>(random() & 0xff);
  return junk;
}

// The finding had 64 properties of 1024 components, one PVRTX giving them, then 3,000
// VRTX lines: each padded 65,536 NaN, 3.2 GB from 179 KB. Here 64 x 16 and 200 VRTX
// lines, so that a missing bound costs 1.6 MB, not gigabytes.
std::string PaddingBeyondTheFileSize()
{
  std::string s = "GOCAD TSurf 1\nPROPERTIES";
  for (int i = 0; i < 64; ++i)
    s += " p" + std::to_string(i);
  s += "\nESIZES";
  for (int i = 0; i < 64; ++i)
    s += " 16";
  s += "\nPVRTX 1 0 0 0";
  for (int i = 0; i < 64 * 16; ++i)
    s += " 0";
  s += "\n";
  for (int id = 2; id <= 201; ++id)
    s += "VRTX " + std::to_string(id) + " 0 0 0\n";
  return s + "END\n";
}

// A property new to the second surface is padded with NaN on every point of the first:
// 1,000 points x 1,024 components from 18 KB.
std::string BackfillBeyondTheFileSize()
{
  std::string s = "GOCAD TSurf 1\n";
  for (int id = 1; id <= 1000; ++id)
    s += "VRTX " + std::to_string(id) + " 0 0 0\n";
  s += "END\nGOCAD TSurf 1\nPROPERTIES spectrum\nESIZES 1024\nPVRTX 1 0 0 0";
  for (int i = 0; i < 1024; ++i)
    s += " 0";
  return s + "\nEND\n";
}

std::vector<BadFile> BadFiles()
{
  return {
    { "UnknownVertexInTrgl",
      "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\n"
      "TRGL 1 2 9\nEND\n",
      "line 7: TRGL refers to unknown vertex id 9" },
    { "NanCoordinate", WithVertex("VRTX 3 0 nan 0"), "line 5: non-finite coordinate 'nan'" },
    { "InfCoordinate", WithVertex("VRTX 3 inf 0 0"), "line 5: non-finite coordinate 'inf'" },
    { "MinusInfinityCoordinate", WithVertex("VRTX 3 0 0 -Infinity"), "line 5: non-finite" },
    { "WindowsInfCoordinate", WithVertex("VRTX 3 1.#INF 0 0"),
      "line 5: non-numeric coordinate '1.#INF'" },
    { "OverflowingCoordinate", WithVertex("VRTX 3 1e999 0 0"), "line 5: non-numeric" },
    { "NonNumericCoordinate", WithVertex("VRTX 3 12a.5 0 0"),
      "line 5: non-numeric coordinate '12a.5'" },
    { "NonIntegerVertexId", WithVertex("VRTX 3.5 0 1 0"), "line 5: vertex id '3.5'" },
    { "MissingCoordinate", WithVertex("VRTX 3 0 1"), "line 5: VRTX needs an id and three" },
    { "DuplicateVertexId", WithVertex("VRTX 2 0 1 0"), "line 5: vertex id 2 is defined twice" },
    { "AtomToUnknownVertex", WithVertex("ATOM 3 7"), "line 5: ATOM 3 refers to unknown vertex" },
    { "PvrtxWithTooFewValues", "GOCAD TSurf 1\nPROPERTIES a b\nPVRTX 1 0 0 0 1\nEND\n",
      "line 3: PVRTX needs 2 property values, found 1" },
    { "EsizesForOtherProperties",
      "GOCAD TSurf 1\nPROPERTIES a b\nESIZES 1\nPVRTX 1 0 0 0 1 2\nEND\n",
      "line 4: ESIZES gives 1 sizes for 2 PROPERTIES" },
    { "TruncatedWithoutEnd",
      "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1 0\nTRGL 1 2 3\n",
      "line 6: unexpected end of file" },
    { "TruncatedInsideALine", "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nVRTX 3 0 1",
      "line 5: VRTX needs" },
    { "TruncatedInsideANumber", "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 1.5e",
      "line 4: non-numeric coordinate '1.5e'" },
    { "TruncatedInsideTheHeader", "GOCAD TSurf 1\nHEADER {\nname:cut", "line 3: unexpected end" },
    { "NextObjectBeforeEnd", "GOCAD TSurf 1\nVRTX 1 0 0 0\nGOCAD TSurf 1\nEND\n",
      "line 3: new GOCAD object before the END" },
    { "EmptyFile", "", "line 1: the file is empty" },
    { "OnlyComments", "# nothing here\n\n", "line 2: no 'GOCAD TSurf' or 'GOCAD VSet' object" },
    { "NotATSurf", "solid cube\nfacet normal 0 0 1\n", "line 1: expected 'GOCAD TSurf'" },
    { "BinaryJunk", BinaryJunk(), "binary data" },
    { "NulInsideAValidFile", WithVertex(std::string("VRTX 3 0 1 0\0", 13)), "line 5: binary" },
    { "BadZPositive", "GOCAD TSurf 1\nZPOSITIVE Up\nEND\n", "line 2: ZPOSITIVE must be" },
    { "PaddingBeyondTheFileSize", PaddingBeyondTheFileSize(),
      "line 6: VRTX 3 would make the properties hold 3072 values" },
    { "BackfillBeyondTheFileSize", BackfillBeyondTheFileSize(),
      "line 1006: the new properties of this surface would make the properties hold 1024000" },
  };
}

class GocadTSurfBadFile : public ::testing::TestWithParam<BadFile>
{
};
}

TEST_P(GocadTSurfBadFile, GivesAnErrorNamingTheLineAndAnEmptyOutput)
{
  const BadFile& bad = GetParam();
  const auto r = Read(WriteText(std::string("bad_") + bad.Name + ".ts", bad.Content));
  EXPECT_NE(r.Errors.find("line"), std::string::npos) << r.Errors;
  EXPECT_NE(r.Errors.find(bad.Expected), std::string::npos) << r.Errors;
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(r.Output->GetNumberOfCells(), 0);
  EXPECT_EQ(r.Output->GetPointData()->GetNumberOfArrays(), 0);
}

INSTANTIATE_TEST_SUITE_P(Reader, GocadTSurfBadFile, ::testing::ValuesIn(BadFiles()),
  [](const ::testing::TestParamInfo<BadFile>& info) { return std::string(info.param.Name); });

TEST(GocadTSurfReader, MissingFileGivesAnErrorAndAnEmptyOutput)
{
  const auto r = Read(gocadtest::WorkPath("does_not_exist.ts"));
  EXPECT_NE(r.Errors.find("Cannot open"), std::string::npos) << r.Errors;
  EXPECT_NE(r.Errors.find("line"), std::string::npos) << r.Errors;
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
}

TEST(GocadTSurfReader, AGoodFileAfterABadOneReadsNormally)
{
  vtkNew<vtkGocadTSurfReader> reader;
  vtkNew<gocadtest::MessageCapture> capture;
  capture->Watch(reader);
  reader->SetFileName(WriteText("bad_then.ts", "GOCAD TSurf 1\nVRTX 1 0 0 nan\nEND\n").c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  reader->SetFileName(WriteText("good_now.ts", WithVertex("VRTX 3 0 1 0")).c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 3);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPolys(), 1);
}

namespace
{
// A stream whose reads throw std::bad_alloc, as an allocation deep in the parser would.
class ThrowingBuffer : public std::streambuf
{
protected:
  int_type underflow() override { throw std::bad_alloc(); }
};
}

TEST(GocadTSurfParser, AnExceptionInsideTheParserBecomesAnError)
{
  ThrowingBuffer buffer;
  std::istream input(&buffer);
  input.exceptions(std::ios::badbit); // rethrow what the buffer throws
  vtkGocadTSurfData data;
  std::string error;
  bool parsed = true;
  EXPECT_NO_THROW(parsed = vtkGocadTSurfParse(input, data, error));
  EXPECT_FALSE(parsed);
  EXPECT_NE(error.find("line 1: out of memory"), std::string::npos) << error;
}

TEST(GocadTSurfReader, TheAllowanceOfPaddingStillReadsMixedSurfaces)
{
  // 64 components per point from the first surface, padded on 100 short VRTX lines.
  std::string s = "GOCAD TSurf 1\nPROPERTIES v\nESIZES 64\nPVRTX 1 0 0 0";
  for (int i = 0; i < 64; ++i)
    s += " 1";
  s += "\nEND\nGOCAD TSurf 1\n";
  for (int id = 1; id <= 100; ++id)
    s += "VRTX " + std::to_string(id) + " 0 0 0\n";
  const auto r = Read(WriteText("padding_allowance.ts", s + "END\n"));
  EXPECT_EQ(r.Errors, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 101);
  vtkDataArray* v = r.Output->GetPointData()->GetArray("v");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->GetComponent(0, 63), 1.0);
  EXPECT_TRUE(std::isnan(v->GetComponent(100, 63)));
}

// Vertex ids that are multiples of a hash table's bucket count all fell in one bucket
// of std::hash's table (the identity): 100,000 such VRTX lines parsed in 4.5 s instead
// of 0.2 s, quadratic in the file's size. The parser's seeded hash spreads them; this
// checks the spread, not a time.
TEST(GocadTSurfParser, VertexIdsAimedAtOneBucketAreSpread)
{
  for (const std::uint64_t seed : { std::uint64_t(0), std::uint64_t(0x1234567890abcdefULL) })
  {
    std::unordered_map<std::int64_t, std::int64_t, vtkGocadTSurfText::VertexIdHash> ids(
      0, vtkGocadTSurfText::VertexIdHash{ seed });
    const std::int64_t buckets = 172933; // libstdc++'s table size for 85,230-172,933 items
    for (std::int64_t i = 0; i < 100000; ++i)
      ids.emplace(i * buckets, i);
    std::size_t largest = 0;
    for (std::size_t b = 0; b < ids.bucket_count(); ++b)
      largest = std::max(largest, ids.bucket_size(b));
    EXPECT_LE(largest, 16u) << "seed " << seed << ", " << ids.bucket_count() << " buckets";
  }
}

TEST(GocadTSurfReader, VertexIdsFarApartReadNormally)
{
  std::string s = "GOCAD TSurf 1\n";
  for (std::int64_t i = 0; i < 1000; ++i)
    s += "VRTX " + std::to_string(i * 172933 - 9000000000000000000LL) + " 0 0 0\n";
  s += "TRGL -9000000000000000000 -8999999999999827067 -8999999999999654134\nEND\n";
  const auto r = Read(WriteText("ids_far_apart.ts", s));
  EXPECT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 1000);
  EXPECT_EQ(r.Output->GetNumberOfCells(), 1);
}

// Long files tell the progress bar how far they are and stop when asked.
TEST(GocadTSurfParser, ReportsProgressByBytesAndStopsWhenAsked)
{
  std::string s = "GOCAD TSurf 1\n";
  for (int id = 1; id <= 5000; ++id)
    s += "VRTX " + std::to_string(id) + " " + std::to_string(id) + " 0 0\n";
  s += "END\n";
  std::vector<double> seen;
  {
    std::istringstream in(s);
    vtkGocadTSurfData data;
    std::string error;
    ASSERT_TRUE(vtkGocadTSurfParse(
      in, data, error,
      [&](double f)
      {
        seen.push_back(f);
        return true;
      },
      s.size()))
      << error;
  }
  EXPECT_GE(seen.size(), 90u);
  EXPECT_LE(seen.size(), 101u);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);

  std::istringstream in(s);
  vtkGocadTSurfData data;
  std::string error;
  int calls = 0;
  EXPECT_FALSE(vtkGocadTSurfParse(
    in, data, error, [&](double) { return ++calls < 10; }, s.size()));
  EXPECT_NE(error.find("stopped at the user's request"), std::string::npos) << error;
  EXPECT_EQ(calls, 10);
}
