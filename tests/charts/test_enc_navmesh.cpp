// The navigation mesh on real charts: random pairs of free points on
// US4MD81M, US5FL4DQ and the Kachemak exchange set, each routed by the
// navmesh and by the reduced visibility graph over the same no-go. The
// lengths agree to 1e-9 relative (the reduced graph's routes are the full
// graph's, tests/planning/test_visibility_planner.cpp; the full graph does
// not build at chart scale), both find a route or neither does, and every
// navmesh route passes the independent checker. DEEPGUIDE_NAVMESH_PAIRS sets
// the pairs per chart (default 20; scripts/navmesh_charts.sh runs 200);
// DEEPGUIDE_ENC_SEED shifts the seeds.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_plan_report.hpp"
#include "deepguide/planning/single_query.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

int pairs_per_chart() {
  const char* env = std::getenv("DEEPGUIDE_NAVMESH_PAIRS");
  return env != nullptr ? std::max(1, std::atoi(env)) : 20;
}

unsigned shifted(unsigned seed) {
  const char* shift = std::getenv("DEEPGUIDE_ENC_SEED");
  return seed + (shift != nullptr ? static_cast<unsigned>(std::atoi(shift)) : 0u);
}

// One query each, as `plan` runs them (plan_single_query), over the cell's
// no-go at `depth` with a 5 m margin; pairs at least `min_km` apart.
void compare_on_chart(const std::string& rel, double depth, double min_km, unsigned seed) {
#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "chart-scale planning runs in the Release build";
#endif
  const std::string path = test::real_file(rel).empty() ? test::real_folder(rel) : test::real_file(rel);
  if (path.empty()) GTEST_SKIP() << "../shared/data/real/" << rel << " is absent: skipping the test on real data";
  EncNoGoOptions options;
  options.operating_depth_m = depth;
  options.vertical_clearance_m = 2.0;
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, options);
  PlannerOptions visibility;
  visibility.margin = 5.0;
  PlannerOptions navmesh = visibility;
  navmesh.graph = GraphKind{"navmesh"};
  const ObstacleField field(no_go.obstacles, visibility.margin);
  const auto [lo, hi] = footprint_box(no_go.obstacles);
  std::mt19937 rng(shifted(seed));
  std::uniform_real_distribution<double> x(lo.x(), hi.x()), y(lo.y(), hi.y());
  auto free_point = [&] {
    for (;;) {
      const Vec2 p(x(rng), y(rng));
      if (field.is_free(p)) return p;
    }
  };
  int routes = 0, none = 0;
  double longest_km = 0.0;
  for (int n = 0; n < pairs_per_chart(); ++n) {
    const Vec2 s = free_point();
    Vec2 g = free_point();
    for (int tries = 0; tries < 100 && (g - s).norm() < 1e3 * min_km; ++tries) g = free_point();
    SCOPED_TRACE(::testing::Message() << rel << " depth " << depth << " pair " << n << " from (" << s.x() << ", "
                                      << s.y() << ") to (" << g.x() << ", " << g.y() << ")");
    const SingleQueryPlan v = plan_single_query(no_go.obstacles, {s, g}, visibility);
    const SingleQueryPlan m = plan_single_query(no_go.obstacles, {s, g}, navmesh);
    ASSERT_EQ(m.outcome.result.found, v.outcome.result.found) << m.outcome.result.message;
    if (!v.outcome.result.found) {
      ++none;
      continue;
    }
    ++routes;
    ASSERT_TRUE(m.outcome.check.safe) << m.outcome.check.describe();
    const double lv = v.outcome.result.route.length(), lm = m.outcome.result.route.length();
    ASSERT_NEAR(lm, lv, 1e-9 * lv);
    longest_km = std::max(longest_km, lv / 1e3);
  }
  std::printf("%s at %g m: %d routes of the visibility graph's length (the longest %.1f km), %d pairs without one\n",
              rel.c_str(), depth, routes, longest_km, none);
}

