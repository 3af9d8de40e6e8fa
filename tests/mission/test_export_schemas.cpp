// Route files as the operator's tools read them (mission/route_export.hpp):
// the sample mission's plan written as GPX, KML and RTZ validates against the
// official schemas (tests/data/schemas, libxml2, no network), and each format
// read back by a reader that is not its writer (libxml2 XPath for the XML
// formats GDAL or we wrote, GDAL without open options for CSV, nlohmann/json
// for GeoJSON) gives every waypoint's name, position, depth, speed, hold and
// turn radius.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/xmlschemas.h>
#include <libxml/xpath.h>
#include <libxml/xpathInternals.h>
#include <ogrsf_frmts.h>

#include <yaml-cpp/yaml.h>
#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

constexpr double kDeg = 1e-7;
constexpr double kCm = 0.01;
constexpr double kNauticalMile = 1852.0;

struct Sample {
  Mission mission;
  MissionPlan plan;
  ExportRoute route;
  ExportRoute corners;  ///< RTZ's: arcs as the corners an ECDIS turns them from
};

const Sample& sample() {
  static const Sample s = [] {
    Mission mission = read_mission(test::source_file("data/missions/sample_mission.yaml"));
    const MissionEnvironment env = load_environment(mission);
    MissionPlan plan = plan_mission(mission, env, expand_mission(mission, env.obstacles)).plan;
    ExportRoute route = export_route(mission, plan);
    ExportRoute corners = export_route(mission, plan, 0.5, true);
    return Sample{std::move(mission), std::move(plan), std::move(route), std::move(corners)};
  }();
  return s;
}

const std::vector<ExportWaypoint>& want() { return sample().route.waypoints; }

std::string exported(ScratchDir& dir, const std::string& name) {
  const std::string path = dir.file(name);
  export_plan(sample().mission, sample().plan, path, export_format_for(path));
  return path;
}

void collect(void* ctx, const char* fmt, ...) {
  char text[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(text, sizeof text, fmt, args);
  va_end(args);
  *static_cast<std::string*>(ctx) += text;
}

// libxml2 without network: the schema's errors and the file's, as text.
std::string schema_errors(const std::string& xsd, const std::string& file) {
  std::string errors;
  xmlSchemaParserCtxtPtr pctx = xmlSchemaNewParserCtxt(xsd.c_str());
  xmlSchemaSetParserErrors(pctx, collect, collect, &errors);
  xmlSchemaPtr schema = xmlSchemaParse(pctx);
  xmlSchemaFreeParserCtxt(pctx);
  if (schema == nullptr) return "schema " + xsd + " did not parse: " + errors;
  xmlSchemaValidCtxtPtr vctx = xmlSchemaNewValidCtxt(schema);
  xmlSchemaSetValidErrors(vctx, collect, collect, &errors);
  xmlDocPtr doc = xmlReadFile(file.c_str(), nullptr, XML_PARSE_NONET);
  const int rc = doc ? xmlSchemaValidateDoc(vctx, doc) : -1;
  if (doc) xmlFreeDoc(doc);
  xmlSchemaFreeValidCtxt(vctx);
  xmlSchemaFree(schema);
  return rc == 0 ? std::string() : "invalid (" + std::to_string(rc) + "): " + errors;
}

std::string schema(const std::string& rel) { return test::source_file("tests/data/schemas/" + rel); }

// An XML file queried with XPath, namespaces bound to prefixes.
class Xml {
 public:
  Xml(const std::string& path, const std::map<std::string, std::string>& ns)
      : doc_(xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET), &xmlFreeDoc),
        ctx_(doc_ ? xmlXPathNewContext(doc_.get()) : nullptr, &xmlXPathFreeContext) {
    for (const auto& [prefix, uri] : ns) {
      xmlXPathRegisterNs(ctx_.get(), reinterpret_cast<const xmlChar*>(prefix.c_str()),
                         reinterpret_cast<const xmlChar*>(uri.c_str()));
    }
  }
  bool ok() const { return ctx_ != nullptr; }
  // The string values of the nodes `xpath` selects, in document order.
  std::vector<std::string> all(const std::string& xpath) const {
    std::vector<std::string> out;
    xmlXPathObjectPtr r = xmlXPathEvalExpression(reinterpret_cast<const xmlChar*>(xpath.c_str()), ctx_.get());
    if (r != nullptr && r->nodesetval != nullptr) {
      for (int i = 0; i < r->nodesetval->nodeNr; ++i) {
        xmlChar* v = xmlNodeGetContent(r->nodesetval->nodeTab[i]);
        out.emplace_back(v ? reinterpret_cast<const char*>(v) : "");
        xmlFree(v);
      }
    }
    xmlXPathFreeObject(r);
    return out;
  }
  std::vector<double> numbers(const std::string& xpath) const {
    std::vector<double> out;
    for (const std::string& s : all(xpath)) out.push_back(std::stod(s));
    return out;
  }

 private:
  std::unique_ptr<xmlDoc, decltype(&xmlFreeDoc)> doc_;
  std::unique_ptr<xmlXPathContext, decltype(&xmlXPathFreeContext)> ctx_;
};

