// The frame rule end to end (issue 39, item 1): a route planned in any frame
// the library accepts keeps its margin in truth. Each scenario is built in
// the test's own azimuthal equidistant frame centred on it (OSR directly, not
// the library's frame code), written as a GeoJSON obstacle file in lon/lat,
// planned through the library in a chosen CRS as `plan --crs` does, and the
// route's lon/lat waypoints are judged back in the test's frame against the
// true obstacles. A frame the rule refuses must be refused with one line.
#include <gtest/gtest.h>

#include <gdal.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/route_plan_report.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/local_frame.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

using V = Eigen::Vector2d;

// The test's own frame: azimuthal equidistant on WGS 84 about the scenario's
// centre. Within 10 km of it distances are true to a part in 1e6.
class Aeqd {
 public:
  Aeqd(double lon, double lat) {
    GDALAllRegister();
    geo_.SetWellKnownGeogCS("WGS84");
    geo_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::string def = "+proj=aeqd +lat_0=" + std::to_string(lat) + " +lon_0=" + std::to_string(lon) +
                            " +x_0=0 +y_0=0 +datum=WGS84 +units=m +no_defs";
    EXPECT_EQ(aeqd_.importFromProj4(def.c_str()), OGRERR_NONE);
    aeqd_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    fwd_.reset(OGRCreateCoordinateTransformation(&geo_, &aeqd_));
    inv_.reset(OGRCreateCoordinateTransformation(&aeqd_, &geo_));
  }
  V to_xy(const V& ll) const { return apply(*fwd_, ll); }
  V to_lonlat(const V& xy) const {
    V ll = apply(*inv_, xy);
    ll.x() = ll.x() - 360.0 * std::floor((ll.x() + 180.0) / 360.0);
    return ll;
  }
  // Unit vector of true north at a point of the frame.
  V north_at(const V& xy) const {
    const V ll = to_lonlat(xy);
    const double step = ll.y() > 89.9 ? -1e-5 : 1e-5;
    V d = to_xy({ll.x(), ll.y() + step}) - xy;
    if (step < 0) d = -d;
    return d.normalized();
  }

 private:
  struct Free {
    void operator()(OGRCoordinateTransformation* t) const { OGRCoordinateTransformation::DestroyCT(t); }
  };
  static V apply(OGRCoordinateTransformation& t, const V& p) {
    double x = p.x(), y = p.y();
    EXPECT_TRUE(t.Transform(1, &x, &y));
    return {x, y};
  }
  OGRSpatialReference geo_, aeqd_;
  std::unique_ptr<OGRCoordinateTransformation, Free> fwd_, inv_;
};

