// S-57 cells as an ECDIS reads them for a submerged vehicle: the no-go rules
// (enc_no_go.hpp), the cells and their updates (enc_cells.hpp), and the chart
// route check (enc_route_check.hpp). Facts come from independent OGR reads of
// the real cells in ../shared/data/real (GEOS predicates through OGR, not the
// library's Boost.Geometry), and from test cells written through GDAL's own
// S57 writer (copies of a real cell with edited attributes).

#include <gdal_utils.h>
#include <gtest/gtest.h>
#include <ogr_api.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <boost/geometry/algorithms/correct.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/enc_route_check.hpp"
#include "deepguide/charts/enc_sea_floor.hpp"
#include "deepguide/charts/iso8211_check.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/planner.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

const char* const kKeyWest = "noaa-enc-US5FL4DQ/US5FL4DQ.000";
const char* const kChesapeake = "noaa-enc-US4MD81M/US4MD81M.000";

GDALDatasetUniquePtr open_ogr(const std::string& path, std::vector<const char*> options = {}) {
  GDALAllRegister();
  options.push_back(nullptr);
  GDALDatasetUniquePtr ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, options.data(), nullptr));
  EXPECT_TRUE(ds) << path;
  return ds;
}

EncNoGoOptions at_depth(double depth, double clearance = 2.0) {
  EncNoGoOptions o;
  o.operating_depth_m = depth;
  o.vertical_clearance_m = clearance;
  return o;
}

void expect_one_line_error(const std::function<void()>& fn, const std::string& names, const std::string& says) {
  try {
    fn();
    ADD_FAILURE() << "no error; expected one naming " << names;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(names), std::string::npos) << what;
    EXPECT_NE(what.find(says), std::string::npos) << what;
  }
}

// A copy of a real cell through GDAL's S57 writer, with the features of the
// layers kept edited on the way (an in-memory copy in between).
// The writer makes its own DSID; `dsco` sets its fields (e.g. "S57_CSCL=50000").
void write_edited_cell(const std::string& src, const std::string& dst, const std::vector<std::string>& layers,
                       const std::function<void(const std::string&, OGRFeature&)>& edit,
                       const std::vector<std::string>& dsco = {}) {
  // The writer needs the cell's spatial primitives, which the reader returns as layers on request.
  GDALDatasetUniquePtr in = open_ogr(src, {"RETURN_PRIMITIVES=ON", "RETURN_LINKAGES=ON", "LNAM_REFS=ON"});
  GDALDriver* mem_driver = GetGDALDriverManager()->GetDriverByName("Memory");
  ASSERT_NE(mem_driver, nullptr);
  GDALDatasetUniquePtr mem(mem_driver->Create("", 0, 0, 0, GDT_Unknown, nullptr));
  std::vector<std::string> all = {"IsolatedNode", "ConnectedNode", "Edge", "Face"};
  all.insert(all.end(), layers.begin(), layers.end());
  for (const std::string& name : all) {
    OGRLayer* from = in->GetLayerByName(name.c_str());
    if (from == nullptr && std::isupper(static_cast<unsigned char>(name[1])) == 0) continue;  // no such primitive
    ASSERT_NE(from, nullptr) << name;
    OGRLayer* to = mem->CopyLayer(from, name.c_str());
    ASSERT_NE(to, nullptr) << name;
    to->ResetReading();
    std::vector<std::unique_ptr<OGRFeature>> feats;
    for (auto& f : *to) feats.emplace_back(f->Clone());
    for (auto& f : feats) {
      edit(name, *f);
      ASSERT_EQ(to->SetFeature(f.get()), OGRERR_NONE);
    }
  }
  std::vector<const char*> argv = {"-f", "S57"};
  for (const std::string& d : dsco) argv.insert(argv.end(), {"-dsco", d.c_str()});
  argv.push_back(nullptr);
  GDALVectorTranslateOptions* opts = GDALVectorTranslateOptionsNew(const_cast<char**>(argv.data()), nullptr);
  GDALDatasetH src_h = GDALDataset::ToHandle(mem.get());
  int usage_error = 0;
  GDALDatasetH out = GDALVectorTranslate(dst.c_str(), nullptr, 1, &src_h, opts, &usage_error);
  GDALVectorTranslateOptionsFree(opts);
  ASSERT_NE(out, nullptr) << CPLGetLastErrorMsg();
  GDALClose(out);
}

// ------------------------------------------------------------------ rules

TEST(EncRules, HazardDepthFollowsValsouThenWatlevCatwrkExpsou) {
  EncFeature h;
  h.cls = "OBSTRN";
  h.valsou = 4.2;
  EXPECT_DOUBLE_EQ(*hazard_depth(h, 30.0), 4.2);
  h.valsou = std::nan("");
  for (int dries : {1, 2, 4, 5, 6, 7}) {
    h.watlev = dries;
    EXPECT_DOUBLE_EQ(*hazard_depth(h, 30.0), 0.0) << dries;
  }
  h.watlev = 3;  // always under water, depth not given
  EXPECT_FALSE(hazard_depth(h, 30.0).has_value());
  h.expsou = 1;  // within the surrounding depth
  EXPECT_DOUBLE_EQ(*hazard_depth(h, 30.0), 30.0);
  EXPECT_FALSE(hazard_depth(h, std::nan("")).has_value()) << "surrounding depth unknown";
  h.expsou = 2;  // shoaler than the surrounding: unknown
  EXPECT_FALSE(hazard_depth(h, 30.0).has_value());
  h.expsou = 0;
  h.cls = "WRECKS";
  h.catwrk = 1;  // non-dangerous
  EXPECT_DOUBLE_EQ(*hazard_depth(h, 30.0), 20.1);
  h.catwrk = 2;
  EXPECT_FALSE(hazard_depth(h, 30.0).has_value());
}

TEST(EncRules, ZonesOfConfidenceAreTheIhoFigures) {
  const EncNoGoOptions o;
  struct Row {
    int catzoc;
    double a, b, pos;
  };
  for (const Row& r : {Row{1, 0.5, 0.01, 5}, Row{2, 1.0, 0.02, 20}, Row{3, 1.0, 0.02, 50}, Row{4, 2.0, 0.05, 500}}) {
    const ZocFigures f = zoc_figures(r.catzoc, o);
    EXPECT_DOUBLE_EQ(f.depth_fixed_m, r.a) << r.catzoc;
    EXPECT_DOUBLE_EQ(f.depth_fraction, r.b) << r.catzoc;
    EXPECT_DOUBLE_EQ(f.position_m, r.pos) << r.catzoc;
  }
  for (int unassessed : {0, 5, 6, 99}) {
    EXPECT_DOUBLE_EQ(zoc_figures(unassessed, o).depth_fixed_m, o.unassessed.depth_fixed_m);
    EXPECT_DOUBLE_EQ(zoc_figures(unassessed, o).position_m, o.unassessed.position_m);
  }
  EXPECT_EQ(zoc_name(1), "A1");
  EXPECT_EQ(zoc_name(3), "B");
  EXPECT_EQ(zoc_name(6), "U");
}