void expect_each(const std::vector<double>& got, const std::function<double(const ExportWaypoint&)>& value,
                 double tolerance, const char* what, const std::vector<ExportWaypoint>& w = want()) {
  ASSERT_EQ(got.size(), w.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got[i], value(w[i]), tolerance) << what << " " << i;
}

void expect_names(const std::vector<std::string>& got, const char* what,
                  const std::vector<ExportWaypoint>& w = want()) {
  ASSERT_EQ(got.size(), w.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], w[i].name) << what << " " << i;
}

// The track an ECDIS sails through waypoints `wp`: straight between the
// turns, and at waypoint i an arc of radius `radius[i]` tangent to both legs
// (arcs sampled every 1/64 of their turn). `fits`, when given, is told for
// each turn whether its tangent length fits both legs (within `slack` m).
std::vector<Vec2> ecdis_track(const std::vector<Vec2>& wp, const std::vector<double>& radius,
                              const std::function<void(std::size_t, bool)>& fits = {}, double slack = 0.0) {
  std::vector<Vec2> track{wp.front()};
  for (std::size_t i = 1; i + 1 < wp.size(); ++i) {
    const Vec2 e1 = (wp[i] - wp[i - 1]).normalized(), e2 = (wp[i + 1] - wp[i]).normalized();
    const double cross = e1.x() * e2.y() - e1.y() * e2.x();
    const double theta = std::atan2(std::abs(cross), e1.dot(e2));
    if (theta < 1e-6) {
      track.push_back(wp[i]);
      continue;
    }
    const double r = radius[i], t = r * std::tan(0.5 * theta);
    if (fits) fits(i, t <= (wp[i] - wp[i - 1]).norm() + slack && t <= (wp[i + 1] - wp[i]).norm() + slack);
    const Vec2 p1 = wp[i] - t * e1;
    const Vec2 centre = p1 + (cross > 0 ? 1.0 : -1.0) * r * Vec2(-e1.y(), e1.x());
    const double a0 = std::atan2(p1.y() - centre.y(), p1.x() - centre.x());
    for (int k = 0; k <= 64; ++k) {
      const double a = a0 + (cross > 0 ? 1.0 : -1.0) * theta * k / 64;
      track.push_back(centre + r * Vec2(std::cos(a), std::sin(a)));
    }
  }
  track.push_back(wp.back());
  return track;
}

}  // namespace

TEST(ExportSchemas, TheSampleHasWhatTheChecksNeed) {
  // Holds, arcs and several depths: else the read-backs below could pass on zeros.
  double holds = 0.0, deepest = 0.0;
  std::size_t arcs = 0;
  for (const ExportWaypoint& w : want()) {
    holds += w.hold_s;
    arcs += w.radius_m > 0.0;
    deepest = std::max(deepest, w.depth_m);
  }
  EXPECT_DOUBLE_EQ(holds, 120.0);
  EXPECT_GT(arcs, 20u);
  EXPECT_GE(deepest, 8.0);
  EXPECT_EQ(want().front().name, "001");
  ASSERT_GE(want().size(), 100u);
  EXPECT_EQ(want()[99].name, "100");
  EXPECT_GT(sample().route.turn_radius_m, 10.0);
}

