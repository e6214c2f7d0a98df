// VTK-free .npz/.npy reading of vtkNpzDEMReader (and of the fuzz targets in Testing/Fuzz).
#include "vtkNpzDEMParser.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace
{
// Deflate's largest expansion: a 258-byte match in 2 bits, 1032:1, plus a few bytes for
// the block header and a first literal.
constexpr std::uint64_t DeflateMaxRatio = 1032;
constexpr std::uint64_t DeflateSlack = 64;

std::string HeaderValue(const std::string& header, const std::string& key)
{
  const std::size_t k = header.find("'" + key + "'");
  if (k == std::string::npos)
    throw std::runtime_error("npy header without '" + key + "'");
  std::size_t v = header.find(':', k);
  if (v == std::string::npos)
    throw std::runtime_error("npy header without a value for '" + key + "'");
  ++v;
  while (v < header.size() && header[v] == ' ')
    ++v;
  const char open = v < header.size() ? header[v] : '\0';
  if (open != '(' && open != '\'')
  {
    // A bare value (True, False): up to the next ',' or '}', without trailing spaces.
    std::size_t end = header.find_first_of(",}", v);
    if (end == std::string::npos)
      throw std::runtime_error("npy header: unterminated value for '" + key + "'");
    while (end > v && header[end - 1] == ' ')
      --end;
    return header.substr(v, end - v);
  }
  const std::size_t end = header.find(open == '(' ? ')' : '\'', v + 1);
  if (end == std::string::npos)
    throw std::runtime_error("npy header: unterminated value for '" + key + "'");
  return header.substr(v + 1, end - v - 1);
}

// A tuple of sizes as numpy writes it: "", "5," or "3, 4" (the trailing comma only after
// the last item); false for anything else (a fraction, a sign, an empty item, junk).
bool ParseShape(const std::string& text, std::vector<std::size_t>& shape)
{
  std::stringstream items(text);
  std::string item;
  bool ended = false; // an empty item was seen: only allowed last, after a size
  while (std::getline(items, item, ','))
  {
    const std::size_t first = item.find_first_not_of(' ');
    if (first == std::string::npos)
    {
      if (ended || shape.empty())
        return false;
      ended = true;
      continue;
    }
    if (ended)
      return false;
    const std::size_t last = item.find_last_not_of(' ');
    const char* begin = item.data() + first;
    const char* end = item.data() + last + 1;
    std::size_t size = 0;
    const auto result = std::from_chars(begin, end, size);
    if (result.ec != std::errc() || result.ptr != end)
      return false;
    shape.push_back(size);
  }
  return true;
}

// The item size of a supported dtype string ('<f8', '|u1', ...), exactly; 0 otherwise.
int ItemSize(const std::string& descr)
{
  if (descr.size() < 3 || (descr[1] != 'f' && descr[1] != 'i' && descr[1] != 'u'))
    return 0;
  int size = 0;
  const char* end = descr.data() + descr.size();
  const auto result = std::from_chars(descr.data() + 2, end, size);
  const bool exact = result.ec == std::errc() && result.ptr == end &&
                     descr.compare(2, std::string::npos, std::to_string(size)) == 0; // not '<f08'
  return exact ? size : 0;
}

template<class T>
void Convert(const char* data, std::size_t count, std::vector<double>& out)
{
  out.resize(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    T value;
    std::memcpy(&value, data + i * sizeof(T), sizeof(T));
    out[i] = double(value);
  }
}

double Scalar(const vtkNpzArchive& npz, const std::string& key)
{
  const vtkNpyArray a = vtkNpyParse(npz.Read(key + ".npy"), key + ".npy");
  if (a.Values.size() != 1)
    throw std::runtime_error(key + ".npy: expected one value");
  return a.Values[0];
}
} // namespace

