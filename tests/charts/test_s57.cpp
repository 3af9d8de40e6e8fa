// S-57 ENC cells: summaries and hazards checked against the facts stated in
// ../shared/data/real/SOURCES.md, and against independent OGR reads of the
// same files (the GeoJSON exports, the split soundings, the VALSOU fields).
// The real files are read in place; only a truncated scratch copy is written.

#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <boost/geometry/algorithms/area.hpp>
#include <boost/geometry/algorithms/correct.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>

#include "deepguide/charts/s57_chart.hpp"
#include "deepguide/core/error.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;

using test::real_file;
#define REAL_FILE_OR_SKIP(var, rel) DEEPGUIDE_REAL_FILE_OR_SKIP(var, rel)

const char* const kKeyWest = "noaa-enc-US5FL4DQ/US5FL4DQ.000";
const char* const kChesapeake = "noaa-enc-US4MD81M/US4MD81M.000";

GDALDatasetUniquePtr open_ogr(const std::string& path, std::vector<const char*> open_options = {}) {
  GDALAllRegister();
  open_options.push_back(nullptr);
  GDALDatasetUniquePtr ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, open_options.data(), nullptr));
  EXPECT_TRUE(ds) << path;
  return ds;
}

// Independent of the library: VALSOU of every feature of a class, by RCID.
std::map<long long, std::optional<double>> valsou_by_rcid(const std::string& path, const char* cls) {
  std::map<long long, std::optional<double>> out;
  auto ds = open_ogr(path);
  OGRLayer* layer = ds->GetLayerByName(cls);
  if (layer == nullptr) return out;
  for (auto& f : *layer) {
    const int i = f->GetFieldIndex("VALSOU");
    out[f->GetFieldAsInteger64("RCID")] =
        i >= 0 && f->IsFieldSetAndNotNull(i) ? std::optional<double>(f->GetFieldAsDouble(i)) : std::nullopt;
  }
  return out;
}

std::string class_of(const std::string& id) { return id.substr(0, id.find('/')); }

template <class Fn>
void for_each_obstacle(const ObstacleSet& set, Fn fn) {
  for (const auto& e : set.ellipses) fn(e.id, e.top_depth_m);
  for (const auto& p : set.polygons) fn(p.id, p.top_depth_m);
}

// ---------------------------------------------------------------- summaries

TEST(S57Summary, KeyWestCellMatchesSources) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  const S57Summary s = summarize_s57(path);
  const std::map<std::string, std::size_t> expected{{"OBSTRN", 15},  {"WRECKS", 4},  {"UWTROC", 22}, {"DEPARE", 97},
                                                    {"DEPCNT", 121}, {"LNDARE", 43}, {"COALNE", 45}, {"SOUNDG", 11}};
  for (const auto& [cls, n] : expected) EXPECT_EQ(s.layer_counts.at(cls), n) << cls;
  EXPECT_EQ(s.edition, "2");
  EXPECT_EQ(s.update_number, 0);
  EXPECT_EQ(s.issue_date, "20231016");
  EXPECT_EQ(s.soundings, 1792u);
  EXPECT_NEAR(s.sounding_min_m, 0.3, 1e-9);
  EXPECT_NEAR(s.sounding_max_m, 10.6, 1e-9);
  EXPECT_NEAR(s.depare_min_m, -0.4, 1e-9);
  EXPECT_NEAR(s.depare_max_m, 18.2, 1e-9);
  EXPECT_NEAR(s.extent.west, -81.900, 1e-6);
  EXPECT_NEAR(s.extent.east, -81.825, 1e-6);
  EXPECT_NEAR(s.extent.south, 24.525, 1e-6);
  EXPECT_NEAR(s.extent.north, 24.600, 1e-6);
}

