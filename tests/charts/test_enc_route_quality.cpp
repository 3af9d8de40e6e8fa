// Route quality on ENCs (charts/enc_route_quality.hpp): the cells a route
// crosses, the least charted depth under it, its length per zone of
// confidence and the nearest no-go feature. Hand-derived on two cells written
// through GDAL's S57 writer (synthetic_cell.hpp), a band-5 harbour cell
// inside a band-4 approach cell; and on the real Kachemak set against the
// test's own OGR reading (larger compilation scale wins where coverages
// overlap), sharing nothing with the library's no-go builder.

#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/enc_route_quality.hpp"
#include "deepguide/mission/mission_report.hpp"
#include "synthetic_cell.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

using test::run_cli;
using test::ScratchDir;

const auto ll = test::synthetic_lonlat;
const auto box = test::synthetic_box;

// An approach cell (band 4, 1:50,000, 6 km x 3 km, 30 m deep but its middle
// third 10 m, CATZOC C) and a harbour cell (band 5, 1:12,000, that middle
// third, 20 m deep, CATZOC B): where both cover, the harbour cell decides.
std::vector<std::string> two_bands(const ScratchDir& tmp) {
  test::SyntheticCell approach;
  approach.name = "US4TEST1";
  approach.usage_band = 4;
  approach.compilation_scale = 50000;
  approach.areas = {{"M_COVR", box(0, 0, 6000, 3000), {}, {{"CATCOV", 1}}},
                    {"DEPARE", box(0, 0, 2000, 3000), {{"DRVAL1", 30.0}, {"DRVAL2", 50.0}}, {}},
                    {"DEPARE", box(2000, 0, 4000, 3000), {{"DRVAL1", 10.0}, {"DRVAL2", 30.0}}, {}},
                    {"DEPARE", box(4000, 0, 6000, 3000), {{"DRVAL1", 30.0}, {"DRVAL2", 50.0}}, {}},
                    {"M_QUAL", box(0, 0, 6000, 3000), {}, {{"CATZOC", 4}}}};
  test::SyntheticCell harbour;
  harbour.name = "US5TEST2";
  harbour.areas = {{"M_COVR", box(2000, 0, 4000, 3000), {}, {{"CATCOV", 1}}},
                   {"DEPARE", box(2000, 0, 4000, 3000), {{"DRVAL1", 20.0}, {"DRVAL2", 30.0}}, {}},
                   {"M_QUAL", box(2000, 0, 4000, 3000), {}, {{"CATZOC", 3}}}};
  const std::string a = tmp.file("US4TEST1.000"), b = tmp.file("US5TEST2.000");
  test::write_synthetic_cell(a, approach);
  test::write_synthetic_cell(b, harbour);
  return {a, b};
}

