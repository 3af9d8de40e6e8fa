// The deepguide binary end to end: exit codes, one-line errors, --json output.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <vector>

#include "test_support.hpp"

using deepguide::test::run_cli;
using deepguide::test::ScratchDir;

namespace {
const std::string kThreeEllipses = R"({"type":"FeatureCollection","features":[
 {"type":"Feature","properties":{"id":"a","semi_major_m":10,"semi_minor_m":4,"orientation_deg":30},"geometry":{"type":"Point","coordinates":[10.20,54.40]}},
 {"type":"Feature","properties":{"id":"b","semi_major_m":20,"semi_minor_m":20,"orientation_deg":0,"height_m":5},"geometry":{"type":"Point","coordinates":[10.21,54.41]}},
 {"type":"Feature","properties":{"id":"c","semi_major_m":6,"semi_minor_m":2,"orientation_deg":135,"top_depth_m":30},"geometry":{"type":"Point","coordinates":[10.22,54.42]}}]})";

int line_count(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }
}  // namespace

TEST(Cli, VersionAndHelp) {
  const auto v = run_cli("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.out.find("deepguide 0."), std::string::npos) << v.out;
  const auto h = run_cli("--help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("obstacles"), std::string::npos);
  const auto oh = run_cli("obstacles info --help");
  EXPECT_EQ(oh.exit_code, 0);
  EXPECT_NE(oh.out.find("--json"), std::string::npos);
}

TEST(Cli, InfoJsonCountsThreeEllipses) {
  ScratchDir dir;
  const std::string p = dir.write("three.geojson", kThreeEllipses);
  const auto r = run_cli("obstacles info --json '" + p + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("count").get<int>(), 3);
  EXPECT_EQ(j.at("ellipses").get<int>(), 3);
  EXPECT_EQ(j.at("polygons").get<int>(), 0);
  EXPECT_EQ(j.at("local_crs").at("id").get<std::string>(), "EPSG:32632");
  EXPECT_DOUBLE_EQ(j.at("semi_major_m").at("max").get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(j.at("semi_minor_m").at("min").get<double>(), 2.0);
  EXPECT_NEAR(j.at("semi_major_m").at("mean").get<double>(), 12.0, 1e-12);
  EXPECT_EQ(j.at("vertical").at("height_above_seafloor").get<int>(), 1);
  EXPECT_EQ(j.at("vertical").at("top_depth").get<int>(), 1);
  // The extent encloses the footprints: the circle b reaches 20 m beyond its centre.
  EXPECT_LT(j.at("extent_lonlat").at("west").get<double>(), 10.20);
  EXPECT_GT(j.at("extent_lonlat").at("north").get<double>(), 54.42);
}

TEST(Cli, InfoTextOnTheBundledSample) {
  const auto r = run_cli("obstacles info '" + deepguide::test::source_file("data/sample_obstacles.geojson") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("count            7"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("EPSG:32632"), std::string::npos) << r.out;
}

TEST(Cli, ConvertRoundTripThroughEveryFormat) {
  ScratchDir dir;
  const std::string in = dir.write("three.geojson", kThreeEllipses);
  std::string prev = in;
  for (const char* ext : {".gpkg", ".csv", ".geojson"}) {
    const std::string out = dir.file(std::string("out") + ext);
    const auto r = run_cli("obstacles convert '" + prev + "' '" + out + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto info = run_cli("obstacles info --json '" + out + "'");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out).at("count").get<int>(), 3) << ext;
    prev = out;
  }
}

TEST(Cli, BadInputExitsOneWithOneLineNamingFileFeatureField) {
  ScratchDir dir;
  const std::string p = dir.write(
      "bad.geojson",
      R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"id":"q","semi_major_m":-2},"geometry":{"type":"Point","coordinates":[10,54]}}]})");
  const auto r = run_cli("obstacles info '" + p + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(p), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("feature 0 (id 'q')"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("semi_major_m"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(Cli, MissingFileAndUnknownCrsExitOne) {
  ScratchDir dir;
  const auto missing = run_cli("obstacles info '" + dir.file("none.gpkg") + "'");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(line_count(missing.err), 1) << missing.err;
  const std::string p = dir.write("three.geojson", kThreeEllipses);
  const auto crs = run_cli("obstacles info --crs EPSG:999999 '" + p + "'");
  EXPECT_EQ(crs.exit_code, 1);
  EXPECT_NE(crs.err.find("--crs"), std::string::npos) << crs.err;
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run_cli("").exit_code, 2);
  EXPECT_EQ(run_cli("obstacles").exit_code, 2);
  EXPECT_EQ(run_cli("obstacles info").exit_code, 2);
  EXPECT_EQ(run_cli("obstacles convert only-one.geojson").exit_code, 2);
  EXPECT_EQ(run_cli("obstacles info --no-such-flag x.geojson").exit_code, 2);
}

TEST(Cli, FailedConvertLeavesNoOutputAndKeepsAnExistingOne) {
  ScratchDir dir;
  const std::string bad = dir.write("bad.csv", "lon,lat,semi_major_m\n10,54,abc\n");
  const std::string out = dir.file("out.geojson");
  EXPECT_EQ(run_cli("obstacles convert '" + bad + "' '" + out + "'").exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
  const std::string keep = dir.write("keep.geojson", kThreeEllipses);
  EXPECT_EQ(run_cli("obstacles convert '" + bad + "' '" + keep + "'").exit_code, 1);
  std::ifstream in(keep);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), kThreeEllipses);
  // Only the two files we wrote are there: no temporary leftovers.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);
}

// Every bad-input class of the foundation issue, through the binary: exit 1,
// one line on stderr naming the file (and the feature and field where there is one).
struct BadInput {
  const char* name;
  const char* file;
  const char* content;  // nullptr: the file does not exist
  std::vector<const char*> expected;
  const char* options = "";
};

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsOneWithOneLine) {
  const BadInput& c = GetParam();
  ScratchDir dir;
  const std::string path = c.content ? dir.write(c.file, c.content) : dir.file(c.file);
  const auto r = run_cli(std::string("obstacles info ") + c.options + " '" + path + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("deepguide: error: ", 0), 0u) << r.err;
  if (std::string(c.options).empty()) {
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  }
  for (const char* part : c.expected) EXPECT_NE(r.err.find(part), std::string::npos) << part << " in " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

#define DG_POINT(props, coords)                                                       \
  R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{)" props \
  R"(},"geometry":{"type":"Point","coordinates":)" coords "}}]}"

