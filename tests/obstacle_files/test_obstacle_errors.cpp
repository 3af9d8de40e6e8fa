// Bad obstacle input: every case gives one InputError line naming the file,
// the feature and the field, and what was expected.
#include <gtest/gtest.h>

#include <boost/geometry.hpp>

#include <initializer_list>

#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

std::string error_of(const std::vector<std::string>& paths, const ObstacleReadOptions& options = {}) {
  try {
    load_obstacles(paths, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using deepguide::test::expect_error;

std::string point_feature(const std::string& props, const std::string& coords = "[10.1, 54.2]") {
  return R"({"type":"Feature","properties":{)" + props + R"(},"geometry":{"type":"Point","coordinates":)" + coords +
         "}}";
}

std::string collection(std::initializer_list<std::string> features) {
  std::string s = R"({"type":"FeatureCollection","features":[)";
  bool first = true;
  for (const auto& f : features) {
    s += (first ? "" : ",") + f;
    first = false;
  }
  return s + "]}";
}

const std::string kGood = point_feature(R"("id":"ok","semi_major_m":5,"semi_minor_m":2)");

}  // namespace

TEST(ObstacleErrors, MissingFile) {
  ScratchDir dir;
  const std::string p = dir.file("nowhere.geojson");
  expect_error(error_of({p}), {p.c_str(), "expected an existing file"});
}

TEST(ObstacleErrors, FormatGdalCannotOpen) {
  ScratchDir dir;
  static const char kPngHeader[] = "\x89PNG\r\n\x1a\n\x00\x01 not a vector file";
  const std::string p = dir.write("garbage.geojson", std::string(kPngHeader, sizeof kPngHeader - 1));
  expect_error(error_of({p}), {p.c_str(), "vector file"});
  const std::string t = dir.write("notes.txt", "just some words\nand more\n");
  expect_error(error_of({t}), {t.c_str(), "vector file"});
}

TEST(ObstacleErrors, TruncatedGeoJson) {
  ScratchDir dir;
  const std::string p = dir.write("cut.geojson", collection({kGood}).substr(0, 60));
  expect_error(error_of({p}), {p.c_str()});
}

TEST(ObstacleErrors, FeatureWithoutSemiMajor) {
  ScratchDir dir;
  const std::string p = dir.write("o.geojson", collection({kGood, point_feature(R"("id":"w7","semi_minor_m":2)")}));
  expect_error(error_of({p}), {p.c_str(), "feature 1", "w7", "semi_major_m", "expected"});
}

TEST(ObstacleErrors, ZeroOrNegativeAxis) {
  ScratchDir dir;
  const std::string zero = dir.write("z.geojson", collection({point_feature(R"("id":"z","semi_major_m":0)")}));
  expect_error(error_of({zero}), {zero.c_str(), "feature 0", "semi_major_m", "at least 1 mm", "got 0"});
  const std::string neg =
      dir.write("n.geojson", collection({kGood, point_feature(R"("id":"n","semi_major_m":4,"semi_minor_m":-1)")}));
  expect_error(error_of({neg}), {neg.c_str(), "feature 1", "semi_minor_m", "at least 1 mm", "got -1"});
}

// Two columns for one coordinate ("x" and "lon"), or a column named twice:
// GDAL's CSV driver crashed on the first feature (found by
// fuzz/fuzz_obstacles_csv), and otherwise read one of them without a word.
TEST(ObstacleErrors, CsvColumnsThatLeaveACoordinateUnclearAreRefused) {
  ScratchDir dir;
  const std::string both = dir.write("both.csv", "id,x,lon,lat,semi_major_m\na,10,54,11,5\n");
  expect_error(error_of({both}), {"both.csv", "line 1", "one column of x/lon/long/longitude/easting", "x and lon"});
  const std::string lat = dir.write("lat.csv", "id,lon,lat,Latitude,semi_major_m\na,10,54,54.1,5\n");
  expect_error(error_of({lat}), {"lat.csv", "y/lat/latitude/northing", "lat and latitude"});
  const std::string twice = dir.write("twice.csv", "id,lon,lat,lon,semi_major_m\na,10,54,11,5\n");
  expect_error(error_of({twice}), {"twice.csv", "line 1", "each column once", "'lon' as columns 2 and 4"});
  const std::string wkt = dir.write("wkt.csv", "WKT,geometry,id\n\"POINT (10 54)\",\"POINT (11 54)\",a\n");
  expect_error(error_of({wkt}), {"wkt.csv", "one column of wkt/geometry/geom"});
  // Positions in a WKT column and in lon, lat columns: GDAL took the WKT without a word (issue 39).
  const std::string wkt_and_lonlat =
      dir.write("wl.csv", "WKT,lon,lat,id,semi_major_m\n\"POINT (10 54)\",10.02,54,a,5\n");
  expect_error(error_of({wkt_and_lonlat}), {"wl.csv", "line 1", "in one place", "'wkt' and 'lon'"});
  // Saved as UTF-16 by an editor: said so, not "not a vector file".
  for (const auto& [name, bom] : std::vector<std::pair<std::string, std::string>>{
           {"u16le.csv", "\xff\xfe"}, {"u16be.gpx", "\xfe\xff"}, {"u32.geojson", std::string("\xff\xfe\0\0", 4)}}) {
    std::string text = bom;
    for (const char c : std::string("id,lon,lat,semi_major_m\na,10,54,5\n")) text += std::string{c, '\0'};
    expect_error(error_of({dir.write(name, text)}), {name.c_str(), "expected UTF-8 text", "UTF-", "save it as UTF-8"});
  }
  // One of each reads.
  const std::string ok = dir.write("ok.csv", "id,Longitude,LAT,semi_major_m\na,10,54,5\n");
  EXPECT_EQ(load_obstacles({ok}).obstacles.ellipses.size(), 1u);
}

TEST(ObstacleErrors, HugeAxesAndHeadingsAreRefused) {
  // Finite but absurd: they printed inf/nan extents with exit 0.
  ScratchDir dir;
  const std::string big =
      dir.write("b.geojson", collection({kGood, point_feature(R"("id":"big","semi_major_m":1e308)")}));
  expect_error(error_of({big}), {big.c_str(), "feature 1", "'big'", "semi_major_m", "100 km", "got 1e+308"});
  const std::string just = dir.write("j.geojson", collection({point_feature(R"("id":"j","semi_major_m":100001)")}));
  expect_error(error_of({just}), {just.c_str(), "semi_major_m", "100 km", "got 100001"});
  const std::string spin = dir.write(
      "s.geojson",
      collection({point_feature(R"("id":"spin","semi_major_m":20,"semi_minor_m":10,"orientation_deg":1e308)")}));
  expect_error(error_of({spin}), {spin.c_str(), "feature 0", "orientation_deg", "+-360", "got 1e+308"});
  // At the bounds: read.
  const std::string edge = dir.write(
      "e.geojson",
      collection({point_feature(R"("id":"e","semi_major_m":100000,"semi_minor_m":10,"orientation_deg":-360)")}));
  EXPECT_EQ(error_of({edge}), "");
  // Axes below a millimetre: 1e-300 squared underflowed in the tangent graph (issue 39).
  const std::string tiny = dir.write("t.geojson", collection({point_feature(R"("id":"t","semi_major_m":1e-300)")}));
  expect_error(error_of({tiny}), {"t.geojson", "'t'", "semi_major_m", "at least 1 mm", "got 1e-300"});
  const std::string flat =
      dir.write("f.geojson", collection({point_feature(R"("id":"f","semi_major_m":5,"semi_minor_m":1e-9)")}));
  expect_error(error_of({flat}), {"f.geojson", "semi_minor_m", "at least 1 mm", "got 1e-09"});
  const std::string mm = dir.write("mm.geojson", collection({point_feature(R"("id":"mm","semi_major_m":0.001)")}));
  EXPECT_EQ(error_of({mm}), "");
}

TEST(ObstacleErrors, SemiMinorLargerThanSemiMajor) {
  ScratchDir dir;
  const std::string p = dir.write("m.csv", "lon,lat,id,semi_major_m,semi_minor_m\n10,54,a,5,2\n10,54.1,b,3,4\n");
  expect_error(error_of({p}), {p.c_str(), "line 3", "'b'", "semi_minor_m", "<= semi_major_m", "got 4"});
}

TEST(ObstacleErrors, NonNumericField) {
  ScratchDir dir;
  const std::string p = dir.write("s.csv", "lon,lat,semi_major_m\n10,54,five\n");
  expect_error(error_of({p}), {p.c_str(), "line 2", "semi_major_m", "a number", "'five'"});
  const std::string inf = dir.write("i.csv", "lon,lat,semi_major_m\n10,54,inf\n");
  expect_error(error_of({inf}), {inf.c_str(), "semi_major_m", "finite"});
}

TEST(ObstacleErrors, NanOrInfiniteCoordinates) {
  ScratchDir dir;
  const std::string nan = dir.write("nan.geojson", collection({point_feature(R"("semi_major_m":5)", "[NaN, 54]")}));
  expect_error(error_of({nan}), {nan.c_str(), "feature 0", "geometry", "finite"});
  const std::string inf =
      dir.write("inf.geojson", collection({kGood, point_feature(R"("semi_major_m":5)", "[Infinity, 54]")}));
  expect_error(error_of({inf}), {inf.c_str(), "feature 1", "geometry", "finite"});
  // A CSV's coordinate columns are named (the geometry is GDAL's, made from them).
  const std::string csv = dir.write("nan.csv", "lon,lat,semi_major_m\n10,54,3\nnan,54,3\n");
  expect_error(error_of({csv}), {csv.c_str(), "line 3", "fields 'lon', 'lat'", "two finite numbers"});
  const std::string blank = dir.write("blank.csv", "x,y,semi_major_m\n10,54,3\n10.001,,3\n");
  expect_error(error_of({blank}), {blank.c_str(), "line 3", "fields 'x', 'y'", "not finite"});
  const std::string wkt = dir.write("w.csv", "WKT,semi_major_m\n\"POINT (inf 54)\",3\n");
  expect_error(error_of({wkt}), {wkt.c_str(), "line 2", "geometry"});
}

TEST(ObstacleErrors, CoordinatesOffTheEarth) {
  // A CSV in UTM metres without a CRS is read as lon/lat and must not pass.
  ScratchDir dir;
  const std::string p = dir.write("utm.csv", "x,y,semi_major_m\n512345,6012345,3\n");
  expect_error(error_of({p}), {p.c_str(), "line 2", "geometry", "`src_crs`"});
  // The same file with its CRS named is fine.
  EXPECT_EQ(error_of({p}, {"", "EPSG:32632"}), "");
}

TEST(ObstacleErrors, UnknownCrsInFile) {
  ScratchDir dir;
  const std::string p = dir.write(
      "crs.geojson",
      R"({"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::999999"}},"features":[)" +
          kGood + "]}");
  expect_error(error_of({p}), {p.c_str(), "field 'crs'", "expected"});
}

TEST(ObstacleErrors, UnknownCrsOptions) {
  const std::string sample = test::source_file("data/sample_obstacles.geojson");
  expect_error(error_of({sample}, {"EPSG:999999", ""}), {"`local_crs`", "EPSG:999999", "expected"});
  expect_error(error_of({sample}, {"", "EPSG:999999"}), {"`src_crs`", "EPSG:999999"});
  expect_error(error_of({sample}, {"EPSG:4326", ""}), {"`local_crs`", "projected"});
}

TEST(ObstacleErrors, UnsupportedGeometry) {
  ScratchDir dir;
  const std::string p = dir.write(
      "l.geojson",
      collection(
          {R"({"type":"Feature","properties":{"id":"cable"},"geometry":{"type":"LineString","coordinates":[[10,54],[10.1,54.1]]}})"}));
  expect_error(error_of({p}), {p.c_str(), "feature 0", "cable", "geometry", "Point or Polygon", "Line String"});
}

TEST(ObstacleErrors, BothHeightAndTopDepth) {
  ScratchDir dir;
  const std::string p =
      dir.write("v.geojson", collection({point_feature(R"("semi_major_m":5,"height_m":3,"top_depth_m":20)")}));
  expect_error(error_of({p}), {p.c_str(), "height_m", "top_depth_m"});
  const std::string neg = dir.write("h.geojson", collection({point_feature(R"("semi_major_m":5,"height_m":-3)")}));
  expect_error(error_of({neg}), {neg.c_str(), "height_m", "> 0"});
}

TEST(ObstacleErrors, DegeneratePolygon) {
  ScratchDir dir;
  const std::string p = dir.write(
      "p.geojson",
      collection(
          {R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[10,54],[10.1,54],[10,54]]]}})"}));
  expect_error(error_of({p}), {p.c_str(), "feature 0", "geometry"});
}