TEST(EncRouteQuality, TwoBandsByHand) {
  ScratchDir tmp;
  EncNoGoOptions o;
  o.operating_depth_m = 5.0;
  const EncNoGo no_go = enc_no_go(two_bands(tmp), std::nullopt, o);
  auto at = [&](double x, double y) { return no_go.frame.from_lonlat(ll(x, y)[0], ll(x, y)[1]); };
  const std::vector<Vec2> route = {at(500, 1500), at(5500, 1500)};
  const double scale = (route[1] - route[0]).norm() / 5000.0;  // the UTM frame against the flat-earth metres
  ASSERT_NEAR(scale, 1.0, 2e-3);
  const RouteQuality q = route_quality(route, no_go);
  EXPECT_NEAR(q.length_m, 5000.0 * scale, 1e-6);
  ASSERT_EQ(q.cells.size(), 2u);
  EXPECT_EQ(q.cells[0].cell, "US4TEST1");  // entered first, at the start
  EXPECT_EQ(q.cells[0].usage_band, 4);
  EXPECT_EQ(q.cells[0].compilation_scale, 50000);
  EXPECT_NEAR(q.cells[0].length_m, 3000.0 * scale, 0.5);  // 1.5 km either side of the harbour cell
  EXPECT_EQ(q.cells[1].cell, "US5TEST2");
  EXPECT_EQ(q.cells[1].usage_band, 5);
  EXPECT_NEAR(q.cells[1].length_m, 2000.0 * scale, 0.5);
  ASSERT_TRUE(q.least_depth.has_value());
  EXPECT_DOUBLE_EQ(q.least_depth->depth_m, 20.0);  // the harbour cell's: the approach cell's 10 m lies under it
  EXPECT_EQ(q.least_depth->cell, "US5TEST2");
  EXPECT_EQ(q.least_depth->zoc, "B");
  EXPECT_NEAR(q.least_depth->along_m, 1500.0 * scale, 0.5);
  ASSERT_EQ(q.length_by_zoc.size(), 2u);
  EXPECT_NEAR(q.length_by_zoc.at("C"), 3000.0 * scale, 0.5);
  EXPECT_NEAR(q.length_by_zoc.at("B"), 2000.0 * scale, 0.5);
  // Nothing is no-go inside: the nearest is the edge of the charts, 500 m off either end.
  ASSERT_TRUE(q.nearest_no_go.has_value());
  EXPECT_EQ(q.nearest_no_go->feature_id, "M_COVR/outside");
  EXPECT_NEAR(q.nearest_no_go->distance_m, 500.0 * scale, 0.5);
  // A route that leaves the charts: its uncharted part is counted, and the parts still add up.
  const RouteQuality out = route_quality({at(500, 1500), at(6500, 1500)}, no_go);
  EXPECT_NEAR(out.length_by_zoc.at("uncharted"), 500.0 * scale, 0.5);
  double sum = 0.0;
  for (const auto& [zoc, len] : out.length_by_zoc) sum += len;
  EXPECT_NEAR(sum, out.length_m, 1e-6);
  EXPECT_DOUBLE_EQ(out.nearest_no_go->distance_m, 0.0);
}