INSTANTIATE_TEST_SUITE_P(
    Foundation, CliBadInput,
    ::testing::Values(
        BadInput{"missing_file", "absent.geojson", nullptr, {"expected an existing file"}},
        BadInput{"not_a_vector_file", "x.geojson", "this is not json {", {"vector file"}},
        BadInput{"no_semi_major",
                 "a.geojson",
                 DG_POINT(R"("id":"k","semi_minor_m":2)", "[10,54]"),
                 {"feature 0 (id 'k')", "field 'semi_major_m'"}},
        BadInput{"zero_axis",
                 "z.geojson",
                 DG_POINT(R"("semi_major_m":0)", "[10,54]"),
                 {"feature 0", "field 'semi_major_m'", "at least 1 mm"}},
        BadInput{"negative_axis",
                 "n.csv",
                 "lon,lat,semi_major_m,semi_minor_m\n10,54,5,-1\n",
                 {"line 2", "field 'semi_minor_m'", "at least 1 mm"}},
        BadInput{"minor_above_major",
                 "m.csv",
                 "lon,lat,semi_major_m,semi_minor_m\n10,54,5,6\n",
                 {"line 2", "field 'semi_minor_m'", "<= semi_major_m"}},
        BadInput{"nan_coordinate",
                 "nan.geojson",
                 DG_POINT(R"("semi_major_m":3)", "[NaN,54]"),
                 {"feature 0", "field 'geometry'", "finite"}},
        BadInput{"infinite_coordinate",
                 "inf.geojson",
                 DG_POINT(R"("semi_major_m":3)", "[10,Infinity]"),
                 {"feature 0", "field 'geometry'", "finite"}},
        BadInput{
            "unknown_crs_in_file",
            "crs.geojson",
            R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::999999"}},"features":[]})",
            {"field 'crs'"}},
        BadInput{"unknown_crs_option",
                 "ok.geojson",
                 DG_POINT(R"("semi_major_m":3)", "[10,54]"),
                 {"--crs", "EPSG:999999"},
                 "--crs EPSG:999999"}),
    [](const auto& info) { return std::string(info.param.name); });