double seg_point(const V& a, const V& b, const V& p) {
  const V ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

bool crosses(const V& a, const V& b, const V& c, const V& d) {
  const auto side = [](const V& p, const V& q, const V& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

bool inside(const std::vector<V>& ring, const V& p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    if ((ring[i].y() > p.y()) != (ring[j].y() > p.y()) &&
        p.x() < (ring[j].x() - ring[i].x()) * (p.y() - ring[i].y()) / (ring[j].y() - ring[i].y()) + ring[i].x())
      in = !in;
  }
  return in;
}

// Least distance from a polyline to a ring's area (0 when they meet).
double clearance(const std::vector<V>& route, const std::vector<V>& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (const V& p : route)
    if (inside(ring, p)) return 0.0;
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {
    for (std::size_t j = 0; j < ring.size(); ++j) {
      const V& c = ring[j];
      const V& d = ring[(j + 1) % ring.size()];
      if (crosses(route[i], route[i + 1], c, d)) return 0.0;
      best = std::min(
          {best, seg_point(route[i], route[i + 1], c), seg_point(c, d, route[i]), seg_point(c, d, route[i + 1])});
    }
  }
  return best;
}

// A true obstacle in the test's frame, and how the file gives it.
struct TrueObstacle {
  std::vector<V> ring;  // an ellipse as a 2000-gon inside it (0.4 mm short at 250 m)
  std::string feature;  // GeoJSON
};

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10f", v);
  return b;
}

TrueObstacle ellipse(const Aeqd& f, const V& c, double a, double b, double heading_deg, int k) {
  TrueObstacle o;
  const V north = f.north_at(c);
  const double h = heading_deg * std::numbers::pi / 180.0;
  const V major(north.x() * std::cos(h) + north.y() * std::sin(h), -north.x() * std::sin(h) + north.y() * std::cos(h));
  const V minor(-major.y(), major.x());
  for (int i = 0; i < 2000; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 2000;
    o.ring.push_back(c + a * std::cos(t) * major + b * std::sin(t) * minor);
  }
  const V ll = f.to_lonlat(c);
  o.feature = R"({"type":"Feature","properties":{"id":"e)" + std::to_string(k) + R"(","semi_major_m":)" + num(a) +
              R"(,"semi_minor_m":)" + num(b) + R"(,"orientation_deg":)" + num(heading_deg) +
              R"(},"geometry":{"type":"Point","coordinates":[)" + num(ll.x()) + "," + num(ll.y()) + "]}}";
  return o;
}

// A rectangle; none when its corners straddle the antimeridian (files hold lon within +-180).
std::optional<TrueObstacle> rectangle(const Aeqd& f, const V& c, double w, double h, double turn, int k) {
  TrueObstacle o;
  const V u(std::cos(turn), std::sin(turn)), v(-std::sin(turn), std::cos(turn));
  std::string coords;
  std::vector<V> lls;
  for (const V& s : {V(-1, -1), V(1, -1), V(1, 1), V(-1, 1)}) {
    o.ring.push_back(c + 0.5 * w * s.x() * u + 0.5 * h * s.y() * v);
    lls.push_back(f.to_lonlat(o.ring.back()));
  }
  for (const V& ll : lls)
    if (std::abs(ll.x() - lls.front().x()) > 90.0) return std::nullopt;
  lls.push_back(lls.front());
  for (const V& ll : lls) coords += (coords.empty() ? "[" : ",[") + num(ll.x()) + "," + num(ll.y()) + "]";
  o.feature = R"({"type":"Feature","properties":{"id":"p)" + std::to_string(k) +
              R"("},"geometry":{"type":"Polygon","coordinates":[[)" + coords + "]]}}";
  return o;
}

struct Outcome {
  enum Kind { planned, refused, no_route } kind = planned;
  std::string message;
  double true_clearance_m = 0.0;  // planned: least over every obstacle, in the test's frame
  double margin_m = 0.0;
};

struct Scenario {
  double lon = 0.0, lat = 0.0;  // centre
  double margin_m = 5.0;
  std::string crs;  // "" = the library chooses
};

// Builds the scenario from the seed, plans it in the CRS, judges the route.
Outcome run(const Scenario& s, std::uint32_t seed, const test::ScratchDir& dir) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Aeqd f(s.lon, s.lat);
  const double length = 1500.0 + 4500.0 * u(rng), turn = 2.0 * std::numbers::pi * u(rng);
  const V along(std::cos(turn), std::sin(turn)), side(-along.y(), along.x());
  const V start = -0.5 * length * along, goal = 0.5 * length * along;
  std::vector<TrueObstacle> obstacles;
  const int n = 3 + static_cast<int>(u(rng) * 5);
  for (int k = 0; k < n && obstacles.size() < 8; ++k) {
    const V c = (u(rng) - 0.5) * 0.7 * length * along + (u(rng) - 0.5) * 600.0 * side;
    std::optional<TrueObstacle> o;
    if (u(rng) < 0.7) {
      const double a = 30.0 + 220.0 * u(rng);
      o = ellipse(f, c, a, a * (0.4 + 0.6 * u(rng)), 180.0 * u(rng), k);
    } else {
      o = rectangle(f, c, 40.0 + 260.0 * u(rng), 40.0 + 260.0 * u(rng), turn + u(rng), k);
    }
    if (!o) continue;
    // The start and goal stay clear of the margin, as a user's would.
    if (clearance({start, start}, o->ring) < s.margin_m + 2.0 || clearance({goal, goal}, o->ring) < s.margin_m + 2.0)
      continue;
    obstacles.push_back(std::move(*o));
  }
  std::string json = R"({"type":"FeatureCollection","features":[)";
  for (std::size_t i = 0; i < obstacles.size(); ++i) json += (i ? "," : "") + obstacles[i].feature;
  json += "]}";
  const std::string path = dir.write("o" + std::to_string(seed) + ".geojson", json);

  Outcome out;
  out.margin_m = s.margin_m;
  try {
    const LoadedObstacles loaded = load_obstacles({path}, {s.crs, ""});
    RoutePlanRequest r;
    r.obstacles = loaded.obstacles;
    r.margin_m = s.margin_m;
    const auto at = [&](const V& xy) {
      const V ll = f.to_lonlat(xy);
      return num(ll.x()) + "," + num(ll.y());
    };
    r.problem.start = parse_position(at(start), "--from", loaded.frame, false);
    r.problem.goal = parse_position(at(goal), "--to", loaded.frame, false);
    const RoutePlanReport report = plan_route_request(loaded.frame, r);
    std::vector<V> route;
    for (const V& p : report.route.points) route.push_back(f.to_xy(loaded.frame.to_lonlat(p)));
    out.true_clearance_m = std::numeric_limits<double>::infinity();
    for (const TrueObstacle& o : obstacles)
      out.true_clearance_m = std::min(out.true_clearance_m, clearance(route, o.ring));
  } catch (const InputError& e) {
    out.kind = Outcome::refused;
    out.message = e.what();
  } catch (const NoRouteError& e) {
    out.kind = Outcome::no_route;
    out.message = e.what();
  }
  return out;
}