TEST(EncRouteQuality, PlanAndCheckRouteReportIt) {
  ScratchDir tmp;
  const std::vector<std::string> cells = two_bands(tmp);
  const std::string charts = " --chart '" + cells[0] + "' '" + cells[1] + "' --depth 5";
  char ends[128];
  std::snprintf(ends, sizeof ends, " --from %.7f,%.7f --to %.7f,%.7f", ll(500, 1500)[0], ll(500, 1500)[1],
                ll(5500, 1500)[0], ll(5500, 1500)[1]);
  const std::string route = tmp.file("r.geojson");
  const test::RunResult plan = run_cli("plan" + charts + ends + " -o '" + route + "' --json");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const nlohmann::json q = nlohmann::json::parse(plan.out).at("chart_quality");
  ASSERT_EQ(q.at("cells").size(), 2u) << q.dump();
  EXPECT_EQ(q.at("cells").at(1).at("cell"), "US5TEST2");
  EXPECT_EQ(q.at("least_depth").at("depth_m"), 20.0);
  const test::RunResult text = run_cli("plan" + charts + ends + " -o '" + tmp.file("r2.geojson") + "'");
  EXPECT_NE(text.out.find("cells            US4TEST1 (band 4, "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("least depth      20 m charted (DRVAL1 of US5TEST2:DEPARE/"), std::string::npos) << text.out;
  const test::RunResult check = run_cli("check route '" + route + "'" + charts + " --json");
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(nlohmann::json::parse(check.out).at("chart_quality"), q);
  const test::RunResult check_text = run_cli("check route '" + route + "'" + charts);
  EXPECT_NE(check_text.out.find("\nzones            B 2.00 km, C 3.00 km"), std::string::npos) << check_text.out;
  // From a prepared chart, the same.
  const std::string gpkg = tmp.file("two.gpkg");
  ASSERT_EQ(run_cli("chart prepare '" + cells[0] + "' '" + cells[1] + "' --depth 5 -o '" + gpkg + "'").exit_code, 0);
  const test::RunResult warm = run_cli("check route '" + route + "' --chart '" + gpkg + "' --depth 5 --json");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  const nlohmann::json wq = nlohmann::json::parse(warm.out).at("chart_quality");
  EXPECT_EQ(wq.at("cells").size(), 2u);
  EXPECT_NEAR(wq.at("length_by_zoc_m").at("B").get<double>(), q.at("length_by_zoc_m").at("B").get<double>(), 1e-3);
  EXPECT_EQ(wq.at("least_depth").at("feature"), q.at("least_depth").at("feature"));
}

// A mission over the two cells, out at 5 m and back at 17 m: each phase is
// judged at its own required depth (D = depth + 2 m). Out (D 7 m) nothing is
// no-go inside, the nearest is the charts' edge 500 m off; back (D 19 m) the
// harbour cell's 20 m in CATZOC B (least 20 - 1 - 0.4 = 18.6 m) is no-go
// under the whole middle third.
TEST(EncRouteQuality, MissionPhasesEachAtTheirDepth) {
  ScratchDir tmp;
  const std::vector<std::string> cells = two_bands(tmp);
  const std::string yaml = tmp.file("out_and_back.yaml");
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: out and back\nenvironment:\n  charts: ['%s', '%s']\nsafety:\n  margin_m: 5\n"
                "  vertical_clearance_m: 2\nstart: {lon: %.8f, lat: %.8f, depth_m: 0}\nmanoeuvres:\n"
                "  - track: {name: out, depth_m: 5, speed_kn: 3, waypoints: [{lon: %.8f, lat: %.8f}]}\n"
                "  - track: {name: back, depth_m: 17, speed_kn: 3, waypoints: [{lon: %.8f, lat: %.8f}]}\n",
                cells[0].c_str(), cells[1].c_str(), ll(500, 1500)[0], ll(500, 1500)[1], ll(5500, 1500)[0],
                ll(5500, 1500)[1], ll(500, 1500)[0], ll(500, 1500)[1]);
  std::ofstream(yaml) << text;
  const MissionCheckReport r = check_mission_file(yaml);
  ASSERT_EQ(r.chart_quality.size(), 2u);
  const PhaseQuality& out = r.chart_quality[0];
  const PhaseQuality& back = r.chart_quality[1];
  const double scale = out.quality.length_m / 5000.0;
  ASSERT_NEAR(scale, 1.0, 2e-3);
  EXPECT_EQ(out.name, "out");
  EXPECT_EQ(out.manoeuvre, 0u);
  EXPECT_DOUBLE_EQ(out.required_depth_m, 7.0);
  EXPECT_DOUBLE_EQ(back.required_depth_m, 19.0);
  EXPECT_NEAR(back.from_m, out.quality.length_m, 1e-6);
  for (const PhaseQuality* p : {&out, &back}) {
    ASSERT_EQ(p->quality.cells.size(), 2u) << p->name;
    EXPECT_EQ(p->quality.cells[0].cell, "US4TEST1");
    EXPECT_NEAR(p->quality.cells[1].length_m, 2000.0 * scale, 0.5);
    EXPECT_NEAR(p->quality.length_by_zoc.at("B"), 2000.0 * scale, 0.5);
    EXPECT_NEAR(p->quality.length_by_zoc.at("C"), 3000.0 * scale, 0.5);
    ASSERT_TRUE(p->quality.least_depth.has_value());
    EXPECT_DOUBLE_EQ(p->quality.least_depth->depth_m, 20.0);
    ASSERT_TRUE(p->quality.nearest_no_go.has_value());
  }
  EXPECT_EQ(out.quality.nearest_no_go->feature_id, "M_COVR/outside");
  EXPECT_NEAR(out.quality.nearest_no_go->distance_m, 500.0 * scale, 0.5);
  EXPECT_EQ(back.quality.nearest_no_go->feature_id.rfind("US5TEST2:DEPARE/", 0), 0u)
      << back.quality.nearest_no_go->feature_id;
  EXPECT_DOUBLE_EQ(back.quality.nearest_no_go->distance_m, 0.0);
  EXPECT_NE(back.quality.nearest_no_go->reason.find("least 18.6 m at CATZOC B, < 19 m"), std::string::npos)
      << back.quality.nearest_no_go->reason;
  // The same quality as the route on its own at that depth.
  EncNoGoOptions o;
  o.operating_depth_m = 17.0;
  const EncNoGo deep = enc_no_go(cells, r.loaded.mission.frame, o);
  const RouteQuality alone = route_quality({r.loaded.plan.basics[1].from, r.loaded.plan.basics[1].to}, deep);
  EXPECT_EQ(alone.nearest_no_go->feature_id, back.quality.nearest_no_go->feature_id);
  EXPECT_NEAR(alone.length_m, back.quality.length_m, 1e-6);

  // Reported by mission check and mission plan, in text and JSON.
  const nlohmann::json j = r.to_json();
  ASSERT_EQ(j.at("chart_quality").size(), 2u);
  EXPECT_EQ(j.at("chart_quality").at(1).at("manoeuvre"), 2);
  EXPECT_EQ(j.at("chart_quality").at(1).at("nearest_no_go").at("distance_m"), 0.0);
  const test::RunResult check = run_cli("mission check '" + yaml + "'");
  EXPECT_NE(check.out.find("phase 2          track 'back': "), std::string::npos) << check.out;
  EXPECT_NE(check.out.find(" m along, at 17 m (required depth 19 m)\n"), std::string::npos) << check.out;
  const test::RunResult plan = run_cli("mission plan '" + yaml + "' --json");
  const nlohmann::json pj = nlohmann::json::parse(plan.out);
  ASSERT_TRUE(pj.contains("chart_quality")) << plan.out;
  EXPECT_EQ(pj.at("chart_quality").at(0).at("required_depth_m"), 7.0);
}