TEST(ExportSchemas, GpxIsGpx11WithNamesElevationsAndExtensions) {
  ScratchDir dir;
  const std::string path = exported(dir, "sample.gpx");
  EXPECT_EQ(schema_errors(schema("gpx/gpx.xsd"), path), "");
  const Xml x(path, {{"g", "http://www.topografix.com/GPX/1/1"}, {"dg", "https://deepguide.dev/gpx/1"}});
  ASSERT_TRUE(x.ok());
  EXPECT_EQ(x.all("/g:gpx/g:rte/g:name"), std::vector<std::string>{sample().mission.name});
  expect_names(x.all("//g:rtept/g:name"), "gpx name");
  expect_each(
      x.numbers("//g:rtept/@lon"), [](const ExportWaypoint& w) { return w.lonlat.x(); }, kDeg, "gpx lon");
  expect_each(
      x.numbers("//g:rtept/@lat"), [](const ExportWaypoint& w) { return w.lonlat.y(); }, kDeg, "gpx lat");
  expect_each(
      x.numbers("//g:rtept/g:ele"), [](const ExportWaypoint& w) { return -w.depth_m; }, kCm, "gpx ele");
  expect_each(
      x.numbers("//g:rtept/g:extensions/dg:depth_m"), [](const ExportWaypoint& w) { return w.depth_m; }, kCm,
      "gpx depth");
  expect_each(
      x.numbers("//g:rtept/g:extensions/dg:speed_mps"), [](const ExportWaypoint& w) { return w.speed_mps; }, 1e-6,
      "gpx speed");
  expect_each(
      x.numbers("//g:rtept/g:extensions/dg:hold_s"), [](const ExportWaypoint& w) { return w.hold_s; }, 1e-6,
      "gpx hold");
  expect_each(
      x.numbers("//g:rtept/g:extensions/dg:radius_m"), [](const ExportWaypoint& w) { return w.radius_m; }, kCm,
      "gpx radius");
}

TEST(ExportSchemas, KmlIsKml22BelowTheSurfaceWithExtendedData) {
  ScratchDir dir;
  const std::string path = exported(dir, "sample.kml");
  EXPECT_EQ(schema_errors(schema("kml22/ogckml22.xsd"), path), "");
  const Xml x(path, {{"k", "http://www.opengis.net/kml/2.2"}});
  ASSERT_TRUE(x.ok());
  // Every geometry is absolute (metres above sea level), so viewers put it under water.
  const std::vector<std::string> modes = x.all("//k:Placemark/*/k:altitudeMode");
  EXPECT_EQ(modes.size(), want().size() + 1);
  for (const std::string& m : modes) EXPECT_EQ(m, "absolute");
  const std::string points = "//k:Placemark[k:Point]";
  expect_names(x.all(points + "/k:name"), "kml name");
  std::vector<double> lon, lat, alt;
  for (const std::string& c : x.all(points + "/k:Point/k:coordinates")) {
    double a = NAN, b = NAN, z = NAN;
    ASSERT_EQ(std::sscanf(c.c_str(), " %lf,%lf,%lf", &a, &b, &z), 3) << c;
    lon.push_back(a), lat.push_back(b), alt.push_back(z);
  }
  expect_each(
      lon, [](const ExportWaypoint& w) { return w.lonlat.x(); }, kDeg, "kml lon");
  expect_each(
      lat, [](const ExportWaypoint& w) { return w.lonlat.y(); }, kDeg, "kml lat");
  expect_each(
      alt, [](const ExportWaypoint& w) { return -w.depth_m; }, kCm, "kml altitude");
  const auto field = [&](const char* name) {
    return x.numbers(points + "/k:ExtendedData//k:SimpleData[@name='" + name + "']");
  };
  expect_each(
      field("depth_m"), [](const ExportWaypoint& w) { return w.depth_m; }, kCm, "kml depth");
  expect_each(
      field("speed_mps"), [](const ExportWaypoint& w) { return w.speed_mps; }, 1e-6, "kml speed");
  expect_each(
      field("hold_s"), [](const ExportWaypoint& w) { return w.hold_s; }, 1e-6, "kml hold");
  expect_each(
      field("radius_m"), [](const ExportWaypoint& w) { return w.radius_m; }, kCm, "kml radius");
  // The line too is below the surface.
  const std::vector<std::string> line = x.all("//k:Placemark/k:LineString/k:coordinates");
  ASSERT_EQ(line.size(), 1u);
  EXPECT_NE(line[0].find(",-8"), std::string::npos);
}