vtkNpzArchive::vtkNpzArchive(std::vector<char> bytes)
  : Bytes(std::move(bytes))
{
  zip_error_t error;
  zip_error_init(&error);
  // freep 0: the source reads this->Bytes in place and never frees them.
  zip_source_t* source = zip_source_buffer_create(
    this->Bytes.empty() ? nullptr : this->Bytes.data(), this->Bytes.size(), 0, &error);
  if (source)
  {
    this->Zip = zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
    if (!this->Zip)
      zip_source_free(source);
  }
  if (!this->Zip)
  {
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    throw std::runtime_error("not a zip (.npz) archive: " + why);
  }
  zip_error_fini(&error);
}

vtkNpzArchive::~vtkNpzArchive()
{
  zip_discard(this->Zip); // read only: nothing to write back
}

std::vector<char> vtkNpzArchive::Read(const std::string& name) const
{
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(this->Zip, name.c_str(), ZIP_FL_ENC_RAW, &stat) != 0)
    throw std::runtime_error("no entry " + name);
  constexpr zip_uint64_t needed = ZIP_STAT_SIZE | ZIP_STAT_COMP_SIZE | ZIP_STAT_COMP_METHOD;
  if ((stat.valid & needed) != needed)
    throw std::runtime_error(name + ": the archive does not give the entry's sizes");
  const std::uint64_t size = stat.size, compressed = stat.comp_size;
  // No entry holds more compressed bytes than the file (this also keeps the ratio
  // bound below from overflowing).
  if (compressed > this->Bytes.size())
    throw std::runtime_error(name + ": truncated zip archive");
  if (stat.comp_method != ZIP_CM_STORE && stat.comp_method != ZIP_CM_DEFLATE)
    throw std::runtime_error(name + ": compression method " + std::to_string(stat.comp_method) +
                             " is not supported (stored or deflated only)");
  if (stat.comp_method == ZIP_CM_STORE && compressed != size)
    throw std::runtime_error(name + ": a stored entry of " + std::to_string(compressed) +
                             " bytes claims " + std::to_string(size) + " bytes uncompressed");
  if (stat.comp_method == ZIP_CM_DEFLATE && size > DeflateMaxRatio * compressed + DeflateSlack)
    throw std::runtime_error(name + ": the entry claims " + std::to_string(size) +
                             " bytes uncompressed from " + std::to_string(compressed) +
                             " compressed bytes, more than deflate can produce (" +
                             std::to_string(DeflateMaxRatio) + " per byte)");
  std::vector<char> out(size);
  zip_file_t* file = zip_fopen_index(this->Zip, stat.index, 0);
  if (!file)
    throw std::runtime_error(name + ": " + zip_strerror(this->Zip));
  // One read of the claimed size, then one more byte: an entry must give exactly `size`
  // bytes (libzip checks the CRC-32 at the end of the data).
  const zip_int64_t got = size > 0 ? zip_fread(file, out.data(), size) : 0;
  char extra = 0;
  const zip_int64_t more = got == zip_int64_t(size) ? zip_fread(file, &extra, 1) : 0;
  const std::string why = got < 0 || more < 0 ? zip_file_strerror(file) : "";
  zip_fclose(file);
  if (got != zip_int64_t(size) || more != 0)
    throw std::runtime_error(
      name + ": corrupt compressed data" + (why.empty() ? std::string() : " (" + why + ")"));
  return out;
}

std::vector<char> vtkNpzReadFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open " + path);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

