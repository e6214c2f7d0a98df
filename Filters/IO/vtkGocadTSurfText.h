/**
 * @file   vtkGocadTSurfText.h
 * @brief  Token and number helpers of the GOCAD TSurf parser (private to GeoShaping::IOGocad).
 */
#ifndef vtkGocadTSurfText_h
#define vtkGocadTSurfText_h

#include <algorithm>
#include <cctype>
#include <charconv>
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
template <typename T>
inline bool ParseNumber(const std::string& token, T& value)
{
  const char* begin = token.data();
  const char* end = begin + token.size();
  if (begin != end && *begin == '+')
    ++begin;
  const auto result = std::from_chars(begin, end, value);
  return begin != end && result.ec == std::errc() && result.ptr == end;
}

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
