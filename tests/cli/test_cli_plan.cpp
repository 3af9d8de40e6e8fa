// deepguide plan and deepguide check route, end to end.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <tuple>

#include "nc_writer.hpp"
#include "test_support.hpp"

using deepguide::test::run_cli;
using deepguide::test::ScratchDir;

namespace {
const std::string kSample = deepguide::test::source_file("data/sample_obstacles.geojson");
// Start and goal on opposite sides of the sample's cluster (lon,lat).
const std::string kFromTo = " --from 10.240,54.440 --to 10.265,54.462";
}  // namespace

TEST(CliPlan, WritesARouteThatTheCheckerAccepts) {
  ScratchDir dir;
  const std::string route = dir.file("route.geojson");
  const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j.at("length_m").get<double>(), 2800.0);
  EXPECT_GE(j.at("min_clearance_m").get<double>(), 5.0 - 1e-9);
  EXPECT_EQ(j.at("crs").get<std::string>(), "EPSG:32632");
  // The route file is RFC 7946 GeoJSON: a line plus one point per waypoint.
  std::ifstream in(route);
  const auto geo = nlohmann::json::parse(in);
  int lines = 0, points = 0;
  for (const auto& f : geo.at("features")) {
    const std::string type = f.at("geometry").at("type");
    lines += type == "LineString";
    points += type == "Point";
  }
  EXPECT_EQ(lines, 1);
  EXPECT_EQ(points, j.at("waypoints").get<int>());
  const auto ok = run_cli("check route '" + route + "' --obstacles '" + kSample + "' --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out).at("safe").get<bool>());
  EXPECT_NEAR(nlohmann::json::parse(ok.out).at("length_m").get<double>(), j.at("length_m").get<double>(), 1e-3);
}

TEST(CliPlan, RoutesThatTouchZonesSurviveTheFileRoundTrip) {
  // These points make every graph hug the zones of c1 and c2 at exactly 5 m;
  // written as lon/lat and read back, the route must still pass the checker.
  ScratchDir dir;
  for (const char* graph : {"visibility", "visibility-full", "tangent"}) {
    const std::string route = dir.file(std::string(graph) + ".geojson");
    const auto r = run_cli("plan --obstacles '" + kSample + "' --from 10.2405,54.4470 --to 10.2640,54.4560 --graph " +
                           graph + " -o '" + route + "' --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LT(nlohmann::json::parse(r.out).at("min_clearance_m").get<double>(), 5.25) << graph;
    const auto ok = run_cli("check route '" + route + "' --obstacles '" + kSample + "'");
    EXPECT_EQ(ok.exit_code, 0) << graph << ": " << ok.err;
  }
}

TEST(CliPlan, ReducedAndFullGraphsAgree) {
  const auto a = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --json");
  const auto b =
      run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --graph visibility-full --search dijkstra --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NEAR(nlohmann::json::parse(a.out).at("length_m").get<double>(),
              nlohmann::json::parse(b.out).at("length_m").get<double>(), 1e-6);
}

TEST(CliPlan, CheckRouteNamesTheSegmentAndObstacleOfAnUnsafeRoute) {
  ScratchDir dir;
  // Its second segment cuts through obstacle c5 (20 m deep, the worst contact).
  const std::string route = dir.write("bad.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[10.24,54.44],[10.245,54.445],[10.26,54.455]]}}]})");
  const auto r = run_cli("check route '" + route + "' --obstacles '" + kSample + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("segment 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("'c5'"), std::string::npos) << r.err;
}

// --html that cannot be written: one line, exit 1, before any work, and no
// file written (neither the page nor the route).
TEST(CliPlan, AWebMapThatCannotBeWrittenIsOneLineAndNothingWritten) {
  ScratchDir dir;
  const std::string route = dir.file("route.geojson");
  for (const auto& [html, words] : {std::pair<std::string, std::string>{dir.file("no/such/map.html"), "does not exist"},
                                    {dir.file("map.png"), "expected a web page file name ending in .html or .htm"},
                                    {kSample, "expected a web page file name"}}) {
    const auto r =
        run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + route + "' --html '" + html + "'");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("--html"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(route));
  }
  // Over an input file with an .html name: refused as the other outputs are.
  const std::string input = dir.file("obstacles.html");
  std::filesystem::copy_file(kSample, input);
  const auto over =
      run_cli("plan --obstacles '" + kSample + "' --chart '" + input + "'" + kFromTo + " --html '" + input + "'");
  EXPECT_EQ(over.exit_code, 1) << over.err;
  EXPECT_EQ(std::count(over.err.begin(), over.err.end(), '\n'), 1) << over.err;
  EXPECT_FALSE(std::filesystem::exists(route));
  // And one that can: a page beside the route.
  const auto ok = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + route + "' --html '" +
                          dir.file("map.html") + "'");
  if (std::filesystem::exists("/usr/share/javascript/leaflet/leaflet.min.js")) {
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_GT(std::filesystem::file_size(dir.file("map.html")), 100000u);
  }
}

// render chart --html needs a depth; without it, or into a missing folder or
// over an input, one line, exit 1, nothing written; -o or --html is required
// (usage, exit 2).
TEST(CliRenderChart, AWebMapAsksForADepth) {
  ScratchDir dir;
  const std::string page = dir.file("chart.html");
  const std::string raster = deepguide::test::source_file("charts/sample_chart.tif");
  const auto no_depth_raster = run_cli("render chart '" + raster + "' --html '" + page + "'");
  EXPECT_EQ(no_depth_raster.exit_code, 1) << no_depth_raster.err;
  EXPECT_NE(no_depth_raster.err.find("--html: expected --depth"), std::string::npos) << no_depth_raster.err;
  EXPECT_EQ(std::count(no_depth_raster.err.begin(), no_depth_raster.err.end(), '\n'), 1) << no_depth_raster.err;
  EXPECT_EQ(run_cli("render chart '" + raster + "'").exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(page));
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, "noaa-enc-US5FL4DQ/US5FL4DQ.000");
  const auto no_depth = run_cli("render chart '" + cell + "' --html '" + page + "'");
  EXPECT_EQ(no_depth.exit_code, 1) << no_depth.err;
  EXPECT_NE(no_depth.err.find("--html: expected --depth"), std::string::npos) << no_depth.err;
  const auto no_folder = run_cli("render chart '" + cell + "' --depth 3 --html '" + dir.file("no/chart.html") + "'");
  EXPECT_EQ(no_folder.exit_code, 1) << no_folder.err;
  EXPECT_NE(no_folder.err.find("does not exist"), std::string::npos) << no_folder.err;
  const auto over = run_cli("render chart '" + cell + "' --depth 3 --html '" + cell + "'");
  EXPECT_EQ(over.exit_code, 1) << over.err;
  EXPECT_FALSE(std::filesystem::exists(page));
  if (std::filesystem::exists("/usr/share/javascript/leaflet/leaflet.min.js")) {
    const auto ok = run_cli("render chart '" + cell + "' --depth 3 --html '" + page + "'");
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_TRUE(std::filesystem::exists(page));
  }
}

// check route --html: the page is written for an unsafe route too (where an
// operator wants to look), its first leg marked unsafe; the exit is still 1.
TEST(CliCheckRoute, AWebMapOfAnUnsafeRoute) {
  if (!std::filesystem::exists("/usr/share/javascript/leaflet/leaflet.min.js")) GTEST_SKIP() << "no Leaflet";
  ScratchDir dir;
  const std::string straight = dir.write("straight.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "LineString",
     "coordinates": [[10.240, 54.440], [10.265, 54.462]]}}]})");
  const std::string page = dir.file("check.html");
  const auto r = run_cli("check route '" + straight + "' --obstacles '" + kSample + "' --html '" + page + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  ASSERT_TRUE(std::filesystem::exists(page));
  std::ifstream in(page);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("straight.geojson: unsafe"), std::string::npos);
  EXPECT_NE(text.find(R"("safe":"no")"), std::string::npos);
  // Bad --html: one line, exit 1, nothing written.
  const auto bad = run_cli("check route '" + straight + "' --obstacles '" + kSample + "' --html '" + straight + "'");
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_NE(bad.err.find("--html"), std::string::npos) << bad.err;
}