// A square of land (0..100 m) in a hand-made no-go: the check's verdict on
// routes a known distance from it.
EncNoGo square_land() {
  EncNoGo no_go{LocalFrame::utm_for(-76.4, 38.8), 0.0, {}, {}, {}, {}, {}, {}, 0, {}, {}, {}};
  EncNoGoFeature land;
  land.id = "LNDARE/1";
  land.cls = "LNDARE";
  land.reason = "land";
  BgPolygon square;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {0.0, 100.0}, {100.0, 100.0}, {100.0, 0.0}, {0.0, 0.0}}) {
    square.outer().emplace_back(x, y);
  }
  boost::geometry::correct(square);
  land.area.push_back(square);
  no_go.features.push_back(land);
  return no_go;
}

TEST(EncRouteCheck, TheToleranceAbsorbsRoundingNotTheMargin) {
  const EncNoGo no_go = square_land();
  // Legs along y = 105 - e: e short of the 5 m margin.
  const auto along = [](double e) { return std::vector<Vec2>{{-50.0, 105.0 - e}, {150.0, 105.0 - e}}; };
  EXPECT_TRUE(check_route_on_chart(along(0.0), no_go, 5.0).safe);
  EXPECT_FALSE(check_route_on_chart(along(1e-4), no_go, 5.0).safe) << "the default tolerance is 1 um";
  EXPECT_TRUE(check_route_on_chart(along(1e-4), no_go, 5.0, 1e-3).safe) << "0.1 mm is rounding at 1 mm";
  const ChartRouteCheck near = check_route_on_chart(along(0.2), no_go, 5.0, 1e-3);
  ASSERT_FALSE(near.safe);
  EXPECT_NEAR(near.first->least_distance_m, 4.8, 1e-9);
  // Where it enters the margin less the tolerance round the corner, bisected to 1 cm.
  EXPECT_NEAR(near.first->at.x(), -std::sqrt(4.999 * 4.999 - 4.8 * 4.8), 0.011);
  const std::string text = near.describe(no_go.frame);
  EXPECT_NE(text.find("passes 4.80 m from LNDARE/1 (land; margin 5 m)"), std::string::npos) << text;
  EXPECT_EQ(text.find("crosses"), std::string::npos) << text;
  // Into the land: "crosses", at its edge.
  const ChartRouteCheck into = check_route_on_chart({{-50.0, 50.0}, {50.0, 50.0}}, no_go, 5.0, 1e-3);
  ASSERT_FALSE(into.safe);
  EXPECT_EQ(into.first->least_distance_m, 0.0);
  EXPECT_NE(into.describe(no_go.frame).find("crosses LNDARE/1 (land)"), std::string::npos);
  // Touching the land with no margin is a crossing whatever the tolerance.
  EXPECT_FALSE(check_route_on_chart({{-50.0, 100.0}, {150.0, 100.0}}, no_go, 0.0, 1e-3).safe);
  EXPECT_TRUE(check_route_on_chart({{-50.0, 100.01}, {150.0, 100.01}}, no_go, 0.0, 1e-3).safe);
  // Points alone.
  EXPECT_EQ(no_go_feature_at(no_go, {50.0, 105.0 - 1e-4}, 5.0, 1e-3), nullptr);
  EXPECT_NE(no_go_feature_at(no_go, {50.0, 105.0 - 1e-2}, 5.0, 1e-3), nullptr);
  EXPECT_NE(no_go_feature_at(no_go, {50.0, 50.0}, 0.0, 1e-3), nullptr) << "inside the land";
  EXPECT_THROW(check_route_on_chart(along(0.0), no_go, 5.0, -1.0), std::invalid_argument);
  EXPECT_THROW(check_route_on_chart(along(0.0), no_go, 5.0, std::nan("")), std::invalid_argument);
}

// ------------------------------------------------------------------ real cells

TEST(EncNoGo, StraightRouteOfTheIssueIsFlaggedWithItsFirstCrossing) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, at_depth(8.0));
  EXPECT_DOUBLE_EQ(no_go.required_depth_m, 10.0);
  const Vec2 a = no_go.frame.from_lonlat(-76.45, 38.45), b = no_go.frame.from_lonlat(-76.42, 38.55);
  const ChartRouteCheck check = check_route_on_chart({a, b}, no_go, 5.0);
  ASSERT_FALSE(check.safe);
  ASSERT_TRUE(check.first.has_value());

  // Independently (OGR, GEOS): the depth area holding the start, and every
  // depth area shallower than 10 m the straight line meets.
  auto ds = open_ogr(path);
  OGRLayer* depare = ds->GetLayerByName("DEPARE");
  OGRPoint start(-76.45, 38.45);
  OGRLineString line;
  line.addPoint(-76.45, 38.45);
  line.addPoint(-76.42, 38.55);
  long long holder = -1;
  double holder_drval1 = 99;
  std::set<double> crossed_depths;
  std::size_t shallow_crossed = 0;
  for (auto& f : *depare) {
    const OGRGeometry* g = f->GetGeometryRef();
    if (g == nullptr) continue;
    const double d1 = f->GetFieldAsDouble("DRVAL1");
    if (g->Contains(&start)) holder = f->GetFieldAsInteger64("RCID"), holder_drval1 = d1;
    if (g->Intersects(&line) && d1 < 10.0) {
      crossed_depths.insert(d1);
      ++shallow_crossed;
    }
  }
  ASSERT_GE(holder, 0);
  EXPECT_EQ(check.first->feature->id, "DEPARE/" + std::to_string(holder));
  EXPECT_DOUBLE_EQ(check.first->feature->charted_depth_m, holder_drval1);
  EXPECT_NEAR(check.first->along_m, 0.0, 1e-6);
  // The issue's depth areas: 0.0, 1.8, 3.6, 5.4 and 9.1 m.
  EXPECT_EQ(crossed_depths, (std::set<double>{0.0, 1.8, 3.6, 5.4, 9.1}));
  EXPECT_GE(check.crossed_features, shallow_crossed);
  const std::string line_text = check.describe(no_go.frame);
  EXPECT_NE(line_text.find("DEPARE/" + std::to_string(holder)), std::string::npos) << line_text;
  EXPECT_NE(line_text.find("DRVAL1 0 m < 10 m"), std::string::npos) << line_text;
}