TEST(EncNavMesh, ChesapeakeRoutesEqualTheVisibilityGraphs) {
  compare_on_chart("noaa-enc-US4MD81M/US4MD81M.000", 5.0, 5.0, 41);
}
TEST(EncNavMesh, KeyWestRoutesEqualTheVisibilityGraphs) {
  compare_on_chart("noaa-enc-US5FL4DQ/US5FL4DQ.000", 1.0, 2.0, 42);
}
TEST(EncNavMesh, KachemakRoutesEqualTheVisibilityGraphs) { compare_on_chart("noaa-enc-kachemak", 5.0, 20.0, 43); }

// `chart prepare` keeps the navmesh in the GeoPackage and `plan` loads it:
// the same route as from the cell, "(prepared)" said, and the mesh rebuilt
// (not taken) for another margin. A table someone damaged is a one-line
// error naming the file; `--graphs none` keeps none; a graph that cannot be
// kept is refused before any cell is read.
TEST(PreparedNavMesh, PlanLoadsTheKeptMeshAndPlansTheSameRoute) {
#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "chart-scale planning runs in the Release build (the kept bytes' checks run sanitized in "
                  "test_navmesh_file and fuzz.nav_mesh)";
#endif
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, "noaa-enc-US4MD81M/US4MD81M.000");
  test::ScratchDir tmp;
  const std::string gpkg = tmp.file("bay.gpkg");
  const test::RunResult prepared = test::run_cli("chart prepare '" + cell + "' --depth 5 -o '" + gpkg + "'");
  ASSERT_EQ(prepared.exit_code, 0) << prepared.err;
  EXPECT_NE(prepared.out.find("graph            navmesh: margin 5 m, "), std::string::npos) << prepared.out;
  // `chart info` describes it (it once read every layer as hazards and
  // stopped at the first disc of no_go_features).
  const test::RunResult info = test::run_cli("chart info '" + gpkg + "' --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto described = nlohmann::json::parse(info.out);
  EXPECT_EQ(described[0]["hazards"].get<std::size_t>(),
            read_prepared_chart(gpkg, std::nullopt, 5.0, 2.0).obstacles.size());
  EXPECT_NE(info.out.find("deepguide_graphs"), std::string::npos) << info.out;
  const std::string trip = " --depth 5 --from -76.41,38.87 --to -76.35,38.60 --graph navmesh --json -o ";
  const test::RunResult from_cell =
      test::run_cli("plan --chart '" + cell + "'" + trip + "'" + tmp.file("a.geojson") + "'");
  const test::RunResult from_gpkg =
      test::run_cli("plan --chart '" + gpkg + "'" + trip + "'" + tmp.file("b.geojson") + "'");
  ASSERT_EQ(from_cell.exit_code, 0) << from_cell.err;
  ASSERT_EQ(from_gpkg.exit_code, 0) << from_gpkg.err;
  const auto a = nlohmann::json::parse(from_cell.out), b = nlohmann::json::parse(from_gpkg.out);
  EXPECT_FALSE(a["graph_prepared"].get<bool>());
  EXPECT_TRUE(b["graph_prepared"].get<bool>());
  // The GeoPackage keeps lon/lat: the obstacles come back within a micrometre, not bit for bit.
  EXPECT_NEAR(b["length_m"].get<double>(), a["length_m"].get<double>(), 1e-3);
  EXPECT_GT(b["length_m"].get<double>(), 1.01 * 30000.0);
  const test::RunResult text =
      test::run_cli("plan --chart '" + gpkg + "' --depth 5 --from -76.41,38.87 --to -76.35,38.60 --graph navmesh -o '" +
                    tmp.file("c.geojson") + "'");
  EXPECT_NE(text.out.find("graph            navmesh (prepared) over "), std::string::npos) << text.out;
  const test::RunResult wider =
      test::run_cli("plan --chart '" + gpkg + "'" + trip + "'" + tmp.file("d.geojson") + "' --margin 6");
  ASSERT_EQ(wider.exit_code, 0) << wider.err;
  EXPECT_FALSE(nlohmann::json::parse(wider.out)["graph_prepared"].get<bool>());

  // A rock from an obstacle file (a store's, say) on the route: the kept
  // mesh is loaded and the rock cut into it, not the whole chart triangulated
  // again; the route is as long as one planned from the cell with the rock.
  {
    const auto route = nlohmann::json::parse(std::ifstream(tmp.file("b.geojson")));
    const auto& line = route["features"][0]["geometry"]["coordinates"];
    ASSERT_GE(line.size(), 2u);
    std::size_t longest = 1;
    double most = 0.0;
    for (std::size_t i = 1; i < line.size(); ++i) {
      const double d = std::hypot(line[i][0].get<double>() - line[i - 1][0].get<double>(),
                                  line[i][1].get<double>() - line[i - 1][1].get<double>());
      if (d > most) most = d, longest = i;
    }
    const double lon = 0.5 * (line[longest][0].get<double>() + line[longest - 1][0].get<double>());
    const double lat = 0.5 * (line[longest][1].get<double>() + line[longest - 1][1].get<double>());
    const std::string rock = tmp.write(
        "rock.geojson",
        "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", \"properties\": {\"id\": \"rock\", "
        "\"semi_major_m\": 30, \"semi_minor_m\": 30, \"orientation_deg\": 0}, \"geometry\": {\"type\": \"Point\", "
        "\"coordinates\": [" +
            printf_text("%.9f, %.9f", lon, lat) + "]}}]}");
    const test::RunResult kept = test::run_cli("plan --chart '" + gpkg + "' --obstacles '" + rock + "'" + trip + "'" +
                                               tmp.file("f.geojson") + "'");
    const test::RunResult built = test::run_cli("plan --chart '" + cell + "' --obstacles '" + rock + "'" + trip + "'" +
                                                tmp.file("g.geojson") + "'");
    ASSERT_EQ(kept.exit_code, 0) << kept.err;
    ASSERT_EQ(built.exit_code, 0) << built.err;
    const auto k = nlohmann::json::parse(kept.out), c = nlohmann::json::parse(built.out);
    EXPECT_TRUE(k["graph_prepared"].get<bool>());
    EXPECT_FALSE(c["graph_prepared"].get<bool>());
    EXPECT_NEAR(k["length_m"].get<double>(), c["length_m"].get<double>(), 1e-3);
    // The rock lay on the route; the new one keeps its zone (30 + 5 m) clear.
    // (Lengths alone say little: round a disc at a long leg's middle adds
    // a fraction of a metre.) Metres from degrees near the rock suffice here.
    const auto nearest = [&](const std::string& file) {
      const auto doc = nlohmann::json::parse(std::ifstream(file));
      const auto& pts = doc["features"][0]["geometry"]["coordinates"];
      const double kx = 6371000.0 * std::numbers::pi / 180.0 * std::cos(lat * std::numbers::pi / 180.0);
      const double ky = 6371000.0 * std::numbers::pi / 180.0;
      double best = 1e300;
      for (std::size_t i = 1; i < pts.size(); ++i) {
        const Vec2 p((pts[i - 1][0].get<double>() - lon) * kx, (pts[i - 1][1].get<double>() - lat) * ky);
        const Vec2 q((pts[i][0].get<double>() - lon) * kx, (pts[i][1].get<double>() - lat) * ky);
        best = std::min(best, point_segment_distance(Vec2::Zero(), p, q));
      }
      return best;
    };
    EXPECT_LT(nearest(tmp.file("b.geojson")), 1.0);
    EXPECT_GT(nearest(tmp.file("f.geojson")), 35.0 - 0.5);
    EXPECT_GE(k["min_clearance_m"].get<double>(), 5.0 - 1e-6) << kept.out;
  }

  // Damage the kept bytes (GDAL, as any GeoPackage tool could).
  {
    GDALAllRegister();
    GDALDatasetUniquePtr ds(GDALDataset::Open(gpkg.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    ASSERT_TRUE(ds);
    OGRLayer* graphs = ds->GetLayerByName("deepguide_graphs");
    ASSERT_NE(graphs, nullptr);
    std::unique_ptr<OGRFeature> row(graphs->GetNextFeature());
    ASSERT_TRUE(row);
    const GByte junk[12] = {'D', 'G', 'N', 'A', 'V', 'M', 'S', 'H', 1, 0, 0, 0};
    row->SetField(row->GetFieldIndex("data"), 12, junk);
    ASSERT_EQ(graphs->SetFeature(row.get()), OGRERR_NONE);
  }
  const test::RunResult damaged =
      test::run_cli("plan --chart '" + gpkg + "'" + trip + "'" + tmp.file("e.geojson") + "'");
  EXPECT_NE(damaged.exit_code, 0);
  EXPECT_NE(damaged.err.find("bay.gpkg: table deepguide_graphs, graph 'navmesh': navigation mesh, byte 12: expected "
                             "the origin, got the end of the data"),
            std::string::npos)
      << damaged.err;
  EXPECT_EQ(std::count(damaged.err.begin(), damaged.err.end(), '\n'), 1) << damaged.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("e.geojson")));

  const std::string bare = tmp.file("bare.gpkg");
  ASSERT_EQ(test::run_cli("chart prepare '" + cell + "' --depth 5 --graphs none -o '" + bare + "'").exit_code, 0);
  EXPECT_TRUE(read_prepared_graphs(bare).empty());
  const test::RunResult refused =
      test::run_cli("chart prepare '" + cell + "' --depth 5 --graphs quadtree -o '" + tmp.file("q.gpkg") + "'");
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_NE(refused.err.find("--graphs quadtree: expected navmesh"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("q.gpkg")));
  // Its zone tolerance is named by its own flag, not chart prepare's --tolerance (the no-go's).
  const test::RunResult flat =
      test::run_cli("chart prepare '" + cell + "' --depth 5 --zone-tolerance 0 -o '" + tmp.file("z.gpkg") + "'");
  EXPECT_NE(flat.exit_code, 0);
  EXPECT_NE(flat.err.find("--zone-tolerance: expected a zone polygon tolerance > 0 m, got 0"), std::string::npos)
      << flat.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("z.gpkg")));
}

