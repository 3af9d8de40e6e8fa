// The library names its parameters in messages (`min_cell_m`); the command
// line shows each as the flag that sets it (--min-cell). Every name a library
// message uses has a flag, but for the few no flag sets, and a flag the
// command that reports it accepts.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;

namespace {

// Names in backquotes inside the string literals of the library's sources.
std::map<std::string, std::string> parameters_in_library_messages() {
  const std::regex literal(R"re("((?:[^"\\]|\\.)*)")re");
  const std::regex name("`([A-Za-z][A-Za-z0-9_]*)`");
  std::map<std::string, std::string> found;  // name -> where first seen
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(DEEPGUIDE_SOURCE_DIR) / "lib")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".hpp") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      if (line.find_first_not_of(' ') != std::string::npos && line.substr(line.find_first_not_of(' '), 2) == "//") {
        continue;
      }
      for (std::sregex_iterator l(line.begin(), line.end(), literal), end; l != end; ++l) {
        const std::string text = (*l)[1];
        for (std::sregex_iterator m(text.begin(), text.end(), name); m != end; ++m) {
          found.emplace((*m)[1], entry.path().filename().string() + ":" + std::to_string(n));
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