TEST(EncNoGo, UpdatesGiveWhatGdalsOwnAppliedReadingGives) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  // At 100 m every depth area, danger and sounding is too shallow: the no-go
  // then lists every feature of those classes, which GDAL's reading must match.
  auto ids_from_gdal = [&](bool apply) {
    std::set<std::string> ids;
    auto ds = open_ogr(path, {apply ? "UPDATES=APPLY" : "UPDATES=IGNORE"});
    for (const char* cls : {"WRECKS", "OBSTRN", "UWTROC", "DEPARE", "SOUNDG"}) {
      for (auto& f : *ds->GetLayerByName(cls)) ids.insert(std::string(cls) + "/" + f->GetFieldAsString("RCID"));
    }
    return ids;
  };
  auto ids_from_no_go = [&](bool apply) {
    EncNoGoOptions o = at_depth(100.0);
    o.apply_updates = apply;
    std::set<std::string> ids;
    for (const EncNoGoFeature& f : enc_no_go({path}, std::nullopt, o).features) {
      if (f.cls == "WRECKS" || f.cls == "OBSTRN" || f.cls == "UWTROC" || f.cls == "DEPARE" || f.cls == "SOUNDG") {
        ids.insert(f.id.substr(0, f.id.find('#')));
      }
    }
    return ids;
  };
  const auto applied = ids_from_gdal(true), ignored = ids_from_gdal(false);
  EXPECT_EQ(ids_from_no_go(true), applied);
  EXPECT_EQ(ids_from_no_go(false), ignored);
  EXPECT_NE(applied, ignored) << "updates 1-3 add a wreck and soundings (SOURCES.md)";
}

TEST(EncNoGo, DepthDecidesDepthAreasAndChartInfoCountsZones) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  EncNoGoOptions exact = at_depth(5.0);
  exact.zoc = ZocPolicy::none;
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, exact);
  // Independently: depth areas with DRVAL1 < 7 m (or none) are no-go, the others pass.
  std::set<std::string> expected;
  auto ds = open_ogr(path);
  std::size_t deep = 0;
  for (auto& f : *ds->GetLayerByName("DEPARE")) {
    const int i = f->GetFieldIndex("DRVAL1");
    const bool shallow = !f->IsFieldSetAndNotNull(i) || f->GetFieldAsDouble(i) < 7.0;
    if (shallow) expected.insert(std::string("DEPARE/") + f->GetFieldAsString("RCID"));
    deep += !shallow;
  }
  std::set<std::string> got;
  for (const EncNoGoFeature& f : no_go.features) {
    if (f.cls == "DEPARE") got.insert(f.id);
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(no_go.passable_by_class.at("DEPARE"), deep);
  // Zones of confidence only add no-go.
  const EncNoGo zoc = enc_no_go({path}, std::nullopt, at_depth(5.0));
  EXPECT_GE(zoc.no_go_by_class.at("DEPARE"), no_go.no_go_by_class.at("DEPARE"));
  EXPECT_GE(zoc.no_go_by_class.at("SOUNDG"), no_go.no_go_by_class.at("SOUNDG"));
  EXPECT_EQ(zoc.zoc_areas.at("A1"), 19u);
  EXPECT_EQ(zoc.zoc_areas.at("C"), 7u);
  EXPECT_EQ(zoc.zoc_areas.at("U"), 16u);
}

TEST(EncNoGo, PointHazardsAreDiscsOfTheirZonesPositionAccuracy) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, at_depth(30.0));
  std::set<double> radii;
  for (const EncNoGoFeature& f : no_go.features) {
    if (f.point) radii.insert(f.radius_m);
  }
  // Key West has zones A1, B and C (SOURCES.md: CATZOC 1, 3, 4).
  for (double r : radii) EXPECT_TRUE(r == 5.0 || r == 50.0 || r == 500.0) << r;
  EXPECT_TRUE(radii.count(5.0) || radii.count(50.0));
}

// Every no-go feature lies inside what the planners get (their merged,
// simplified polygons and discs), checked with GEOS through OGR: an overlay
// the library's Boost-based merging shares nothing with.
TEST(EncNoGo, PlannersPolygonsCoverEveryNoGoFeature) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(chesapeake, kChesapeake);
  DEEPGUIDE_REAL_FILE_OR_SKIP(key_west, kKeyWest);
  auto to_ogr = [](const BgPolygon& p) {
    auto poly = std::make_unique<OGRPolygon>();
    auto ring = [](const auto& r) {
      OGRLinearRing out;
      for (const BgPoint& q : r) out.addPoint(q.x(), q.y());
      return out;
    };
    OGRLinearRing outer = ring(p.outer());
    poly->addRing(&outer);
    for (const auto& in : p.inners()) {
      OGRLinearRing r = ring(in);
      poly->addRing(&r);
    }
    return poly;
  };
  for (const auto& [path, depth] : {std::pair{chesapeake, 5.0}, std::pair{key_west, 3.0}}) {
    const EncNoGo no_go = enc_no_go({path}, std::nullopt, at_depth(depth));
    OGRMultiPolygon planners;
    for (const PolygonObstacle& p : no_go.obstacles.polygons)
      planners.addGeometryDirectly(to_ogr(p.footprint).release());
    ASSERT_TRUE(planners.IsValid()) << path;
    std::size_t areas = 0;
    for (const EncNoGoFeature& f : no_go.features) {
      if (f.area.empty()) continue;
      ++areas;
      OGRMultiPolygon feature;
      for (const BgPolygon& p : f.area) feature.addGeometryDirectly(to_ogr(p).release());
      std::unique_ptr<OGRGeometry> left(feature.Difference(&planners));
      ASSERT_TRUE(left) << f.id;
      const double uncovered = left->IsEmpty() ? 0.0 : OGR_G_Area(OGRGeometry::ToHandle(left.get()));
      EXPECT_LT(uncovered, 0.01) << path << " " << f.id << " (m2 outside the planners' polygons)";
    }
    EXPECT_GT(areas, 100u) << path;
    // A disc left out lies inside a polygon by at least its radius.
    std::set<std::string> discs;
    for (const EllipticCylinder& e : no_go.obstacles.ellipses) discs.insert(e.id);
    for (const EncNoGoFeature& f : no_go.features) {
      if (!f.point || discs.count(f.id)) continue;
      OGRPoint c(f.point->x(), f.point->y());
      std::unique_ptr<OGRGeometry> disc(c.Buffer(f.radius_m, 16));
      EXPECT_TRUE(planners.Contains(disc.get())) << f.id;
    }
  }
}