// What `plan` takes without --graph: the navmesh for routes by length on
// S-57 charts, else the visibility graph, the tangent graph with a heading.
TEST(DefaultPlanGraph, TheNavmeshForRoutesByLengthOnS57Charts) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, "noaa-enc-US4MD81M/US4MD81M.000");
  const std::string raster = test::source_file("charts/sample_chart.tif");
  const std::string hazards = test::source_file("charts/sample_chart_hazards.gpkg");
  const GraphKind navmesh{"navmesh"};
  EXPECT_EQ(default_plan_graph({cell}, CostKind::length, false, false), navmesh);
  EXPECT_EQ(default_plan_graph({hazards, cell}, CostKind::length, false, false), navmesh);
  EXPECT_EQ(default_plan_graph({cell}, CostKind::time, false, false), GraphKind::visibility);
  EXPECT_EQ(default_plan_graph({cell}, CostKind::energy, false, false), GraphKind::visibility);
  EXPECT_EQ(default_plan_graph({cell}, CostKind::length, true, false), GraphKind::visibility);
  EXPECT_EQ(default_plan_graph({cell}, CostKind::length, false, true), GraphKind::tangent);
  EXPECT_EQ(default_plan_graph({raster, hazards}, CostKind::length, false, false), GraphKind::visibility);
  EXPECT_EQ(default_plan_graph({}, CostKind::length, false, false), GraphKind::visibility);
  // The CLI says which it took.
#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "chart-scale planning runs in the Release build";
#endif
  test::ScratchDir tmp;
  const test::RunResult planned =
      test::run_cli("plan --chart '" + cell + "' --depth 5 --from -76.41,38.87 --to -76.35,38.60 --json -o '" +
                    tmp.file("r.geojson") + "'");
  ASSERT_EQ(planned.exit_code, 0) << planned.err;
  EXPECT_EQ(nlohmann::json::parse(planned.out)["graph"], "navmesh");
}

}  // namespace
}  // namespace deepguide