// render chart --html on a bathymetry raster: its depth shading as a picture
// warped into Web Mercator, laid where the raster is (chart info's extent),
// and its no-go at the depth as chart info counts it.
TEST(CliRenderChart, ARastersWebMapHasItsShadingAndItsNoGo) {
  if (!std::filesystem::exists("/usr/share/javascript/leaflet/leaflet.min.js")) GTEST_SKIP() << "no Leaflet";
  ScratchDir dir;
  const std::string raster = deepguide::test::source_file("charts/sample_chart.tif");
  const std::string page = dir.file("raster.html");
  const auto r = run_cli("render chart '" + raster + "' --depth 3 --html '" + page + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(page);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string open = "<script id=\"dg-data\" type=\"application/json\">";
  const std::size_t from = text.find(open) + open.size();
  const auto data = nlohmann::json::parse(text.substr(from, text.find("</script>", from) - from));
  ASSERT_EQ(data.at("images").size(), 1u);
  const auto& image = data.at("images")[0];
  EXPECT_EQ(image.at("url").get<std::string>().rfind("data:image/png;base64,iVBORw0KGgo", 0), 0u);
  const auto info = run_cli("chart info '" + raster + "' --depth 3 --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  auto j = nlohmann::json::parse(info.out);
  if (j.is_array()) j = j.at(0);
  const auto& e = j.at("extent");
  // Warped into Web Mercator, the picture's box holds the raster's and is hardly larger (a cell or two).
  for (const char* side : {"west", "south"}) EXPECT_LE(image.at(side).get<double>(), e.at(side).get<double>() + 1e-9);
  for (const char* side : {"east", "north"}) EXPECT_GE(image.at(side).get<double>(), e.at(side).get<double>() - 1e-9);
  for (const char* side : {"west", "east", "south", "north"}) {
    EXPECT_NEAR(image.at(side).get<double>(), e.at(side).get<double>(), 1e-3) << side;
  }
  const auto no_go = std::find_if(data.at("layers").begin(), data.at("layers").end(),
                                  [](const nlohmann::json& l) { return l.at("id") == "raster_no_go"; });
  ASSERT_NE(no_go, data.at("layers").end());
  EXPECT_EQ((*no_go).at("features").size(), j.at("no_go").at("polygons").get<std::size_t>());
}

TEST(CliPlan, ExitCodes) {
  ScratchDir dir;
  // Goal inside obstacle c1's zone: no safe route, exit 3, naming c1.
  const auto inside = run_cli("plan --obstacles '" + kSample + "' --from 10.240,54.440 --to 10.2500,54.4501");
  EXPECT_EQ(inside.exit_code, 3) << inside.err;
  EXPECT_NE(inside.err.find("'c1'"), std::string::npos) << inside.err;
  // Identical start and goal, malformed and out-of-range positions: bad input.
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "' --from 10.24,54.44 --to 10.24,54.44").exit_code, 1);
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "' --from 10.24 --to 10.26,54.46").exit_code, 1);
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "' --from nan,54 --to 10.26,54.46").exit_code, 1);
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "' --from 10.24,95 --to 10.26,54.46").exit_code, 1);
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --graph magic").exit_code, 1);
  EXPECT_EQ(run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --margin -3").exit_code, 1);
  EXPECT_EQ(run_cli("plan --from 1,2 --to 3,4").exit_code, 2);  // --obstacles missing
  // A goal walled in by the sample's polygon: its interior is unreachable.
  const std::string walls = dir.write("walls.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"id":"ring"},"geometry":{"type":"Polygon","coordinates":[
      [[10.0,54.0],[10.1,54.0],[10.1,54.1],[10.0,54.1],[10.0,54.0]],
      [[10.02,54.02],[10.08,54.02],[10.08,54.08],[10.02,54.08],[10.02,54.02]]]}}]})");
  const auto enclosed = run_cli("plan --obstacles '" + walls + "' --from 9.9,53.9 --to 10.05,54.05 --margin 1");
  EXPECT_EQ(enclosed.exit_code, 3) << enclosed.err;
  // The navigation mesh says both in the same one line with the same exit.
  const auto mesh_inside =
      run_cli("plan --obstacles '" + kSample + "' --from 10.240,54.440 --to 10.2500,54.4501 --graph navmesh");
  EXPECT_EQ(mesh_inside.exit_code, 3) << mesh_inside.err;
  EXPECT_EQ(mesh_inside.err, inside.err);
  const auto mesh_enclosed =
      run_cli("plan --obstacles '" + walls + "' --from 9.9,53.9 --to 10.05,54.05 --margin 1 --graph navmesh");
  EXPECT_EQ(mesh_enclosed.exit_code, 3) << mesh_enclosed.err;
  EXPECT_EQ(std::count(mesh_enclosed.err.begin(), mesh_enclosed.err.end(), '\n'), 1) << mesh_enclosed.err;
}

