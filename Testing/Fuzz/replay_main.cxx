// For compilers without libFuzzer: runs a fuzz target's LLVMFuzzerTestOneInput once on
// every file named on the command line, or in a directory named there (its corpus), so
// the corpus and its regression inputs are tested in every build.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace
{
int RunFile(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    std::fprintf(stderr, "cannot open %s\n", path.c_str());
    return 1;
  }
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::fprintf(stderr, "Running: %s (%zu bytes)\n", path.c_str(), bytes.size());
  LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  return 0;
}
}

int main(int argc, char** argv)
{
  int failures = 0, files = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (!arg.empty() && arg[0] == '-')
      continue; // libFuzzer flags, ignored
    const std::filesystem::path path(arg);
    if (std::filesystem::is_directory(path))
    {
      std::vector<std::filesystem::path> entries;
      for (const auto& entry : std::filesystem::directory_iterator(path))
        if (entry.is_regular_file() && entry.path().filename() != "README.md")
          entries.push_back(entry.path());
      std::sort(entries.begin(), entries.end());
      for (const auto& entry : entries)
      {
        failures += RunFile(entry);
        ++files;
      }
    }
    else
    {
      failures += RunFile(path);
      ++files;
    }
  }
  std::fprintf(stderr, "Executed %d inputs, %d unreadable\n", files, failures);
  return failures == 0 && files > 0 ? 0 : 1;
}
