#include "vtkGocadTSurfParser.h"
#include "vtkGocadTSurfText.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

using namespace vtkGocadTSurfText;

namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
// A text line of a TSurf is short; a longer one means binary data without newlines.
constexpr std::size_t MaxLineLength = 1 << 20;
constexpr int MaxComponents = 1024;

struct ParseFailure
{
  std::string Message;
};

class Parser
{
public:
  Parser(std::istream& input, vtkGocadTSurfData& data)
    : Input(input)
    , Data(data)
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
        this->Fail("expected 'GOCAD TSurf', found " + Quote(t[0]));
      if (t.size() >= 2 && t[1] == "TSurf")
        this->ReadSurface();
      else
        this->SkipObject(t.size() >= 2 ? t[1] : std::string("(unnamed)"));
    }
    if (this->LineNumber == 0)
      throw ParseFailure{ "line 1: the file is empty" };
    if (this->Data.Surfaces.empty())
      this->Fail("no 'GOCAD TSurf' object in the file");
  }

private:
  // State of the surface being read; vertex ids are local to a surface.
  struct SurfaceState
  {
    std::unordered_map<std::int64_t, std::int64_t> IdToPoint;
    std::size_t FirstPoint = 0;
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
    if (!std::getline(this->Input, this->Line))
      return false;
    ++this->LineNumber;
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

  void ReadSurface()
  {
    this->S = SurfaceState();
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
      ": skipped a GOCAD " + type + " object (only TSurf is read)");
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
    {
      this->S.PropertyNames.assign(t.begin() + 1, t.end());
      this->S.Resolved = false;
    }
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
    for (std::size_t i = 0; i < n; ++i)
    {
      s.LocalOffset[i] = s.TotalComponents;
      s.TotalComponents += s.ESizes[i];
      auto it = std::find_if(global.begin(), global.end(),
        [&](const vtkGocadTSurfProperty& p) { return p.Name == s.PropertyNames[i]; });
      if (it == global.end())
      {
        vtkGocadTSurfProperty p{ s.PropertyNames[i], s.ESizes[i], {} };
        p.Values.assign(this->Data.GetNumberOfPoints() * s.ESizes[i], NaN);
        global.push_back(std::move(p));
        it = global.end() - 1;
      }
      else if (it->NumberOfComponents != s.ESizes[i])
        this->Fail("property " + Quote(it->Name) + " changes its number of components");
      localToGlobal[i] = static_cast<int>(it - global.begin());
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
    if (!this->S.IdToPoint.emplace(id, point).second)
      this->Fail("vertex id " + std::to_string(id) + " is defined twice");
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
      this->Fail(t[0] + " " + std::to_string(id) + " refers to unknown vertex id " +
        std::to_string(ref));
    if (!this->S.IdToPoint.emplace(id, it->second).second)
      this->Fail("vertex id " + std::to_string(id) + " is defined twice");
  }

  void AddTriangle(const Tokens& t)
  {
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
};
}

bool vtkGocadTSurfParse(std::istream& input, vtkGocadTSurfData& data, std::string& error)
{
  try
  {
    Parser(input, data).Run();
    return true;
  }
  catch (const ParseFailure& failure)
  {
    error = failure.Message;
    return false;
  }
}

bool vtkGocadTSurfLooksLikeTSurf(std::istream& input)
{
  std::string line;
  for (int i = 0; i < 100 && std::getline(input, line); ++i)
  {
    const Tokens t = Tokenize(line.substr(0, 256));
    if (IsComment(t))
      continue;
    return t.size() >= 2 && t[0] == "GOCAD" && t[1] == "TSurf";
  }
  return false;
}