TEST(S57Summary, ChesapeakeCellAppliesItsUpdates) {
  REAL_FILE_OR_SKIP(path, kChesapeake);
  const S57Summary s = summarize_s57(path);
  const std::map<std::string, std::size_t> expected{{"OBSTRN", 219}, {"WRECKS", 111}, {"UWTROC", 18},   {"DEPARE", 525},
                                                    {"DEPCNT", 566}, {"LNDARE", 183}, {"COALNE", 1826}, {"SOUNDG", 56}};
  for (const auto& [cls, n] : expected) EXPECT_EQ(s.layer_counts.at(cls), n) << cls;
  EXPECT_EQ(s.edition, "31");
  EXPECT_EQ(s.update_number, 3);
  EXPECT_EQ(s.issue_date, "20250923");
  EXPECT_EQ(s.soundings, 3326u);
  EXPECT_NEAR(s.sounding_min_m, 0.1, 1e-9);
  EXPECT_NEAR(s.sounding_max_m, 41.4, 1e-9);
  EXPECT_NEAR(s.depare_min_m, -0.4, 1e-9);
  EXPECT_NEAR(s.depare_max_m, 54.8, 1e-9);
  EXPECT_NEAR(s.extent.west, -76.6223, 1e-4);
  EXPECT_NEAR(s.extent.east, -75.9975, 1e-4);
  EXPECT_NEAR(s.extent.south, 38.3468, 1e-4);
  EXPECT_NEAR(s.extent.north, 39.0532, 1e-4);
}

TEST(S57Summary, ChesapeakeCellWithUpdatesIgnored) {
  REAL_FILE_OR_SKIP(path, kChesapeake);
  const S57Summary with = summarize_s57(path, true);
  const S57Summary without = summarize_s57(path, false);
  EXPECT_EQ(without.update_number, 0);
  EXPECT_EQ(without.layer_counts.at("SOUNDG"), 52u);
  EXPECT_EQ(without.layer_counts.at("WRECKS"), 110u);
  // "The other counts above are unchanged."
  for (const char* cls : {"OBSTRN", "UWTROC", "DEPARE", "DEPCNT", "LNDARE", "COALNE"}) {
    EXPECT_EQ(without.layer_counts.at(cls), with.layer_counts.at(cls)) << cls;
  }
}

