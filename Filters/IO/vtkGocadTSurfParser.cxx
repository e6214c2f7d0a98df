#include "vtkGocadTSurfParser.h"
#include "vtkGocadTSurfText.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <random>
#include <unordered_map>

using namespace vtkGocadTSurfText;

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
// A text line of a TSurf is short; a longer one means binary data without newlines.
constexpr std::size_t MaxLineLength = 1 << 20;
constexpr int MaxComponents = 1024;
// Memory is bounded by the file's size (docs/tsurf.md, "Memory and time"): every point
// holds a value of every property of the file, and a vertex line that does not give them
// (a VRTX, or a PVRTX of a surface without them) is padded with NaN; a property new to a
// later surface is padded on every earlier point. So that a few short lines cannot make
// gigabytes of padding (64 properties of ESIZES 1024 gave 65,536 NaN per 14-byte VRTX),
// the values stored over all properties and points may not exceed the number of bytes
// read so far plus PaddingPerPoint per point; checked before they are stored. A PVRTX
// giving its values always fits (each value takes at least 2 bytes of its line).
constexpr std::uint64_t PaddingPerPoint = 64;

// GOCAD's point-set objects: VSet, and PointSet as some exports name it.
bool IsPointSet(const std::string& type)
{
  return type == "VSet" || type == "PointSet";
}

struct ParseFailure
{
  std::string Message;
};

class Parser
{
public:
  Parser(std::istream& input, vtkGocadTSurfData& data, const std::function<bool(double)>& progress,
    std::uint64_t totalBytes)
    : Input(input)
    , Data(data)
    , Progress(progress)
    , TotalBytes(totalBytes)
    , ReportStep(totalBytes / 100 + 1)
    , NextReport(ReportStep)
  {
  }

  void Run()
  {
    while (this->NextLine())
    {
      const Tokens t = Tokenize(this->Line);
      if (IsComment(t))
        continue;
      if (t[0] != "GOCAD")
        this->Fail("expected 'GOCAD TSurf' or 'GOCAD VSet', found " + Quote(t[0]));
      if (t.size() >= 2 && t[1] == "TSurf")
        this->ReadSurface(false);
      else if (t.size() >= 2 && IsPointSet(t[1]))
        this->ReadSurface(true);
      else
        this->SkipObject(t.size() >= 2 ? t[1] : std::string("(unnamed)"));
    }
    if (this->LineNumber == 0)
      throw ParseFailure{ "line 1: the file is empty" };
    if (this->Data.Surfaces.empty())
      this->Fail("no 'GOCAD TSurf' or 'GOCAD VSet' object in the file");
  }

  // The line being read or handled.
  std::size_t GetLineNumber() const { return this->LineNumber; }

private:
  // State of the surface being read; vertex ids are local to a surface.
  struct SurfaceState
  {
    std::unordered_map<std::int64_t, std::int64_t, VertexIdHash> IdToPoint;
    std::size_t FirstPoint = 0;
    bool PointSet = false; // a VSet (or PointSet): its points are vertex cells, no TRGL
    int TFace = 0;
    bool TFaceSeen = false;
    std::size_t NumberOfTriangles = 0;
    bool InCoordinateSystem = false;
    Tokens PropertyNames;
    std::vector<int> ESizes;
    std::vector<double> NoData;
    bool Resolved = false;
    int TotalComponents = 0;
    std::vector<int> GlobalToLocal; // per global property: local index or -1
    std::vector<int> LocalOffset;   // per local property: first value column
  };

  [[noreturn]] void Fail(const std::string& what) const
  {
    throw ParseFailure{ "line " + std::to_string(this->LineNumber) + ": " + what };
  }