TEST(ExportSchemas, RtzIsRtz10WithDefaultsRadiiAndASchedule) {
  ScratchDir dir;
  const std::string path = exported(dir, "sample.rtz");
  // RTZ carries each arc as the corners an ECDIS turns it from.
  const std::vector<ExportWaypoint>& want = sample().corners.waypoints;
  ASSERT_LT(want.size(), sample().route.waypoints.size());
  EXPECT_EQ(schema_errors(schema("rtz/rtz_1_0.xsd"), path), "");
  const Xml x(path, {{"r", "http://www.cirm.org/RTZ/1/0"}});
  ASSERT_TRUE(x.ok());
  EXPECT_EQ(x.all("/r:route/r:routeInfo/@routeName"), std::vector<std::string>{"sample"});  // the file's name
  // The default turn is the vehicle's; arcs keep their own radius (NM).
  const std::vector<double> turn = x.numbers("//r:defaultWaypoint/@radius");
  ASSERT_EQ(turn.size(), 1u);
  EXPECT_NEAR(turn[0] * kNauticalMile, sample().route.turn_radius_m, kCm);
  EXPECT_NEAR(x.numbers("//r:defaultWaypoint/r:leg/@speedMax").at(0) * kMetresPerSecondPerKnot,
              sample().mission.vehicle.max_speed_mps, 1e-3);
  expect_names(x.all("//r:waypoint/@name"), "rtz name", want);
  std::vector<double> radius;
  for (std::size_t i = 1; i <= want.size(); ++i) {
    const std::vector<double> r = x.numbers("//r:waypoint[@id='" + std::to_string(i) + "']/@radius");
    radius.push_back(r.empty() ? 0.0 : r[0] * kNauticalMile);
  }
  expect_each(
      radius, [](const ExportWaypoint& w) { return w.radius_m; }, kCm, "rtz radius", want);
  expect_each(
      x.numbers("//r:waypoint/r:position/@lon"), [](const ExportWaypoint& w) { return w.lonlat.x(); }, kDeg, "rtz lon",
      want);
  expect_each(
      x.numbers("//r:waypoint//r:depth_m"), [](const ExportWaypoint& w) { return w.depth_m; }, kCm, "rtz depth", want);
  // The planned speed is the schedule's (knots), not a leg's speedMax.
  EXPECT_TRUE(x.all("//r:waypoint/r:leg/@speedMax").empty());
  const std::string element = "//r:schedules/r:schedule/r:calculated/r:sheduleElement";
  expect_each(
      x.numbers(element + "/@speed"), [](const ExportWaypoint& w) { return w.speed_mps / kMetresPerSecondPerKnot; },
      1e-3, "rtz speed", want);
  std::vector<double> stays(want.size(), 0.0);
  for (std::size_t i = 1; i <= want.size(); ++i) {
    for (const std::string& s : x.all(element + "[@waypointId='" + std::to_string(i) + "']/@stay")) {
      int h = 0, m = 0, sec = 0;
      ASSERT_EQ(std::sscanf(s.c_str(), "%d:%d:%d", &h, &m, &sec), 3) << s;
      stays[i - 1] = h * 3600.0 + m * 60.0 + sec;
    }
  }
  expect_each(
      stays, [](const ExportWaypoint& w) { return std::round(w.hold_s); }, 1e-9, "rtz stay", want);
}