// On a part of the cell small enough for the seed's full visibility graph,
// the reduced graph (what plan uses) finds the same route, and both lie
// within the zone polygons' tolerance of the exact optimum (the tangent
// graph along the zones' true boundaries).
TEST(EncNoGo, ClippedPartRoutesMatchTheFullGraphAndTheExactOptimum) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, at_depth(5.0));
  const LocalFrame& frame = no_go.frame;
  const Vec2 lo = frame.from_lonlat(-76.42, 38.54), hi = frame.from_lonlat(-76.36, 38.59);
  OGRPolygon box;
  OGRLinearRing ring;
  for (const Vec2& c : {lo, Vec2(lo.x(), hi.y()), hi, Vec2(hi.x(), lo.y()), lo}) ring.addPoint(c.x(), c.y());
  box.addRing(&ring);
  ObstacleSet part;
  for (const PolygonObstacle& p : no_go.obstacles.polygons) {
    OGRPolygon op;
    auto to_ring = [](const auto& r) {
      OGRLinearRing out;
      for (const BgPoint& q : r) out.addPoint(q.x(), q.y());
      return out;
    };
    OGRLinearRing outer = to_ring(p.footprint.outer());
    op.addRing(&outer);
    for (const auto& in : p.footprint.inners()) {
      OGRLinearRing r = to_ring(in);
      op.addRing(&r);
    }
    std::unique_ptr<OGRGeometry> cut(op.Intersection(&box));
    ASSERT_TRUE(cut);
    auto take = [&](const OGRPolygon& q) {
      PolygonObstacle piece;
      piece.id = p.id + "#" + std::to_string(part.polygons.size());
      auto copy = [](const OGRLinearRing& r, auto& dst) {
        for (int i = 0; i < r.getNumPoints(); ++i) dst.push_back(BgPoint(r.getX(i), r.getY(i)));
      };
      copy(*q.getExteriorRing(), piece.footprint.outer());
      for (int k = 0; k < q.getNumInteriorRings(); ++k)
        copy(*q.getInteriorRing(k), piece.footprint.inners().emplace_back());
      boost::geometry::correct(piece.footprint);
      part.polygons.push_back(std::move(piece));
    };
    if (wkbFlatten(cut->getGeometryType()) == wkbPolygon && !cut->IsEmpty()) take(*cut->toPolygon());
    if (wkbFlatten(cut->getGeometryType()) == wkbMultiPolygon) {
      for (const OGRPolygon* q : *cut->toMultiPolygon()) take(*q);
    }
  }
  for (const EllipticCylinder& e : no_go.obstacles.ellipses) {
    const Vec2 c = e.footprint.centre;
    if (c.x() > lo.x() - e.footprint.a && c.x() < hi.x() + e.footprint.a && c.y() > lo.y() - e.footprint.a &&
        c.y() < hi.y() + e.footprint.a) {
      part.ellipses.push_back(e);
    }
  }
  ASSERT_FALSE(part.polygons.empty());
  const PlanningProblem problem{frame.from_lonlat(-76.401, 38.575), frame.from_lonlat(-76.375, 38.5766), false};
  double length[3] = {0, 0, 0};
  const GraphKind kinds[3] = {GraphKind::visibility, GraphKind::visibility_full, GraphKind::tangent};
  for (int k = 0; k < 3; ++k) {
    PlannerOptions o;
    o.margin = 5.0;
    o.graph = kinds[k];
    Planner planner(part, o);
    const PlanOutcome out = planner.solve(problem);
    ASSERT_TRUE(out.result.found) << to_string(kinds[k]) << ": " << out.result.message;
    EXPECT_TRUE(out.check.safe) << to_string(kinds[k]) << ": " << out.check.describe();
    length[k] = k == 2 ? out.result.exact_length_m : out.result.route.length();
    std::printf("%-16s %.3f m, build %.1f ms, query %.2f ms\n", to_string(kinds[k]).c_str(), length[k],
                out.result.stats.build_ms, out.result.stats.query_ms);
  }
  EXPECT_GT(length[0], (problem.goal - problem.start).norm() * 1.05) << "the straight line crosses the shoal";
  EXPECT_NEAR(length[0], length[1], 1e-6 * length[1]) << "reduced and full graphs: the same shortest path";
  EXPECT_GE(length[0], length[2] - 1e-6);
  EXPECT_LE(length[0], length[2] * 1.002) << "within the zone polygons' 0.5 m tolerance of the exact optimum";
}

// ------------------------------------------------------------------ a test cell through GDAL's writer

TEST(EncNoGo, ZoneOfConfidenceChangesTheVerdictOnA9p5mArea) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  ScratchDir tmp;
  auto make = [&](const std::string& name, int catzoc) {
    const std::string cell = (tmp.path() / (name + ".000")).string();
    write_edited_cell(path, cell, {"M_COVR", "M_QUAL", "DEPARE"}, [&](const std::string& layer, OGRFeature& f) {
      if (layer == "DEPARE") f.SetField("DRVAL1", 9.5);
      if (layer == "M_QUAL") f.SetField("CATZOC", catzoc);
    });
    return cell;
  };
  const std::string a1 = make("ZOCA1", 1), b = make("ZOCB", 3);
  // D = 7 + 2 = 9 m. As charted 9.5 m passes; A1 takes 0.5 + 0.095 = 0.595 m off (8.905 < 9).
  EncNoGoOptions o = at_depth(7.0, 2.0);
  o.zoc = ZocPolicy::none;
  const EncNoGo charted = enc_no_go({a1}, std::nullopt, o);
  EXPECT_EQ(charted.no_go_by_class.count("DEPARE"), 0u);
  EXPECT_EQ(charted.passable_by_class.at("DEPARE"), 97u);
  const EncNoGo zoc = enc_no_go({a1}, std::nullopt, at_depth(7.0, 2.0));
  EXPECT_EQ(zoc.no_go_by_class.at("DEPARE"), 97u);
  ASSERT_FALSE(zoc.features.empty());
  EXPECT_NE(zoc.features.front().reason.find("least 8.905 m at CATZOC A1"), std::string::npos)
      << zoc.features.front().reason;
  // At D = 8.9 m A1 passes (8.905) and B does not (9.5 - 1.19 = 8.31).
  EXPECT_EQ(enc_no_go({a1}, std::nullopt, at_depth(6.9, 2.0)).no_go_by_class.count("DEPARE"), 0u);
  EXPECT_EQ(enc_no_go({b}, std::nullopt, at_depth(6.9, 2.0)).no_go_by_class.at("DEPARE"), 97u);
}

// ------------------------------------------------------------------ bad input