  bool NextLine()
  {
    ++this->LineNumber;
    if (!std::getline(this->Input, this->Line))
    {
      --this->LineNumber;
      return false;
    }
    this->BytesRead += this->Line.size() + 1;
    if (this->Progress && this->TotalBytes > 0 && this->BytesRead >= this->NextReport)
    {
      this->NextReport = this->BytesRead + this->ReportStep;
      if (!this->Progress(std::min(1.0, double(this->BytesRead) / double(this->TotalBytes))))
        this->Fail("stopped at the user's request");
    }
    if (!this->Line.empty() && this->Line.back() == '\r')
      this->Line.pop_back();
    if (this->Line.size() > MaxLineLength)
      this->Fail("line too long: binary data, not a GOCAD TSurf text file");
    for (const char c : this->Line)
    {
      const auto u = static_cast<unsigned char>(c);
      if ((u < 0x20 && c != '\t') || u == 0x7f)
        this->Fail("binary data (byte " + std::to_string(u) + "), not a GOCAD TSurf text file");
    }
    return true;
  }

  vtkGocadTSurfSurfaceInfo& Info() { return this->Data.Surfaces.back(); }

  void ReadSurface(bool pointSet)
  {
    this->S = SurfaceState();
    this->S.PointSet = pointSet;
    this->S.IdToPoint = decltype(this->S.IdToPoint)(0, VertexIdHash{ this->IdSeed });
    this->S.FirstPoint = this->Data.GetNumberOfPoints();
    this->Data.Surfaces.emplace_back();
    while (this->NextLine())
    {
      const Tokens t = Tokenize(this->Line);
      if (IsComment(t))
        continue;
      if (t[0] == "END")
      {
        this->EndSurface();
        return;
      }
      if (t[0] == "GOCAD")
        this->Fail("new GOCAD object before the END of the previous surface");
      this->HandleKeyword(t);
    }
    this->Fail("unexpected end of file, the surface has no END (truncated file?)");
  }

  void SkipObject(const std::string& type)
  {
    this->Data.Warnings.push_back("line " + std::to_string(this->LineNumber) +
                                  ": skipped a GOCAD " + type +
                                  " object (only TSurf and VSet are read)");
    while (this->NextLine())
    {
      const Tokens t = Tokenize(this->Line);
      if (!t.empty() && t[0] == "END")
        return;
    }
    this->Fail("unexpected end of file inside a GOCAD " + type + " object");
  }

  void EndSurface()
  {
    if (this->S.PointSet)
      for (std::size_t i = this->S.FirstPoint; i < this->Data.GetNumberOfPoints(); ++i)
      {
        this->Data.Vertices.push_back(static_cast<std::int64_t>(i));
        this->Data.VertexSurface.push_back(static_cast<int>(this->Data.Surfaces.size() - 1));
      }
    if (!EqualsNoCase(this->Info().ZPositive, "depth"))
      return;
    for (std::size_t i = this->S.FirstPoint; i < this->Data.GetNumberOfPoints(); ++i)
      this->Data.Points[3 * i + 2] = -this->Data.Points[3 * i + 2];
  }

  void HandleKeyword(const Tokens& t)
  {
    const std::string& k = t[0];
    if (k == "VRTX" || k == "PVRTX")
      this->AddVertex(t, k == "PVRTX");
    else if (k == "ATOM" || k == "PATOM")
      this->AddAtom(t);
    else if (k == "TRGL")
      this->AddTriangle(t);
    else if (k == "TFACE")
    {
      if (this->S.TFaceSeen || this->S.NumberOfTriangles > 0)
        ++this->S.TFace;
      this->S.TFaceSeen = true;
    }
    else if (k == "PROPERTIES")
      this->ReadPropertyNames(t);
    else if (k == "ESIZES")
      this->ReadESizes(t);
    else if (k == "NO_DATA_VALUES")
      this->ReadNoData(t);
    else if (this->Line.find('{') != std::string::npos)
      this->ReadBlock(k == "HEADER");
    else if (k == "GOCAD_ORIGINAL_COORDINATE_SYSTEM" || k == "END_ORIGINAL_COORDINATE_SYSTEM")
      this->S.InCoordinateSystem = (k == "GOCAD_ORIGINAL_COORDINATE_SYSTEM");
    else if (k == "NAME" && this->S.InCoordinateSystem && t.size() > 1)
      this->Info().CoordinateSystemName = t[1];
    else if (k == "AXIS_NAME" || k == "AXIS_UNIT")
    {
      auto& axes = (k == "AXIS_NAME") ? this->Info().AxisNames : this->Info().AxisUnits;
      for (std::size_t i = 0; i < 3 && i + 1 < t.size(); ++i)
        axes[i] = t[i + 1];
    }
    else if (k == "ZPOSITIVE")
    {
      if (t.size() < 2 || !(EqualsNoCase(t[1], "depth") || EqualsNoCase(t[1], "elevation")))
        this->Fail("ZPOSITIVE must be Elevation or Depth");
      this->Info().ZPositive = t[1];
    }
    // Any other keyword (BSTONE, BORDER, PROPERTY_CLASS, UNITS, ...) leaves the mesh as is.
  }