// The summary counts the points of the SOUNDG multipoints and takes their z;
// GDAL's own split (SPLIT_MULTIPOINT, ADD_SOUNDG_DEPTH) must give the same.
TEST(S57Summary, SoundingsAgreeWithTheDriversSplitMultipoints) {
  for (const char* rel : {kKeyWest, kChesapeake}) {
    REAL_FILE_OR_SKIP(path, rel);
    const S57Summary s = summarize_s57(path);
    auto ds = open_ogr(path, {"SPLIT_MULTIPOINT=ON", "ADD_SOUNDG_DEPTH=ON"});
    OGRLayer* layer = ds->GetLayerByName("SOUNDG");
    ASSERT_NE(layer, nullptr);
    std::size_t n = 0;
    double lo = 1e9, hi = -1e9;
    for (auto& f : *layer) {
      ++n;
      const double d = f->GetFieldAsDouble("DEPTH");
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    EXPECT_EQ(s.soundings, n) << rel;
    EXPECT_DOUBLE_EQ(s.sounding_min_m, lo) << rel;
    EXPECT_DOUBLE_EQ(s.sounding_max_m, hi) << rel;
  }
}

// ------------------------------------------------------------------ hazards

TEST(S57Hazards, KeyWestMatchesTheGeoJsonExportsFeatureByFeature) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  const std::string geo_dir = real_file("geojson-US5FL4DQ/US5FL4DQ_OBSTRN.geojson");
  if (geo_dir.empty()) GTEST_SKIP() << "../shared/data/real/geojson-US5FL4DQ is absent";
  const S57Summary s = summarize_s57(path);
  const LocalFrame frame = s57_local_frame(s);
  const S57Hazards h = s57_hazards(path, frame);
  EXPECT_EQ(h.skipped_lines, 0u);
  EXPECT_EQ(h.skipped_empty, 0u);
  EXPECT_EQ(h.removed_by_depth, 0u);

  std::map<std::string, const EllipticCylinder*> ellipses;
  std::map<std::string, const PolygonObstacle*> polygons;
  for (const auto& e : h.obstacles.ellipses) ellipses[e.id] = &e;
  for (const auto& p : h.obstacles.polygons) polygons[p.id] = &p;
  EXPECT_EQ(ellipses.size(), h.obstacles.ellipses.size()) << "ids are unique";
  EXPECT_EQ(polygons.size(), h.obstacles.polygons.size()) << "ids are unique";

  const std::map<std::string, std::size_t> sources_counts{
      {"OBSTRN", 15}, {"WRECKS", 4}, {"UWTROC", 22}, {"LNDARE", 43}};
  std::size_t total = 0;
  for (const auto& [cls, expected] : sources_counts) {
    auto ds = open_ogr(fs::path(geo_dir).parent_path() / ("US5FL4DQ_" + cls + ".geojson"));
    OGRLayer* layer = ds->GetLayer(0);
    EXPECT_EQ(layer->GetFeatureCount(), static_cast<GIntBig>(expected)) << cls;
    EXPECT_EQ(h.features_read.at(cls), expected) << cls;
    std::size_t from_cell = 0;
    for_each_obstacle(h.obstacles, [&](const std::string& id, const auto&) { from_cell += class_of(id) == cls; });
    EXPECT_EQ(from_cell, expected) << cls << ": one obstacle per feature";
    total += expected;
    for (auto& f : *layer) {
      const std::string id = cls + "/" + std::to_string(f->GetFieldAsInteger64("RCID"));
      const OGRGeometry* g = f->GetGeometryRef();
      const int vi = f->GetFieldIndex("VALSOU");
      const std::optional<double> valsou = cls != "LNDARE" && vi >= 0 && f->IsFieldSetAndNotNull(vi)
                                               ? std::optional<double>(f->GetFieldAsDouble(vi))
                                               : std::nullopt;
      if (wkbFlatten(g->getGeometryType()) == wkbPoint) {
        ASSERT_TRUE(ellipses.count(id)) << id;
        const EllipticCylinder& e = *ellipses[id];
        const Vec2 expected_xy = frame.from_lonlat(g->toPoint()->getX(), g->toPoint()->getY());
        // The export keeps 7 decimals (about 1 cm); the cell stores 1e-7 degree units too.
        EXPECT_LT((e.footprint.centre - expected_xy).norm(), 0.02) << id;
        EXPECT_DOUBLE_EQ(e.footprint.a, 10.0) << id;
        EXPECT_DOUBLE_EQ(e.footprint.b, 10.0) << id;
        EXPECT_EQ(e.top_depth_m.has_value(), valsou.has_value()) << id;
        if (valsou) {
          EXPECT_DOUBLE_EQ(*e.top_depth_m, std::max(*valsou, 0.0)) << id;
        }
      } else {
        ASSERT_EQ(wkbFlatten(g->getGeometryType()), wkbPolygon) << id;
        ASSERT_TRUE(polygons.count(id)) << id;
        const PolygonObstacle& p = *polygons[id];
        BgPolygon expected_poly;
        const OGRLinearRing* ring = g->toPolygon()->getExteriorRing();
        for (int i = 0; i < ring->getNumPoints(); ++i) {
          expected_poly.outer().push_back(to_bg(frame.from_lonlat(ring->getX(i), ring->getY(i))));
        }
        for (int k = 0; k < g->toPolygon()->getNumInteriorRings(); ++k) {
          const OGRLinearRing* in = g->toPolygon()->getInteriorRing(k);
          auto& dst = expected_poly.inners().emplace_back();
          for (int i = 0; i < in->getNumPoints(); ++i) {
            dst.push_back(to_bg(frame.from_lonlat(in->getX(i), in->getY(i))));
          }
        }
        boost::geometry::correct(expected_poly);
        EXPECT_EQ(p.footprint.outer().size(), expected_poly.outer().size()) << id;
        EXPECT_EQ(p.footprint.inners().size(), expected_poly.inners().size()) << id;
        const double a = boost::geometry::area(p.footprint);
        EXPECT_GT(a, 0.0) << id << ": corrected orientation";
        EXPECT_NEAR(a, boost::geometry::area(expected_poly), 1e-4 * a + 0.05) << id;
        EXPECT_EQ(p.top_depth_m.has_value(), valsou.has_value()) << id;
      }
    }
  }
  EXPECT_EQ(h.obstacles.size(), total);
  // SOURCES: WRECKS is mixed Point/Polygon (3 points, 1 polygon); the others are all one kind.
  EXPECT_EQ(h.obstacles.ellipses.size(), 15u + 3u + 22u);
  EXPECT_EQ(h.obstacles.polygons.size(), 1u + 43u);
}