TEST(ObstacleErrors, PolygonsThatAreNotSimpleAreRefusedNotGuessed) {
  // A bow-tie has no area of its own (its lobes cancel): planners routed
  // through it, and the route check then failed as an internal error.
  ScratchDir dir;
  const auto polygon = [](const std::string& id, const std::string& rings) {
    return R"({"type":"Feature","properties":{"id":")" + id + R"("},"geometry":{"type":"Polygon","coordinates":)" +
           rings + "}}";
  };
  const std::string bow = dir.write(
      "bow.geojson", collection({polygon("bowtie", "[[[10,54],[10.01,54.01],[10.01,54],[10,54.01],[10,54]]]")}));
  expect_error(error_of({bow}), {bow.c_str(), "feature 0", "bowtie", "geometry", "simple polygon", "cross themselves"});
  // A bow-tie whose lobes cancel exactly (a projected CSV, an array from
  // Python): Boost reports the orientation before the crossing, which
  // passed as harmless until the area of its lobes summed to 0 bit for bit.
  PolygonObstacle exact;
  exact.id = "exact";
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {10.0, 10.0}, {10.0, 0.0}, {0.0, 10.0}, {0.0, 0.0}}) {
    exact.footprint.outer().push_back(to_bg(Vec2(500000.0 + x, 6000000.0 + y)));
  }
  ObstacleSet into;
  try {
    add_polygon_obstacle(exact, false, {"arrays", "polygon 0", ""}, into);
    ADD_FAILURE() << "an exact bow-tie was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cross themselves"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(into.polygons.empty());
  // The library's own files (a prepared chart) ask for a repair instead: the bow-tie's two lobes, each valid.
  ObstacleReadOptions repair;
  repair.repair_polygons = true;
  const LoadedObstacles fixed = load_obstacles({bow}, repair);
  ASSERT_EQ(fixed.obstacles.polygons.size(), 2u);
  EXPECT_EQ(fixed.obstacles.polygons[0].id, "bowtie");
  EXPECT_EQ(fixed.obstacles.polygons[1].id, "bowtie#2");
  double lobes = 0.0;
  for (const PolygonObstacle& p : fixed.obstacles.polygons) {
    EXPECT_TRUE(boost::geometry::is_valid(p.footprint));
    lobes += boost::geometry::area(p.footprint);
  }
  // Each lobe is a quarter of the 0.01 x 0.01 degree square (about 1113 m x 654 m at 54 N).
  EXPECT_NEAR(lobes, 0.5 * 1113.2 * 654.4, 0.02 * 0.5 * 1113.2 * 654.4);
  const std::string spike =
      dir.write("spike.geojson",
                collection({polygon("spike", "[[[10,54],[10.01,54],[10.02,54],[10.01,54],[10.01,54.01],[10,54]]]")}));
  expect_error(error_of({spike}), {spike.c_str(), "spike", "simple polygon"});
  const std::string hole =
      dir.write("hole.geojson", collection({polygon("hole",
                                                    "[[[10,54],[10.01,54],[10.01,54.01],[10,54.01],[10,54]],"
                                                    "[[10.02,54],[10.03,54],[10.03,54.01],[10.02,54]]]")}));
  expect_error(error_of({hole}), {hole.c_str(), "hole outside the outer ring"});
  // A square with a square hole, and a ring given the other way round, are fine.
  const std::string fine = dir.write(
      "fine.geojson",
      collection({polygon("ring",
                          "[[[10,54],[10.01,54],[10.01,54.01],[10,54.01],[10,54]],"
                          "[[10.004,54.004],[10.006,54.004],[10.006,54.006],[10.004,54.006],[10.004,54.004]]]"),
                  polygon("cw", "[[[10.1,54],[10.1,54.01],[10.11,54.01],[10.11,54],[10.1,54]]]")}));
  EXPECT_EQ(error_of({fine}), "");
}