TEST(CliPlan, ProjectedCoordinatesWithCrs) {
  // The same plan given in UTM 32N metres instead of lon/lat.
  const auto ll = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --json");
  ASSERT_EQ(ll.exit_code, 0) << ll.err;
  const auto r = run_cli("plan --obstacles '" + kSample +
                         "' --crs EPSG:32632 --from 580440.5,6033365.3 --to 582000,6035800 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out).at("length_m").get<double>(), 2000.0);
}

// ---- Charts as input -------------------------------------------------------------------

namespace {
const std::string kChart = deepguide::test::source_file("charts/sample_chart.tif");
const std::string kHazards = deepguide::test::source_file("charts/sample_chart_hazards.gpkg");
// From the harbour basin to open water in the north-east of the sample chart.
const std::string kHarbourToSea = " --from 10.2446,54.4413 --to 10.2626,54.4606";
}  // namespace

TEST(CliPlan, ChartRouteLeavesTheHarbourThroughTheChannelClearOfTheNoGoArea) {
  ScratchDir dir;
  const std::string route = dir.file("route.geojson");
  const auto r = run_cli("plan --chart '" + kChart + "' '" + kHazards + "' --depth 10" + kHarbourToSea + " -o '" +
                         route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // The basin's mouth and the channel force a dog-leg: longer than the
  // straight line (about 2.4 km) but not by much.
  const double straight = 2430.0;
  EXPECT_GT(j.at("length_m").get<double>(), straight);
  EXPECT_LT(j.at("length_m").get<double>(), 1.05 * straight);
  EXPECT_GE(j.at("min_clearance_m").get<double>(), 5.0 - 1e-9);
  EXPECT_EQ(j.at("crs").get<std::string>(), "EPSG:32632");  // the start's UTM zone
  EXPECT_EQ(j.at("passed_over").get<int>(), 3);             // hazards deeper than 10 + 2 m
  // Independently: the no-go polygons written by `chart nogo`, checked by `check route`.
  const std::string nogo = dir.file("nogo.gpkg");
  const auto n = run_cli("chart nogo '" + kChart + "' --depth 10 -o '" + nogo + "'");
  ASSERT_EQ(n.exit_code, 0) << n.err;
  const auto ok = run_cli("check route '" + route + "' --obstacles '" + nogo + "' --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out).at("safe").get<bool>());
  // At 4 m the shoal bank (6-8 m) is open water: a straighter, shorter route.
  const auto shallow = run_cli("plan --chart '" + kChart + "' --depth 4" + kHarbourToSea + " --json");
  ASSERT_EQ(shallow.exit_code, 0) << shallow.err;
  EXPECT_LE(nlohmann::json::parse(shallow.out).at("length_m").get<double>(), j.at("length_m").get<double>());
}

TEST(CliPlan, ChartInputErrors) {
  // A raster without an operating depth cannot be judged: exit 1, naming the file and --depth.
  const auto r = run_cli("plan --chart '" + kChart + "'" + kHarbourToSea);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("sample_chart.tif"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--depth"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // Neither obstacles nor charts: usage error.
  EXPECT_EQ(run_cli("plan" + kHarbourToSea).exit_code, 2);
  // A chart that is not there.
  const auto missing = run_cli("plan --chart /nonexistent/chart.tif --depth 10" + kHarbourToSea);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/nonexistent/chart.tif"), std::string::npos) << missing.err;
}

// --- Costs in a current (issue 6) ---------------------------------------------------------------

TEST(CliPlanCost, EnergyRouteReportsLegsAndWritesSpeedsPerWaypoint) {
  ScratchDir dir;
  const std::string route = dir.file("eco.geojson");
  const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo +
                         " --cost energy --speed optimal --current-const 0.8,200 -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("cost").get<std::string>(), "energy");
  EXPECT_TRUE(j.at("feasible").get<bool>());
  EXPECT_DOUBLE_EQ(j.at("max_current_mps").get<double>(), 0.8);
  const auto& legs = j.at("legs");
  ASSERT_EQ(legs.size() + 1, j.at("waypoints").get<std::size_t>());
  double time = 0.0, energy = 0.0;
  for (const auto& leg : legs) {
    const double v = leg.at("speed_mps").get<double>();
    EXPECT_GE(v, 1852.0 / 3600.0 - 1e-9);  // the vehicle's minimum, 1 kn
    EXPECT_LE(v, 6 * 1852.0 / 3600.0 + 1e-9);
    // E = P(v) t per leg with the default model.
    EXPECT_NEAR(leg.at("energy_j").get<double>(), (1050.0 + 60.0 * v * v * v) * leg.at("time_s").get<double>(),
                1e-6 * leg.at("energy_j").get<double>());
    time += leg.at("time_s").get<double>();
    energy += leg.at("energy_j").get<double>();
  }
  EXPECT_NEAR(j.at("time_s").get<double>(), time, 1e-6);
  EXPECT_NEAR(j.at("energy_j").get<double>(), energy, 1e-3);
  // Choosing the speed per leg spends no more than cruising, and the shortest route is reported beside it.
  const auto cruise =
      run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --cost energy --current-const 0.8,200 --json");
  ASSERT_EQ(cruise.exit_code, 0) << cruise.err;
  const auto c = nlohmann::json::parse(cruise.out);
  EXPECT_LT(energy, 0.99 * c.at("energy_j").get<double>());
  EXPECT_LE(c.at("energy_j").get<double>(), c.at("shortest_energy_j").get<double>() * (1.0 + 1e-9));
  // The file's waypoints carry the arriving leg's speed (the start: the first leg's) and the energy so far.
  std::ifstream in(route);
  const auto geo = nlohmann::json::parse(in);
  int waypoints = 0;
  for (const auto& f : geo.at("features")) {
    if (f.at("properties").at("kind") != "waypoint") continue;
    const auto& p = f.at("properties");
    const int i = p.at("index").get<int>();
    EXPECT_DOUBLE_EQ(p.at("speed_mps").get<double>(),
                     legs.at(static_cast<std::size_t>(std::max(i - 1, 0))).at("speed_mps").get<double>());
    if (i == 0) {
      EXPECT_EQ(p.at("cum_energy_j").get<double>(), 0.0);
    }
    ++waypoints;
  }
  EXPECT_EQ(waypoints, j.at("waypoints").get<int>());
}

TEST(CliPlanCost, ACurrentStrongerThanTheVehicleIsExit3) {
  // 3 m/s setting south-west; the goal lies north-east and the vehicle makes 2.06 m/s.
  const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --cost time --current-const 3,225");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("no feasible route"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliPlanCost, BadCostOptionsAreOneLineErrors) {
  ScratchDir dir;
  const std::string base = "plan --obstacles '" + kSample + "'" + kFromTo;
  const std::string vehicle = dir.write("v.yaml", "name: x\nhotel_power_w: -100\n");
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {" --cost fastest", {"--cost", "length, time or energy", "fastest"}},
      {" --cost time --speed brisk", {"--speed", "brisk"}},
      {" --cost time --speed 9", {"--speed", "maximum"}},
      {" --cost time --depart yesterday --current-const 1,0", {"--depart", "yesterday"}},
      {" --cost energy --vehicle '" + vehicle + "'", {"v.yaml", "line 2", "hotel_power_w", "> 0"}},
      {" --cost time --graph tangent", {"--cost time", "visibility"}},
      {" --cost time --current-const 1,north", {"--current-const"}},
      {" --cost time --current /nonexistent/tide.nc", {"/nonexistent/tide.nc"}},
      {" --cost time --current-const 1,0 --waypoint-grid 0", {"--waypoint-grid", "> 0", "got 0"}},
      {" --margin 1e308", {"--margin", "100 km", "1e+308"}},
      {" --margin -1", {"--margin", "100 km", "-1"}},
  };
  for (const auto& [args, words] : cases) {
    const auto r = run_cli(base + args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << args << ": " << r.err;
  }
  // Both kinds of current at once: usage.
  EXPECT_EQ(run_cli(base + " --current a.nc --current-const 1,0").exit_code, 2);
}

TEST(CliPlanCost, TimeRouteThroughTheRealGulfStream) {
  // HYCOM off Cape Hatteras (a 1.5-2 m/s stream setting north-east): a route
  // south-west against it around two synthetic banks, by length and by time.
  DEEPGUIDE_REAL_FILE_OR_SKIP(hycom, "currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc");
  ScratchDir dir;
  const std::string banks = dir.write("banks.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"id": "bank-a"}, "geometry": {"type": "Polygon", "coordinates":
      [[[-75.05, 34.90], [-74.95, 34.90], [-74.95, 35.00], [-75.05, 35.00], [-75.05, 34.90]]]}},
    {"type": "Feature", "properties": {"id": "bank-b"}, "geometry": {"type": "Polygon", "coordinates":
      [[[-75.25, 34.75], [-75.15, 34.75], [-75.15, 34.82], [-75.25, 34.82], [-75.25, 34.75]]]}}]})");
  const std::string base =
      "plan --obstacles '" + banks + "' --from -74.80,35.10 --to -75.40,34.60 --current '" + hycom + "' --json";
  const auto by_length = run_cli(base + " --cost length");
  const auto by_time = run_cli(base + " --cost time");
  ASSERT_EQ(by_length.exit_code, 0) << by_length.err;
  ASSERT_EQ(by_time.exit_code, 0) << by_time.err;
  const auto l = nlohmann::json::parse(by_length.out), t = nlohmann::json::parse(by_time.out);
  EXPECT_EQ(t.at("crs").get<std::string>(), "EPSG:32618");
  EXPECT_GT(t.at("max_current_mps").get<double>(), 1.0);
  // The time route is never slower, and never shorter, than the length route.
  EXPECT_LE(t.at("time_s").get<double>(), l.at("time_s").get<double>() * (1.0 + 1e-9));
  EXPECT_GE(t.at("length_m").get<double>(), l.at("length_m").get<double>() * (1.0 - 1e-9));
  EXPECT_GE(t.at("min_clearance_m").get<double>(), 5.0 - 1e-9);
}

TEST(CliPlanCost, ATidalFieldChoosesTheSideByTheDepartureTime) {
  // An island about 650 m square; north of it the tidal stream sets east
  // when south of it it sets west, reversing every 6.21 h (hourly steps over a day).
  ScratchDir dir;
  const std::string island = dir.write("island.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"id": "island"}, "geometry": {"type": "Polygon", "coordinates":
      [[[10.245, 54.447], [10.255, 54.447], [10.255, 54.453], [10.245, 54.453], [10.245, 54.447]]]}}]})");
  deepguide::test::NcSpec tide;
  tide.lon.clear();
  tide.lat.clear();
  for (int i = 0; i <= 20; ++i) tide.lon.push_back(10.20 + 0.005 * i);
  for (int j = 0; j <= 16; ++j) tide.lat.push_back(54.43 + 0.0025 * j);
  for (int k = 0; k <= 24; ++k) tide.time.push_back(k);
  tide.time_units = "hours since 2020-01-01 00:00:00";
  tide.u = [](double, double lat, double hours, double) {
    return 1.2 * std::tanh((lat - 54.45) / 0.0015) * std::cos(2.0 * M_PI * hours / 12.42);
  };
  tide.v = [](double, double, double, double) { return 0.0; };
  const std::string nc = dir.file("tide.nc");
  deepguide::test::write_nc(nc, tide);
  const std::string base =
      "plan --obstacles '" + island + "' --from 10.225,54.45 --to 10.275,54.45 --cost time " + "--current '" + nc + "'";
  // The mean latitude of a written route's waypoints, against the island's middle.
  const auto side = [&](const std::string& depart, const std::string& file) {
    const auto r = run_cli(base + " --depart " + depart + " -o '" + file + "' --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("depart").get<std::string>(), depart);
    EXPECT_TRUE(j.contains("arrive"));
    std::ifstream in(file);
    const auto geo = nlohmann::json::parse(in);
    double lat = 0.0;
    int n = 0;
    for (const auto& f : geo.at("features")) {
      if (f.at("properties").at("kind") != "waypoint") continue;
      lat += f.at("geometry").at("coordinates").at(1).get<double>();
      EXPECT_TRUE(f.at("properties").contains("eta"));
      ++n;
    }
    return lat / n - 54.45;
  };
  EXPECT_GT(side("2020-01-01T00:00:00Z", dir.file("high.geojson")), 0.0);  // the east-setting stream is north
  EXPECT_LT(side("2020-01-01T06:13:00Z", dir.file("half.geojson")), 0.0);  // six hours later it is south
  // Before the forecast, and a speed per leg in a changing current: one-line errors.
  const auto early = run_cli(base + " --depart 2019-12-31T23:00:00Z");
  EXPECT_EQ(early.exit_code, 1) << early.err;
  for (const char* w : {"--depart", "2020-01-01T00:00:00Z", "2020-01-02T00:00:00Z", "2019-12-31T23:00:00Z"}) {
    EXPECT_NE(early.err.find(w), std::string::npos) << early.err;
  }
  const auto optimal =
      run_cli("plan --obstacles '" + island + "' --from 10.225,54.45 --to 10.275,54.45 --cost energy " + "--current '" +
              nc + "' --speed optimal");
  EXPECT_EQ(optimal.exit_code, 1) << optimal.err;
  EXPECT_NE(optimal.err.find("steady"), std::string::npos) << optimal.err;
  // Leaving five minutes before the forecast ends (the crossing takes 20 to 40):
  // no time route (exit 3); the length route is planned, with a warning and
  // its legs past the end infeasible.
  const auto late = run_cli(base + " --depart 2020-01-01T23:55:00Z");
  EXPECT_EQ(late.exit_code, 3) << late.err;
  // The reason is the forecast's end, with both ends of its time axis (issue 39).
  for (const char* w : {"time axis 2020-01-01T00:00:00Z .. 2020-01-02T00:00:00Z", "ends before the vehicle can arrive",
                        "departing 2020-01-01T23:55:00Z"})
    EXPECT_NE(late.err.find(w), std::string::npos) << late.err;
  const std::string length_base = "plan --obstacles '" + island + "' --from 10.225,54.45 --to 10.275,54.45 " +
                                  "--current '" + nc + "' --cost length --depart 2020-01-01T23:55:00Z --json";
  const auto length = run_cli(length_base);
  EXPECT_EQ(length.exit_code, 0) << length.err;
  EXPECT_NE(length.err.find("warning"), std::string::npos) << length.err;
  const auto lj = nlohmann::json::parse(length.out);
  EXPECT_FALSE(lj.at("feasible").get<bool>());
  EXPECT_FALSE(lj.at("legs").back().at("feasible").get<bool>());
}