vtkNpyArray vtkNpyParse(const std::vector<char>& bytes, const std::string& name)
{
  auto fail = [&name](const std::string& what) { return std::runtime_error(name + ": " + what); };
  if (bytes.size() < 10 || std::memcmp(bytes.data(), "\x93NUMPY", 6) != 0)
    throw fail("not a .npy array");
  const int major = static_cast<unsigned char>(bytes[6]);
  std::size_t length = 0, start = 0;
  if (major == 1)
  {
    length = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
    start = 10;
  }
  else if ((major == 2 || major == 3) && bytes.size() >= 12)
  {
    for (int i = 3; i >= 0; --i)
      length = (length << 8) | static_cast<unsigned char>(bytes[8 + i]);
    start = 12;
  }
  else
    throw fail("npy format version " + std::to_string(major) + " is not supported");
  if (length > bytes.size() - start)
    throw fail("truncated npy header");
  const std::string header(&bytes[start], length);
  const std::string descr = HeaderValue(header, "descr");
  const std::string fortranOrder = HeaderValue(header, "fortran_order");
  if (fortranOrder == "True")
    throw fail("Fortran-ordered arrays are not supported");
  if (fortranOrder != "False")
    throw fail("fortran_order '" + fortranOrder + "' is not True or False");
  vtkNpyArray array;
  const std::string shape = HeaderValue(header, "shape");
  if (!ParseShape(shape, array.Shape))
    throw fail("shape '" + shape + "' is not a tuple of sizes");
  std::size_t count = 1;
  for (const std::size_t n : array.Shape)
  {
    if (n != 0 && count > SIZE_MAX / n)
      throw fail("the shape's size overflows (shape '" + shape + "')");
    count *= n;
  }
  if (descr.size() < 3 || (descr[0] != '<' && descr[0] != '|' && descr[0] != '='))
    throw fail("dtype '" + descr + "' is not little-endian");
  const char kind = descr[1];
  const int size = ItemSize(descr);
  if (size == 0)
    throw fail("dtype '" + descr + "' is not supported (integers or floats)");
  // The data is exactly shape product x item size: no more, no less.
  const std::size_t data = start + length;
  const std::size_t available = bytes.size() - data;
  if (count > available / std::size_t(size) || count * std::size_t(size) != available)
    throw fail(std::to_string(available) + " bytes of data for " + std::to_string(count) +
               " values of " + std::to_string(size) + " bytes");
  const char* p = bytes.data() + data;
  if (kind == 'f' && size == 4)
    Convert<float>(p, count, array.Values);
  else if (kind == 'f' && size == 8)
    Convert<double>(p, count, array.Values);
  else if (kind == 'i' && size == 1)
    Convert<std::int8_t>(p, count, array.Values);
  else if (kind == 'i' && size == 2)
    Convert<std::int16_t>(p, count, array.Values);
  else if (kind == 'i' && size == 4)
    Convert<std::int32_t>(p, count, array.Values);
  else if (kind == 'i' && size == 8)
    Convert<std::int64_t>(p, count, array.Values);
  else if (kind == 'u' && size == 1)
    Convert<std::uint8_t>(p, count, array.Values);
  else if (kind == 'u' && size == 2)
    Convert<std::uint16_t>(p, count, array.Values);
  else if (kind == 'u' && size == 4)
    Convert<std::uint32_t>(p, count, array.Values);
  else
    throw fail("dtype '" + descr + "' is not supported (integers or floats)");
  return array;
}

geoshaping::ElevationGrid vtkNpzDEMParse(const vtkNpzArchive& npz)
{
  vtkNpyArray elevation = vtkNpyParse(npz.Read("elevation.npy"), "elevation.npy");
  if (elevation.Shape.size() != 2)
    throw std::runtime_error("elevation.npy: expected a 2D array");
  // Rows and columns are int (geoshaping::index_t) from here on.
  if (elevation.Shape[0] > std::size_t(INT_MAX) || elevation.Shape[1] > std::size_t(INT_MAX))
    throw std::runtime_error("elevation.npy: " + std::to_string(elevation.Shape[0]) + " x " +
                             std::to_string(elevation.Shape[1]) + " is too large a grid (at most " +
                             std::to_string(INT_MAX) + " rows and columns)");
  geoshaping::ElevationGrid grid;
  grid.rows = geoshaping::index_t(elevation.Shape[0]);
  grid.cols = geoshaping::index_t(elevation.Shape[1]);
  grid.elevation = std::move(elevation.Values);
  // matplotlib's naming: xmin/ymin are the first column/row, xmax/ymax the last ones
  // (its Jacksboro DEM has ymin > ymax: the rows run north to south).
  grid.x_first = Scalar(npz, "xmin");
  grid.x_last = Scalar(npz, "xmax");
  grid.y_first = Scalar(npz, "ymin");
  grid.y_last = Scalar(npz, "ymax");
  return grid;
}