TEST(S57Hazards, ValsouRangesMatchSources) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  REAL_FILE_OR_SKIP(chesapeake, kChesapeake);
  struct Range {
    const char* file;
    const char* cls;
    double lo, hi;
  };
  for (const Range& r :
       {Range{path.c_str(), "OBSTRN", 5.7, 7.0}, Range{path.c_str(), "WRECKS", 3.0, 3.0},
        Range{chesapeake.c_str(), "WRECKS", 0.6, 31.5}, Range{chesapeake.c_str(), "OBSTRN", 0.3, 27.4}}) {
    const S57Summary s = summarize_s57(r.file);
    const S57Hazards h = s57_hazards(r.file, s57_local_frame(s));
    double lo = 1e9, hi = -1e9;
    for_each_obstacle(h.obstacles, [&](const std::string& id, const std::optional<double>& top) {
      if (class_of(id) == r.cls && top) lo = std::min(lo, *top), hi = std::max(hi, *top);
    });
    EXPECT_NEAR(lo, r.lo, 1e-9) << r.file << " " << r.cls;
    EXPECT_NEAR(hi, r.hi, 1e-9) << r.file << " " << r.cls;
  }
}

TEST(S57Hazards, ChesapeakeCountsLinesAndUpdates) {
  REAL_FILE_OR_SKIP(path, kChesapeake);
  const S57Summary s = summarize_s57(path);
  const LocalFrame frame = s57_local_frame(s);
  const S57Hazards h = s57_hazards(path, frame);
  EXPECT_EQ(h.features_read.at("OBSTRN"), 219u);
  EXPECT_EQ(h.features_read.at("WRECKS"), 111u);
  EXPECT_EQ(h.features_read.at("UWTROC"), 18u);
  EXPECT_EQ(h.features_read.at("LNDARE"), 183u);
  // Independently: line features of the four classes are skipped and counted.
  std::size_t lines = 0, multi_parts_extra = 0;
  auto ds = open_ogr(path);
  for (const char* cls : {"OBSTRN", "WRECKS", "UWTROC", "LNDARE"}) {
    for (auto& f : *ds->GetLayerByName(cls)) {
      const OGRGeometry* g = f->GetGeometryRef();
      if (g == nullptr) continue;
      const auto t = wkbFlatten(g->getGeometryType());
      lines += t == wkbLineString || t == wkbMultiLineString;
      if (t == wkbMultiPolygon || t == wkbMultiPoint) {
        multi_parts_extra += g->toGeometryCollection()->getNumGeometries() - 1;
      }
    }
  }
  EXPECT_EQ(h.skipped_lines, lines);
  EXPECT_GE(h.skipped_lines, 1u) << "the cell has an OBSTRN line";
  EXPECT_EQ(h.obstacles.size() + h.skipped_lines + h.skipped_empty, 219u + 111u + 18u + 183u + multi_parts_extra);

  S57Options base_only;
  base_only.apply_updates = false;
  const S57Hazards old = s57_hazards(path, frame, base_only);
  EXPECT_EQ(old.features_read.at("WRECKS"), 110u);
  EXPECT_EQ(old.features_read.at("OBSTRN"), 219u);
}