// --- Quadtree graph and replanning (issue 5) ----------------------------------------------------

TEST(CliPlanQuadtree, SmoothedRouteIsCheckedAndReplanningWritesEachRepair) {
  ScratchDir dir;
  const std::string route = dir.file("q.geojson");
  const auto r =
      run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --graph quadtree --smooth -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("graph").get<std::string>(), "quadtree");
  const auto ok = run_cli("check route '" + route + "' --obstacles '" + kSample + "' --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out).at("safe").get<bool>());
  // The README's replay: two obstacles reported on the way; each repair is written next to the route.
  const std::string events = deepguide::test::source_file("data/replan_events.csv");
  const std::string replanned = dir.file("r.geojson");
  const std::string figure = dir.file("replay.png");
  const auto rp = run_cli("plan --obstacles '" + kSample + "' --from 10.2405,54.4470 --to 10.2640,54.4560" +
                          " --graph quadtree --replan-events '" + events + "' -o '" + replanned + "' --render '" +
                          figure + "' --json");
  ASSERT_EQ(rp.exit_code, 0) << rp.err;
  const auto rj = nlohmann::json::parse(rp.out);
  ASSERT_EQ(rj.at("repairs").size(), 2u);
  EXPECT_TRUE(rj.at("reached_goal").get<bool>());
  for (const auto& repair : rj.at("repairs")) {
    const std::string file = repair.at("file").get<std::string>();
    EXPECT_TRUE(std::filesystem::exists(file)) << file;
  }
  // The rocks lie on the route: each blocks edges, and the first repair is longer than what was left.
  for (const auto& repair : rj.at("repairs")) EXPECT_GT(repair.at("blocked_edges").get<int>(), 0);
  EXPECT_GT(std::filesystem::file_size(figure), 10000u);  // the chart with the reports, repairs and track
}

TEST(CliPlanQuadtree, BadOptionsAndAWalledInVehicle) {
  ScratchDir dir;
  const std::string base = "plan --obstacles '" + kSample + "'" + kFromTo;
  const std::string no_distance = dir.write("nd.csv", "lon,lat,semi_major_m\n10.25,54.45,15\n");
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {" --graph quadtree --min-cell 0", {"--min-cell", "> 0"}},
      {" --graph quadtree --min-cell -3", {"--min-cell", "-3"}},
      // Cells wider than half the 1.8 km trip: it became a 314 km route through far cell centres.
      {" --graph quadtree --min-cell 1e5", {"--min-cell", "at most half the distance from start to goal", "100000"}},
      {" --smooth", {"--smooth", "quadtree"}},
      {" --replan-events '" + no_distance + "'", {"--replan-events", "quadtree"}},
      {" --graph quadtree --replan-events '" + no_distance + "'", {"nd.csv", "line 2", "detected_at_m"}},
      {" --graph quadtree --replan-events /nonexistent/events.csv", {"/nonexistent/events.csv"}},
  };
  for (const auto& [args, words] : cases) {
    const auto r = run_cli(base + args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << args << ": " << r.err;
  }
  // A wall reported across the whole way: the replay says where the vehicle stopped, exit 3.
  const std::string wall =
      dir.write("wall.geojson",
                R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"id": "new-wall",
      "detected_at_m": 0}, "geometry": {"type": "Polygon", "coordinates": [[[10.2425, 54.40], [10.2430, 54.40],
      [10.2430, 54.50], [10.2425, 54.50], [10.2425, 54.40]]]}}]})");
  const auto walled = run_cli(base + " --graph quadtree --replan-events '" + wall + "'");
  EXPECT_EQ(walled.exit_code, 3) << walled.out << walled.err;
  EXPECT_NE(walled.err.find("after report 1"), std::string::npos) << walled.err;
  EXPECT_NE(walled.out.find("no route"), std::string::npos) << walled.out;
}

// The navigation mesh replays detections too: a rock reported on the exact
// route 420 m out, reported 300 m out, is cut out of the mesh, the route
// found again round it from where the vehicle is (longer than what was left),
// written and checked; a ring closed round the goal stops the vehicle, exit 3
// (a wall would not: the mesh's area widens round its ends).
TEST(CliPlanNavMesh, ReplanningCutsEachReportOutOfTheMeshAndRoutesRoundIt) {
  ScratchDir dir;
  const std::string base = "plan --obstacles '" + kSample + "' --from 10.2405,54.4470 --to 10.2640,54.4560";
  const std::string rock = dir.write("rock.csv",
                                     "lon,lat,semi_major_m,semi_minor_m,orientation_deg,detected_at_m,id\n"
                                     "10.24600,54.44902,20,20,0,300,new-rock\n");
  const std::string route = dir.file("m.geojson");
  const auto r = run_cli(base + " --graph navmesh --replan-events '" + rock + "' -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("repairs").size(), 1u);
  EXPECT_TRUE(j.at("reached_goal").get<bool>());
  const auto& repair = j.at("repairs").at(0);
  EXPECT_GT(repair.at("remeshed_faces").get<int>(), 0);
  EXPECT_NEAR(repair.at("along_m").get<double>(), 300.0, 1e-6);
  const double initial = j.at("length_m").get<double>();
  EXPECT_GT(300.0 + repair.at("length_m").get<double>(), initial + 1.0);  // the rock lies on the way
  const std::string file = repair.at("file").get<std::string>();
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  // The repair keeps the margin from the chart's obstacles and from the rock (the reader's own check).
  const auto ok = run_cli("check route '" + file + "' --obstacles '" + kSample + "' '" + rock + "' --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out).at("safe").get<bool>());
  const std::string wall =
      dir.write("ring.geojson",
                R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"id": "new-ring",
      "detected_at_m": 100}, "geometry": {"type": "Polygon", "coordinates": [[[10.2620, 54.4548], [10.2660, 54.4548],
      [10.2660, 54.4572], [10.2620, 54.4572], [10.2620, 54.4548]], [[10.2630, 54.4554], [10.2630, 54.4566],
      [10.2650, 54.4566], [10.2650, 54.4554], [10.2630, 54.4554]]]}}]})");
  // Repairs are not rounded: a turning radius, given or a vehicle's, is refused in one line.
  for (const std::string& radius : {std::string(" --turn-radius 20"),
                                    " --vehicle '" + deepguide::test::source_file("data/vehicles/deepc.yaml") + "'"}) {
    const auto refused = run_cli(base + " --graph navmesh --replan-events '" + rock + "'" + radius);
    EXPECT_EQ(refused.exit_code, 1) << radius << ": " << refused.out << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << radius << ": " << refused.err;
    EXPECT_NE(refused.err.find("--replan-events"), std::string::npos) << radius << ": " << refused.err;
  }
  const auto walled = run_cli(base + " --graph navmesh --replan-events '" + wall + "'");
  EXPECT_EQ(walled.exit_code, 3) << walled.out << walled.err;
  EXPECT_NE(walled.err.find("after report 1"), std::string::npos) << walled.err;
  EXPECT_NE(walled.out.find("no route"), std::string::npos) << walled.out;
}

