// The web map's page (render/web_map.hpp) without a browser: what it holds,
// that hostile text cannot leave its JSON, that it needs nothing from the
// network, and that a page that cannot be written is one line and no file.
// tests/browser/web_map_plan.sh opens pages in Chromium.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/render/web_map.hpp"
#include "test_support.hpp"

namespace {

using deepguide::InputError;
using deepguide::WebMap;
using deepguide::WebMapLayer;
using deepguide::test::ScratchDir;
using json = nlohmann::ordered_json;

bool leaflet_installed() { return std::filesystem::exists(deepguide::leaflet_dir() + "/leaflet.min.js"); }

WebMap two_layers() {
  WebMap map;
  map.title = "Two <layers> & a table";
  WebMapLayer area;
  area.id = "no_go";
  area.name = "No-go";
  area.explained = true;
  area.features.push_back(deepguide::web_map_feature(
      {{"type", "Polygon"}, {"coordinates", {{{10.0, 54.0}, {10.1, 54.0}, {10.1, 54.1}, {10.0, 54.0}}}}},
      {{"record", "DEPARE/1"}, {"why", "</script><script>alert(1)</script>"}}));
  WebMapLayer points;
  points.id = "waypoints";
  points.name = "Waypoints";
  for (int i = 0; i < 3; ++i) {
    points.features.push_back(deepguide::web_map_feature(
        {{"type", "Point"}, {"coordinates", deepguide::web_map_position(10.0 + i * 0.01, 54.05)}}, {{"waypoint", i}}));
  }
  map.layers = {area, points};
  map.table.columns = {"#", "lon", "lat"};
  map.table.rows = {{1, 10.0, 54.05}};
  return map;
}

// The page's data, as the page's script reads it.
json page_data(const std::string& page) {
  const std::string open = "<script id=\"dg-data\" type=\"application/json\">";
  const std::size_t from = page.find(open) + open.size();
  std::string text = page.substr(from, page.find("</script>", from) - from);
  for (std::size_t at = text.find("<\\/"); at != std::string::npos; at = text.find("<\\/", at)) text.erase(at + 1, 1);
  return json::parse(text);
}

TEST(WebMap, ThePageHoldsItsLayersAndNothingLeavesTheirJson) {
  if (!leaflet_installed()) GTEST_SKIP() << "Leaflet is absent (apt-get install libjs-leaflet)";
  const std::string page = deepguide::web_map_html(two_layers());
  // A property's "</script>" would end the data element: written "<\/script>".
  EXPECT_EQ(page.find("</script><script>alert"), std::string::npos);
  const json data = page_data(page);
  ASSERT_EQ(data.at("layers").size(), 2u);
  EXPECT_EQ(data.at("layers")[0].at("features")[0].at("properties").at("why"), "</script><script>alert(1)</script>");
  EXPECT_EQ(data.at("layers")[1].at("features").size(), 3u);
  EXPECT_TRUE(data.at("layers")[0].at("explained").get<bool>());
  EXPECT_EQ(data.at("table").at("rows")[0][1], 10.0);
  // The title is text, not markup.
  EXPECT_NE(page.find("<title>Two &lt;layers&gt; &amp; a table</title>"), std::string::npos);
  // Offline: Leaflet inlined; no element that fetches (a script's src, a
  // stylesheet link, an image) and no stylesheet url() but url(#...).
  // (Leaflet's attribution text holds a link; the page leaves that control off.)
  EXPECT_NE(page.find("L.map("), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find("<img"), std::string::npos);
  EXPECT_FALSE(std::regex_search(page, std::regex(R"(url\((?!#))")));
}

TEST(WebMap, PositionsAreWrittenToATenMillionthOfADegree) {
  const json p = deepguide::web_map_position(-76.418543149999, 38.754951849999);
  EXPECT_DOUBLE_EQ(p[0].get<double>(), -76.4185431);
  EXPECT_DOUBLE_EQ(p[1].get<double>(), 38.7549518);
}

TEST(WebMap, APageThatCannotBeWrittenIsOneLineAndNoFile) {
  ScratchDir dir;
  const std::string missing = dir.file("no/such/folder/map.html");
  try {
    deepguide::write_web_map(two_layers(), missing);
    if (leaflet_installed()) FAIL() << "wrote into a missing folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("map.html"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("no")));
  EXPECT_THROW(deepguide::write_web_map(two_layers(), dir.file("map.png")), InputError);
  EXPECT_THROW(deepguide::check_web_map_path("map.htmlx", "--html"), InputError);
  EXPECT_NO_THROW(deepguide::check_web_map_path("MAP.htm", "--html"));
  // Leaflet missing: the file and the package named, nothing written.
  setenv("DEEPGUIDE_LEAFLET_DIR", dir.path().c_str(), 1);
  try {
    deepguide::write_web_map(two_layers(), dir.file("map.html"));
    ADD_FAILURE() << "wrote a page without Leaflet";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("leaflet.min.js"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("libjs-leaflet"), std::string::npos) << e.what();
  }
  unsetenv("DEEPGUIDE_LEAFLET_DIR");
  EXPECT_FALSE(std::filesystem::exists(dir.file("map.html")));
}

}  // namespace

namespace {

// The frame's grid: round spacing, a line at every multiple in the box,
// each straight in the frame (its positions, read back, at the same easting
// or northing to the page's 1e-7 degrees, about a centimetre).
TEST(WebMap, TheFramesGridIsRoundAndStraightInTheFrame) {
  const deepguide::LocalFrame frame = deepguide::LocalFrame::from_user_crs("EPSG:32632");
  const WebMapLayer grid = deepguide::frame_grid_layer(frame, {500000.0, 6000000.0}, {510000.0, 6004000.0});
  EXPECT_EQ(grid.id, "grid");
  EXPECT_FALSE(grid.shown);
  EXPECT_NE(grid.name.find("every 1000 m"), std::string::npos) << grid.name;
  std::size_t eastings = 0, northings = 0;
  for (const auto& f : grid.features) {
    const auto& props = f.at("properties");
    const bool east = props.contains("easting (m)");
    const double value = props.at(east ? "easting (m)" : "northing (m)").get<double>();
    EXPECT_DOUBLE_EQ(std::fmod(value, 1000.0), 0.0);
    (east ? eastings : northings) += 1;
    for (const auto& p : f.at("geometry").at("coordinates")) {
      const deepguide::Vec2 xy = frame.from_lonlat(p[0].get<double>(), p[1].get<double>());
      EXPECT_NEAR(east ? xy.x() : xy.y(), value, 0.02);
    }
  }
  EXPECT_EQ(eastings, 11u);
  EXPECT_EQ(northings, 5u);
  // A box of no size: no lines, no failure.
  EXPECT_TRUE(deepguide::frame_grid_layer(frame, {0.0, 0.0}, {0.0, 0.0}).features.empty());
}

}  // namespace