// ------------------------------------------------------------------ the real set, read by the test itself

using Geom = std::unique_ptr<OGRGeometry>;

struct OwnCell {
  long scale = 0;
  int band = 0;
  std::string name;
  Geom coverage;
  std::vector<std::pair<double, Geom>> depth_areas;  // DRVAL1, area (UTM)
};

OwnCell read_cell(const std::string& path, OGRCoordinateTransformation& ct) {
  OwnCell c;
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) {
    ADD_FAILURE() << path << ": OGR could not open it";
    c.coverage = std::make_unique<OGRMultiPolygon>();
    return c;
  }
  for (auto& f : *ds->GetLayerByName("DSID")) {
    c.scale = f->GetFieldAsInteger("DSPM_CSCL");
    c.band = f->GetFieldAsInteger("DSID_INTU");
    c.name = std::filesystem::path(f->GetFieldAsString("DSID_DSNM")).stem().string();
  }
  auto cov = std::make_unique<OGRMultiPolygon>();
  for (auto& f : *ds->GetLayerByName("M_COVR")) {
    if (f->GetFieldAsInteger("CATCOV") != 1) continue;
    Geom g(f->GetGeometryRef()->clone());
    g->transform(&ct);
    cov->addGeometry(g.get());
  }
  c.coverage.reset(cov->UnionCascaded());
  for (const char* cls : {"DEPARE", "DRGARE"}) {
    OGRLayer* layer = ds->GetLayerByName(cls);
    if (layer == nullptr) continue;
    for (auto& f : *layer) {
      const int i = f->GetFieldIndex("DRVAL1");
      if (i < 0 || !f->IsFieldSetAndNotNull(i) || f->GetGeometryRef() == nullptr) continue;
      if (wkbFlatten(f->GetGeometryRef()->getGeometryType()) != wkbPolygon) continue;
      Geom g(f->GetGeometryRef()->clone());
      g->transform(&ct);
      c.depth_areas.emplace_back(f->GetFieldAsDouble(i), std::move(g));
    }
  }
  return c;
}

