// One set of chart options for every command that reads S-57 charts
// (charts/chart_options.hpp, apps/cli.cpp add_chart_options): the policies
// and their comparison by hand, every command run with them on a real cell,
// a prepared chart that records them and refuses others naming the option,
// and bad values as one line each.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

using test::run_cli;
using test::ScratchDir;

const char* const kKeyWest = "noaa-enc-US5FL4DQ/US5FL4DQ.000";
// Two points in Key West's 5.4 m depth area (DEPARE/186), 3.8 km apart with shoals between: at 3 m with
// the clearance of 2 m the area passes only without zones of confidence (with them, its least depth is 4.85 m).
const char* const kEnds = " --from -81.8317,24.5666 --to -81.8294,24.5282";

TEST(ChartOptions, PoliciesParseAndDifferencesAreNamed) {
  EXPECT_EQ(parse_zoc_policy("clipped"), ZocPolicy::clipped);
  EXPECT_EQ(parse_zoc_policy("STRICT"), ZocPolicy::strict);
  EXPECT_EQ(parse_zoc_policy("none"), ZocPolicy::none);
  EXPECT_EQ(parse_zoc_policy("off"), ZocPolicy::none);
  EXPECT_FALSE(parse_zoc_policy("maybe").has_value());
  EXPECT_FALSE(parse_zoc_policy("").has_value());
  EXPECT_STREQ(to_string(ZocPolicy::clipped), "clipped");

  ChartOptions a, b;
  EXPECT_EQ(chart_options_difference(a, b), "");
  EXPECT_TRUE(a.zones_of_confidence());
  b.zoc = ZocPolicy::strict;
  EXPECT_EQ(chart_options_difference(a, b), "zones of confidence clipped, expected strict");
  b = a;
  b.restricted_areas = true;
  EXPECT_EQ(chart_options_difference(a, b), "restricted areas passable, expected restricted areas as no-go");
  b = a;
  b.unassessed.position_m = 100.0;
  EXPECT_EQ(chart_options_difference(a, b), "unassessed zone figures 2,0.05,500, expected 2,0.05,100");
  // Without zones of confidence their figures do not matter.
  a.zoc = b.zoc = ZocPolicy::none;
  EXPECT_EQ(chart_options_difference(a, b), "");
}

TEST(ChartOptions, OutOfRangeFiguresAreRefused) {
  for (const ZocFigures& bad :
       {ZocFigures{-1.0, 0.05, 500.0}, ZocFigures{2.0, 1.0, 500.0}, ZocFigures{2.0, 0.05, 0.0},
        ZocFigures{std::nan(""), 0.05, 500.0}, ZocFigures{2.0, 0.05, 1e308}, ZocFigures{1e308, 0.05, 500.0}}) {
    ChartOptions o;
    o.unassessed = bad;
    test::expect_error(test::error_of([&] { check_chart_options(o); }), {"`unassessed`", "expected"});
  }
}

// Every command that reads S-57 charts takes --zoc none and --restricted
// (and the rest of the set) with the same meaning.
TEST(ChartOptionsCli, EveryChartCommandTakesThem) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, kKeyWest);
  ScratchDir tmp;
  const std::string q = "'" + cell + "'";
  const std::string opts = " --zoc none --restricted --unassessed-zoc 2,0.05,500 --vertical-clearance 2";
  auto ok = [](const test::RunResult& r, const std::string& what) {
    EXPECT_EQ(r.exit_code, 0) << what << "\n" << r.out << r.err;
  };
  ok(run_cli("chart info " + q + " --depth 3" + opts), "chart info");
  ok(run_cli("chart nogo " + q + " --depth 3 -o '" + tmp.file("nogo.geojson") + "'" + opts), "chart nogo");
  ok(run_cli("render chart " + q + " --depth 3 -o '" + tmp.file("chart.png") + "' --width 400" + opts), "render chart");
  const std::string route = tmp.file("r.geojson");
  ok(run_cli("plan --chart " + q + " --depth 3" + kEnds + " -o '" + route + "'" + opts), "plan");
  ok(run_cli("check route '" + route + "' --chart " + q + " --depth 3" + opts), "check route");

  // Prepared with them, the chart serves a plan that asks for them, and refuses one that does not.
  const std::string gpkg = tmp.file("kw.gpkg");
  ok(run_cli("chart prepare " + q + " --depth 3 -o '" + gpkg + "'" + opts), "chart prepare");
  ok(run_cli("plan --chart '" + gpkg + "' --depth 3" + kEnds + " -o '" + tmp.file("r2.geojson") + "'" + opts),
     "plan on the prepared chart");
  const test::RunResult other =
      run_cli("plan --chart '" + gpkg + "' --depth 3" + kEnds + " -o '" + tmp.file("r3.geojson") + "' --restricted");
  EXPECT_EQ(other.exit_code, 1) << other.err;
  EXPECT_NE(other.err.find("prepared with zones of confidence none, expected clipped"), std::string::npos) << other.err;
  EXPECT_EQ(std::count(other.err.begin(), other.err.end(), '\n'), 1) << other.err;
  const test::RunResult no_restricted =
      run_cli("plan --chart '" + gpkg + "' --depth 3" + kEnds + " -o '" + tmp.file("r4.geojson") + "' --zoc none");
  EXPECT_EQ(no_restricted.exit_code, 1) << no_restricted.err;
  EXPECT_NE(no_restricted.err.find("restricted areas as no-go, expected restricted areas passable"), std::string::npos)
      << no_restricted.err;

  // A mission over the cell: check, plan and simulate take them too.
  const std::string yaml = tmp.file("kw.yaml");
  std::ofstream(yaml) << "name: channel transit\nenvironment:\n  charts: ['" << cell
                      << "']\nsafety:\n  margin_m: 5\n  vertical_clearance_m: 2\n"
                         "start: {lon: -81.8281, lat: 24.5538, depth_m: 0}\nmanoeuvres:\n  - track:\n"
                         "      depth_m: 3\n      speed_kn: 3\n      waypoints:\n"
                         "        - {lon: -81.8343, lat: 24.5262}\n";
  for (const char* sub : {"check", "plan", "simulate"}) {
    ok(run_cli(std::string("mission ") + sub + " '" + yaml + "' --zoc none --restricted"), sub);
  }
}