TEST(S57Hazards, DepthFilterDropsHazardsTheVehiclePassesAbove) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  const LocalFrame frame = s57_local_frame(summarize_s57(path));
  const S57Hazards all = s57_hazards(path, frame);
  S57Options o;
  o.operating_depth_m = 1.0;
  o.vertical_clearance_m = 2.0;  // drop VALSOU > 3 m
  const S57Hazards shallow = s57_hazards(path, frame, o);

  // Counted from the cell's VALSOU fields, independently of the library.
  std::set<std::string> deep;
  std::size_t at_limit = 0;
  for (const char* cls : {"OBSTRN", "WRECKS", "UWTROC"}) {
    for (const auto& [rcid, valsou] : valsou_by_rcid(path, cls)) {
      if (valsou && *valsou > 3.0) deep.insert(std::string(cls) + "/" + std::to_string(rcid));
      at_limit += valsou && *valsou == 3.0;
    }
  }
  ASSERT_FALSE(deep.empty()) << "OBSTRN VALSOU runs 5.7-7.0";
  EXPECT_GE(at_limit, 1u) << "the WRECKS polygon has VALSOU 3.0";
  EXPECT_EQ(shallow.removed_by_depth, deep.size());
  EXPECT_EQ(shallow.obstacles.size(), all.obstacles.size() - deep.size());
  std::size_t land = 0, kept_at_limit = 0;
  for_each_obstacle(shallow.obstacles, [&](const std::string& id, const std::optional<double>& top) {
    EXPECT_FALSE(deep.count(id)) << id;
    if (top) {
      EXPECT_LE(*top, 3.0) << id;
    }
    kept_at_limit += top && *top == 3.0;
    land += class_of(id) == "LNDARE";
  });
  EXPECT_EQ(land, 43u) << "land is always an obstacle";
  EXPECT_EQ(kept_at_limit, at_limit) << "a top exactly at depth + clearance stays an obstacle";

  // Deep enough, every hazard with a VALSOU is in the way; shallower than all, none is.
  o.operating_depth_m = 20.0;
  EXPECT_EQ(s57_hazards(path, frame, o).removed_by_depth, 0u);
  o.operating_depth_m = 0.0;
  o.vertical_clearance_m = 0.0;
  std::size_t with_valsou = 0;
  for_each_obstacle(all.obstacles,
                    [&](const std::string&, const std::optional<double>& top) { with_valsou += top && *top > 0.0; });
  EXPECT_EQ(s57_hazards(path, frame, o).removed_by_depth, with_valsou);
}

TEST(S57Hazards, PointHazardRadiusIsTheDocumentedDefaultOrTheOption) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  const LocalFrame frame = s57_local_frame(summarize_s57(path));
  EXPECT_DOUBLE_EQ(S57Options{}.point_hazard_radius_m, 10.0);
  S57Options o;
  o.point_hazard_radius_m = 25.0;
  const S57Hazards h = s57_hazards(path, frame, o);
  ASSERT_EQ(h.obstacles.ellipses.size(), 40u);
  for (const auto& e : h.obstacles.ellipses) {
    EXPECT_DOUBLE_EQ(e.footprint.a, 25.0) << e.id;
    EXPECT_DOUBLE_EQ(e.footprint.b, 25.0) << e.id;
  }
  for (double bad : {0.0, -1.0, std::nan("")}) {
    o.point_hazard_radius_m = bad;
    EXPECT_THROW(s57_hazards(path, frame, o), InputError) << bad;
  }
}