TEST(CliPlanOctree, ARouteInDepthOverTheSampleChart) {
  // Out of the harbour to the north-east over the sample chart's sea floor and
  // hazards: the route climbs over the shoal and passes over wreck-1.
  ScratchDir dir;
  const std::string chart = "'" + deepguide::test::source_file("charts/sample_chart.tif") + "' '" +
                            deepguide::test::source_file("charts/sample_chart_hazards.gpkg") + "'";
  const std::string route = dir.file("r.geojson"), profile = dir.file("p.png");
  const auto r = run_cli("plan --chart " + chart +
                         " --graph octree --depth 10 --from 10.2446,54.4413 --to "
                         "10.2626,54.4606 --min-cell 1 --smooth -o '" +
                         route + "' --render-profile '" + profile + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("graph"), "octree");
  EXPECT_TRUE(j.at("sea_floor").get<bool>());
  EXPECT_GE(j.at("min_floor_gap_m").get<double>(), 2.0 - 1e-9);
  // The dive angle is the vehicle's: asin(0.5 m/s / 4 kn) = 14.07 deg.
  EXPECT_NEAR(j.at("max_dive_deg").get<double>(), 14.07, 0.01);
  EXPECT_LE(j.at("steepest_deg").get<double>(), j.at("max_dive_deg").get<double>() + 1e-6);
  EXPECT_GT(j.at("free_cells").get<int>(), 1000);
  EXPECT_TRUE(std::filesystem::exists(profile));
  // Every waypoint carries its depth, and the floor under it lies deeper by the clearance.
  std::ifstream in(route);
  const auto geo = nlohmann::json::parse(in);
  int waypoints = 0;
  for (const auto& f : geo.at("features")) {
    if (f.at("geometry").at("type") != "Point") continue;
    ++waypoints;
    const auto& p = f.at("properties");
    EXPECT_GE(p.at("depth_m").get<double>(), 2.0 - 1e-9);
    EXPECT_LE(p.at("depth_m").get<double>(), p.at("floor_depth_m").get<double>() - 2.0 + 1e-9);
  }
  EXPECT_EQ(waypoints, j.at("waypoints").get<int>());
}

TEST(CliPlanOctree, BadInputIsOneLineAndExitOne) {
  const std::string chart = "'" + deepguide::test::source_file("charts/sample_chart.tif") + "'";
  const std::string base = "plan --chart " + chart + " --graph octree --from 10.2446,54.4413 --to 10.2626,54.4606";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {" --depth 10 --min-cell 0", {"--min-cell", "> 0"}},
      {" --depth 10 --depth-band -5,-1", {"depth band", "surface"}},
      {" --depth 10 --depth-band 5", {"--depth-band", "TOP,BOTTOM"}},
      {" --depth 40", {"the start", "sea floor"}},  // deeper than the floor at the harbour
      {" --from-depth 10 --to-depth 1", {"the goal", "band"}},
      {"", {"--depth"}},
      {" --depth 10 --max-dive 95", {"--max-dive"}},
      // Issue 39: a dive so shallow that one cell is wider than the voyage (was "a raster that covers the work area").
      {" --depth 10 --max-dive 1e-9", {"--max-dive", "1e-09 deg", "1.14592e+11 m wide", "at least 0.375 deg"}},
      {" --depth 10 --max-dive 0.2", {"--max-dive", "572.955 m wide", "at least 0.375 deg"}},
      // A coarse floor (1 deg: 115 m cells) says how coarse.
      {" --depth 10 --max-dive 1", {"the start", "sea floor", "sampled every 114.6 m"}},
      {" --depth 10 --cost energy", {"--graph octree", "--cost"}},
      {" --depth 10 --render-profile p.txt", {"p.txt"}},
  };
  for (const auto& [args, words] : cases) {
    const auto r = run_cli(base + args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << args << ": " << r.err;
  }
  const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --depth-band 5,50");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--graph octree"), std::string::npos) << r.err;
}

// Vincenty's inverse on WGS 84 (m): the geodesic the frame's length is compared with.
static double vincenty_m(double lon1, double lat1, double lon2, double lat2) {
  const double a = 6378137.0, f = 1.0 / 298.257223563, b = a * (1.0 - f);
  const double d2r = M_PI / 180.0;
  const double L = (lon2 - lon1) * d2r;
  const double U1 = std::atan((1.0 - f) * std::tan(lat1 * d2r)), U2 = std::atan((1.0 - f) * std::tan(lat2 * d2r));
  double lambda = L, sin_s = 0, cos_s = 0, sigma = 0, cos2a = 0, cos2sm = 0;
  for (int i = 0; i < 200; ++i) {
    const double sl = std::sin(lambda), cl = std::cos(lambda);
    sin_s = std::hypot(std::cos(U2) * sl, std::cos(U1) * std::sin(U2) - std::sin(U1) * std::cos(U2) * cl);
    cos_s = std::sin(U1) * std::sin(U2) + std::cos(U1) * std::cos(U2) * cl;
    sigma = std::atan2(sin_s, cos_s);
    const double sin_a = std::cos(U1) * std::cos(U2) * sl / sin_s;
    cos2a = 1.0 - sin_a * sin_a;
    cos2sm = cos_s - 2.0 * std::sin(U1) * std::sin(U2) / cos2a;
    const double C = f / 16.0 * cos2a * (4.0 + f * (4.0 - 3.0 * cos2a));
    const double next =
        L + (1.0 - C) * f * sin_a * (sigma + C * sin_s * (cos2sm + C * cos_s * (-1.0 + 2.0 * cos2sm * cos2sm)));
    if (std::abs(next - lambda) < 1e-13) {
      lambda = next;
      break;
    }
    lambda = next;
  }
  const double u2 = cos2a * (a * a - b * b) / (b * b);
  const double A = 1.0 + u2 / 16384.0 * (4096.0 + u2 * (-768.0 + u2 * (320.0 - 175.0 * u2)));
  const double B = u2 / 1024.0 * (256.0 + u2 * (-128.0 + u2 * (74.0 - 47.0 * u2)));
  const double ds = B * sin_s *
                    (cos2sm + B / 4.0 *
                                  (cos_s * (-1.0 + 2.0 * cos2sm * cos2sm) -
                                   B / 6.0 * cos2sm * (-3.0 + 4.0 * sin_s * sin_s) * (-3.0 + 4.0 * cos2sm * cos2sm)));
  return b * A * (sigma - ds);
}

// An obstacle file with nothing in it fixes no frame: the start's UTM zone does (issue 24).
TEST(CliPlan, EmptyObstacleFileLeavesTheFrameToTheStart) {
  ScratchDir dir;
  const std::string empty = dir.write("empty.geojson", R"({"type":"FeatureCollection","features":[]})");
  const auto r = run_cli("plan --obstacles '" + empty + "' --from 100.0,10.0 --to 100.05,10.02 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["crs"], "EPSG:32647");
  const double geodesic = vincenty_m(100.0, 10.0, 100.05, 10.02);
  // By hand: 0.02 deg of latitude is 2212 m and 0.05 deg of longitude at 10 N is 5482 m, 5911 m together.
  EXPECT_NEAR(geodesic, 5911.3, 0.5);
  EXPECT_NEAR(j["length_m"].get<double>(), geodesic, 1e-3 * geodesic);
}

// plan writes GeoJSON routes only: another extension is refused before the work, with no file.
TEST(CliPlan, RouteFileInEveryFormatByItsName) {
  ScratchDir dir;
  // What each format's file begins with or holds: the writer that names it, not GeoJSON under another name.
  const std::vector<std::pair<std::string, std::string>> formats = {{"route.gpx", "<gpx"},
                                                                    {"route.kml", "<kml"},
                                                                    {"route.rtz", "http://www.cirm.org/RTZ/1/0"},
                                                                    {"route.plan", "\"Plan\""},
                                                                    {"route.bhv", "BHV_Waypoint"},
                                                                    {"route.csv", "WKT,name,lon,lat"},
                                                                    {"route.geojson", "FeatureCollection"}};
  for (const auto& [name, mark] : formats) {
    const std::string out = dir.file(name);
    const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " --depth 5 -o '" + out + "'");
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    std::ifstream in(out);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(text.find(mark), std::string::npos) << name;
    if (name != "route.geojson") {
      EXPECT_EQ(text.find("FeatureCollection"), std::string::npos) << name;
    }
  }
  for (const char* name : {"route.txt", "route.yaml", "route"}) {
    const std::string out = dir.file(name);
    const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + out + "'");
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("expected"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << name;
  }
}