// Single flipped bytes GDAL 3.6 read as data without a word (found by the
// truncation sweep, tests/cli/test_truncation_sweep.cpp): each is one line now.
TEST(EncCells, FlippedBytesGdalTookAsDataAreRefused) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(key_west, kKeyWest);
  DEEPGUIDE_REAL_FILE_OR_SKIP(chesapeake, kChesapeake);
  ScratchDir tmp;
  auto bytes_of = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  auto write = [](const fs::path& p, const std::string& b) { std::ofstream(p, std::ios::binary) << b; };
  const std::string kw = bytes_of(key_west);
  {
    // A label in the file's field descriptions: "ATTL" -> "ATTX". GDAL then
    // read no attribute at all: every depth area lost its depths, every zone
    // of confidence its CATZOC, and chart info said so as if the chart did.
    std::string b = kw;
    const std::size_t at = b.find("*ATTL!ATVL", b.find("Feature record attribute field"));
    ASSERT_LT(at, 1582u) << "within the data descriptive record";
    b[at + 4] = 'X';
    write(tmp.path() / "US5FL4DQ.000", b);
    expect_one_line_error([&] { chart_info((tmp.path() / "US5FL4DQ.000").string()); }, "US5FL4DQ.000",
                          "field ATTF described with labels '*ATTX!ATVL'");
  }
  {
    // A digit of a record's directory (record 1371, at byte 315070): GDAL dropped that feature.
    std::string b = kw;
    ASSERT_TRUE(std::isdigit(static_cast<unsigned char>(b[315113])));
    b[315113] = 'x';
    write(tmp.path() / "US5FL4DQ.000", b);
    expect_one_line_error([&] { chart_info((tmp.path() / "US5FL4DQ.000").string()); }, "US5FL4DQ.000",
                          "a directory entry with a letter where its length or position goes at byte 315070");
  }
  {
    // A byte of a sounding's depth (SG3D of SOUNDG/1671): 661 914.5 m, which
    // chart info gave as the cell's depth range. No sea is that deep.
    std::string b = kw;
    b[17661] = static_cast<char>(static_cast<unsigned char>(b[17661]) ^ 101);
    write(tmp.path() / "US5FL4DQ.000", b);
    expect_one_line_error([&] { chart_info((tmp.path() / "US5FL4DQ.000").string()); }, "SOUNDG/1671 (a sounding)",
                          "holds a depth of 661914.5 m: expected one between -9000 and 11100 m");
    expect_one_line_error([&] { enc_no_go({(tmp.path() / "US5FL4DQ.000").string()}, std::nullopt, at_depth(5.0)); },
                          "US5FL4DQ.000", "holds a depth of 661914.5 m");
  }
  {
    // An object class code (FRID OBJL of a coastline in US4MD81M.000): GDAL
    // moved the feature to a layer "Generic", one coastline fewer, exit 0.
    const fs::path dir = tmp.path() / "objl";
    fs::create_directories(dir);
    std::string b = bytes_of(chesapeake);
    b[2644814] = static_cast<char>(static_cast<unsigned char>(b[2644814]) ^ 170);
    write(dir / "US4MD81M.000", b);
    expect_one_line_error([&] { chart_info((dir / "US4MD81M.000").string()); }, "US4MD81M.000",
                          "expected an object class S-57 defines, got code");
  }
  {
    // An update's instruction (RUIN of the last feature record of .002, insert)
    // turned into 250: GDAL skipped that record, one wreck fewer, exit 0.
    const fs::path dir = tmp.path() / "ches";
    fs::create_directories(dir);
    const fs::path src = fs::path(chesapeake).parent_path();
    for (const char* ext : {".000", ".001", ".002", ".003"}) {
      fs::copy_file(src / ("US4MD81M" + std::string(ext)), dir / ("US4MD81M" + std::string(ext)));
    }
    std::string b = bytes_of(dir / "US4MD81M.002");
    ASSERT_EQ(b[2096], 1) << "the insert instruction of the last feature record";
    b[2096] = static_cast<char>(250);
    write(dir / "US4MD81M.002", b);
    expect_one_line_error([&] { chart_info((dir / "US4MD81M.000").string()); }, "US4MD81M.002",
                          "update instruction 250 (S-57 has 1 insert, 2 delete, 3 modify)");
  }
}

// ISO 8211 writes "00000" for the length of a record over 99 999 bytes (a
// long edge of a real cell); its directory gives where it ends.
TEST(EncCells, ARecordWithLengthZeroIsWalkedByItsDirectory) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(chesapeake, kChesapeake);
  ScratchDir tmp;
  std::ifstream in(fs::path(chesapeake).parent_path() / "US4MD81M.003", std::ios::binary);
  std::string b((std::istreambuf_iterator<char>(in)), {});
  const std::size_t second = static_cast<std::size_t>(std::stoi(b.substr(0, 5)));  // the first data record
  ASSERT_LT(second + 5, b.size());
  b.replace(second, 5, "00000");
  const std::string path = (tmp.path() / "US4MD81M.003").string();
  std::ofstream(path, std::ios::binary) << b;
  EXPECT_EQ(s57_structure_problem(path, true), "");
  b.resize(b.size() - 3);  // and cut short it is still seen
  std::ofstream(path, std::ios::binary | std::ios::trunc) << b;
  EXPECT_NE(s57_structure_problem(path, true), "");
}

TEST(EncCells, BrokenInputIsOneLineEach) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  ScratchDir tmp;
  const fs::path src = fs::path(path).parent_path();
  // A missing update in the sequence: .001 and .003 without .002.
  const fs::path gap = tmp.path() / "gap";
  fs::create_directories(gap);
  for (const char* ext : {".000", ".001", ".003"})
    fs::copy_file(src / ("US4MD81M" + std::string(ext)), gap / ("US4MD81M" + std::string(ext)));
  expect_one_line_error([&] { find_enc_cells({(gap / "US4MD81M.000").string()}); }, "US4MD81M.003",
                        "expected update 2");
  // chart info too (GDAL alone applied .001, stopped at the gap and said nothing).
  expect_one_line_error([&] { chart_info((gap / "US4MD81M.000").string()); }, "US4MD81M.003", "expected update 2");
  // A damaged update: GDAL stops applying there.
  const fs::path cut = tmp.path() / "cut";
  fs::create_directories(cut);
  fs::copy_file(src / "US4MD81M.000", cut / "US4MD81M.000");
  fs::copy_file(src / "US4MD81M.001", cut / "US4MD81M.001");
  fs::resize_file(cut / "US4MD81M.001", fs::file_size(cut / "US4MD81M.001") / 2);
  expect_one_line_error([&] { enc_no_go({(cut / "US4MD81M.000").string()}, std::nullopt, at_depth(5.0)); },
                        "US4MD81M.001", "expected an intact S-57 update");
  // A file named .000 that is not S-57.
  const fs::path fake = tmp.path() / "FAKE.000";
  std::ofstream(fake) << "{\"type\": \"FeatureCollection\", \"features\": []}\n";
  expect_one_line_error([&] { enc_no_go({fake.string()}, std::nullopt, at_depth(5.0)); }, "FAKE.000",
                        "expected an S-57 ENC cell");
  // A folder without cells, a missing path, a file not named *.000.
  const fs::path empty = tmp.path() / "empty";
  fs::create_directories(empty);
  expect_one_line_error([&] { find_enc_cells({empty.string()}); }, "empty", "found none");
  expect_one_line_error([&] { find_enc_cells({(tmp.path() / "nothing").string()}); }, "nothing", "found nothing");
  expect_one_line_error([&] { find_enc_cells({(src / "US4MD81A.TXT").string()}); }, "US4MD81A.TXT", "*.000");
  // An update given alone: named, with the base to give instead (chart info
  // passed GDAL's own two-line message through before).
  const std::string update = (src / "US4MD81M.001").string();
  expect_one_line_error([&] { find_enc_cells({update}); }, "US4MD81M.001", "got an update; give US4MD81M.000");
  expect_one_line_error([&] { chart_info(update); }, "US4MD81M.001", "got an update; give US4MD81M.000");
  expect_one_line_error([&] { enc_no_go({update}, std::nullopt, at_depth(5.0)); }, "US4MD81M.001",
                        "got an update; give US4MD81M.000");
  // A cell without depth areas (written through GDAL from the real one).
  DEEPGUIDE_REAL_FILE_OR_SKIP(key_west, kKeyWest);
  const std::string no_depare = (tmp.path() / "NODEPARE.000").string();
  write_edited_cell(key_west, no_depare, {"M_COVR", "LNDARE"}, [](const std::string&, OGRFeature&) {});
  expect_one_line_error([&] { enc_no_go({no_depare}, std::nullopt, at_depth(5.0)); }, "NODEPARE.000", "DEPARE");
  // Options.
  expect_one_line_error([&] { enc_no_go({path}, std::nullopt, at_depth(std::nan(""))); }, "`operating_depth_m`",
                        "operating depth");
  expect_one_line_error([&] { enc_no_go({path}, std::nullopt, at_depth(5.0, -1.0)); }, "`vertical_clearance_m`",
                        ">= 0");
}

