// Obstacle files through OGR: reading each format, and round trips.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <boost/geometry/algorithms/area.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_summary.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

// Difference of two axis directions, modulo pi (an ellipse is symmetric).
double axis_diff(double a, double b) {
  const double d = std::fmod(std::abs(a - b), kPi);
  return std::min(d, kPi - d);
}

// A random obstacle set in UTM 32N around Kiel Bight, local coordinates.
ObstacleSet random_set(std::mt19937& rng, int n_ellipses, int n_polygons) {
  std::uniform_real_distribution<double> x(570000.0, 590000.0), y(6020000.0, 6040000.0);
  std::uniform_real_distribution<double> axis(0.5, 200.0), ang(-kPi, kPi), u(0.0, 1.0);
  ObstacleSet set;
  for (int i = 0; i < n_ellipses; ++i) {
    EllipticCylinder c;
    c.id = "e" + std::to_string(i);
    c.footprint.centre = {x(rng), y(rng)};
    const double a = axis(rng), b = axis(rng);
    c.footprint.a = std::max(a, b);
    c.footprint.b = std::min(a, b);
    c.footprint.theta = ang(rng);
    if (i % 3 == 0) c.height_m = 0.1 + 30.0 * u(rng);
    if (i % 3 == 1) c.top_depth_m = 100.0 * u(rng);
    set.ellipses.push_back(c);
  }
  for (int i = 0; i < n_polygons; ++i) {
    PolygonObstacle p;
    p.id = "p" + std::to_string(i);
    const Vec2 c(x(rng), y(rng));
    const int n = 3 + i % 6;
    for (int k = 0; k < n; ++k) {
      const double t = -2.0 * kPi * k / n;  // clockwise, as Boost expects
      p.footprint.outer().push_back(to_bg(c + (20.0 + 80.0 * u(rng)) * Vec2(std::cos(t), std::sin(t))));
    }
    p.footprint.outer().push_back(p.footprint.outer().front());
    if (i % 2 == 0) p.top_depth_m = 5.0 + i;
    set.polygons.push_back(p);
  }
  return set;
}

void expect_same(const ObstacleSet& want, const ObstacleSet& got, double tol_m) {
  ASSERT_EQ(got.ellipses.size(), want.ellipses.size());
  ASSERT_EQ(got.polygons.size(), want.polygons.size());
  for (std::size_t i = 0; i < want.ellipses.size(); ++i) {
    const auto& w = want.ellipses[i];
    const auto& g = got.ellipses[i];
    EXPECT_EQ(g.id, w.id);
    EXPECT_LT((g.footprint.centre - w.footprint.centre).norm(), tol_m) << w.id;
    EXPECT_NEAR(g.footprint.a, w.footprint.a, 1e-9);
    EXPECT_NEAR(g.footprint.b, w.footprint.b, 1e-9);
    // Angle error times the semi-major axis is the displacement of the axis tip.
    EXPECT_LT(axis_diff(g.footprint.theta, w.footprint.theta) * w.footprint.a, tol_m) << w.id;
    EXPECT_EQ(g.height_m.has_value(), w.height_m.has_value());
    EXPECT_EQ(g.top_depth_m.has_value(), w.top_depth_m.has_value());
    if (w.height_m) {
      EXPECT_NEAR(*g.height_m, *w.height_m, 1e-9);
    }
    if (w.top_depth_m) {
      EXPECT_NEAR(*g.top_depth_m, *w.top_depth_m, 1e-9);
    }
  }
  for (std::size_t i = 0; i < want.polygons.size(); ++i) {
    const auto& w = want.polygons[i].footprint.outer();
    const auto& g = got.polygons[i].footprint.outer();
    EXPECT_EQ(got.polygons[i].id, want.polygons[i].id);
    ASSERT_EQ(g.size(), w.size());
    // Same closed ring, possibly starting at another vertex: match by nearest.
    for (const auto& pw : w) {
      double best = 1e300;
      for (const auto& pg : g) best = std::min(best, (to_eigen(pg) - to_eigen(pw)).norm());
      EXPECT_LT(best, tol_m);
    }
    EXPECT_EQ(got.polygons[i].top_depth_m.has_value(), want.polygons[i].top_depth_m.has_value());
  }
}

}  // namespace

class RoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, LocalToFileToLocalWithinAMicrometre) {
  ScratchDir dir;
  std::mt19937 rng(2024);
  const ObstacleSet set = random_set(rng, 60, 12);
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const std::string path = dir.file("obstacles" + GetParam());
  write_obstacles(path, set, frame);
  const LoadedObstacles back = load_obstacles({path}, {"EPSG:32632", ""});
  EXPECT_EQ(back.frame.id(), "EPSG:32632");
  expect_same(set, back.obstacles, 1e-6);
  // A second round trip from the file read back is stable too.
  const std::string again = dir.file("again" + GetParam());
  write_obstacles(again, back.obstacles, back.frame);
  expect_same(set, load_obstacles({again}, {"EPSG:32632", ""}).obstacles, 1e-6);
}

TEST_P(RoundTrip, AxesSurviveWhereTheFrameStretchesThem) {
  // 190 to 210 km east of 9 E the UTM frame stretches lengths by 4e-5 to 1.3e-4: the reader
  // makes a file's true metres frame metres there, so the writer must give
  // true metres back, or every round trip grew the axes by that much.
  ScratchDir dir;
  std::mt19937 rng(77);
  ObstacleSet set = random_set(rng, 30, 0);
  for (EllipticCylinder& e : set.ellipses) e.footprint.centre.x() += 120000.0;
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  ASSERT_GT(frame.scale_at(frame.to_lonlat(set.ellipses[0].footprint.centre)).greatest, 1.00003);
  // The scale is read at the centre as the file gives it back, to about 1e-8:
  // the axes return to that, where the old writer grew them by the stretch.
  const auto expect_axes = [&](const ObstacleSet& got) {
    ASSERT_EQ(got.ellipses.size(), set.ellipses.size());
    for (std::size_t i = 0; i < set.ellipses.size(); ++i) {
      const Ellipse &w = set.ellipses[i].footprint, &g = got.ellipses[i].footprint;
      EXPECT_LT((g.centre - w.centre).norm(), 1e-6);
      EXPECT_NEAR(g.a, w.a, 1e-7 * w.a) << i;
      EXPECT_NEAR(g.b, w.b, 1e-7 * w.b) << i;
      EXPECT_LT(axis_diff(g.theta, w.theta) * w.a, 1e-6) << i;
    }
  };
  const std::string path = dir.file("stretched" + GetParam());
  write_obstacles(path, set, frame);
  const LoadedObstacles back = load_obstacles({path}, {"EPSG:32632", ""});
  expect_axes(back.obstacles);
  const std::string again = dir.file("again" + GetParam());
  write_obstacles(again, back.obstacles, back.frame);
  expect_axes(load_obstacles({again}, {"EPSG:32632", ""}).obstacles);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip, ::testing::Values(".geojson", ".gpkg", ".csv"),
                         [](const auto& info) { return info.param.substr(1); });

