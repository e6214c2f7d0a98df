// vtkNpzDEMReader on small hand-built .npz archives: good ones read, hostile ones give a
// clear error and no output, and sizes read from the file are checked before any
// allocation (a claimed size is kept small here, so a missing check fails an assertion
// rather than allocating gigabytes).
#include "GocadTestUtilities.h"

#include "vtkFieldData.h"
#include "vtkNpzDEMReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include "vtk_zlib.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using gocadtest::MessageCapture;
using gocadtest::WorkPath;

namespace
{
// A .npy file, version 1.0: the header dict as numpy writes it, padded to 64 bytes.
std::string Npy(const std::string& descr, const std::string& fortranOrder, const std::string& shape,
  const std::string& payload)
{
  std::string header =
    "{'descr': '" + descr + "', 'fortran_order': " + fortranOrder + ", 'shape': (" + shape + "), }";
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string npy("\x93NUMPY\x01\x00", 8);
  npy += static_cast<char>(header.size() & 0xff);
  npy += static_cast<char>(header.size() >> 8);
  return npy + header + payload;
}

template<typename T>
std::string Bytes(const std::vector<T>& values)
{
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

std::string Scalar(double value)
{
  return Npy("<f8", "False", "", Bytes(std::vector<double>{ value }));
}

// 3 rows x 4 columns of elevations (metres), doubles.
std::string Elevation3x4()
{
  return Npy(
    "<f8", "False", "3, 4", Bytes(std::vector<double>{ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 }));
}

struct ZipEntry
{
  std::string Name;
  std::string Data;
  bool Deflate = false;
  std::int64_t ClaimedSize = -1; // uncompressed size written in the headers; -1: the true one
  bool WrongCrc = false;         // headers carry a CRC-32 that does not match the data
};

std::string Deflated(const std::string& data)
{
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, 9, Z_DEFLATED, -MAX_WBITS, 9, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(&out[0]);
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void Put16(std::string& s, std::uint32_t v)
{
  s += static_cast<char>(v & 0xff);
  s += static_cast<char>((v >> 8) & 0xff);
}

void Put32(std::string& s, std::uint32_t v)
{
  Put16(s, v & 0xffff);
  Put16(s, v >> 16);
}

// A zip archive (what numpy.savez writes): local headers and data, central directory,
// end of central directory.
std::string Zip(const std::vector<ZipEntry>& entries)
{
  std::string zip, directory;
  for (const ZipEntry& e : entries)
  {
    const std::string data = e.Deflate ? Deflated(e.Data) : e.Data;
    const auto size =
      static_cast<std::uint32_t>(e.ClaimedSize >= 0 ? e.ClaimedSize : std::int64_t(e.Data.size()));
    const auto crc = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(e.Data.data()), static_cast<uInt>(e.Data.size())) ^
      (e.WrongCrc ? 1u : 0u));
    const auto offset = static_cast<std::uint32_t>(zip.size());
    Put32(zip, 0x04034b50u);
    Put16(zip, 20);
    Put16(zip, 0);
    Put16(zip, e.Deflate ? 8 : 0);
    Put32(zip, 0); // time, date
    Put32(zip, crc);
    Put32(zip, static_cast<std::uint32_t>(data.size()));
    Put32(zip, size);
    Put16(zip, static_cast<std::uint32_t>(e.Name.size()));
    Put16(zip, 0);
    zip += e.Name + data;

    Put32(directory, 0x02014b50u);
    Put16(directory, 20);
    Put16(directory, 20);
    Put16(directory, 0);
    Put16(directory, e.Deflate ? 8 : 0);
    Put32(directory, 0);
    Put32(directory, crc);
    Put32(directory, static_cast<std::uint32_t>(data.size()));
    Put32(directory, size);
    Put16(directory, static_cast<std::uint32_t>(e.Name.size()));
    Put32(directory, 0); // extra, comment lengths
    Put32(directory, 0); // disk, internal attributes
    Put32(directory, 0); // external attributes
    Put32(directory, offset);
    directory += e.Name;
  }
  const auto start = static_cast<std::uint32_t>(zip.size());
  zip += directory;
  Put32(zip, 0x06054b50u);
  Put32(zip, 0);
  Put16(zip, static_cast<std::uint32_t>(entries.size()));
  Put16(zip, static_cast<std::uint32_t>(entries.size()));
  Put32(zip, static_cast<std::uint32_t>(directory.size()));
  Put32(zip, start);
  Put16(zip, 0);
  return zip;
}

// A DEM archive with `elevation` and the four bounds.
std::vector<ZipEntry> Dem(const std::string& elevation, bool deflate = false, double xmin = -84.5,
  double xmax = -84.4, double ymin = 36.3, double ymax = 36.2)
{
  return { { "elevation.npy", elevation, deflate }, { "xmin.npy", Scalar(xmin), deflate },
    { "xmax.npy", Scalar(xmax), deflate }, { "ymin.npy", Scalar(ymin), deflate },
    { "ymax.npy", Scalar(ymax), deflate } };
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Output;
  std::string Errors;
};

ReadResult ReadNpz(const std::string& name, const std::vector<ZipEntry>& entries, int stride = 1)
{
  const std::string path = WorkPath(name);
  std::ofstream(path, std::ios::binary) << Zip(entries);
  vtkNew<vtkNpzDEMReader> reader;
  vtkNew<MessageCapture> capture;
  capture->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetStride(stride);
  reader->Update();
  return { reader->GetOutput(), capture->Errors };
}

// The reader's own error (not only the executive's "Algorithm ... returned failure").
void ExpectRefused(const ReadResult& r, const std::string& expected)
{
  EXPECT_NE(r.Errors.find(expected), std::string::npos) << r.Errors;
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
  EXPECT_EQ(r.Output->GetNumberOfCells(), 0);
}
}

