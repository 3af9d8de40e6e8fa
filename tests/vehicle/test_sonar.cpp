// The forward-looking sonar: what lies in its sector, exact detections without
// noise, the configured error statistics at two ranges, seeding and the scan rate.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "deepguide/core/error.hpp"
#include "deepguide/vehicle/sonar.hpp"

using namespace deepguide;

namespace {

const double kNorth = kPi / 2.0;  // sonar looking north (math angle)

EllipticCylinder cylinder(const std::string& id, Vec2 c, double a, double b, double theta = 0.0) {
  EllipticCylinder o;
  o.id = id;
  o.footprint = Ellipse{c, a, b, theta};
  return o;
}

SonarParams exact() {
  SonarParams p;  // 120 m, 120 deg
  p.position_sigma_m = p.position_sigma_per_m = p.size_sigma_m = p.size_sigma_per_m = 0.0;
  return p;
}

std::vector<Detection> scan_once(const SonarParams& p, const Vec2& at, double heading,
                                 const std::vector<EllipticCylinder>& obstacles) {
  Sonar s(p);
  EXPECT_TRUE(s.update(0.0, at, heading, obstacles));
  return s.detections();
}

bool seen(const SonarParams& p, const EllipticCylinder& o, const Vec2& at = {0, 0}, double heading = kNorth) {
  return !scan_once(p, at, heading, {o}).empty();
}

}  // namespace

TEST(Sonar, RangeLimit) {
  const SonarParams p = exact();
  EXPECT_TRUE(seen(p, cylinder("near", {0, 100}, 2, 2)));
  EXPECT_TRUE(seen(p, cylinder("edge", {0, 121.9}, 2, 2)));      // nearest point 119.9 m
  EXPECT_FALSE(seen(p, cylinder("far", {0, 122.1}, 2, 2)));      // nearest point 120.1 m
  EXPECT_FALSE(seen(p, cylinder("big far", {0, 200}, 60, 60)));  // centre test alone would be fooled: 200 - 60 > 120
  // Moving the sonar moves the sector.
  EXPECT_TRUE(seen(p, cylinder("far", {0, 122.1}, 2, 2), {0, 5}));
}

TEST(Sonar, FieldOfView) {
  const SonarParams p = exact();  // +-60 deg about the heading
  EXPECT_FALSE(seen(p, cylinder("behind", {0, -50}, 2, 2)));
  // Bearing 59 deg and 61 deg from north at 80 m; radius 0.1 m (0.07 deg wide).
  const Vec2 in = 80.0 * vector_of_course_deg(59.0), out = 80.0 * vector_of_course_deg(61.0);
  EXPECT_TRUE(seen(p, cylinder("in", in, 0.1, 0.1)));
  EXPECT_FALSE(seen(p, cylinder("out", out, 0.1, 0.1)));
  // The same object with the vehicle turned 10 deg to starboard is inside, to port outside.
  EXPECT_TRUE(seen(p, cylinder("out", out, 0.1, 0.1), {0, 0}, kNorth - deg_to_rad(10.0)));
  EXPECT_FALSE(seen(p, cylinder("in", in, 0.1, 0.1), {0, 0}, kNorth + deg_to_rad(10.0)));
  // Wider sonar sees it.
  SonarParams wide = p;
  wide.field_of_view = deg_to_rad(130.0);
  EXPECT_TRUE(seen(wide, cylinder("out", out, 0.1, 0.1)));
}

TEST(Sonar, ObjectReachingIntoTheSectorFromTheSide) {
  // A wall east of the sonar, long axis north: its nearest point (55, 0) has
  // bearing 90 deg, outside the +-60 deg sector, but the wall reaches into the
  // sector: the edge ray at 60 deg passes (57.7, 33.3), inside the wall.
  const SonarParams p = exact();
  const EllipticCylinder wall = cylinder("wall", {60, 0}, 50, 5, kNorth);
  const auto d = scan_once(p, {0, 0}, kNorth, {wall});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_NEAR(d[0].range_m, 55.0, 1e-9);
  EXPECT_NEAR(math_rad_to_heading_deg(d[0].bearing), 90.0, 1e-9);
  // A short wall there (a = 20: up to y = 20, the edge ray is at y = 31.8 by x = 55) is not seen.
  EXPECT_FALSE(seen(p, cylinder("short", {60, 0}, 20, 5, kNorth)));
}

TEST(Sonar, SonarInsideAnObjectDetectsItAtRangeZero) {
  const auto d = scan_once(exact(), {1, 1}, kNorth, {cylinder("around", {0, 0}, 10, 5)});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].range_m, 0.0);
}

TEST(Sonar, ZeroSigmasReportTheTruth) {
  const std::vector<EllipticCylinder> obstacles{cylinder("a", {10, 50}, 8, 3, 0.4), cylinder("behind", {0, -30}, 3, 2),
                                                cylinder("b", {-20, 90}, 4, 4)};
  const auto d = scan_once(exact(), {0, 0}, kNorth, obstacles);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].obstacle, 0u);
  EXPECT_EQ(d[1].obstacle, 2u);
  for (const Detection& x : d) {
    const Ellipse& truth = obstacles[x.obstacle].footprint;
    EXPECT_EQ(x.estimate.centre, truth.centre);
    EXPECT_EQ(x.estimate.a, truth.a);
    EXPECT_EQ(x.estimate.b, truth.b);
    EXPECT_EQ(x.estimate.theta, truth.theta);
  }
  // Range and bearing to the circle b: centre distance sqrt(20^2 + 90^2) minus 4.
  EXPECT_NEAR(d[1].range_m, std::hypot(20.0, 90.0) - 4.0, 1e-9);
  EXPECT_NEAR(math_rad_to_heading_deg(d[1].bearing), 360.0 - rad_to_deg(std::atan2(20.0, 90.0)), 1e-9);
}