  // A "{ ... }" block, possibly over several lines; HEADER blocks give the name.
  void ReadBlock(bool header)
  {
    std::string text = this->Line.substr(this->Line.find('{') + 1);
    for (;;)
    {
      const std::size_t close = text.find('}');
      const std::string entry = Trim(text.substr(0, close));
      if (header && entry.compare(0, 5, "name:") == 0)
        this->Info().Name = Trim(entry.substr(5));
      if (close != std::string::npos)
        return;
      if (!this->NextLine())
        this->Fail("unexpected end of file inside a { } block (truncated file?)");
      text = this->Line;
    }
  }

  // An empty name ("") would give an unnamed array, which the writer leaves out: it is
  // named unnamed_<position> instead (with '_' appended until no other name is the same).
  void ReadPropertyNames(const Tokens& t)
  {
    Tokens& names = this->S.PropertyNames;
    names.assign(t.begin() + 1, t.end());
    for (std::size_t i = 0; i < names.size(); ++i)
    {
      if (!names[i].empty())
        continue;
      std::string name = "unnamed_" + std::to_string(i + 1);
      while (std::find(names.begin(), names.end(), name) != names.end())
        name += '_';
      names[i] = name;
      this->Data.Warnings.push_back("line " + std::to_string(this->LineNumber) + ": property " +
                                    std::to_string(i + 1) + " has an empty name, read as " +
                                    Quote(name));
    }
    this->S.Resolved = false;
  }

  // Refuses (before storing them) property values beyond the bound of PaddingPerPoint.
  void CheckPropertyValues(
    std::uint64_t values, std::uint64_t points, const std::string& what) const
  {
    const std::uint64_t allowed = this->BytesRead + PaddingPerPoint * points;
    if (values > allowed)
      this->Fail(what + " would make the properties hold " + std::to_string(values) +
                 " values for " + std::to_string(points) + " points from " +
                 std::to_string(this->BytesRead) + " bytes, more than the " +
                 std::to_string(allowed) + " allowed (one per byte read plus " +
                 std::to_string(PaddingPerPoint) +
                 " per point; the values a vertex line does not give are padded with NaN)");
  }

  void ReadESizes(const Tokens& t)
  {
    this->S.ESizes.clear();
    for (std::size_t i = 1; i < t.size(); ++i)
    {
      int size = 0;
      if (!ParseNumber(t[i], size) || size < 1 || size > MaxComponents)
        this->Fail("ESIZES value " + Quote(t[i]) + " is not a component count");
      this->S.ESizes.push_back(size);
    }
    this->S.Resolved = false;
  }

  void ReadNoData(const Tokens& t)
  {
    this->S.NoData.clear();
    for (std::size_t i = 1; i < t.size(); ++i)
      this->S.NoData.push_back(this->Number(t[i], "NO_DATA_VALUES value"));
    this->S.Resolved = false;
  }

  double Number(const std::string& token, const char* what) const
  {
    double value = 0.0;
    if (!ParseNumber(token, value))
      this->Fail(std::string("non-numeric ") + what + " " + Quote(token));
    if (!std::isfinite(value))
      this->Fail(std::string("non-finite ") + what + " " + Quote(token));
    return value;
  }

  std::int64_t Id(const std::string& token) const
  {
    std::int64_t id = 0;
    if (!ParseNumber(token, id))
      this->Fail("vertex id " + Quote(token) + " is not an integer");
    return id;
  }