TEST(ExportSchemas, TheMissionsRtzTurnsOnItsArcsWithFewerWaypoints) {
  // The sample mission's RTZ read back and sailed as an ECDIS sails it (at
  // each waypoint a turn on its radius, the route's default where it has
  // none, tangent to both legs): every arc of the plan lies on that track.
  ScratchDir dir;
  const std::string path = exported(dir, "sample.rtz");
  const Xml x(path, {{"r", "http://www.cirm.org/RTZ/1/0"}});
  ASSERT_TRUE(x.ok());
  const double fallback = x.numbers("//r:defaultWaypoint/@radius").at(0) * kNauticalMile;
  const std::vector<double> lon = x.numbers("//r:waypoint/r:position/@lon"),
                            lat = x.numbers("//r:waypoint/r:position/@lat");
  const LocalFrame& frame = sample().mission.frame;
  std::vector<Vec2> wp;
  std::vector<double> radius;
  for (std::size_t i = 0; i < lon.size(); ++i) {
    wp.push_back(frame.from_lonlat(lon[i], lat[i]));
    const std::vector<double> r = x.numbers("//r:waypoint[@id='" + std::to_string(i + 1) + "']/@radius");
    radius.push_back(r.empty() ? fallback : r[0] * kNauticalMile);
  }
  // 250 waypoints as chords, 205 legs under 10 m: each arc is now its corners.
  EXPECT_LT(wp.size(), sample().route.waypoints.size() * 3 / 4);
  const std::vector<Vec2> track = ecdis_track(wp, radius);
  const auto off_track = [&](const Vec2& q) {
    double best = 1e9;
    for (std::size_t i = 0; i + 1 < track.size(); ++i) {
      const Vec2 d = track[i + 1] - track[i];
      const double f = d.squaredNorm() > 0 ? std::clamp((q - track[i]).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (track[i] + f * d - q).norm());
    }
    return best;
  };
  int arcs = 0;
  double worst = 0.0;
  for (const BasicManoeuvre& b : sample().plan.basics) {
    if (b.kind != BasicManoeuvre::Kind::arc) continue;
    ++arcs;
    for (int k = 0; k <= 8; ++k) worst = std::max(worst, off_track(b.point_at(b.length_m * k / 8)));
  }
  ASSERT_GT(arcs, 10);
  EXPECT_LT(worst, 0.02) << "an arc's point is this far (m) from the track an ECDIS sails";
}

TEST(ExportSchemas, CsvOpensInGdalWithoutOptions) {
  ScratchDir dir;
  const std::string path = exported(dir, "sample.csv");
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_TRUE(ds);
  std::vector<double> lon, lat, alt, speed, hold, radius;
  std::vector<std::string> names;
  for (auto& f : ds->GetLayer(0)) {
    const OGRGeometry* g = f->GetGeometryRef();
    ASSERT_NE(g, nullptr) << "GDAL made no geometry of the WKT column";
    const OGRPoint* p = g->toPoint();
    lon.push_back(p->getX()), lat.push_back(p->getY()), alt.push_back(p->getZ());
    names.emplace_back(f->GetFieldAsString("name"));
    speed.push_back(f->GetFieldAsDouble("speed_mps"));
    hold.push_back(f->GetFieldAsDouble("hold_s"));
    radius.push_back(f->GetFieldAsDouble("radius_m"));
    EXPECT_STREQ(f->GetFieldAsString("crs"), sample().mission.frame.id().c_str());
  }
  expect_names(names, "csv name");
  expect_each(
      lon, [](const ExportWaypoint& w) { return w.lonlat.x(); }, kDeg, "csv lon");
  expect_each(
      lat, [](const ExportWaypoint& w) { return w.lonlat.y(); }, kDeg, "csv lat");
  expect_each(
      alt, [](const ExportWaypoint& w) { return -w.depth_m; }, kCm, "csv altitude");
  expect_each(
      speed, [](const ExportWaypoint& w) { return w.speed_mps; }, 1e-6, "csv speed");
  expect_each(
      hold, [](const ExportWaypoint& w) { return w.hold_s; }, 1e-6, "csv hold");
  expect_each(
      radius, [](const ExportWaypoint& w) { return w.radius_m; }, kCm, "csv radius");
}

TEST(ExportSchemas, GeoJsonCarriesEveryField) {
  ScratchDir dir;
  std::ifstream in(exported(dir, "sample.geojson"));
  const nlohmann::json j = nlohmann::json::parse(in);
  std::vector<double> lon, depth, speed, hold, radius;
  std::vector<std::string> names;
  for (const auto& f : j.at("features")) {
    const auto& p = f.at("properties");
    if (p.at("kind") != "waypoint") {
      EXPECT_EQ(p.at("name"), sample().mission.name);
      EXPECT_NEAR(p.at("turn_radius_m").get<double>(), sample().route.turn_radius_m, 1e-9);
      continue;
    }
    lon.push_back(f.at("geometry").at("coordinates")[0].get<double>());
    names.push_back(p.at("name"));
    depth.push_back(p.at("depth_m"));
    speed.push_back(p.at("speed_mps"));
    hold.push_back(p.at("hold_s"));
    radius.push_back(p.at("radius_m"));
  }
  expect_names(names, "geojson name");
  expect_each(
      lon, [](const ExportWaypoint& w) { return w.lonlat.x(); }, kDeg, "geojson lon");
  expect_each(
      depth, [](const ExportWaypoint& w) { return w.depth_m; }, kCm, "geojson depth");
  expect_each(
      speed, [](const ExportWaypoint& w) { return w.speed_mps; }, 1e-9, "geojson speed");
  expect_each(
      hold, [](const ExportWaypoint& w) { return w.hold_s; }, 1e-9, "geojson hold");
  expect_each(
      radius, [](const ExportWaypoint& w) { return w.radius_m; }, 1e-9, "geojson radius");
}