TEST(EncRouteQuality, KachemakLeastDepthAndCellsAgreeWithTheTestsOwnReading) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(set, "noaa-enc-kachemak");
  ScratchDir tmp;
  // From Homer's harbour cell (band 5) out into Kachemak Bay (band 4) and the band-3 cell beyond.
  const std::string route = tmp.file("r.geojson");
  const test::RunResult plan = run_cli(
      "plan --chart '" + set + "' --depth 5 --from -151.4810,59.5710 --to -151.5613,59.5475 -o '" + route + "' --json");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const nlohmann::json j = nlohmann::json::parse(plan.out);
  const nlohmann::json q = j.at("chart_quality");
  double sum = 0.0;
  for (const auto& [zoc, len] : q.at("length_by_zoc_m").items()) sum += len.get<double>();
  EXPECT_NEAR(sum, j.at("length_m").get<double>(), 1.0);
  ASSERT_GE(q.at("cells").size(), 2u) << q.dump();
  std::set<int> bands;
  for (const nlohmann::json& c : q.at("cells")) bands.insert(c.at("usage_band").get<int>());
  EXPECT_GE(bands.size(), 2u) << q.dump();

  // The test's own least depth: every depth area the route runs through, where its cell is the best scale.
  OGRSpatialReference wgs, utm;
  wgs.SetWellKnownGeogCS("WGS84");
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  utm.importFromEPSG(32605);
  utm.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs, &utm));
  std::vector<OwnCell> cells;
  for (const auto& e : std::filesystem::recursive_directory_iterator(set)) {
    if (e.path().extension() == ".000") cells.push_back(read_cell(e.path().string(), *ct));
  }
  std::sort(cells.begin(), cells.end(), [](const OwnCell& a, const OwnCell& b) { return a.scale < b.scale; });
  GDALAllRegister();
  GDALDatasetUniquePtr rds(GDALDataset::Open(route.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(rds);
  OGRFeature* rf = rds->GetLayer(0)->GetNextFeature();
  ASSERT_NE(rf, nullptr);
  Geom line(rf->GetGeometryRef()->clone());
  OGRFeature::DestroyFeature(rf);
  line->transform(ct.get());
  double least = INFINITY;
  std::string least_cell;
  std::set<std::string> crossed;
  Geom better(new OGRMultiPolygon());
  for (const OwnCell& c : cells) {
    Geom decides(c.coverage->Difference(better.get()));
    Geom here(line->Intersection(decides.get()));
    if (here && !here->IsEmpty() && OGR_G_Length(OGRGeometry::ToHandle(here.get())) > 1.0) crossed.insert(c.name);
    for (const auto& [drval1, area] : c.depth_areas) {
      if (drval1 >= least || !area->Intersects(here.get())) continue;
      Geom part(here->Intersection(area.get()));
      if (part && !part->IsEmpty() && OGR_G_Length(OGRGeometry::ToHandle(part.get())) > 1e-3) {
        least = drval1;
        least_cell = c.name;
      }
    }
    better.reset(better->Union(c.coverage.get()));
  }
  ASSERT_TRUE(std::isfinite(least));
  EXPECT_DOUBLE_EQ(q.at("least_depth").at("depth_m").get<double>(), least);
  EXPECT_EQ(q.at("least_depth").at("cell"), least_cell);
  std::set<std::string> listed;
  for (const nlohmann::json& c : q.at("cells")) listed.insert(c.at("cell").get<std::string>());
  EXPECT_EQ(listed, crossed);
}

}  // namespace
}  // namespace deepguide