  // Map the surface's PROPERTIES onto the file-wide property list (created on demand).
  void ResolveProperties()
  {
    SurfaceState& s = this->S;
    const std::size_t n = s.PropertyNames.size();
    if (s.ESizes.empty())
      s.ESizes.assign(n, 1);
    if (s.ESizes.size() != n)
      this->Fail("ESIZES gives " + std::to_string(s.ESizes.size()) + " sizes for " +
                 std::to_string(n) + " PROPERTIES");
    if (!s.NoData.empty() && s.NoData.size() != n)
      this->Fail("NO_DATA_VALUES gives " + std::to_string(s.NoData.size()) + " values for " +
                 std::to_string(n) + " PROPERTIES");
    auto& global = this->Data.Properties;
    s.LocalOffset.assign(n, 0);
    s.TotalComponents = 0;
    std::vector<int> localToGlobal(n);
    // The padding of the new properties on the points already read, checked first.
    const std::uint64_t points = this->Data.GetNumberOfPoints();
    std::uint64_t padding = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (this->PropertyIndex.count(s.PropertyNames[i]) == 0)
        padding += points * static_cast<std::uint64_t>(s.ESizes[i]);
    this->CheckPropertyValues(
      this->PropertyValues + padding, points, "the new properties of this surface");
    for (std::size_t i = 0; i < n; ++i)
    {
      s.LocalOffset[i] = s.TotalComponents;
      s.TotalComponents += s.ESizes[i];
      const auto found = this->PropertyIndex.emplace(s.PropertyNames[i], global.size());
      if (found.second)
      {
        vtkGocadTSurfProperty p{ s.PropertyNames[i], s.ESizes[i], {} };
        p.Values.assign(points * s.ESizes[i], NaN);
        global.push_back(std::move(p));
        this->PropertyValues += points * s.ESizes[i];
        this->ComponentsPerPoint += s.ESizes[i];
      }
      else if (global[found.first->second].NumberOfComponents != s.ESizes[i])
        this->Fail("property " + Quote(s.PropertyNames[i]) + " changes its number of components");
      localToGlobal[i] = static_cast<int>(found.first->second);
    }
    s.GlobalToLocal.assign(global.size(), -1);
    for (std::size_t i = 0; i < n; ++i)
      s.GlobalToLocal[localToGlobal[i]] = static_cast<int>(i);
    s.Resolved = true;
  }

  void AddVertex(const Tokens& t, bool withProperties)
  {
    if (t.size() < 5)
      this->Fail(t[0] + " needs an id and three coordinates");
    if (withProperties && !this->S.Resolved)
      this->ResolveProperties();
    const int expected = withProperties ? this->S.TotalComponents : 0;
    if (withProperties && t.size() != static_cast<std::size_t>(5 + expected))
      this->Fail("PVRTX needs " + std::to_string(expected) + " property values, found " +
                 std::to_string(t.size() - 5));
    const std::int64_t id = this->Id(t[1]);
    double xyz[3];
    for (int c = 0; c < 3; ++c)
      xyz[c] = this->Number(t[2 + c], "coordinate");
    const auto point = static_cast<std::int64_t>(this->Data.GetNumberOfPoints());
    this->CheckPropertyValues(this->PropertyValues + this->ComponentsPerPoint,
      static_cast<std::uint64_t>(point) + 1, t[0] + " " + t[1]);
    if (!this->S.IdToPoint.emplace(id, point).second)
      this->Fail("vertex id " + std::to_string(id) + " is defined twice");
    this->PropertyValues += this->ComponentsPerPoint;
    this->Data.Points.insert(this->Data.Points.end(), xyz, xyz + 3);
    for (std::size_t g = 0; g < this->Data.Properties.size(); ++g)
    {
      auto& p = this->Data.Properties[g];
      const int local =
        (withProperties && g < this->S.GlobalToLocal.size()) ? this->S.GlobalToLocal[g] : -1;
      for (int c = 0; c < p.NumberOfComponents; ++c)
      {
        double value = NaN;
        if (local >= 0)
        {
          value = this->Number(t[5 + this->S.LocalOffset[local] + c], "property value");
          if (!this->S.NoData.empty() && value == this->S.NoData[local])
            value = NaN;
        }
        p.Values.push_back(value);
      }
    }
  }