TEST(EncCells, FoldersAreSearchedAndEachCellReadOnce) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  const fs::path dir = fs::path(path).parent_path();
  const auto cells = find_enc_cells({dir.string(), path});
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells.front().updates.size(), 3u);
  EXPECT_NE(cells.front().updates.back().find("US4MD81M.003"), std::string::npos);
}

TEST(EncNoGo, SeveralCellsLetTheBetterScaleWin) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  ScratchDir tmp;
  // The same Key West cell twice, the copy said to be at 1:50,000 with every
  // depth area 30 m: where both cover, the 1:10,000 original decides.
  const std::string coarse = (tmp.path() / "COARSE.000").string();
  write_edited_cell(path, coarse, {"M_COVR", "DEPARE"},
                    [](const std::string& layer, OGRFeature& f) {
                      if (layer == "DEPARE") f.SetField("DRVAL1", 30.0);
                    },
                    {"S57_CSCL=50000"});
  const EncNoGo both = enc_no_go({coarse, path}, std::nullopt, at_depth(5.0));
  ASSERT_EQ(both.cells.size(), 2u);
  EXPECT_EQ(both.cells.front().name, "US5FL4DQ");
  EXPECT_EQ(both.cells.front().compilation_scale, 10000);
  const EncNoGo alone = enc_no_go({path}, std::nullopt, at_depth(5.0));
  std::size_t from_coarse = 0;
  for (const EncNoGoFeature& f : both.features) from_coarse += f.cell == "COARSE";
  EXPECT_EQ(from_coarse, 0u) << "the coarse cell covers nothing the fine one does not";
  EXPECT_EQ(both.no_go_by_class.at("DEPARE"), alone.no_go_by_class.at("DEPARE"));
  // The same cell from two folders: one would clip the other.
  const std::filesystem::path copy = tmp.path() / "copy";
  std::filesystem::create_directories(copy);
  std::filesystem::copy_file(path, copy / "US5FL4DQ.000");
  expect_one_line_error(
      [&] {
        enc_no_go({path, (copy / "US5FL4DQ.000").string()}, std::nullopt, at_depth(5.0));
      },
      "US5FL4DQ.000", "expected each cell once");
}

// ------------------------------------------------------------------ prepared charts

// `chart prepare` as a library call: the file it writes is a prepared chart,
// and its JSON and text say what it holds.
TEST(PreparedChart, PrepareChartReportsWhatItWrote) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  ScratchDir tmp;
  const std::string gpkg = tmp.file("area.gpkg");
  const ChartPreparation done = prepare_chart({path}, "", at_depth(3.0), gpkg, false);
  ASSERT_TRUE(is_prepared_chart(gpkg));
  const nlohmann::json j = done.to_json();
  EXPECT_EQ(j["output"], gpkg);
  EXPECT_EQ(j["cells"], 1);
  EXPECT_EQ(j["local_crs"], "EPSG:32617");
  EXPECT_DOUBLE_EQ(j["required_depth_m"].get<double>(), 5.0);
  EXPECT_EQ(j["polygons"], done.no_go.obstacles.polygons.size());
  const std::string text = done.to_text();
  EXPECT_EQ(text.rfind("cell             US5FL4DQ  1:", 0), 0u) << text;
  EXPECT_NE(text.find("required depth   5.00 m (3.00 + 2.00 clearance)"), std::string::npos) << text;
  EXPECT_NE(text.find("wrote            " + gpkg + "\n"), std::string::npos) << text;
  // The output exists now: a second call is refused and leaves it.
  EXPECT_THROW(prepare_chart({path}, "", at_depth(3.0), gpkg, false), InputError);
  EXPECT_TRUE(is_prepared_chart(gpkg));
}

// is_prepared_chart keeps its answer per file (a plan asks several times):
// the same path holding another file must get that file's answer.
TEST(PreparedChart, IsPreparedChartFollowsTheFileAtThePath) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  ScratchDir tmp;
  const EncNoGoOptions o = at_depth(3.0);
  const EncNoGo made = enc_no_go({path}, std::nullopt, o);
  const std::string gpkg = tmp.file("area.gpkg");
  const std::string prepared = tmp.file("prepared.gpkg");
  const std::string plain = tmp.file("plain.gpkg");
  write_prepared_chart(prepared, made, o, false);
  write_obstacles(plain, made.obstacles, made.frame);
  std::filesystem::copy_file(prepared, gpkg);
  EXPECT_TRUE(is_prepared_chart(gpkg));
  std::filesystem::copy_file(plain, gpkg, std::filesystem::copy_options::overwrite_existing);
  EXPECT_FALSE(is_prepared_chart(gpkg));  // a GeoPackage of obstacles only
  std::ofstream(gpkg, std::ios::trunc) << "not a database";
  EXPECT_FALSE(is_prepared_chart(gpkg));
  std::filesystem::copy_file(prepared, gpkg, std::filesystem::copy_options::overwrite_existing);
  EXPECT_TRUE(is_prepared_chart(gpkg));
  EXPECT_FALSE(is_prepared_chart(tmp.file("absent.gpkg")));
}