TEST(NpzDEMReader, ReadsStoredAndDeflatedArchives)
{
  for (const bool deflate : { false, true })
  {
    const auto r =
      ReadNpz(deflate ? "dem_deflated.npz" : "dem_stored.npz", Dem(Elevation3x4(), deflate));
    EXPECT_EQ(r.Errors, "");
    ASSERT_EQ(r.Output->GetNumberOfPoints(), 12);
    EXPECT_EQ(r.Output->GetNumberOfPolys(), 12);
    double p[3];
    r.Output->GetPoint(11, p);
    EXPECT_EQ(p[2], 12.0);
  }
}

// Deflate at (nearly) its best ratio (zlib: about 935:1 on zeros) is still accepted: the size bound
// is not tighter than the format.
TEST(NpzDEMReader, ReadsAnEntryAtDeflatesBestRatio)
{
  const std::string zeros = Npy("|i1", "False", "1000, 1000", std::string(1000000, '\0'));
  const std::string compressed = Deflated(zeros);
  EXPECT_GT(zeros.size(), 900 * compressed.size()) << "zlib at level 9 gives about 935:1";
  const auto r = ReadNpz("dem_zeros.npz", Dem(zeros, true), 999);
  EXPECT_EQ(r.Errors, "");
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 4);
}

// The finding: a 1 KB archive whose entry claimed 0xfffffffe bytes made the reader
// allocate and zero 4 GB before inflate failed. Claimed here: 100 MB, still far above
// what the compressed bytes can give, so a missing check costs 100 MB, not 4 GB.
TEST(NpzDEMReader, RefusesADeflatedSizeAboveDeflatesMaximumRatioBeforeAllocating)
{
  auto entries = Dem(Elevation3x4(), true);
  entries[0].ClaimedSize = 100000000;
  ExpectRefused(ReadNpz("dem_bomb.npz", entries),
    "elevation.npy: the entry claims 100000000 bytes uncompressed");
  ExpectRefused(ReadNpz("dem_bomb.npz", entries), "more than deflate can produce");
}

TEST(NpzDEMReader, RefusesAStoredEntryWhoseSizesDiffer)
{
  auto entries = Dem(Elevation3x4());
  entries[0].ClaimedSize = 100000000;
  ExpectRefused(ReadNpz("dem_stored_sizes.npz", entries),
    "elevation.npy: a stored entry of 224 bytes claims 100000000 bytes uncompressed");
}

// The projection is UTM through PROJ, checked where transverse Mercator is exact by
// construction: a 3 x 3 grid centred on zone 16's central meridian (87 W) and the
// equator puts its centre at 500,000 E, 0 N (the false easting), its columns symmetric
// about it, and its rows symmetric about the equator (north of it, northings grow).
TEST(NpzDEMReader, ProjectsToTheUtmZoneOfTheGridCentreWithProj)
{
  const std::string nine =
    Npy("<f8", "False", "3, 3", Bytes(std::vector<double>{ 1, 2, 3, 4, 5, 6, 7, 8, 9 }));
  const auto r = ReadNpz("dem_utm.npz", Dem(nine, false, -87.5, -86.5, 0.5, -0.5));
  EXPECT_EQ(r.Errors, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 9);
  double p[9][3];
  for (int i = 0; i < 9; ++i)
    r.Output->GetPoint(i, p[i]);
  EXPECT_NEAR(p[4][0], 500000.0, 1e-6);
  EXPECT_NEAR(p[4][1], 0.0, 1e-6);
  EXPECT_NEAR(p[3][0] - 500000.0, 500000.0 - p[5][0], 1e-6); // columns 87.5 W, 86.5 W
  EXPECT_NEAR(p[1][1], -p[7][1], 1e-6);                      // rows 0.5 N, 0.5 S
  // Half a degree of longitude at the equator, scale 0.9996 on the central meridian:
  // about 55.6 km; half a degree of latitude about 55.3 km.
  EXPECT_NEAR(500000.0 - p[3][0], 55640.0, 100.0);
  EXPECT_NEAR(p[1][1], 55270.0, 100.0);
  auto* about =
    vtkStringArray::SafeDownCast(r.Output->GetFieldData()->GetAbstractArray("Projection"));
  ASSERT_NE(about, nullptr);
  EXPECT_EQ(about->GetValue(0).rfind("UTM zone 16N (WGS84, PROJ ", 0), 0u) << about->GetValue(0);
}

