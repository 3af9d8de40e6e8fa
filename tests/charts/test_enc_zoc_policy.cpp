// The zone-of-confidence policies (charts/chart_options.hpp) on a cell written
// through GDAL's S57 writer (synthetic_cell.hpp): a dredged channel 150 m
// wide, 12 m deep, in a CATZOC B zone 200 m wide, the water either side 1 m
// deep in CATZOC C, and a 2 m sounding charted 200 m off the channel's edge
// in the C zone. Its disc of C's position accuracy (500 m) reaches across the
// channel: `strict` shuts it, `clipped` keeps the disc out of the B survey's
// water, `none` takes the sounding where it is charted.
//
// Positions are built in metres east and north of a corner and turned into
// lon/lat by a flat-earth scale (the cell's own geometry and the planner's
// UTM frame differ from it by well under the 25 m between the channel and
// the zone's edge).

#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "deepguide/charts/enc_no_go.hpp"
#include "synthetic_cell.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

using test::run_cli;
using test::ScratchDir;

const auto ll = test::synthetic_lonlat;
const auto box = test::synthetic_box;

std::string lonlat_text(double east_m, double north_m) {
  const auto p = ll(east_m, north_m);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.7f,%.7f", p[0], p[1]);
  return buf;
}

// The channel y in [1425, 1575] m, the B zone y in [1400, 1600] m, 3 km long.
std::string write_channel_cell(const ScratchDir& tmp) {
  test::SyntheticCell cell;
  cell.name = "US5TEST1";
  const double W = 3000.0;
  cell.areas.push_back({"M_COVR", box(0, 0, W, W), {}, {{"CATCOV", 1}}});
  cell.areas.push_back({"DEPARE", box(0, 0, W, 1425), {{"DRVAL1", 1.0}, {"DRVAL2", 2.0}}, {}});
  cell.areas.push_back({"DEPARE", box(0, 1575, W, W), {{"DRVAL1", 1.0}, {"DRVAL2", 2.0}}, {}});
  cell.areas.push_back({"DRGARE", box(0, 1425, W, 1575), {{"DRVAL1", 12.0}}, {}});
  cell.areas.push_back({"M_QUAL", box(0, 1400, W, 1600), {}, {{"CATZOC", 3}}});
  cell.areas.push_back({"M_QUAL", box(0, 0, W, 1400), {}, {{"CATZOC", 4}}});
  cell.areas.push_back({"M_QUAL", box(0, 1600, W, W), {}, {{"CATZOC", 4}}});
  const auto s = ll(1500, 1775);
  cell.soundings.push_back({s[0], s[1], 2.0});
  const std::string path = tmp.file("US5TEST1.000");
  test::write_synthetic_cell(path, cell);
  return path;
}

EncNoGoOptions at_depth(double d, ZocPolicy zoc) {
  EncNoGoOptions o;
  o.operating_depth_m = d;
  o.zoc = zoc;
  return o;
}

const EncNoGoFeature& the_sounding(const EncNoGo& n) {
  const auto it =
      std::find_if(n.features.begin(), n.features.end(), [](const EncNoGoFeature& f) { return f.cls == "SOUNDG"; });
  if (it == n.features.end()) throw std::runtime_error("no sounding among the no-go features");
  return *it;
}