  void AddAtom(const Tokens& t)
  {
    if (t.size() < 3)
      this->Fail(t[0] + " needs an id and the id of the vertex it refers to");
    const std::int64_t id = this->Id(t[1]);
    const std::int64_t ref = this->Id(t[2]);
    const auto it = this->S.IdToPoint.find(ref);
    if (it == this->S.IdToPoint.end())
      this->Fail(
        t[0] + " " + std::to_string(id) + " refers to unknown vertex id " + std::to_string(ref));
    if (!this->S.IdToPoint.emplace(id, it->second).second)
      this->Fail("vertex id " + std::to_string(id) + " is defined twice");
  }

  void AddTriangle(const Tokens& t)
  {
    if (this->S.PointSet)
      this->Fail("TRGL in a GOCAD VSet: a point set has no triangles");
    if (t.size() != 4)
      this->Fail("TRGL needs exactly three vertex ids");
    for (int c = 1; c <= 3; ++c)
    {
      const std::int64_t id = this->Id(t[c]);
      const auto it = this->S.IdToPoint.find(id);
      if (it == this->S.IdToPoint.end())
        this->Fail("TRGL refers to unknown vertex id " + std::to_string(id));
      this->Data.Triangles.push_back(it->second);
    }
    this->Data.TFace.push_back(this->S.TFace);
    this->Data.Surface.push_back(static_cast<int>(this->Data.Surfaces.size() - 1));
    ++this->S.NumberOfTriangles;
  }

  std::istream& Input;
  vtkGocadTSurfData& Data;
  std::string Line;
  std::size_t LineNumber = 0;
  SurfaceState S;
  std::uint64_t BytesRead = 0; // lines read so far, with their line ends
  const std::function<bool(double)>& Progress;
  const std::uint64_t TotalBytes;
  const std::uint64_t ReportStep; // bytes between two progress reports (1 %)
  std::uint64_t NextReport;
  std::uint64_t PropertyValues = 0;     // values stored over all properties and points
  std::uint64_t ComponentsPerPoint = 0; // sum of NumberOfComponents over all properties
  std::unordered_map<std::string, std::size_t> PropertyIndex; // name -> Data.Properties
  std::uint64_t IdSeed = RandomSeed();

  static std::uint64_t RandomSeed()
  {
    try
    {
      std::random_device device;
      return (std::uint64_t(device()) << 32) ^ device();
    }
    catch (const std::exception&)
    {
      // No entropy source: the clock's ticks still differ from one parse to the next.
      return static_cast<std::uint64_t>(
        std::chrono::steady_clock::now().time_since_epoch().count());
    }
  }
};
}

bool vtkGocadTSurfParse(std::istream& input, vtkGocadTSurfData& data, std::string& error,
  const std::function<bool(double)>& progress, std::uint64_t totalBytes)
{
  Parser parser(input, data, progress, totalBytes);
  try
  {
    parser.Run();
    if (progress)
    {
      progress(1.0); // the end, whatever the last 1 % step was
    }
    return true;
  }
  catch (const ParseFailure& failure)
  {
    error = failure.Message;
  }
  // Nothing may escape into the caller (ParaView): an allocation that fails, or any other
  // exception from the stream or the standard library, is an error of the file's line.
  catch (const std::bad_alloc&)
  {
    error = "line " + std::to_string(parser.GetLineNumber()) + ": out of memory";
  }
  catch (const std::exception& e)
  {
    error = "line " + std::to_string(parser.GetLineNumber()) + ": " + e.what();
  }
  return false;
}

bool vtkGocadTSurfLooksLikeTSurf(std::istream& input)
{
  std::string line;
  for (int i = 0; i < 100 && std::getline(input, line); ++i)
  {
    const Tokens t = Tokenize(line.substr(0, 256));
    if (IsComment(t))
      continue;
    return t.size() >= 2 && t[0] == "GOCAD" && (t[1] == "TSurf" || IsPointSet(t[1]));
  }
  return false;
}