TEST(CliPlan, GridsWithoutACrsTakeSrcCrs) {
  // NOAA's Coastal Relief Model as ESRI ASCII without a .prj, and GMT's cached ETOPO grid.
  DEEPGUIDE_REAL_FILE_OR_SKIP(crm, "bathy-usml-crm/small_crm.asc");
  DEEPGUIDE_REAL_FILE_OR_SKIP(gmt, "bathy-gmt-cache/bathy_1m.nc");
  const auto refused = run_cli("chart info '" + crm + "'");
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_NE(refused.err.find("--src-crs"), std::string::npos) << refused.err;
  const auto info = run_cli("chart info '" + crm + "' --src-crs EPSG:4326 --depth 700 --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out).at(0);
  EXPECT_EQ(j.at("crs"), "EPSG:4326");
  EXPECT_NEAR(j.at("extent").at("west").get<double>(), -79.900417, 1e-5);
  EXPECT_NEAR(j.at("extent").at("north").get<double>(), 29.600417, 1e-5);
  EXPECT_GT(j.at("no_go").at("area_m2").get<double>(), 0.0);  // depths run 622 to 771 m: some water is too shallow
  for (const std::string& chart : {crm, gmt}) {
    const std::string from = chart == crm ? "-79.85,29.45" : "-30,38";
    const std::string to = chart == crm ? "-79.75,29.55" : "-29.5,38.2";
    const auto r = run_cli("plan --chart '" + chart + "' --src-crs EPSG:4326 --depth 100 --from " + from + " --to " +
                           to + " --json");
    ASSERT_EQ(r.exit_code, 0) << chart << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("crs"), chart == crm ? "EPSG:32617" : "EPSG:32626");
  }
  ScratchDir dir;
  const auto drawn =
      run_cli("render chart '" + crm + "' --src-crs EPSG:4326 --depth 700 -o '" + dir.file("crm.png") + "'");
  EXPECT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_GT(std::filesystem::file_size(dir.file("crm.png")), 10000u);
}

TEST(CliPlan, CheckRouteReadsEcdisAndOpenCpnRoutes) {
  // The Norwegian Coastal Administration's RTZ routes and an OpenCPN GPX route: every waypoint read
  // (counted in the files with xmllint), in the route's own UTM zone when no obstacle fixes the frame.
  ScratchDir dir;
  const std::string none = dir.write("none.geojson", "{\"type\": \"FeatureCollection\", \"features\": []}");
  const std::vector<std::tuple<std::string, std::size_t, std::string>> routes = {
      {"rtz-nca-norway/NCA_7_5m_Bergen_Stad_Krakhelle_In_20250731.rtz", 82, "EPSG:32631"},  // 5.2 E
      {"rtz-nca-norway/NCA_Bergen_Fedjeosen_In_20250801.rtz", 18, "EPSG:32631"},
      {"rtz-nca-norway/NCA_OsloEast_In_20250731.rtz", 18, "EPSG:32632"},
      {"opencpn-gpx/opencpn_route_foo.gpx", 13, "EPSG:32634"}};
  for (const auto& [rel, count, crs] : routes) {
    DEEPGUIDE_REAL_FILE_OR_SKIP(path, rel);
    const auto r = run_cli("check route '" + path + "' --obstacles '" + none + "' --json");
    ASSERT_EQ(r.exit_code, 0) << rel << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("waypoints").get<std::size_t>(), count) << rel;
    EXPECT_EQ(j.at("crs"), crs) << rel;
    EXPECT_GT(j.at("length_m").get<double>(), 1000.0) << rel;
  }
}

TEST(CliPlan, CheckRouteChecksEveryLineAndPointOfTheFile) {
  // A first line clear of every obstacle; a second through c2's centre, or a point on c5's, is not safe.
  ScratchDir dir;
  const std::string clear =
      "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"LineString\", "
      "\"coordinates\": [[10.230, 54.440], [10.231, 54.441]]}}";
  const std::string through =
      "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"LineString\", "
      "\"coordinates\": [[10.250, 54.453], [10.262, 54.453]]}}";
  const std::string on_c5 =
      "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"Point\", "
      "\"coordinates\": [10.248, 54.447]}}";
  const auto file = [&](const std::string& name, const std::vector<std::string>& features) {
    std::string text = "{\"type\": \"FeatureCollection\", \"features\": [";
    for (std::size_t i = 0; i < features.size(); ++i) text += (i ? ", " : "") + features[i];
    return dir.write(name, text + "]}");
  };
  auto r = run_cli("check route '" + file("one.geojson", {clear}) + "' --obstacles '" + kSample + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("lines"), 1);
  r = run_cli("check route '" + file("two.geojson", {clear, through}) + "' --obstacles '" + kSample + "'");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("feature 1"), std::string::npos) << r.err;  // the second line, named
  EXPECT_NE(r.err.find("c2"), std::string::npos) << r.err;
  r = run_cli("check route '" + file("point.geojson", {clear, on_c5}) + "' --obstacles '" + kSample + "' --json");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("c5"), std::string::npos) << r.err;
  // The ends of the line through c2 as points alone (a file of waypoints): each
  // is clear, the leg between them is not, and the legs are what is checked.
  const auto point = [](const char* lonlat) {
    return std::string(
               "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"Point\", "
               "\"coordinates\": [") +
           lonlat + "]}}";
  };
  const std::string ends = file("ends.geojson", {point("10.250, 54.453"), point("10.262, 54.453")});
  r = run_cli("check route '" + ends + "' --obstacles '" + kSample + "' --margin 0");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.err.find("segment 0 enters obstacle 'c2'"), std::string::npos) << r.err;
}

TEST(CliPlan, AnOutputNeverDestroysAnInput) {
  // The same file by device and inode, under its own name, a hard link or another spelling.
  ScratchDir dir;
  const auto copy = [&](const std::string& from, const std::string& name) {
    std::filesystem::copy_file(from, dir.file(name));
    return dir.file(name);
  };
  const auto text = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string obstacles = copy(kSample, "obstacles.geojson");
  const std::string kept = text(obstacles);
  std::filesystem::create_hard_link(obstacles, dir.file("link.geojson"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plan --obstacles '" + obstacles + "'" + kFromTo + " -o '" + obstacles + "'", "--obstacles"},
      {"plan --obstacles '" + obstacles + "'" + kFromTo + " -o '" + dir.file("link.geojson") + "'", "--obstacles"},
      {"plan --obstacles '" + obstacles + "'" + kFromTo + " -o '" + dir.file("r.png") + "' --render '" +
           dir.file("sub/../r.png") + "'",
       "expected"},
      {"obstacles convert '" + obstacles + "' '" + dir.file("./obstacles.geojson") + "'", "input"},
      {"mission export '" + deepguide::test::source_file("data/missions/sample_mission.yaml") +
           "' --format yaml --overwrite -o '" + deepguide::test::source_file("data/missions/sample_mission.yaml") + "'",
       "MISSION"},
  };
  std::filesystem::create_directories(dir.path() / "sub");
  const std::string mission_text = text(deepguide::test::source_file("data/missions/sample_mission.yaml"));
  for (const auto& [args, names] : cases) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
  }
  EXPECT_EQ(text(obstacles), kept);
  EXPECT_EQ(text(deepguide::test::source_file("data/missions/sample_mission.yaml")), mission_text);
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.png")));
  const std::string scenario = copy(deepguide::test::source_file("data/scenarios/one_obstacle.yaml"), "s.yaml");
  const std::string scenario_text = text(scenario);
  const auto r = run_cli("simulate '" + scenario + "' --method geometric -o '" + scenario + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(text(scenario), scenario_text);
}

TEST(CliPlan, EscapeFromInsideAnObstacleLeavesItAndSaysSo) {
  // The start at c1's centre (semi-minor 15 m, margin 5): was "internal error:
  // the planned route failed the independent check" for every graph.
  ScratchDir dir;
  for (const char* graph : {"visibility", "tangent", "quadtree"}) {
    const auto r = run_cli("plan --obstacles '" + kSample +
                           "' --from 10.2500,54.4500 --to 10.265,54.462 --escape "
                           "--graph " +
                           std::string(graph) + " -o '" + dir.file(std::string(graph) + ".geojson") + "'");
    ASSERT_EQ(r.exit_code, 0) << graph << ": " << r.err;
    EXPECT_NE(r.out.find("escape           the first leg, 20.0 m, leaves obstacle 'c1''s zone from inside it"),
              std::string::npos)
        << graph << ": " << r.out;
    EXPECT_NE(r.out.find("min clearance    5.00 m"), std::string::npos) << graph << ": " << r.out;
  }
}

TEST(CliPlan, GdalsOwnErrorLinesAreNeverPrinted) {
  // GDAL printed "ERROR 1: XML parsing of JML file failed ..." to stderr
  // wherever no quiet handler was active (a layer read after the open); the
  // libFuzzer soak's input also showed that GDAL's OpenJUMP driver took a
  // damaged *.000 cell, which is now read by the S57 driver alone.
  ScratchDir dir;
  const std::string xml = "<JCSDataFile><JCSGMLInputTemplate></JCSDataFile>\n";
  for (const std::string name : {"bad.jml", "CELL.000"}) {
    const auto r = run_cli("chart info '" + dir.write(name, xml) + "'");
    // GDAL's own lines start "ERROR 1:" (the sanitizers' own "==N==ERROR" report
    // GDAL's JML driver leaking on bad.jml, which is GDAL's, not a line of ours).
    EXPECT_EQ(r.err.rfind("ERROR ", 0), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(r.err.find("\nERROR "), std::string::npos) << name << ": " << r.err;
    if (name == "CELL.000") {
      EXPECT_EQ(r.exit_code, 1) << r.err;
      EXPECT_NE(r.err.find("expected an S-57 ENC cell"), std::string::npos) << r.err;
    }
  }
}

TEST(CliPlan, NamedPipesAreRefusedNotWaitedOn) {
  // GDAL and libxml2 block on a FIFO until a writer comes: every reader
  // refuses one at once, naming it (the test would hang otherwise).
  ScratchDir dir;
  const std::string fifo = dir.file("pipe.geojson"), rtz = dir.file("pipe.rtz");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(rtz.c_str(), 0600), 0);
  for (const std::string& args :
       {"plan --obstacles '" + fifo + "'" + kFromTo, "check route '" + fifo + "' --obstacles '" + kSample + "'",
        "check route '" + rtz + "' --obstacles '" + kSample + "'", "obstacles info '" + fifo + "'",
        "chart info '" + fifo + "'", "plan --chart '" + fifo + "' --depth 5" + kFromTo,
        // The YAML readers (they refused a pipe before, saying "expected an existing ... file").
        "mission check '" + fifo + "'", "simulate '" + fifo + "' --method geometric", "identify '" + fifo + "'",
        "evaluate '" + fifo + "' --methods geometric -o '" + dir.file("ev") + "'"}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find("expected a file, got a named pipe (FIFO)"), std::string::npos) << args << ": " << r.err;
  }
}

