// The library names its parameters in messages (`min_cell_m`); the command
// line shows each as the flag that sets it (--min-cell). Every name a library
// message uses has a flag in the table, but for the few no flag sets. (Which
// command accepts that flag is not checked here: a name raised from a file,
// such as a mission's, shows the flag of the command that plans alone.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "commands.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

// The string literals of one line of C++, in order ("a \" b" as one; no raw
// strings in lib/). A line that is a comment has none.
std::vector<std::string> string_literals(const std::string& line) {
  std::vector<std::string> out;
  const std::size_t first = line.find_first_not_of(' ');
  if (first == std::string::npos || line.compare(first, 2, "//") == 0) return out;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') {  // a character literal: '"' is not a string
      i = line.find('\'', i + (line[i + 1] == '\\' ? 3 : 2));
      if (i == std::string::npos) break;
      continue;
    }
    if (line[i] != '"') continue;
    std::string text;
    for (++i; i < line.size() && line[i] != '"'; ++i) {
      if (line[i] == '\\' && i + 1 < line.size()) text += line[i++];
      text += line[i];
    }
    out.push_back(text);
  }
  return out;
}

bool is_name(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s.front()))) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Names in backquotes inside the string literals of the library's sources.
std::map<std::string, std::string> parameters_in_library_messages() {
  std::map<std::string, std::string> found;  // name -> where first seen
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(DEEPGUIDE_SOURCE_DIR) / "lib")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      for (const std::string& text : string_literals(line)) {
        for (std::size_t open = text.find('`'); open != std::string::npos;) {
          const std::size_t close = text.find('`', open + 1);
          if (close == std::string::npos) break;
          const std::string name = text.substr(open + 1, close - open - 1);
          if (!is_name(name)) {
            open = close;
            continue;
          }
          found.emplace(name, entry.path().filename().string() + ":" + std::to_string(n));
          open = text.find('`', close + 1);
        }
      }
    }
  }
  return found;
}

}  // namespace

TEST(ParameterFlags, EveryNameALibraryMessageUsesHasAFlag) {
  // No flag sets these: the obstacle store's import time is a library option,
  // and `generate` is prose a suite file carries.
  const std::set<std::string> library_only = {"import_time", "generate"};
  const auto names = parameters_in_library_messages();
  ASSERT_GE(names.size(), 30u) << "the scan found too few names to be reading the library's messages";
  for (const auto& [name, where] : names) {
    if (library_only.count(name)) continue;
    EXPECT_TRUE(deepguide::app::flag_of_parameter(name).has_value())
        << "`" << name << "` (" << where << ") has no flag";
  }
  for (const std::string& name : library_only) EXPECT_TRUE(names.count(name)) << name << " is no longer used";
}

TEST(ParameterFlags, TheCommandLineShowsFlags) {
  // The quadtree's own check, raised in the library, reaches the terminal
  // naming the flag the user typed.
  const auto r =
      deepguide::test::run_cli("plan --obstacles '" + deepguide::test::source_file("data/sample_obstacles.geojson") +
                               "' --from 10.240,54.440 --to 10.265,54.462 --graph quadtree --min-cell 0");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("--min-cell: expected a cell size > 0 m, got 0"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('`'), std::string::npos) << r.err;
}
