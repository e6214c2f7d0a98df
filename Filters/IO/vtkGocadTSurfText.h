/**
 * @file   vtkGocadTSurfText.h
 * @brief  Token and number helpers of the GOCAD TSurf parser (private to GeoShaping::IO).
 */
#ifndef vtkGocadTSurfText_h
#define vtkGocadTSurfText_h

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

namespace vtkGocadTSurfText
{
using Tokens = std::vector<std::string>;

// Whitespace-separated tokens; a double-quoted token may contain spaces.
inline Tokens Tokenize(const std::string& line)
{
  Tokens tokens;
  const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  std::size_t i = 0;
  while (i < line.size())
  {
    if (isSpace(line[i]))
    {
      ++i;
    }
    else if (line[i] == '"')
    {
      const std::size_t end = std::min(line.find('"', i + 1), line.size());
      tokens.push_back(line.substr(i + 1, end - i - 1));
      i = end + 1;
    }
    else
    {
      const std::size_t start = i;
      while (i < line.size() && !isSpace(line[i]))
        ++i;
      tokens.push_back(line.substr(start, i - start));
    }
  }
  return tokens;
}

inline std::string Trim(const std::string& s)
{
  const auto first = s.find_first_not_of(" \t");
  const auto last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// Quoted in messages, shortened so a binary token cannot flood the log.
inline std::string Quote(const std::string& token)
{
  return "'" + (token.size() > 40 ? token.substr(0, 40) + "..." : token) + "'";
}

inline bool IsComment(const Tokens& t)
{
  return t.empty() || t[0][0] == '#';
}

// std::from_chars, unlike strtod, ignores the C locale; the whole token must be used.
template<typename T>
inline bool ParseNumber(const std::string& token, T& value)
{
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+')
    ++begin;
  const auto result = std::from_chars(begin, end, value);
  return begin != end && result.ec == std::errc() && result.ptr == end;
}

// Hash of vertex ids: the standard library's std::hash<int64_t> is the identity, so ids
// that are multiples of the table's bucket count (a file can choose them) all land in one
// bucket and the parse becomes quadratic (docs/readers.md, "GOCAD TSurf").
// The ids are mixed with a seed (splitmix64's finalizer; the parser draws the seed at
// random) so that no file can aim at a bucket. Only the speed depends on the seed.
struct VertexIdHash
{
  std::uint64_t Seed = 0;
  std::size_t operator()(std::int64_t id) const noexcept
  {
    std::uint64_t x = static_cast<std::uint64_t>(id) + this->Seed + 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::size_t>(x ^ (x >> 31));
  }
};

inline bool EqualsNoCase(const std::string& a, const char* b)
{
  std::string lower(a);
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower == b;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkGocadTSurfText.h