TEST(CliPlan, AFullDiskIsAnErrorAndLeavesNoFile) {
  // RLIMIT_FSIZE (with SIGXFSZ ignored, so writes fail with EFBIG as on a full disk): every writer
  // says it could not write, exits 1 and leaves neither the file nor a temporary one behind.
  ScratchDir dir;
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  const auto limited = [&](int kib, const std::string& args) {
    const std::string cmd = "bash -c \"ulimit -f " + std::to_string(kib) + "; trap '' XFSZ; exec '" +
                            std::string(DEEPGUIDE_CLI) + "' " + args + "\" >'" + dir.file("out.txt") + "' 2>'" +
                            dir.file("err.txt") + "'";
    const int status = std::system(cmd.c_str());
    std::ifstream err(dir.file("err.txt"));
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                          std::string(std::istreambuf_iterator<char>(err), {}));
  };
  std::filesystem::create_directories(dir.path() / "w");
  std::filesystem::create_directories(dir.path() / "chart");
  ASSERT_EQ(run_cli("chart synth -o '" + dir.file("chart") + "'").exit_code, 0);
  const std::string chart = dir.file("chart/sample_chart.tif");
  const auto w = [&](const std::string& name) { return (dir.path() / "w" / name).string(); };
  const std::vector<std::pair<int, std::string>> cases = {
      {1, "obstacles convert '" + kSample + "' '" + w("o.geojson") + "'"},
      {1, "chart nogo '" + chart + "' --depth 10 -o '" + w("n.geojson") + "'"},
      {1, "plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + w("r.geojson") + "'"},
      {1, "plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + w("r.gpx") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.gpx") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.kml") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.geojson") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.csv") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.rtz") + "'"},
      {16, "mission export '" + mission + "' -o '" + w("m.plan") + "'"},
      {4, "mission export '" + mission + "' -o '" + w("m.bhv") + "'"},
  };
  for (const auto& [kib, args] : cases) {
    const auto [code, err] = limited(kib, args);
    EXPECT_EQ(code, 1) << args << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("could not"), std::string::npos) << err;
    std::vector<std::string> left;
    for (const auto& e : std::filesystem::directory_iterator(dir.path() / "w")) left.push_back(e.path().string());
    EXPECT_TRUE(left.empty()) << args << ": left " << left.front();
    for (const std::string& f : left) std::filesystem::remove(f);
  }
  // Without the limit the same commands write their files (the limit, not the command, failed them).
  const auto [code, err] = limited(100000, "mission export '" + mission + "' -o '" + w("m.kml") + "'");
  EXPECT_EQ(code, 0) << err;
  EXPECT_TRUE(std::filesystem::exists(w("m.kml")));
}

TEST(CliPlan, TemporariesAKilledRunLeftAreRemovedByTheNextWrite) {
  // A run killed mid-write leaves ".NAME.tmpPID-N.EXT" (a file, or a folder for a suite); the next
  // write into that folder removes those whose process is gone, and keeps a live process's.
  ScratchDir dir;
  int dead = 4000000;  // a pid no process has (pid_max is at most 2^22)
  while (kill(dead, 0) == 0 || errno != ESRCH) ++dead;
  const std::string stale_file = dir.write(".route.tmp" + std::to_string(dead) + "-0.geojson", "{\"type\":");
  std::filesystem::create_directories(dir.path() / (".suite.tmp" + std::to_string(dead) + "-3"));
  dir.write(".suite.tmp" + std::to_string(dead) + "-3/scenario-0001.yaml", "start:");
  const std::string live = dir.write(".other.tmp" + std::to_string(getppid()) + "-0.gpx", "<gpx");
  const std::string mine = dir.write("notes.tmp" + std::to_string(dead) + "-0.txt", "not ours: no leading dot");
  const auto r = run_cli("plan --obstacles '" + kSample + "'" + kFromTo + " -o '" + dir.file("route.geojson") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(stale_file));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / (".suite.tmp" + std::to_string(dead) + "-3")));
  EXPECT_TRUE(std::filesystem::exists(live));
  EXPECT_TRUE(std::filesystem::exists(mine));
  EXPECT_TRUE(std::filesystem::exists(dir.file("route.geojson")));
}

