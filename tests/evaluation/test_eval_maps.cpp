// evaluate --html (evaluation/eval_maps.hpp): the scenarios the report points
// at as web maps. Each method's closest approach is among them, the page
// holds every method's track, and the track drawn is the run the row
// measured: its least distance to the obstacles, worked out here from the
// page's own positions, is the row's min_clearance_m (to the rows' 1e-3 m).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "../test_support.hpp"
#include "deepguide/evaluation/eval_maps.hpp"
#include "deepguide/evaluation/evaluate.hpp"
#include "deepguide/evaluation/monte_carlo.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/render/web_map.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The page's layers, lines decoded from their steps of 1e-7 as the page does.
nlohmann::json page_layers(const std::string& page) {
  const std::string open = "<script id=\"dg-data\" type=\"application/json\">";
  const std::size_t from = page.find(open) + open.size();
  std::string text = page.substr(from, page.find("</script>", from) - from);
  for (std::size_t at = text.find("<\\/"); at != std::string::npos; at = text.find("<\\/", at)) text.erase(at + 1, 1);
  nlohmann::json data = nlohmann::json::parse(text);
  for (auto& layer : data.at("layers")) {
    for (auto& f : layer.at("features")) {
      auto& g = f.at("geometry");
      if (g.value("type", "") != "LineString" || !g.contains("q")) continue;
      nlohmann::json positions = nlohmann::json::array();
      long long x = 0, y = 0;
      for (std::size_t i = 0; i + 1 < g.at("q").size(); i += 2) {
        x += g.at("q")[i].get<long long>(), y += g.at("q")[i + 1].get<long long>();
        positions.push_back({x / 1e7, y / 1e7});
      }
      g["coordinates"] = positions;
    }
  }
  return data;
}

TEST(EvaluationMaps, TheClosestApproachesAreDrawnAsTheRowsMeasuredThem) {
  if (!std::filesystem::exists(leaflet_dir() + "/leaflet.min.js")) GTEST_SKIP() << "Leaflet is absent";
  ScratchDir tmp;
  MonteCarloParams p;
  p.scenarios = 6;
  p.seed = 33;
  p.max_obstacles = 4;
  write_suite(tmp.file("suite"), "maps", p, true, true);
  const Suite suite = read_suite(tmp.file("suite"));
  EvaluateOptions o;
  o.methods = {parse_eval_method("geometric"), parse_eval_method("dipole"), parse_eval_method("visibility")};
  o.threads = 2;
  o.timing = false;
  o.maps = true;
  const EvaluationRun run = evaluate_suite(suite, tmp.file("out"), o);
  const std::string report = slurp(tmp.file("out/report.html"));
  ASSERT_NE(report.find("Scenarios as maps"), std::string::npos);
  for (const std::string& method : run.manifest.methods) {
    // The method's closest approach, and its page.
    const EvalRow* closest = nullptr;
    for (const EvalRow& r : run.rows) {
      if (r.method == method && std::isfinite(r.run.min_clearance_m) && r.run.end != "no_route" &&
          (closest == nullptr || r.run.min_clearance_m < closest->run.min_clearance_m)) {
        closest = &r;
      }
    }
    ASSERT_NE(closest, nullptr) << method;
    const std::string file = "maps/" + closest->scenario + ".html";
    EXPECT_NE(report.find("href=\"" + file + "\""), std::string::npos) << file;
    const nlohmann::json data = page_layers(slurp(tmp.file("out/" + file)));
    EXPECT_TRUE(data.at("planar").get<bool>()) << "a generated scenario has no CRS";
    const Scenario sc = load_suite_scenario(suite, closest->scenario_index);
    // Every method's track is on the page; this one's least distance to the obstacles is its row's.
    for (const std::string& m : run.manifest.methods) {
      const auto layer = std::find_if(data.at("layers").begin(), data.at("layers").end(),
                                      [&](const nlohmann::json& l) { return l.at("id") == "track:" + m; });
      ASSERT_NE(layer, data.at("layers").end()) << m << " in " << file;
      if (m != method) continue;
      double least = std::numeric_limits<double>::infinity();
      for (const auto& pos : (*layer).at("features").at(0).at("geometry").at("coordinates")) {
        const Vec2 xy(pos[0].get<double>(), pos[1].get<double>());
        for (const EllipticCylinder& ob : sc.obstacles) least = std::min(least, signed_distance(ob.footprint, xy));
      }
      // The page's positions are the track's to 1e-7 m; rows.csv keeps the clearance to 1e-3 m.
      EXPECT_NEAR(least, closest->run.min_clearance_m, 5e-4 + 1e-6) << method << " in " << closest->scenario;
    }
    const auto obstacles = std::find_if(data.at("layers").begin(), data.at("layers").end(),
                                        [](const nlohmann::json& l) { return l.at("id") == "obstacles"; });
    EXPECT_EQ((*obstacles).at("features").size(), sc.obstacles.size());
  }
  // A run without --html leaves no maps behind.
  o.maps = false;
  o.fresh = true;
  evaluate_suite(suite, tmp.file("out"), o);
  EXPECT_FALSE(std::filesystem::exists(tmp.file("out/maps")));
  EXPECT_EQ(slurp(tmp.file("out/report.html")).find("Scenarios as maps"), std::string::npos);
}

}  // namespace
