// rename_parameters: how a program shows the library's parameter names
// (`min_cell_m`) as its own (a flag, --min-cell), and leaves all else alone.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <string_view>

#include "deepguide/core/error.hpp"

using deepguide::rename_parameters;

namespace {

std::optional<std::string> as_flag(std::string_view name) {
  if (name == "min_cell_m") return "--min-cell";
  if (name == "graph") return "--graph";
  return std::nullopt;
}

}  // namespace

TEST(RenameParameters, KnownNamesBecomeFlags) {
  EXPECT_EQ(rename_parameters("`min_cell_m`: expected a cell size > 0 m, got 0", as_flag),
            "--min-cell: expected a cell size > 0 m, got 0");
  EXPECT_EQ(rename_parameters("`graph` tangent: expected `graph` visibility", as_flag),
            "--graph tangent: expected --graph visibility");
  EXPECT_EQ(rename_parameters("`graph``graph`", as_flag), "--graph--graph");
}

TEST(RenameParameters, EverythingElseStaysAsItIs) {
  // Unknown names, spans that are not names, and stray backquotes.
  EXPECT_EQ(rename_parameters("`import_time`: expected a time", as_flag), "`import_time`: expected a time");
  EXPECT_EQ(rename_parameters("run `deepguide evaluate` on it", as_flag), "run `deepguide evaluate` on it");
  EXPECT_EQ(rename_parameters("`1graph` and `` and `graph", as_flag), "`1graph` and `` and `graph");
  EXPECT_EQ(rename_parameters("a `b c` `graph` d", as_flag), "a `b c` --graph d");
  // An unknown name's closing backquote does not open the next one.
  EXPECT_EQ(rename_parameters("`foo`graph`x`", as_flag), "`foo`graph`x`");
  EXPECT_EQ(rename_parameters("`foo``graph`", as_flag), "`foo`--graph");
  EXPECT_EQ(rename_parameters("", as_flag), "");
  EXPECT_EQ(rename_parameters("no names here", as_flag), "no names here");
  // A file's name that holds backquotes is text, not a parameter, unless it
  // spells one exactly.
  EXPECT_EQ(rename_parameters("`my chart`.tif: expected", as_flag), "`my chart`.tif: expected");
}