TEST(PreparedChart, RoundTripKeepsTheNoGoAndRefusesAnotherDepth) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kKeyWest);
  ScratchDir tmp;
  const EncNoGoOptions o = at_depth(3.0);
  const EncNoGo made = enc_no_go({path}, std::nullopt, o);
  const std::string gpkg = tmp.file("area.gpkg");
  write_prepared_chart(gpkg, made, o, false);
  ASSERT_TRUE(is_prepared_chart(gpkg));
  EXPECT_FALSE(is_prepared_chart(path));
  PreparedChartInfo info;
  const EncNoGo back = read_prepared_chart(gpkg, std::nullopt, 3.0, 2.0, &info);
  EXPECT_EQ(back.frame.id(), made.frame.id());
  EXPECT_DOUBLE_EQ(back.required_depth_m, 5.0);
  EXPECT_NE(info.cells.find("US5FL4DQ edition 2"), std::string::npos) << info.cells;
  ASSERT_EQ(back.obstacles.polygons.size(), made.obstacles.polygons.size());
  ASSERT_EQ(back.obstacles.ellipses.size(), made.obstacles.ellipses.size());
  for (std::size_t i = 0; i < made.obstacles.polygons.size(); ++i) {
    const auto& a = made.obstacles.polygons[i].footprint.outer();
    const auto& b = back.obstacles.polygons[i].footprint.outer();
    ASSERT_EQ(a.size(), b.size()) << i;
    for (std::size_t k = 0; k < a.size(); k += 97) {
      EXPECT_LT((to_eigen(a[k]) - to_eigen(b[k])).norm(), 1e-6) << i << " " << k;
    }
  }
  ASSERT_EQ(back.features.size(), made.features.size());
  for (std::size_t i = 0; i < made.features.size(); ++i) {
    EXPECT_EQ(back.features[i].id, made.features[i].id);
    EXPECT_EQ(back.features[i].reason, made.features[i].reason);
    EXPECT_EQ(back.features[i].point.has_value(), made.features[i].point.has_value());
  }
  // The same route verdicts from both.
  const Vec2 a = made.frame.from_lonlat(-81.87, 24.54), b = made.frame.from_lonlat(-81.83, 24.59);
  EXPECT_EQ(check_route_on_chart({a, b}, back, 5.0).safe, check_route_on_chart({a, b}, made, 5.0).safe);
  // Another depth, or clearance, is refused; an existing file is kept without replace.
  expect_one_line_error([&] { read_prepared_chart(gpkg, std::nullopt, 4.0, 2.0); }, "area.gpkg",
                        "prepared for depth 3 m");
  expect_one_line_error([&] { read_prepared_chart(gpkg, std::nullopt, 3.0, 1.0); }, "area.gpkg", "prepare it again");
  expect_one_line_error([&] { write_prepared_chart(gpkg, made, o, false); }, "area.gpkg", "`overwrite`");
  expect_one_line_error([&] { write_prepared_chart(tmp.file("area.geojson"), made, o, true); }, "area.geojson",
                        "*.gpkg");
  expect_one_line_error([&] { read_prepared_chart(path, std::nullopt, 3.0, 2.0); }, "US5FL4DQ.000",
                        "expected a prepared chart");
  // Other options than it was prepared with are refused too.
  EncNoGoOptions exact = at_depth(3.0);
  exact.zoc = ZocPolicy::none;
  expect_one_line_error([&] { chart_no_go({gpkg}, std::nullopt, exact); }, "area.gpkg",
                        "prepared with zones of confidence");
  EXPECT_EQ(chart_no_go({gpkg}, std::nullopt, o).features.size(), made.features.size());
}

// The sea floor routes in depth take from a cell: never deeper than the
// depth area holding a point (less its least zone uncertainty, 0.5 m), land
// above the surface, and a route in depth over it found and checked.
TEST(EncSeaFloor, NeverDeeperThanTheChartAndLandIsDry) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32618");
  const Vec2 channel = frame.from_lonlat(-76.41, 38.87);
  const SeaFloor floor = enc_sea_floor({path}, frame, channel - Vec2(3000, 3000), channel + Vec2(3000, 3000), 10.0);
  // Independently: the depth area holding the point (OGR, GEOS).
  auto ds = open_ogr(path);
  OGRPoint here(-76.41, 38.87);
  double drval1 = std::nan("");
  for (auto& f : *ds->GetLayerByName("DEPARE")) {
    if (f->GetGeometryRef() != nullptr && f->GetGeometryRef()->Contains(&here)) drval1 = f->GetFieldAsDouble("DRVAL1");
  }
  ASSERT_TRUE(std::isfinite(drval1));
  EXPECT_GT(floor.depth_at(channel), 0.0);
  EXPECT_LE(floor.depth_at(channel), drval1 - 0.5 + 1e-9);
  // A point on land (west shore of the bay at 38.87 N).
  int land_nodes = 0;
  for (std::size_t j = 0; j < floor.ny(); ++j) {
    for (std::size_t i = 0; i < floor.nx(); ++i) land_nodes += floor.node_depth(i, j) < 0.0;
  }
  EXPECT_GT(land_nodes, 0);
  expect_one_line_error([&] { enc_sea_floor({path}, frame, channel, channel, 10.0); }, "sea floor", "box");
  expect_one_line_error([&] { enc_sea_floor({path}, frame, channel - Vec2(1, 1), channel, 0.0); }, "spacing", "> 0");
}

TEST(EncSeaFloor, RouteInDepthOverACell) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  ScratchDir tmp;
  const auto r = test::run_cli("plan --chart '" + path +
                               "' --graph octree --depth 5 --from -76.41,38.87 --to -76.415,38.84 --min-cell 2 -o '" +
                               tmp.file("r.geojson") + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GE(j["min_floor_gap_m"].get<double>(), 2.0 - 1e-9) << r.out;
}

TEST(EncSeaFloor, MissionOnACell) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  ScratchDir tmp;
  const std::string yaml = tmp.file("bay.yaml");
  std::ofstream(yaml) << "name: channel transit\nenvironment:\n  charts: ['" << path
                      << "']\nsafety:\n  margin_m: 5\n  vertical_clearance_m: 2\n"
                         "start: {lon: -76.41, lat: 38.87, depth_m: 0}\nmanoeuvres:\n  - track:\n      depth_m: 5\n"
                         "      speed_kn: 3\n      waypoints:\n        - {lon: -76.415, lat: 38.84}\n"
                         "        - {lon: -76.425, lat: 38.80}\n";
  const auto planned = test::run_cli("mission plan '" + yaml + "'");
  EXPECT_EQ(planned.exit_code, 0) << planned.err;
  EXPECT_NE(planned.out.find("check            safe"), std::string::npos) << planned.out;
  // A waypoint over a 3 m bank: refused with its place.
  std::string text;
  {
    std::ifstream in(yaml);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text.replace(text.find("-76.425"), 7, "-76.400");
  std::ofstream(yaml) << text;
  const auto shoal = test::run_cli("mission check '" + yaml + "'");
  EXPECT_EQ(shoal.exit_code, 1) << shoal.out;
  EXPECT_NE(shoal.err.find("expected water deeper than the manoeuvre's 5.0 m"), std::string::npos) << shoal.err;
}

// ------------------------------------------------------------------ the command line