TEST(ObstacleRead, LonLatToUtmToLonLatKeepsPositions) {
  // Hand-written lon/lat file -> local UTM -> written lon/lat, compared in metres.
  ScratchDir dir;
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> lon(-81.9, -81.8), lat(24.50, 24.60);
  std::string json = R"({"type":"FeatureCollection","features":[)";
  std::vector<Eigen::Vector2d> want;
  for (int i = 0; i < 50; ++i) {
    want.emplace_back(lon(rng), lat(rng));
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  R"(%s{"type":"Feature","properties":{"id":"k%d","semi_major_m":12.5,"semi_minor_m":4,)"
                  R"("orientation_deg":%d},"geometry":{"type":"Point","coordinates":[%.15f,%.15f]}})",
                  i ? "," : "", i, 7 * i, want.back().x(), want.back().y());
    json += buf;
  }
  json += "]}";
  const std::string in = dir.write("in.geojson", json);
  const LoadedObstacles loaded = load_obstacles({in});
  EXPECT_EQ(loaded.frame.id(), "EPSG:32617");
  const std::string out = dir.file("out.geojson");
  write_obstacles(out, loaded.obstacles, loaded.frame);

  // Read the written coordinates with OGR directly, not with our reader.
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR));
  ASSERT_TRUE(ds);
  OGRLayer* layer = ds->GetLayer(0);
  int i = 0;
  for (auto& f : *layer) {
    const OGRPoint* p = f->GetGeometryRef()->toPoint();
    const double dlat_m = (p->getY() - want[i].y()) * 111320.0;
    const double dlon_m = (p->getX() - want[i].x()) * 111320.0 * std::cos(deg_to_rad(want[i].y()));
    EXPECT_LT(std::hypot(dlat_m, dlon_m), 1e-6) << "feature " << i;
    EXPECT_NEAR(f->GetFieldAsDouble("orientation_deg"), std::fmod(7.0 * i, 180.0), 1e-9);
    ++i;
  }
  EXPECT_EQ(i, 50);
}

TEST(ObstacleRead, OrientationIsFromTrueNorthNotGridNorth) {
  // 3 degrees east of the central meridian of zone 32 at 54.45 N grid north and
  // true north differ by ~2.44 degrees; a heading of 0 must follow the meridian.
  ScratchDir dir;
  const std::string path = dir.write("n.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"semi_major_m":100,"semi_minor_m":10,"orientation_deg":0},
     "geometry":{"type":"Point","coordinates":[12.0,54.45]}}]})");
  const LoadedObstacles l = load_obstacles({path}, {"EPSG:32632", ""});
  const Ellipse& e = l.obstacles.ellipses.at(0).footprint;
  // The tip of the major axis and the point 100 m due north (from the frame) coincide.
  const Eigen::Vector2d centre_ll = l.frame.to_lonlat(e.centre);
  const Eigen::Vector2d north_tip = l.frame.from_lonlat(centre_ll.x(), centre_ll.y() + 100.0 / 111400.0);
  const Vec2 dir_north = (north_tip - e.centre).normalized();
  EXPECT_LT(axis_diff(math_angle(dir_north), e.theta), 1e-6);
  EXPECT_GT(std::abs(e.theta - kPi / 2), deg_to_rad(2.0));  // and it is not grid north
}

TEST(ObstacleRead, PointAtCentralMeridianLandsAtFalseEasting) {
  ScratchDir dir;
  const std::string path = dir.write("c.csv", "lon,lat,semi_major_m,semi_minor_m,orientation_deg\n9,0,10,5,30\n");
  const LoadedObstacles l = load_obstacles({path}, {"EPSG:32632", ""});
  ASSERT_EQ(l.obstacles.ellipses.size(), 1u);
  const Ellipse& e = l.obstacles.ellipses[0].footprint;
  EXPECT_NEAR(e.centre.x(), 500000.0, 1e-6);
  EXPECT_NEAR(e.centre.y(), 0.0, 1e-6);
  EXPECT_NEAR(e.theta, deg_to_rad(60.0), 1e-9);  // heading 30 = math 60 degrees here
  EXPECT_EQ(e.a, 10.0);
  EXPECT_EQ(e.b, 5.0);
}

TEST(ObstacleRead, DefaultsCircleAndWholeWaterColumn) {
  ScratchDir dir;
  const std::string path = dir.write("d.csv", "lon,lat,semi_major_m\n10.1,54.2,7.5\n");
  const LoadedObstacles l = load_obstacles({path});
  const EllipticCylinder& c = l.obstacles.ellipses.at(0);
  EXPECT_EQ(c.footprint.a, 7.5);
  EXPECT_EQ(c.footprint.b, 7.5);
  EXPECT_FALSE(c.height_m);
  EXPECT_FALSE(c.top_depth_m);
  EXPECT_EQ(l.sources.at(0).crs, "none in file, read as EPSG:4326");
}