TEST(ExportSchemas, ABrokenFileFailsTheSchemaCheck) {
  // The validator is not a rubber stamp: a GPX point without its lat, an RTZ with one waypoint.
  ScratchDir dir;
  const std::string gpx = dir.write("bad.gpx",
                                    "<?xml version=\"1.0\"?><gpx version=\"1.1\" creator=\"t\" "
                                    "xmlns=\"http://www.topografix.com/GPX/1/1\"><rte><rtept lon=\"1\"/></rte></gpx>");
  EXPECT_NE(schema_errors(schema("gpx/gpx.xsd"), gpx), "");
  const std::string rtz =
      dir.write("bad.rtz",
                "<?xml version=\"1.0\"?><route xmlns=\"http://www.cirm.org/RTZ/1/0\" version=\"1.0\">"
                "<routeInfo routeName=\"x\"/><waypoints><waypoint id=\"1\"><position lat=\"1\" "
                "lon=\"2\"/></waypoint></waypoints></route>");
  EXPECT_NE(schema_errors(schema("rtz/rtz_1_0.xsd"), rtz), "");
  const std::string kml = dir.write("bad.kml",
                                    "<?xml version=\"1.0\"?><kml xmlns=\"http://www.opengis.net/kml/2.2\"><Placemark>"
                                    "<Point><altitudeMode>underwater</altitudeMode><coordinates>1,2,-3</coordinates>"
                                    "</Point></Placemark></kml>");
  EXPECT_NE(schema_errors(schema("kml22/ogckml22.xsd"), kml), "");
}