TEST(EncCli, PlanGoesRoundTheShallowsAndCheckRouteNamesTheFirstCrossing) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  ScratchDir tmp;
  const std::string chart = "--chart '" + path + "' ";
  // The issue's straight route: flagged, the feature named, one line, exit 1.
  const std::string straight = tmp.file("straight.geojson");
  std::ofstream(straight) << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                          << R"("geometry":{"type":"LineString","coordinates":[[-76.45,38.45],[-76.42,38.55]]}}]})";
  const auto flagged = test::run_cli("check route '" + straight + "' " + chart + "--depth 8");
  EXPECT_EQ(flagged.exit_code, 1) << flagged.err;
  EXPECT_NE(flagged.err.find("crosses DEPARE/4363 of US4MD81M (DRVAL1 0 m < 10 m)"), std::string::npos) << flagged.err;
  EXPECT_EQ(std::count(flagged.err.begin(), flagged.err.end(), '\n'), 1) << flagged.err;
  // Its start lies on that bank: plan refuses with the feature named (exit 3).
  const auto refused = test::run_cli("plan " + chart + "--depth 8 --from -76.45,38.45 --to -76.42,38.55 -o '" +
                                     tmp.file("r.geojson") + "'");
  EXPECT_EQ(refused.exit_code, 3) << refused.err;
  EXPECT_NE(refused.err.find("start lies within 5.00 m of DEPARE/4363"), std::string::npos) << refused.err;
  // Two points in the deep channel whose straight line crosses shoals: the
  // route goes round them, and the check (which shares no code with the
  // planner's zones) passes it.
  const std::string route = tmp.file("round.geojson");
  const auto planned =
      test::run_cli("plan " + chart + "--depth 5 --from -76.41,38.87 --to -76.35,38.60 -o '" + route + "' --json");
  ASSERT_EQ(planned.exit_code, 0) << planned.err;
  const auto summary = nlohmann::json::parse(planned.out);
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, at_depth(5.0));
  const Vec2 a = no_go.frame.from_lonlat(-76.41, 38.87), b = no_go.frame.from_lonlat(-76.35, 38.60);
  EXPECT_FALSE(check_route_on_chart({a, b}, no_go, 5.0).safe) << "the straight line crosses shoals";
  EXPECT_GT(summary["length_m"].get<double>(), (b - a).norm() * 1.01);
  // Prepared once, the same route from the GeoPackage.
  const std::string gpkg = tmp.file("area.gpkg");
  ASSERT_EQ(test::run_cli("chart prepare '" + path + "' --depth 5 -o '" + gpkg + "'").exit_code, 0);
  const auto from_gpkg =
      test::run_cli("plan --chart '" + gpkg + "' --depth 5 --from -76.41,38.87 --to -76.35,38.60 -o '" +
                    tmp.file("round2.geojson") + "' --json");
  ASSERT_EQ(from_gpkg.exit_code, 0) << from_gpkg.err;
  EXPECT_NEAR(nlohmann::json::parse(from_gpkg.out)["length_m"].get<double>(), summary["length_m"].get<double>(), 1e-3);
  const auto other_depth = test::run_cli("plan --chart '" + gpkg + "' --depth 6 --from -76.41,38.87 --to -76.35,38.60");
  EXPECT_EQ(other_depth.exit_code, 1) << other_depth.err;
  const auto passed = test::run_cli("check route '" + route + "' " + chart + "--depth 5 --json");
  EXPECT_EQ(passed.exit_code, 0) << passed.err;
  EXPECT_TRUE(nlohmann::json::parse(passed.out)["safe"].get<bool>());
}

// The README's channel trip, planned to every format check route reads: the
// planner routes along the 5 m margin round a point of land, and each file
// read back passes (it once said "crosses LNDARE/6685"), while a margin 1 cm
// larger fails there, naming the land 5.00 m off. Under the sanitizers, one
// file read by OGR and one by libxml2 (each run reads the chart: 7 s there).
// With unclipped discs (--zoc strict): the default, clipped, takes another
// way 13 m shorter past a sounding whose C-zone disc no longer reaches there.
TEST(EncCli, EveryRouteFilePlanWritesPassesTheCheckAtItsMargin) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  ScratchDir tmp;
  const std::string chart = "--chart '" + path + "' --depth 5 --zoc strict ";
#ifdef DEEPGUIDE_SANITIZED
  const std::vector<const char*> formats = {"geojson", "rtz"};
#else
  const std::vector<const char*> formats = {"geojson", "gpx", "kml", "rtz", "csv"};
#endif
  for (const char* ext : formats) {
    const std::string route = tmp.file(std::string("trip.") + ext);
    const auto planned = test::run_cli("plan " + chart + "--from -76.41,38.87 --to -76.38,38.80 -o '" + route + "'");
    ASSERT_EQ(planned.exit_code, 0) << ext << ": " << planned.err;
    const auto passed = test::run_cli("check route '" + route + "' " + chart + "--json");
    EXPECT_EQ(passed.exit_code, 0) << ext << ": " << passed.err;
    if (passed.exit_code == 0) {
      const auto j = nlohmann::json::parse(passed.out);
      EXPECT_TRUE(j["safe"].get<bool>()) << ext;
      EXPECT_EQ(j["waypoints"].get<int>(), 10) << ext << ": the legs, not only the points";
      EXPECT_NEAR(j["length_m"].get<double>(), 8232.6, 0.1) << ext;
    }
    const auto tighter = test::run_cli("check route '" + route + "' " + chart + "--margin 5.01");
    EXPECT_EQ(tighter.exit_code, 1) << ext;
    EXPECT_NE(tighter.err.find("passes 5.00 m from LNDARE/6685 of US4MD81M (land; margin 5.01 m)"), std::string::npos)
        << ext << ": " << tighter.err;
  }
}

TEST(EncCli, BadChartsAreOneLineAndExitOne) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kChesapeake);
  DEEPGUIDE_REAL_FILE_OR_SKIP(key_west, kKeyWest);
  ScratchDir tmp;
  namespace fs = std::filesystem;
  const fs::path src = fs::path(path).parent_path();
  const fs::path gap = tmp.path() / "gap";
  fs::create_directories(gap);
  for (const char* ext : {".000", ".001", ".003"}) {
    fs::copy_file(src / ("US4MD81M" + std::string(ext)), gap / ("US4MD81M" + std::string(ext)));
  }
  const fs::path fake = tmp.path() / "FAKE.000";
  std::ofstream(fake) << "not a chart\n";
  const fs::path empty = tmp.path() / "empty";
  fs::create_directories(empty);
  const std::string no_depare = (tmp.path() / "NODEPARE.000").string();
  write_edited_cell(key_west, no_depare, {"M_COVR", "LNDARE"}, [](const std::string&, OGRFeature&) {});
  const std::string straight = tmp.file("straight.geojson");
  std::ofstream(straight) << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                          << R"("geometry":{"type":"LineString","coordinates":[[-76.45,38.45],[-76.42,38.55]]}}]})";
  for (const auto& [chart, says] :
       std::vector<std::pair<std::string, std::string>>{{(gap / "US4MD81M.000").string(), "expected update 2"},
                                                        {no_depare, "DEPARE"},
                                                        {fake.string(), "expected an S-57 ENC cell"},
                                                        {empty.string(), "found none"}}) {
    for (const std::string& cmd : {"check route '" + straight + "' --chart '" + chart + "' --depth 5",
                                   "plan --chart '" + chart + "' --depth 5 --from -76.41,38.87 --to -76.35,38.60",
                                   "chart prepare '" + chart + "' --depth 5 -o '" + tmp.file("x.gpkg") + "'"}) {
      const auto r = test::run_cli(cmd);
      EXPECT_EQ(r.exit_code, 1) << cmd << "\n" << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << cmd << "\n" << r.err;
      EXPECT_NE(r.err.find(says), std::string::npos) << cmd << "\n" << r.err;
    }
  }
  EXPECT_FALSE(fs::exists(tmp.file("x.gpkg"))) << "no half-written prepared chart";
}

}  // namespace
}  // namespace deepguide