// The rule lets a frame lengthen distances by kGreatestFrameScale - 1: a
// margin is kept to that fraction (3 cm of 5 m); 1 mm covers the test's 2000-gons.
double kept(double margin_m) { return margin_m / kGreatestFrameScale - 1e-3; }

std::string utm(int zone, bool north) { return "EPSG:" + std::to_string((north ? 32600 : 32700) + zone); }
int zone_of(double lon) { return std::clamp(static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1, 1, 60); }

}  // namespace

// The frames the fault hunt tried, each refused with one line or planned and true.
TEST(FrameRule, TheFramesOfTheFaultHuntAreRefusedOrPlannedTrue) {
  test::ScratchDir dir;
  struct Case {
    const char* what;
    Scenario s;
    bool refused;
  };
  const Case cases[] = {
      {"Web Mercator at 54 N", {10.25, 54.45, 5.0, "EPSG:3857"}, true},
      {"World Mercator at 54 N", {10.25, 54.45, 5.0, "EPSG:3395"}, true},
      {"a US-foot UTM", {10.25, 54.45, 5.0, "+proj=utm +zone=32 +datum=WGS84 +units=us-ft"}, true},
      {"a far UTM zone", {10.25, 54.45, 5.0, "EPSG:32635"}, true},
      {"its own UTM zone", {10.25, 54.45, 5.0, "EPSG:32632"}, false},
      {"Antarctic polar stereographic at 60 S", {20.0, -60.0, 5.0, "EPSG:3031"}, true},
      {"Antarctic polar stereographic at 71 S", {20.0, -71.0, 5.0, "EPSG:3031"}, false},
      {"Arctic polar stereographic at 60 N", {-45.0, 60.0, 5.0, "EPSG:3413"}, true},
      {"Arctic polar stereographic at 70 N", {-45.0, 70.0, 5.0, "EPSG:3413"}, false},
      {"PDC Mercator off the equator", {179.95, -17.0, 5.0, "EPSG:3832"}, true},
      {"PDC Mercator at the equator", {179.95, 0.3, 5.0, "EPSG:3832"}, false},
      {"the default frame across the antimeridian", {179.99, -17.0, 5.0, ""}, false},
      {"the default frame near the pole", {60.0, 88.5, 5.0, ""}, false},
  };
  std::uint32_t seed = 7;
  for (const Case& c : cases) {
    const Outcome o = run(c.s, seed++, dir);
    if (c.refused) {
      EXPECT_EQ(o.kind, Outcome::refused) << c.what << ": " << o.message << " clearance " << o.true_clearance_m;
      EXPECT_EQ(o.message.find('\n'), std::string::npos) << c.what;
    } else {
      ASSERT_EQ(o.kind, Outcome::planned) << c.what << ": " << o.message;
      EXPECT_GE(o.true_clearance_m, kept(c.s.margin_m)) << c.what;
    }
  }
}