TEST(Sonar, ErrorStatisticsMatchConfiguredSigmasAtTwoRanges) {
  // Ellipse with its nearest point exactly R ahead: centre (0, R + b), major axis east.
  // N = 4000 scans. The sample mean has standard error sigma / sqrt(N) = 0.016 sigma,
  // the sample stdev about sigma / sqrt(2N) = 0.011 sigma; tolerances are 4 of those.
  // a - b = 15 m is > 8 sigma of the size error, so the a >= b re-sort never fires.
  SonarParams p;
  p.position_sigma_m = 0.5;
  p.position_sigma_per_m = 0.01;
  p.size_sigma_m = 0.25;
  p.size_sigma_per_m = 0.01;
  p.seed = 20240607;
  const int n = 4000;
  for (double range : {20.0, 100.0}) {
    const double a = 20.0, b = 5.0;
    const EllipticCylinder o = cylinder("o", {0.0, range + b}, a, b);
    Sonar sonar(p);
    std::vector<double> ex, ey, ea, eb;
    for (int k = 0; k < n; ++k) {
      ASSERT_TRUE(sonar.update(k / p.update_rate_hz, {0, 0}, kNorth, {o}));
      ASSERT_EQ(sonar.detections().size(), 1u);
      const Detection& d = sonar.detections()[0];
      ASSERT_NEAR(d.range_m, range, 1e-9);
      ex.push_back(d.estimate.centre.x());
      ey.push_back(d.estimate.centre.y() - (range + b));
      ea.push_back(d.estimate.a - a);
      eb.push_back(d.estimate.b - b);
    }
    auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / v.size(); };
    auto stdev = [&](const std::vector<double>& v) {
      const double m = mean(v);
      double s = 0.0;
      for (double x : v) s += (x - m) * (x - m);
      return std::sqrt(s / (v.size() - 1));
    };
    const double sp = 0.5 + 0.01 * range, ss = 0.25 + 0.01 * range;  // 0.7/1.5 m and 0.45/1.25 m
    for (const auto* v : {&ex, &ey}) {
      EXPECT_NEAR(mean(*v), 0.0, 4.0 * sp / std::sqrt(n)) << "range " << range;
      EXPECT_NEAR(stdev(*v), sp, 4.0 * sp / std::sqrt(2.0 * n)) << "range " << range;
    }
    for (const auto* v : {&ea, &eb}) {
      EXPECT_NEAR(mean(*v), 0.0, 4.0 * ss / std::sqrt(n)) << "range " << range;
      EXPECT_NEAR(stdev(*v), ss, 4.0 * ss / std::sqrt(2.0 * n)) << "range " << range;
    }
  }
}

TEST(Sonar, SameSeedSameDetections) {
  const std::vector<EllipticCylinder> obstacles{cylinder("a", {10, 50}, 8, 3, 0.4), cylinder("b", {-20, 90}, 4, 4)};
  auto record = [&](std::uint64_t seed) {
    SonarParams p;
    p.seed = seed;
    Sonar s(p);
    std::vector<Detection> all;
    for (int k = 0; k < 50; ++k) {
      s.update(0.5 * k, {0.3 * k, 0.0}, kNorth, obstacles);
      all.insert(all.end(), s.detections().begin(), s.detections().end());
    }
    return all;
  };
  const auto a = record(7), b = record(7), c = record(8);
  ASSERT_EQ(a.size(), 100u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(Sonar, ScansOnlyAtItsRate) {
  SonarParams p = exact();
  p.update_rate_hz = 2.0;
  Sonar s(p);
  std::vector<EllipticCylinder> obstacles{cylinder("a", {0, 50}, 2, 2)};
  double t = 0.0;
  int scans = 0;
  for (int i = 0; i <= 100; ++i) {  // 10 Hz simulation, times summed as a simulator does
    const bool scanned = s.update(t, {0, 0}, kNorth, obstacles);
    EXPECT_EQ(scanned, i % 5 == 0) << "step " << i << ", t = " << t;
    scans += scanned;
    ASSERT_EQ(s.detections().size(), 1u);
    EXPECT_NEAR(s.detections()[0].time_s, 0.5 * (i / 5), 1e-9);  // the last scan's time
    if (i == 2) obstacles.clear();                               // between scans: the old detections stay
    if (i == 3) obstacles = {cylinder("a", {0, 50}, 2, 2)};
    t += 0.1;
  }
  EXPECT_EQ(scans, 21);
  EXPECT_NEAR(s.next_scan_s(), 10.5, 1e-12);
  // A late caller gets one scan, then the schedule resumes on the grid.
  EXPECT_TRUE(s.update(12.34, {0, 0}, kNorth, obstacles));
  EXPECT_NEAR(s.next_scan_s(), 12.5, 1e-12);
  EXPECT_FALSE(s.update(12.4, {0, 0}, kNorth, obstacles));
}

TEST(Sonar, RejectsBadParameters) {
  auto bad = [](auto change) {
    SonarParams p;
    change(p);
    EXPECT_THROW(Sonar{p}, InputError);
  };
  bad([](SonarParams& p) { p.range_m = 0.0; });
  bad([](SonarParams& p) { p.range_m = std::nan(""); });
  bad([](SonarParams& p) { p.field_of_view = deg_to_rad(361.0); });
  bad([](SonarParams& p) { p.update_rate_hz = -1.0; });
  bad([](SonarParams& p) { p.position_sigma_per_m = -0.01; });
  bad([](SonarParams& p) { p.size_sigma_m = INFINITY; });
  try {
    SonarParams p;
    p.range_m = -5;
    Sonar s(p);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("range_m"), std::string::npos) << e.what();
  }
}