TEST(S57Hazards, EveryObstacleLiesInsideTheCell) {
  for (const char* rel : {kKeyWest, kChesapeake}) {
    REAL_FILE_OR_SKIP(path, rel);
    const S57Summary s = summarize_s57(path);
    const LocalFrame frame = s57_local_frame(s);
    const S57Hazards h = s57_hazards(path, frame);
    ASSERT_FALSE(h.obstacles.empty());
    const double tol = 1e-7;  // degrees; the round trip through the frame is far finer
    auto inside = [&](const Vec2& xy, const std::string& id) {
      const Eigen::Vector2d ll = frame.to_lonlat(xy);
      EXPECT_GE(ll.x(), s.extent.west - tol) << rel << " " << id;
      EXPECT_LE(ll.x(), s.extent.east + tol) << rel << " " << id;
      EXPECT_GE(ll.y(), s.extent.south - tol) << rel << " " << id;
      EXPECT_LE(ll.y(), s.extent.north + tol) << rel << " " << id;
    };
    for (const auto& e : h.obstacles.ellipses) inside(e.footprint.centre, e.id);
    for (const auto& p : h.obstacles.polygons) {
      for (const auto& v : p.footprint.outer()) inside(Vec2(v.x(), v.y()), p.id);
    }
  }
}

TEST(S57Hazards, ExplicitLocalCrsIsUsed) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  S57Options o;
  o.local_crs = "EPSG:32617";  // Key West lies in UTM zone 17N
  const S57Summary s = summarize_s57(path);
  EXPECT_EQ(s57_local_frame(s, o).id(), "EPSG:32617");
  EXPECT_EQ(s57_local_frame(s).id(), "EPSG:32617");
  o.local_crs = "EPSG:4326";  // not projected
  EXPECT_THROW(s57_local_frame(s, o), InputError);
}

// ---------------------------------------------------------------- bad input

void expect_one_line_error_naming(const std::function<void()>& fn, const std::string& path) {
  try {
    fn();
    ADD_FAILURE() << "no InputError for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

TEST(S57Errors, TruncatedCellIsAOneLineErrorNamingTheFile) {
  REAL_FILE_OR_SKIP(path, kKeyWest);
  test::ScratchDir tmp;
  std::string head(20000, '\0');
  {
    std::ifstream in(path, std::ios::binary);
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    ASSERT_EQ(in.gcount(), 20000);
  }
  const std::string cut = tmp.write("US5FL4DQ.000", head);
  const LocalFrame frame = LocalFrame::utm_for(-81.86, 24.56);
  ::testing::internal::CaptureStderr();
  expect_one_line_error_naming([&] { summarize_s57(cut); }, cut);
  expect_one_line_error_naming([&] { s57_hazards(cut, frame); }, cut);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "GDAL's own message stays quiet";
}

TEST(S57Errors, MissingFileNotAnS57CellAndAFolder) {
  test::ScratchDir tmp;
  const LocalFrame frame = LocalFrame::utm_for(-81.86, 24.56);
  const std::string missing = tmp.file("NOPE0000.000");
  expect_one_line_error_naming([&] { summarize_s57(missing); }, missing);
  expect_one_line_error_naming([&] { s57_hazards(missing, frame); }, missing);
  // GeoJSON text under an S-57 name: only the S57 driver may open a chart.
  const std::string geojson =
      tmp.write("FAKE0000.000", R"({"type":"FeatureCollection","features":[{"type":"Feature",)"
                                R"("properties":{},"geometry":{"type":"Point","coordinates":[1,2]}}]})");
  expect_one_line_error_naming([&] { summarize_s57(geojson); }, geojson);
  const std::string empty = tmp.write("EMPTY000.000", "");
  expect_one_line_error_naming([&] { s57_hazards(empty, frame); }, empty);
  expect_one_line_error_naming([&] { summarize_s57(tmp.path().string()); }, tmp.path().string());
}

}  // namespace
}  // namespace deepguide