TEST(ExportSchemas, RtzOfATurningRouteTurnsOnItsArcs) {
  // A route planned within a 40 m turning radius round a box and an ellipse,
  // written as RTZ and read back: an ECDIS turns each waypoint on the route's
  // radius (defaultWaypoint), and those turns rebuild the planned arcs: the
  // track they make keeps the margin and stays within the arcs' polyline
  // tolerance of the exact route.
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const Vec2 o(500000.0, 6000000.0);
  ObstacleSet set;
  PolygonObstacle box;
  box.id = "box";
  for (const Vec2& q : {Vec2(0, 0), Vec2(0, 60), Vec2(80, 60), Vec2(80, 0), Vec2(0, 0)})
    box.footprint.outer().push_back(to_bg(o + q));
  boost::geometry::correct(box.footprint);
  set.polygons.push_back(box);
  EllipticCylinder rock;
  rock.id = "rock";
  rock.footprint = Ellipse{o + Vec2(220.0, -30.0), 40.0, 6.0, 0.3};
  set.ellipses.push_back(rock);
  const double margin = 10.0, radius = 40.0, tolerance = 0.5;
  PlannerOptions options;
  options.margin = margin;
  options.tolerance = tolerance;
  options.graph = GraphKind::tangent;
  options.turn_radius_m = radius;
  Planner planner(set, options);
  const PlanOutcome plan = planner.solve({o + Vec2(-150.0, 20.0), o + Vec2(400.0, -10.0)});
  ASSERT_TRUE(plan.result.found);
  int arcs = 0;
  for (const RouteLeg& leg : plan.result.legs) arcs += leg.kind == RouteLeg::Kind::arc;
  ASSERT_GE(arcs, 2);

  ScratchDir dir;
  const std::string path = dir.file("turning.rtz");
  RouteExportSettings settings;
  settings.name = "turning";
  settings.margin_m = margin;
  settings.turn_radius_m = radius;
  write_route_file(export_route(plan.result.route, frame, VehicleParams{}, settings), path, ExportFormat::rtz);
  EXPECT_EQ(schema_errors(schema("rtz/rtz_1_0.xsd"), path), "");
  const Xml x(path, {{"r", "http://www.cirm.org/RTZ/1/0"}});
  ASSERT_TRUE(x.ok());
  const std::vector<double> turn = x.numbers("//r:defaultWaypoint/@radius");
  ASSERT_EQ(turn.size(), 1u);
  const double r = turn[0] * kNauticalMile;
  EXPECT_NEAR(r, radius, kCm);
  const std::vector<double> lon = x.numbers("//r:waypoint/r:position/@lon"),
                            lat = x.numbers("//r:waypoint/r:position/@lat");
  ASSERT_EQ(lon.size(), lat.size());
  std::vector<Vec2> wp;
  for (std::size_t i = 0; i < lon.size(); ++i) wp.push_back(frame.from_lonlat(lon[i], lat[i]));

  // The track an ECDIS draws: straight between the turns, and at each
  // waypoint an arc of radius r tangent to both legs. Each turn fits
  // between its neighbours' (the polyline's corners are a tangent length
  // from the arc's tangent points; positions to 1e-7 degrees bend legs of a
  // few centimetres by a few milliradians).
  const std::vector<Vec2> track = ecdis_track(
      wp, std::vector<double>(wp.size(), r), [](std::size_t i, bool fits) { EXPECT_TRUE(fits) << i; }, 0.2);
  const ObstacleField field(set, margin);
  double least = 1e9, furthest = 0.0;
  for (std::size_t i = 0; i + 1 < track.size(); ++i)
    least = std::min(least, field.segment_clearance(track[i], track[i + 1]).distance);
  for (const Vec2& q : track) {
    double nearest = 1e9;
    for (const RouteLeg& leg : plan.result.legs) {
      Vec2 p = leg.from;
      if (leg.kind == RouteLeg::Kind::line) {
        const Vec2 d = leg.to - leg.from;
        p = leg.from + std::clamp((q - leg.from).dot(d) / d.squaredNorm(), 0.0, 1.0) * d;
      } else {
        for (int k = 0; k <= 2000; ++k) {
          const Vec2 c = arc_point(leg, leg.phi_from + (leg.phi_to - leg.phi_from) * k / 2000);
          if ((c - q).norm() < (p - q).norm()) p = c;
        }
      }
      nearest = std::min(nearest, (p - q).norm());
    }
    furthest = std::max(furthest, nearest);
  }
  EXPECT_GE(least, margin - 1e-3);
  EXPECT_LT(furthest, 0.05);  // the turns are the arcs (to the RTZ's 1e-7 degrees and the sampling)
  std::printf(
      "[ export ] RTZ of a route within %.0f m: %zu waypoints, %d arcs; the ECDIS track keeps %.3f m, "
      "at most %.3f m off the planned arcs\n",
      radius, wp.size(), arcs, least, furthest);
}