TEST(ObstacleRead, CsvWithWktColumnAndProjectedSourceCrs) {
  ScratchDir dir;
  const std::string path =
      dir.write("w.csv",
                "WKT,id,semi_major_m,semi_minor_m,orientation_deg,top_depth_m\n"
                "\"POINT (500000 6000000)\",a,20,10,90,\n"
                "\"POLYGON ((500100 6000100,500200 6000100,500200 6000200,500100 6000100))\",b,,,,12.5\n");
  const LoadedObstacles l = load_obstacles({path}, {"EPSG:32632", "EPSG:32632"});
  ASSERT_EQ(l.obstacles.ellipses.size(), 1u);
  ASSERT_EQ(l.obstacles.polygons.size(), 1u);
  EXPECT_NEAR(l.obstacles.ellipses[0].footprint.centre.x(), 500000.0, 1e-6);
  EXPECT_NEAR(l.obstacles.ellipses[0].footprint.centre.y(), 6000000.0, 1e-6);
  EXPECT_EQ(*l.obstacles.polygons[0].top_depth_m, 12.5);
  EXPECT_NEAR(std::abs(boost::geometry::area(l.obstacles.polygons[0].footprint)), 5000.0, 1e-6);
  EXPECT_EQ(l.obstacles.polygons[0].id, "b");
}

// Writes one Point feature at (x, y) of EPSG:32632 with the given real fields,
// through OGR directly (not our writer), into a new file of the named driver.
void write_utm_point(const char* driver, const std::string& path,
                     const std::vector<std::pair<const char*, double>>& fields, double x, double y) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(driver);
  ASSERT_NE(drv, nullptr);
  GDALDatasetUniquePtr ds(drv->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  ASSERT_TRUE(ds);
  OGRSpatialReference srs;
  srs.importFromEPSG(32632);
  OGRLayer* layer = ds->CreateLayer("contacts", &srs, wkbPoint, nullptr);
  for (const auto& [name, value] : fields) {
    OGRFieldDefn fd(name, OFTReal);
    ASSERT_EQ(layer->CreateField(&fd), OGRERR_NONE);
  }
  OGRFeature f(layer->GetLayerDefn());
  for (const auto& [name, value] : fields) f.SetField(name, value);
  OGRPoint p(x, y);
  f.SetGeometry(&p);
  ASSERT_EQ(layer->CreateFeature(&f), OGRERR_NONE);
}

TEST(ObstacleRead, ShapefileInAProjectedCrsWithTruncatedFieldNames) {
  // Shapefile field names are at most 10 characters, so semi_major_m arrives
  // as semi_major; the reader accepts that.
  ScratchDir dir;
  const std::string shp = dir.file("hazards.shp");
  write_utm_point("ESRI Shapefile", shp,
                  {{"semi_major", 30.0}, {"semi_minor", 12.0}, {"orientatio", 90.0}, {"top_depth_", 17.0}}, 512345.0,
                  6012345.0);
  const LoadedObstacles l = load_obstacles({shp}, {"EPSG:32632", ""});
  ASSERT_EQ(l.obstacles.ellipses.size(), 1u);
  const EllipticCylinder& c = l.obstacles.ellipses[0];
  EXPECT_NEAR(c.footprint.centre.x(), 512345.0, 1e-6);
  EXPECT_NEAR(c.footprint.centre.y(), 6012345.0, 1e-6);
  EXPECT_EQ(c.footprint.a, 30.0);
  EXPECT_EQ(c.footprint.b, 12.0);
  EXPECT_EQ(*c.top_depth_m, 17.0);
  EXPECT_NEAR(l.frame.local_to_heading(c.footprint.theta, c.footprint.centre), 90.0, 1e-9);
  EXPECT_EQ(l.sources[0].driver, "ESRI Shapefile");
}