TEST(EncZocPolicy, TheSoundingsDiscIsClippedToZonesNotBetterThanItsOwn) {
  ScratchDir tmp;
  const std::string cell = write_channel_cell(tmp);
  const EncNoGo strict = enc_no_go({cell}, std::nullopt, at_depth(5.0, ZocPolicy::strict));
  const EncNoGoFeature& s = the_sounding(strict);
  ASSERT_TRUE(s.point.has_value());
  EXPECT_DOUBLE_EQ(s.radius_m, 500.0);  // CATZOC C

  const EncNoGo clipped = enc_no_go({cell}, std::nullopt, at_depth(5.0, ZocPolicy::clipped));
  const EncNoGoFeature& c = the_sounding(clipped);
  EXPECT_FALSE(c.point.has_value()) << "a disc reaching into a better zone becomes an area";
  EXPECT_NE(c.reason.find("its 500 m disc clipped to zones not better than CATZOC C"), std::string::npos) << c.reason;
  // The test's own B zone in the frame: what is left of the disc does not enter it.
  const auto lo = ll(0, 1400), hi = ll(3000, 1600);
  const Vec2 a = clipped.frame.from_lonlat(lo[0], lo[1]), b = clipped.frame.from_lonlat(hi[0], hi[1]);
  BgPolygon zone_b;
  boost::geometry::convert(BgBox(BgPoint(a.x() + 1.0, a.y() + 1.0), BgPoint(b.x() - 1.0, b.y() - 1.0)), zone_b);
  boost::geometry::correct(zone_b);
  BgMultiPolygon inside;
  boost::geometry::intersection(c.area, zone_b, inside);
  EXPECT_LT(boost::geometry::area(inside), 1.0);
  // And keeps the rest: the disc less its part in the band 175 .. 375 m south of its centre
  // (the disc is a 16-gon round the circle: within 2 % of it).
  const double R = 500.0;
  const auto segment = [R](double y) { return 0.5 * y * std::sqrt(R * R - y * y) + 0.5 * R * R * std::asin(y / R); };
  const double expected = std::numbers::pi * R * R - 2.0 * (segment(375.0) - segment(175.0));
  EXPECT_NEAR(boost::geometry::area(c.area), expected, 0.02 * expected);
  const Vec2 sounding = clipped.frame.from_lonlat(ll(1500, 1775)[0], ll(1500, 1775)[1]);
  EXPECT_TRUE(boost::geometry::covered_by(to_bg(sounding), c.area));

  const EncNoGo none = enc_no_go({cell}, std::nullopt, at_depth(5.0, ZocPolicy::none));
  ASSERT_TRUE(the_sounding(none).point.has_value());
  EXPECT_DOUBLE_EQ(the_sounding(none).radius_m, 10.0);
}

TEST(EncZocPolicy, ClippedAndNoneRouteThroughTheChannelStrictRefusesNamingTheSounding) {
  ScratchDir tmp;
  const std::string cell = write_channel_cell(tmp);
  const std::string plan = "plan --chart '" + cell + "' --depth 5 --from " + lonlat_text(100, 1500) + " --to " +
                           lonlat_text(2900, 1500) + " --json -o ";
  for (const char* zoc : {"clipped", "none"}) {
    const std::string route = tmp.file(std::string(zoc) + ".geojson");
    const test::RunResult r = run_cli(plan + "'" + route + "' --zoc " + zoc);
    ASSERT_EQ(r.exit_code, 0) << zoc << ": " << r.err;
    EXPECT_NEAR(nlohmann::json::parse(r.out).at("length_m").get<double>(), 2800.0, 10.0) << zoc;
    const test::RunResult check = run_cli("check route '" + route + "' --chart '" + cell + "' --depth 5 --zoc " + zoc);
    EXPECT_EQ(check.exit_code, 0) << zoc << ": " << check.out << check.err;
  }
  const test::RunResult strict = run_cli(plan + "'" + tmp.file("strict.geojson") + "' --zoc strict");
  EXPECT_EQ(strict.exit_code, 3) << strict.out << strict.err;
  EXPECT_NE(strict.err.find("SOUNDG/"), std::string::npos) << strict.err;
  EXPECT_NE(strict.err.find("sounding 2 m"), std::string::npos) << strict.err;
  EXPECT_EQ(std::count(strict.err.begin(), strict.err.end(), '\n'), 1) << strict.err;
  // The default is clipped.
  const test::RunResult by_default = run_cli(plan + "'" + tmp.file("default.geojson") + "'");
  EXPECT_EQ(by_default.exit_code, 0) << by_default.err;
}

}  // namespace
}  // namespace deepguide