TEST(ObstacleErrors, WriteToMissingFolderOrUnknownFormat) {
  ScratchDir dir;
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  try {
    write_obstacles(dir.file("no/such/folder/o.geojson"), {}, frame);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("folder"), std::string::npos) << e.what();
  }
  try {
    write_obstacles(dir.file("o.kml"), {}, frame);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".kml"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(ObstacleErrors, HostileLongAndOddStrings) {
  // A huge id, quotes and control characters must not break reading or messages.
  ScratchDir dir;
  const std::string id(100000, 'x');
  const std::string p =
      dir.write("big.geojson", collection({point_feature(R"("id":")" + id + R"(\"\u0000\n","semi_major_m":-1)")}));
  const std::string msg = error_of({p});
  expect_error(msg, {p.c_str(), "semi_major_m", "xxx..."});
  EXPECT_LT(msg.size(), 400u) << "the id must be cut in the message";
}

TEST(Printable, EscapesWhatWouldChangeHowALineIsShown) {
  EXPECT_EQ(printable("c2"), "c2");
  EXPECT_EQ(printable("a\nb\x1b[31mc"), "a\\x0ab\\x1b[31mc");
  // Bidirectional and invisible controls are escaped, other UTF-8 is kept.
  EXPECT_EQ(printable("wreck\u202e1gnp.exe"), "wreck\\u202e1gnp.exe");
  EXPECT_EQ(printable("a\u200bb\u2066c\ufeff"), "a\\u200bb\\u2066c\\ufeff");
  EXPECT_EQ(printable("Wrack S\u00fcdmole 54\u00b0"), "Wrack S\u00fcdmole 54\u00b0");
  EXPECT_EQ(printable("\xc2\x85"), "\\x85");  // C1 control NEL
  // Bytes that are not UTF-8: a stray continuation, a cut sequence, an overlong '/'.
  EXPECT_EQ(printable("a\x80z"), "a\\x80z");
  EXPECT_EQ(printable("a\xe2\x80"), "a\\xe2\\x80");
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");
  EXPECT_EQ(printable(std::string(100, 'x'), 10), std::string(10, 'x') + "...");
}