TEST(ObstacleRead, GeoPackageInAProjectedCrsWithCorrectFields) {
  ScratchDir dir;
  const std::string gpkg = dir.file("store.gpkg");
  write_utm_point("GPKG", gpkg, {{"semi_major_m", 30.0}, {"semi_minor_m", 12.0}, {"orientation_deg", 45.0}}, 512345.0,
                  6012345.0);
  const LoadedObstacles l = load_obstacles({gpkg}, {"EPSG:32632", ""});
  ASSERT_EQ(l.obstacles.ellipses.size(), 1u);
  EXPECT_NEAR(l.obstacles.ellipses[0].footprint.centre.x(), 512345.0, 1e-6);
  EXPECT_NEAR(l.obstacles.ellipses[0].footprint.centre.y(), 6012345.0, 1e-6);
  EXPECT_NEAR(
      l.frame.local_to_heading(l.obstacles.ellipses[0].footprint.theta, l.obstacles.ellipses[0].footprint.centre), 45.0,
      1e-9);
  EXPECT_EQ(l.sources[0].crs, "EPSG:32632");
  EXPECT_EQ(l.sources[0].driver, "GPKG");
}

TEST(ObstacleRead, SeveralFilesMergeIntoOneFrame) {
  const std::string sample = test::source_file("data/sample_obstacles.geojson");
  ScratchDir dir;
  const std::string other = dir.write("o.csv", "lon,lat,semi_major_m\n10.30,54.46,5\n");
  const LoadedObstacles l = load_obstacles({sample, other});
  EXPECT_EQ(l.obstacles.ellipses.size(), 7u);
  EXPECT_EQ(l.obstacles.polygons.size(), 1u);
  EXPECT_EQ(l.sources.size(), 2u);
  EXPECT_EQ(l.frame.id(), "EPSG:32632");
}

TEST(ObstacleRead, BundledSampleHasSixEllipsesAndOneArea) {
  const LoadedObstacles l = load_obstacles({test::source_file("data/sample_obstacles.geojson")});
  ASSERT_EQ(l.obstacles.ellipses.size(), 6u);
  ASSERT_EQ(l.obstacles.polygons.size(), 1u);
  const EllipticCylinder& c3 = l.obstacles.ellipses[2];
  EXPECT_EQ(c3.id, "c3");
  EXPECT_EQ(c3.footprint.a, 60.0);
  EXPECT_EQ(c3.footprint.b, 8.0);
  EXPECT_EQ(*c3.top_depth_m, 12.0);
  EXPECT_NEAR(l.frame.local_to_heading(c3.footprint.theta, c3.footprint.centre), 115.0, 1e-9);
  // What `obstacles info` prints, from the same summary as its JSON.
  const ObstacleSummary s = summarize(l);
  const nlohmann::json j = to_json(s);
  EXPECT_EQ(j["count"], 7);
  const std::string text = to_text(s);
  EXPECT_NE(text.find("count            7 (6 elliptical cylinder(s), 1 polygon(s))\n"), std::string::npos) << text;
  EXPECT_NE(text.find("local frame      " + s.local_crs_id + " ("), std::string::npos) << text;
  EXPECT_NE(text.find(printf_text("semi-major axis  min %.2f m, ", s.semi_major_m.min)), std::string::npos) << text;
  EXPECT_NE(text.find("elliptical cylinder(s), 1 polygon(s)\n"), std::string::npos) << text;
}

TEST(ObstacleWrite, EmptySetWritesAValidEmptyFile) {
  ScratchDir dir;
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  for (const char* ext : {".geojson", ".gpkg", ".csv"}) {
    const std::string p = dir.file(std::string("empty") + ext);
    write_obstacles(p, {}, frame);
    EXPECT_EQ(load_obstacles({p}, {"EPSG:32632", ""}).obstacles.size(), 0u) << ext;
  }
}

TEST(ObstacleWrite, ReplacesAnExistingFileAndLeavesNoTemporaryFiles) {
  ScratchDir dir;
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  std::mt19937 rng(5);
  const std::string p = dir.file("o.geojson");
  write_obstacles(p, random_set(rng, 5, 0), frame);
  write_obstacles(p, random_set(rng, 3, 1), frame);
  EXPECT_EQ(load_obstacles({p}, {"EPSG:32632", ""}).obstacles.size(), 4u);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}