TEST(ChartOptionsCli, BadValuesAreOneLineEach) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, kKeyWest);
  const std::string q = "'" + cell + "'";
  struct Case {
    std::string flags, says;
    int exit_code;
  };
  for (const Case& c : std::vector<Case>{
           {"--zoc maybe", "--zoc: expected clipped, strict or none, got 'maybe'", 1},
           {"--unassessed-zoc 2,0.05", "--unassessed-zoc: expected DEPTH_M,FRACTION,POSITION_M", 1},
           {"--unassessed-zoc 2,0.05,500,7", "--unassessed-zoc: expected DEPTH_M,FRACTION,POSITION_M", 1},
           {"--unassessed-zoc 2,1.5,500", "--unassessed-zoc: expected a depth fraction in [0, 1)", 1},
           {"--unassessed-zoc 2,0.05,nan", "--unassessed-zoc: expected a position accuracy in (0, 10000] m", 1},
           {"--unassessed-zoc 2,0.05,1e308", "--unassessed-zoc: expected a position accuracy in (0, 10000] m", 1},
           {"--zoc strict --no-zoc", "excludes", 2},
       }) {
    const test::RunResult r = run_cli("chart info " + q + " --depth 3 " + c.flags);
    EXPECT_EQ(r.exit_code, c.exit_code) << c.flags << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.flags << ": " << r.err;
    if (c.exit_code == 1) {
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
  }
}

// A prepared chart planned on without --depth: the operating depth is asked
// for by its flag, and no header of the library is named.
TEST(ChartOptionsCli, APreparedChartWithoutDepthAsksForTheDepth) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, kKeyWest);
  ScratchDir tmp;
  const std::string gpkg = tmp.file("kw.gpkg");
  ASSERT_EQ(run_cli("chart prepare '" + cell + "' --depth 3 -o '" + gpkg + "'").exit_code, 0);
  const test::RunResult r = run_cli("plan --chart '" + gpkg + "'" + kEnds + " -o '" + tmp.file("r.geojson") + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("--depth"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".hpp"), std::string::npos) << r.err;
}

// A prepared chart draws as its cells do: the frame it was prepared in, its
// no-go. (The drawing once took the frame by reading the file as an obstacle
// file, and failed on the no-go layer's first point feature.)
TEST(ChartOptionsCli, APreparedChartDraws) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, kKeyWest);
  ScratchDir tmp;
  const std::string gpkg = tmp.file("kw.gpkg");
  ASSERT_EQ(run_cli("chart prepare '" + cell + "' --depth 3 -o '" + gpkg + "'").exit_code, 0);
  const test::RunResult drawn = run_cli("render chart '" + gpkg + "' --depth 3 -o '" + tmp.file("kw.png") + "'");
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  const test::RunResult cells = run_cli("render chart '" + cell + "' --depth 3 -o '" + tmp.file("cell.png") + "'");
  ASSERT_EQ(cells.exit_code, 0) << cells.err;
  // The same frame and no-go polygons as the cell's own drawing ("wrote F (W x H px, FRAME, N no-go polygon(s), ...").
  const auto frame_and_no_go = [](const std::string& out) {
    const std::size_t from = out.find("px, ");
    const std::size_t to = out.find(" no-go polygon");
    return from == std::string::npos || to == std::string::npos ? std::string() : out.substr(from, to - from);
  };
  EXPECT_NE(frame_and_no_go(drawn.out), "") << drawn.out;
  EXPECT_EQ(frame_and_no_go(drawn.out), frame_and_no_go(cells.out)) << drawn.out << cells.out;
  EXPECT_TRUE(std::filesystem::exists(tmp.file("kw.png")));
}

// `chart info` takes the exchange set plan takes: its cells read together,
// through their catalogues, best scale first.
TEST(ChartOptionsCli, ChartInfoReadsAnExchangeSet) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(set, "noaa-enc-kachemak");
  const test::RunResult r = run_cli("chart info '" + set + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out).at(0);
  EXPECT_EQ(info.at("kind"), "S-57 cell");
  ASSERT_EQ(info.at("cells").size(), 11u);
  for (const nlohmann::json& c : info.at("cells")) {
    EXPECT_TRUE(c.at("catalogue").is_string()) << c.dump();
  }
  // The set's extent is the band-3 cell's, which covers all the others (SOURCES.md).
  EXPECT_NEAR(info.at("extent").at("west").get<double>(), -154.409230, 1e-6);
  EXPECT_NEAR(info.at("extent").at("north").get<double>(), 60.294694, 1e-6);
  const test::RunResult text = run_cli("chart info '" + set + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("cell           US5AK5QG"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("(from its catalogue, CRC checked)"), std::string::npos) << text.out;
}

}  // namespace
}  // namespace deepguide