TEST(CliPlan, ARouteOffTheChartIsNotSafe) {
  // Outside a bathymetry raster the depth is not known (NoData inside it is no-go already).
  const std::string chart = deepguide::test::source_file("charts/sample_chart.tif");
  auto r = run_cli("plan --chart '" + chart + "' --depth 10 --from 10.0,54.0 --to 10.05,54.02");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("start lies outside the coverage of"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  // From inside the chart (the harbour) to a goal 3 km east of its edge: the route leaves it.
  r = run_cli("plan --chart '" + chart + "' --depth 10 --from 10.2446,54.4413 --to 10.32,54.45");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("leaves the coverage"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("leg"), std::string::npos) << r.err;
  // Inside, as before.
  r = run_cli("plan --chart '" + chart + "' --depth 10 --from 10.2446,54.4413 --to 10.2626,54.4606 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

TEST(CliPlan, TurnRadiusRoutesTurnNoTighterAndSayWhereTheyCannot) {
  ScratchDir dir;
  const std::string route = dir.file("wide.geojson");
  // Round c2 on a 60 m radius where the free route turns on 35 m.
  const std::string base =
      "plan --obstacles '" + kSample + "' --from 10.2405,54.4470 --to 10.2640,54.4560 --graph tangent --margin 10";
  const auto free = run_cli(base + " --json");
  ASSERT_EQ(free.exit_code, 0) << free.err;
  EXPECT_NEAR(nlohmann::json::parse(free.out).at("min_turn_radius_m").get<double>(), 35.0, 1e-6);
  const auto r = run_cli(base + " --turn-radius 60 -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("min_turn_radius_m").get<double>(), 60.0, 1e-6);
  EXPECT_EQ(j.at("turn_radius_m").get<double>(), 60.0);
  EXPECT_GT(j.at("exact_length_m").get<double>(), nlohmann::json::parse(free.out).at("exact_length_m").get<double>());
  const auto ok = run_cli("check route '" + route + "' --obstacles '" + kSample + "' --margin 10 --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out).at("safe").get<bool>());
  // The visibility graph keeps the radius too, by rounding its corners; it
  // cannot be shorter than the tangent graph's exact route within the radius
  // by more than the tolerance its polygons allow.
  std::string vis_base = base;
  vis_base.replace(vis_base.find("--graph tangent"), 15, "--graph visibility");
  const std::string vis_route = dir.file("vis60.geojson");
  const auto vis = run_cli(vis_base + " --turn-radius 60 -o '" + vis_route + "' --json");
  ASSERT_EQ(vis.exit_code, 0) << vis.err;
  const auto vj = nlohmann::json::parse(vis.out);
  EXPECT_NEAR(vj.at("min_turn_radius_m").get<double>(), 60.0, 1e-6);
  EXPECT_GE(vj.at("min_clearance_m").get<double>(), 10.0 - 1e-6);
  EXPECT_GT(vj.at("exact_length_m").get<double>(), j.at("exact_length_m").get<double>() - 0.5);
  EXPECT_EQ(run_cli("check route '" + vis_route + "' --obstacles '" + kSample + "' --margin 10").exit_code, 0);

  // A pocket left only over the end of a 10 m wall: a 5 m turn fits, 19.6 m does not.
  const std::string pocket = dir.write("pocket.geojson", R"({"type": "FeatureCollection",
    "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32632"}}, "features": [
    {"type": "Feature", "properties": {"id": "wall"}, "geometry": {"type": "Polygon", "coordinates": [[[499995, 5999800], [500005, 5999800], [500005, 6000000], [499995, 6000000], [499995, 5999800]]]}},
    {"type": "Feature", "properties": {"id": "roof"}, "geometry": {"type": "Polygon", "coordinates": [[[499890, 6000012], [500100, 6000012], [500100, 6000040], [499890, 6000040], [499890, 6000012]]]}},
    {"type": "Feature", "properties": {"id": "floor"}, "geometry": {"type": "Polygon", "coordinates": [[[499890, 5999780], [500100, 5999780], [500100, 5999800], [499890, 5999800], [499890, 5999780]]]}},
    {"type": "Feature", "properties": {"id": "back"}, "geometry": {"type": "Polygon", "coordinates": [[[499890, 5999780], [499900, 5999780], [499900, 6000040], [499890, 6000040], [499890, 5999780]]]}}]})");
  const std::string in_pocket =
      "plan --obstacles '" + pocket + "' --crs EPSG:32632 --from 499950,5999900 --to 500050,5999900 --margin 5";
  EXPECT_EQ(run_cli(in_pocket + " --graph tangent").exit_code, 0);
  const auto tight = run_cli(in_pocket + " --graph tangent --turn-radius 19.6");
  EXPECT_EQ(tight.exit_code, 3) << tight.err;
  EXPECT_EQ(std::count(tight.err.begin(), tight.err.end(), '\n'), 1) << tight.err;
  for (const char* word : {"19.6 m", "'wall'", "5.0 m radius"})
    EXPECT_NE(tight.err.find(word), std::string::npos) << tight.err;

  // A vehicle sets the radius it can follow: 1.15 x 2.06 m/s / 5 deg/s at DeepC's cruise.
  const auto deepc =
      run_cli(base + " --vehicle '" + deepguide::test::source_file("data/vehicles/deepc.yaml") + "' --json");
  ASSERT_EQ(deepc.exit_code, 0) << deepc.err;
  const auto dj = nlohmann::json::parse(deepc.out);
  EXPECT_NEAR(dj.at("turn_radius_m").get<double>(), 1.15 * 4 * 1852.0 / 3600.0 / (5.0 * M_PI / 180.0), 0.01);
  EXPECT_GE(dj.at("min_turn_radius_m").get<double>(), dj.at("turn_radius_m").get<double>() - 1e-9);

  // Bad radii and graphs that cannot keep one: one line, exit 1.
  for (const auto& [args, word] : std::vector<std::pair<std::string, std::string>>{
           {" --graph tangent --turn-radius 0", "--turn-radius"},
           {" --graph tangent --turn-radius -5", "--turn-radius"},
           {" --graph tangent --turn-radius nan", "--turn-radius"},
           {" --graph quadtree --turn-radius 20", "--graph tangent, visibility"}}) {
    const auto bad = run_cli(in_pocket + args);
    EXPECT_EQ(bad.exit_code, 1) << args << ": " << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(word), std::string::npos) << args << ": " << bad.err;
  }
}

TEST(CliPlan, HeadingsGiveDubinsEnds) {
  ScratchDir dir;
  const std::string route = dir.file("dubins.geojson");
  const std::string base = "plan --obstacles '" + kSample + "' --from 10.2405,54.4470 --to 10.2640,54.4560";
  const auto free = run_cli(base + " --graph tangent --turn-radius 25 --json");
  ASSERT_EQ(free.exit_code, 0) << free.err;
  // No --graph: the tangent graph, the one that plans Dubins ends.
  const auto r = run_cli(base + " --turn-radius 25 --from-heading 200 --to-heading 0 -o '" + route + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("from_heading_deg").get<double>(), 200.0, 1e-9);
  EXPECT_NEAR(std::remainder(j.at("to_heading_deg").get<double>(), 360.0), 0.0, 1e-9);
  EXPECT_GE(j.at("min_turn_radius_m").get<double>(), 25.0 - 1e-9);
  EXPECT_GT(j.at("exact_length_m").get<double>(), nlohmann::json::parse(free.out).at("exact_length_m").get<double>());
  EXPECT_EQ(run_cli("check route '" + route + "' --obstacles '" + kSample + "'").exit_code, 0);
  // The route file's first and last steps run along the headings (true bearings from lon/lat).
  std::ifstream in(route);
  const auto coords = nlohmann::json::parse(in)["features"][0]["geometry"]["coordinates"];
  auto bearing = [](const nlohmann::json& a, const nlohmann::json& b) {
    const double lat = a[1].get<double>() * M_PI / 180.0;
    const double dx = (b[0].get<double>() - a[0].get<double>()) * std::cos(lat);
    const double dy = b[1].get<double>() - a[1].get<double>();
    return std::fmod(std::atan2(dx, dy) * 180.0 / M_PI + 360.0, 360.0);
  };
  EXPECT_NEAR(bearing(coords[0], coords[1]), 200.0, 0.5);
  EXPECT_NEAR(std::remainder(bearing(coords[coords.size() - 2], coords[coords.size() - 1]), 360.0), 0.0, 0.5);
  // What cannot plan Dubins ends: one line, exit 1.
  for (const auto& [args, word] : std::vector<std::pair<std::string, std::string>>{
           {" --graph visibility --turn-radius 25 --from-heading 10", "--graph tangent"},
           {" --from-heading 10", "--turn-radius or --vehicle"},
           {" --turn-radius 25 --to-heading nan", "--to-heading"},
           {" --graph octree --depth 5 --turn-radius 25 --from-heading 10", "--graph tangent"}}) {
    const auto bad = run_cli(base + args);
    EXPECT_EQ(bad.exit_code, 1) << args << ": " << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(word), std::string::npos) << args << ": " << bad.err;
  }
}

TEST(CliPlan, FramesBeyondUtmAreRefused) {
  // Near the pole, and half the globe away in one UTM zone: the frame would
  // be off by far more than the margin, so neither is planned.
  const std::string base = "plan --obstacles '" + kSample + "'";
  const auto polar = run_cli(base + " --from 10.0,89.99 --to 10.1,89.98");
  EXPECT_EQ(polar.exit_code, 1) << polar.err;
  EXPECT_EQ(std::count(polar.err.begin(), polar.err.end(), '\n'), 1) << polar.err;
  for (const char* w : {"--from", "89.99", "84 N", "+proj=stere +lat_0=89.99 +lon_0=10.00"})
    EXPECT_NE(polar.err.find(w), std::string::npos) << polar.err;
  const auto far = run_cli(base + " --from 10.2405,54.4470 --to 100,10");
  EXPECT_EQ(far.exit_code, 1) << far.err;
  EXPECT_EQ(std::count(far.err.begin(), far.err.end(), '\n'), 1) << far.err;
  for (const char* w : {"--to", "91.00 degrees", "EPSG:32632", "6 degrees", "--crs"}) {
    EXPECT_NE(far.err.find(w), std::string::npos) << far.err;
  }
  // Within a zone's width of the sample's zone (central meridian 9 E): planned.
  const auto near = run_cli(base + " --from 10.2405,54.4470 --to 14.5,54.6");
  EXPECT_EQ(near.exit_code, 0) << near.err;
  const auto beyond = run_cli(base + " --from 10.2405,54.4470 --to 15.5,54.6");
  EXPECT_EQ(beyond.exit_code, 1) << beyond.err;
  EXPECT_NE(beyond.err.find("6.50 degrees"), std::string::npos) << beyond.err;
}

TEST(CliPlan, HostileObstacleIdsArePrintedEscapedOnOneLine) {
  ScratchDir dir;
  const std::string evil =
      dir.write("evil.geojson",
                "{\"type\":\"FeatureCollection\",\"features\":[{\"type\":\"Feature\",\"properties\":{\"id\":"
                "\"evil\\n\\u001b[31mred\\u202e\",\"semi_major_m\":5},\"geometry\":{\"type\":\"Point\",\"coordinates\":"
                "[10.25,54.45]}}]}");
  const auto r = run_cli("plan --obstacles '" + evil + "' --from 10.2499,54.45 --to 10.26,54.45");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("\u202e"), std::string::npos) << r.err;
  for (const char* w : {"evil\\x0a\\x1b[31mred\\u202e", "safety zone"})
    EXPECT_NE(r.err.find(w), std::string::npos) << r.err;
}