// Issue 39, item 3: a name is whole in every format, or refused naming it.
// Names a user may type (markup, CDATA's end without its '>', quotes, format
// specifiers, any script) come back byte for byte through each format's own
// reader; names no format carries whole (a control character, "]]>", bytes
// that are not UTF-8) are refused before any file is written.
TEST(ExportSchemas, HostileNamesComeBackWholeFromEveryFormatOrAreRefusedNamingTheField) {
  ScratchDir dir;
  const std::vector<std::string> kept = {"a]]b ]> <!-- x <![CDATA[ y", "&amp; <b>\"q\" 'a' %s %n {{n}} ${x}",
                                         "\xc3\xa9 \xe4\xb8\xad\xe6\x96\x87 \xf0\x9f\x9a\xa2 \xe2\x80\xae rtl",
                                         "a,b;c|d\\e=f"};
  const std::vector<std::string> formats = {"gpx", "kml", "rtz", "geojson", "csv", "plan", "bhv"};
  int k = 0;
  for (const std::string& name : kept) {
    ExportRoute route = sample().route;
    route.name = name;
    for (ExportWaypoint& w : route.waypoints) w.manoeuvre = name;
    for (const std::string& ext : formats) {
      const std::string path = dir.file("r" + std::to_string(k++) + "." + ext);
      ASSERT_NO_THROW(write_route_file(route, path, export_format_for(path), {0.5, false, name})) << ext << " " << name;
      if (ext == "gpx") {
        EXPECT_EQ(schema_errors(schema("gpx/gpx.xsd"), path), "") << name;
        const Xml x(path, {{"g", "http://www.topografix.com/GPX/1/1"}});
        EXPECT_EQ(x.all("//g:rte/g:name"), std::vector<std::string>{name});
      } else if (ext == "kml") {
        EXPECT_EQ(schema_errors(schema("kml22/ogckml22.xsd"), path), "") << name;
        const Xml x(path, {{"k", "http://www.opengis.net/kml/2.2"}});
        EXPECT_EQ(x.all("//k:Placemark[k:LineString]/k:name"), std::vector<std::string>{name});
      } else if (ext == "rtz") {
        EXPECT_EQ(schema_errors(schema("rtz/rtz_1_0.xsd"), path), "") << name;
        const Xml x(path, {{"r", "http://www.cirm.org/RTZ/1/0"}});
        EXPECT_EQ(x.all("//r:routeInfo/@routeName"), std::vector<std::string>{name});
      } else if (ext == "geojson") {
        std::ifstream in(path);
        const nlohmann::json j = nlohmann::json::parse(in);
        int lines = 0;
        for (const auto& f : j.at("features")) {
          if (f.at("properties").at("kind") == "waypoint") continue;
          ++lines;
          EXPECT_EQ(f.at("properties").at("name"), name);
        }
        EXPECT_EQ(lines, 1);
      } else if (ext == "csv") {
        GDALAllRegister();
        GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
        ASSERT_TRUE(ds);
        std::size_t rows = 0;
        for (auto& f : ds->GetLayer(0)) {
          ++rows;
          EXPECT_EQ(std::string(f->GetFieldAsString("manoeuvre")), name);
        }
        EXPECT_EQ(rows, route.waypoints.size());
      } else if (ext == "plan") {
        std::ifstream in(path);
        EXPECT_TRUE(nlohmann::json::accept(in)) << name;
      } else if (ext == "bhv") {
        std::ifstream in(path, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(text.substr(0, text.find('\n')), "// deepguide route for pHelmIvP: " + name);
        for (const char c : text) EXPECT_TRUE(c == '\n' || static_cast<unsigned char>(c) >= 0x20) << int(c);
      }
    }
  }
  const std::vector<std::string> refused = {"a]]>b<!-- c",
                                            "a\x01"
                                            "b",
                                            "\x1b[31mred",
                                            "a\x7f"
                                            "b",
                                            "a\x0b"
                                            "b",
                                            std::string("a\0b", 3),
                                            "a\xff"
                                            "b",
                                            "tab\there",
                                            "new\nline",
                                            "c1 \xc2\x85 next-line"};
  for (const std::string& name : refused) {
    for (const std::string& ext : formats) {
      ExportRoute route = sample().route;
      route.name = name;
      const std::string path = dir.file("bad" + std::to_string(k++) + "." + ext);
      try {
        write_route_file(route, path, export_format_for(path), {0.5, false, "plain"});
        ADD_FAILURE() << ext << ": accepted '" << name << "'";
      } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("route name"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.find('\x1b'), std::string::npos) << what;
      }
      EXPECT_FALSE(std::filesystem::exists(path)) << ext;
    }
  }
  // The route name plan -o takes from the output file's name, and a manoeuvre's.
  {
    ExportRoute route = sample().route;
    const std::string path = dir.file("x]]>y.kml");
    EXPECT_THROW(write_route_file(route, path, ExportFormat::kml, {}), InputError);
    EXPECT_FALSE(std::filesystem::exists(path));
    route.waypoints[1].manoeuvre = "m\x01";
    try {
      write_route_file(route, dir.file("m.gpx"), ExportFormat::gpx, {});
      ADD_FAILURE() << "a manoeuvre name with a control character accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("manoeuvre name"), std::string::npos) << e.what();
    }
  }
  // A mission's plan as YAML: the name comes back through yaml-cpp, or is refused.
  for (const std::string& name : {kept[0], kept[1], kept[2], refused[1], refused[5]}) {
    Mission mission = sample().mission;
    mission.name = name;
    const std::string path = dir.file("m" + std::to_string(k++) + ".yaml");
    const bool bad = name == refused[1] || name == refused[5];
    if (bad) {
      EXPECT_THROW(export_plan(mission, sample().plan, path, ExportFormat::yaml), InputError);
      EXPECT_FALSE(std::filesystem::exists(path));
      continue;
    }
    export_plan(mission, sample().plan, path, ExportFormat::yaml);
    EXPECT_EQ(YAML::LoadFile(path)["name"].as<std::string>(), name);
  }
}