// A damaged entry whose bytes still parse (one bit of the elevations flipped on disk) gave
// wrong heights silently while the reader skipped the CRC-32; libzip checks it.
TEST(NpzDEMReader, RefusesAnEntryWhoseDataDoNotMatchItsCrc)
{
  for (const bool deflate : { false, true })
  {
    auto entries = Dem(Elevation3x4(), deflate);
    entries[0].WrongCrc = true;
    ExpectRefused(ReadNpz("dem_bad_crc.npz", entries), "elevation.npy: corrupt compressed data");
  }
}

// UBSan: memcpy from/to a null pointer for an empty stored entry.
TEST(NpzDEMReader, AnEmptyStoredEntryIsAnErrorNotACrash)
{
  auto entries = Dem(Elevation3x4());
  entries[1].Data.clear();
  ExpectRefused(ReadNpz("dem_empty_entry.npz", entries), "xmin.npy: not a .npy array");
  entries[1].Deflate = true;
  ExpectRefused(ReadNpz("dem_empty_deflated.npz", entries), "xmin.npy: not a .npy array");
}

namespace
{
struct BadNpy
{
  const char* Name;
  std::vector<ZipEntry> Entries;
  const char* Expected; // must appear in the error message
};

void PrintTo(const BadNpy& bad, std::ostream* os)
{
  *os << bad.Name;
}

std::string Twelve()
{
  return Bytes(std::vector<double>{ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 });
}

std::vector<BadNpy> BadNpys()
{
  return {
    // 9223372036854775811 x 4 wraps to 12 in 64 bits; the rows were cut to 3 in 32 bits.
    { "ShapeProductOverflows", Dem(Npy("<f8", "False", "9223372036854775811, 4", Twelve())),
      "elevation.npy: the shape's size overflows" },
    { "RowsDoNotFitInInt", Dem(Npy("<f8", "False", "4294967299, 0", "")),
      "elevation.npy: 4294967299 x 0 is too large a grid" },
    { "FractionalShape", Dem(Npy("<f8", "False", "3.5, 4", Twelve())),
      "elevation.npy: shape '3.5, 4' is not a tuple of sizes" },
    { "NegativeShape", Dem(Npy("<f8", "False", "-3, 4", Twelve())),
      "elevation.npy: shape '-3, 4' is not a tuple of sizes" },
    { "EmptyShapeItem", Dem(Npy("<f8", "False", "3,, 4", Twelve())),
      "elevation.npy: shape '3,, 4' is not a tuple of sizes" },
    { "FortranOrderNotABoolean", Dem(Npy("<f8", "NotFalseAtAll", "3, 4", Twelve())),
      "elevation.npy: fortran_order 'NotFalseAtAll' is not True or False" },
    { "FortranOrderTrue", Dem(Npy("<f8", "True", "3, 4", Twelve())),
      "elevation.npy: Fortran-ordered arrays are not supported" },
    { "DescrWithTrailingJunk", Dem(Npy("<f8junk", "False", "3, 4", Twelve())),
      "elevation.npy: dtype '<f8junk' is not supported" },
    { "BigEndian", Dem(Npy(">f8", "False", "3, 4", Twelve())),
      "elevation.npy: dtype '>f8' is not little-endian" },
    { "PayloadLongerThanTheShape", Dem(Npy("<f8", "False", "3, 3", Twelve())),
      "elevation.npy: 96 bytes of data for 9 values of 8 bytes" },
    { "PayloadShorterThanTheShape", Dem(Npy("<f8", "False", "3, 5", Twelve())),
      "elevation.npy: 96 bytes of data for 15 values of 8 bytes" },
    // Finite bounds whose span is not.
    { "InfiniteSpan", Dem(Elevation3x4(), false, -1e308, 1e308), "spans must be finite" },
  };
}

class NpzDEMReaderBadArray : public ::testing::TestWithParam<BadNpy>
{
};
}

TEST_P(NpzDEMReaderBadArray, GivesAClearErrorAndNoOutput)
{
  const BadNpy& bad = GetParam();
  ExpectRefused(ReadNpz(std::string("dem_bad_") + bad.Name + ".npz", bad.Entries), bad.Expected);
}

INSTANTIATE_TEST_SUITE_P(Reader, NpzDEMReaderBadArray, ::testing::ValuesIn(BadNpys()),
  [](const ::testing::TestParamInfo<BadNpy>& info) { return std::string(info.param.Name); });