// Random places on the globe (poles, the antimeridian, the polar frames'
// standard parallels and the equator weighted in), random obstacles, and a
// random CRS among those a user might try: every planned route keeps its margin.
TEST(FrameRule, RandomPlacesAndFramesNeverGiveAnUnsafeRoute) {
  test::ScratchDir dir;
  const char* env = std::getenv("DEEPGUIDE_FRAME_SEED");
  const std::uint32_t seed0 = env != nullptr ? static_cast<std::uint32_t>(std::atoi(env)) : 20261206u;
  std::mt19937 rng(seed0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = test::cases(500);
  std::map<std::string, int> planned, refused, no_route;
  int unsafe = 0;
  for (int i = 0; i < n; ++i) {
    Scenario s;
    const double pick = u(rng);
    s.lon = -180.0 + 360.0 * u(rng);
    if (pick < 0.45) {
      s.lat = -75.0 + 155.0 * u(rng);
    } else if (pick < 0.6) {
      s.lat = (u(rng) < 0.5 ? 1 : -1) * (80.0 + 9.5 * u(rng));
    } else if (pick < 0.75) {
      s.lon = 179.8 + 0.4 * u(rng) - (u(rng) < 0.5 ? 0.0 : 360.0);
      s.lon = s.lon - 360.0 * std::floor((s.lon + 180.0) / 360.0);
      s.lat = -60.0 + 120.0 * u(rng);
    } else if (pick < 0.85) {
      s.lat = u(rng) < 0.5 ? 69.5 + u(rng) : -71.5 + u(rng);
    } else {
      s.lat = -0.5 + u(rng);
    }
    s.margin_m = std::vector<double>{2.0, 5.0, 20.0}[static_cast<std::size_t>(u(rng) * 3) % 3];
    const int zone = zone_of(s.lon);
    const bool north = s.lat >= 0.0;
    const std::vector<std::string> crs = {
        "",
        "EPSG:3857",
        "EPSG:3395",
        "EPSG:3413",
        "EPSG:3031",
        "EPSG:3832",
        "EPSG:3035",
        utm(zone, north),
        utm(zone % 60 + 1, north),
        utm((zone + 8) % 60 + 1, north),
        "+proj=stere +lat_0=" + num(s.lat) + " +lon_0=" + num(s.lon) + " +k=1 +datum=WGS84 +units=m",
        "+proj=tmerc +lon_0=" + num(s.lon) + " +k=0.99 +datum=WGS84 +units=m",
        "+proj=utm +zone=" + std::to_string(zone) + " +datum=WGS84 +units=us-ft"};
    s.crs = crs[static_cast<std::size_t>(u(rng) * crs.size()) % crs.size()];
    const bool utm_code = s.crs.rfind("EPSG:326", 0) == 0 || s.crs.rfind("EPSG:327", 0) == 0;
    const std::string kind = s.crs.empty() ? "default" : utm_code ? "a UTM zone" : s.crs.substr(0, 14);
    const Outcome o = run(s, seed0 + 1000u + static_cast<std::uint32_t>(i), dir);
    if (o.kind == Outcome::refused) {
      ++refused[kind];
      EXPECT_EQ(o.message.find('\n'), std::string::npos) << o.message;
      // The library's own choice is never refused: it picks a frame that keeps the rule.
      EXPECT_FALSE(s.crs.empty()) << "lon " << s.lon << " lat " << s.lat << ": " << o.message;
      continue;
    }
    if (o.kind == Outcome::no_route) {
      ++no_route[kind];
      continue;
    }
    ++planned[kind];
    if (o.true_clearance_m < kept(s.margin_m)) {
      ++unsafe;
      ADD_FAILURE() << "scenario " << i << " (lon " << s.lon << ", lat " << s.lat << ", crs '" << s.crs << "', margin "
                    << s.margin_m << "): true clearance " << o.true_clearance_m;
    }
  }
  int total_planned = 0;
  for (const auto& [k, c] : planned) total_planned += c;
  std::printf("seed %u: %d scenarios, %d planned, %d unsafe\n", seed0, n, total_planned, unsafe);
  for (const auto& [k, c] : planned)
    std::printf("  %-16s planned %3d, refused %3d, no route %d\n", k.c_str(), c, refused[k], no_route[k]);
  for (const auto& [k, c] : refused)
    if (!planned.count(k)) std::printf("  %-16s planned   0, refused %3d, no route %d\n", k.c_str(), c, no_route[k]);
  EXPECT_EQ(unsafe, 0);
  EXPECT_GT(total_planned, n / 5);  // the test plans, not only refuses (most frames tried are refused)
}
