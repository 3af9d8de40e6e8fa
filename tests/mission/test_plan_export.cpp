// Mission exports (mission/plan_export.hpp): the sample mission's plan written
// in every format and read back by an independent reader (GDAL for GeoJSON,
// GPX, KML and CSV; nlohmann/json for QGroundControl's plan; libxml2 for RTZ;
// a text parser for the MOOS-IvP behaviour file; our reader for the YAML),
// equal to the waypoints within 1e-6 degrees or 1 cm and in depth within
// 1 cm; writes are atomic and never replace a file without overwrite.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <ogrsf_frmts.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/moos_helm.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

constexpr double kDeg = 1e-7;  // degrees (1 cm in latitude; the acceptance asks 1e-6)
constexpr double kCm = 0.01;   // metres

struct Sample {
  Mission mission;
  MissionPlan plan;
  std::vector<ExportWaypoint> waypoints;
  std::vector<ExportWaypoint> corners;  ///< RTZ's: arcs as the corners an ECDIS turns them from
};

const Sample& sample() {
  static const Sample s = [] {
    Sample out{read_mission(test::source_file("data/missions/sample_mission.yaml")), {}, {}, {}};
    const MissionEnvironment env = load_environment(out.mission);
    out.plan = plan_mission(out.mission, env, expand_mission(out.mission, env.obstacles)).plan;
    out.waypoints = export_waypoints(out.mission, out.plan);
    out.corners = export_corner_waypoints(out.mission, out.plan);
    return out;
  }();
  return s;
}

std::string exported(ScratchDir& dir, const std::string& name) {
  const std::string path = dir.file(name);
  export_plan(sample().mission, sample().plan, path, export_format_for(path));
  return path;
}

// Lon, lat, depth of each point read back, against the waypoints (depths
// as `depth_of` says the format carries them; default: on arrival).
void expect_waypoints(const std::vector<Eigen::Vector3d>& got, const char* format,
                      const std::function<double(std::size_t)>& depth_of = {}, bool corners = false) {
  const std::vector<ExportWaypoint>& want = corners ? sample().corners : sample().waypoints;
  ASSERT_EQ(got.size(), want.size()) << format;
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_NEAR(got[i].x(), want[i].lonlat.x(), kDeg) << format << " " << i;
    ASSERT_NEAR(got[i].y(), want[i].lonlat.y(), kDeg) << format << " " << i;
    ASSERT_NEAR(got[i].z(), depth_of ? depth_of(i) : want[i].depth_m, kCm) << format << " " << i;
  }
}

GDALDatasetUniquePtr open_vector(const std::string& path) {
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << path;
  return ds;
}

}  // namespace

TEST(PlanExport, WaypointsFollowThePlan) {
  const Sample& s = sample();
  ASSERT_GT(s.waypoints.size(), s.plan.basics.size());  // arcs give several
  EXPECT_LT((s.waypoints.front().xy - s.mission.start).norm(), 1e-9);
  EXPECT_NEAR(s.waypoints.back().along_m, s.plan.length_m, 1e-6);
  double hold = 0.0;
  for (const ExportWaypoint& w : s.waypoints) hold += w.hold_s;
  EXPECT_DOUBLE_EQ(hold, 120.0);  // the GPS fix's (going around holds nowhere)
  for (std::size_t i = 1; i < s.waypoints.size(); ++i) EXPECT_GE(s.waypoints[i].time_s, s.waypoints[i - 1].time_s);
}

TEST(PlanExport, GdalFormatsReadBack) {
  ScratchDir dir;
  {  // GeoJSON: the waypoint points carry depth_m.
    auto ds = open_vector(exported(dir, "plan.geojson"));
    std::vector<Eigen::Vector3d> got;
    for (auto& f : ds->GetLayer(0)) {
      if (std::string(f->GetFieldAsString("kind")) != "waypoint") continue;
      const auto* p = f->GetGeometryRef()->toPoint();
      got.emplace_back(p->getX(), p->getY(), f->GetFieldAsDouble("depth_m"));
    }
    expect_waypoints(got, "geojson");
  }
  {  // GPX: route points, elevation = -depth.
    auto ds = open_vector(exported(dir, "plan.gpx"));
    OGRLayer* points = ds->GetLayerByName("route_points");
    ASSERT_NE(points, nullptr);
    std::vector<Eigen::Vector3d> got;
    for (auto& f : points) {
      const auto* p = f->GetGeometryRef()->toPoint();
      got.emplace_back(p->getX(), p->getY(), -f->GetFieldAsDouble("ele"));
    }
    expect_waypoints(got, "gpx");
  }
  {  // KML: the route line, altitude = -depth.
    auto ds = open_vector(exported(dir, "plan.kml"));
    OGRLayer* route = ds->GetLayerByName("route");
    ASSERT_NE(route, nullptr);
    OGRFeatureUniquePtr f(route->GetNextFeature());
    ASSERT_TRUE(f);
    const auto* line = f->GetGeometryRef()->toLineString();
    std::vector<Eigen::Vector3d> got;
    for (int i = 0; i < line->getNumPoints(); ++i) got.emplace_back(line->getX(i), line->getY(i), -line->getZ(i));
    expect_waypoints(got, "kml");
  }
  {  // CSV: lon, lat, depth_m columns.
    auto ds = open_vector(exported(dir, "plan.csv"));
    std::vector<Eigen::Vector3d> got;
    for (auto& f : ds->GetLayer(0)) {
      got.emplace_back(f->GetFieldAsDouble("lon"), f->GetFieldAsDouble("lat"), f->GetFieldAsDouble("depth_m"));
    }
    expect_waypoints(got, "csv");
  }
}

TEST(PlanExport, QGroundControlPlanFollowsItsFormat) {
  ScratchDir dir;
  std::ifstream in(exported(dir, "plan.plan"));
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("fileType"), "Plan");
  EXPECT_EQ(j.at("version"), 1);
  const auto& mission = j.at("mission");
  EXPECT_EQ(mission.at("version"), 2);
  EXPECT_EQ(mission.at("vehicleType"), 12);  // MAV_TYPE_SUBMARINE
  EXPECT_EQ(mission.at("firmwareType"), 3);  // ArduPilot
  EXPECT_EQ(j.at("groundStation"), "QGroundControl");
  EXPECT_EQ(j.at("geoFence").at("version"), 2);
  EXPECT_EQ(j.at("rallyPoints").at("version"), 2);
  ASSERT_EQ(mission.at("plannedHomePosition").size(), 3u);
  EXPECT_NEAR(mission.at("plannedHomePosition")[0].get<double>(), sample().waypoints.front().lonlat.y(), kDeg);
  std::vector<Eigen::Vector3d> got;
  std::vector<double> acceptance;
  double speed = -1.0;
  std::size_t k = 0;
  for (const auto& item : mission.at("items")) {
    EXPECT_EQ(item.at("type"), "SimpleItem");
    const auto& p = item.at("params");
    ASSERT_EQ(p.size(), 7u);
    if (item.at("command") == 178) {
      speed = p[1].get<double>();
      continue;
    }
    ASSERT_EQ(item.at("command"), 16);
    EXPECT_EQ(item.at("frame"), 3);
    ASSERT_LT(k, sample().waypoints.size());
    EXPECT_NEAR(speed, sample().waypoints[k].speed_mps, 1e-9) << k;
    EXPECT_NEAR(p[0].get<double>(), sample().waypoints[k].hold_s, 1e-9) << k;
    // ArduSub reads an altitude of 0 as "keep the depth": the surface is 1 cm deep.
    EXPECT_LT(p[6].get<double>(), 0.0) << k;
    got.emplace_back(p[5].get<double>(), p[4].get<double>(), -p[6].get<double>());
    acceptance.push_back(p[1].get<double>());
    ++k;
  }
  expect_waypoints(got, "plan");
  // The acceptance radius is where the turn begins: R tan(theta / 2) before
  // the corner, theta the course change between the legs read back from the
  // file (lon/lat to metres locally), at least 2 m, at most half the shorter
  // leg, 2 m at the ends and where the vehicle holds.
  const auto& w = sample().waypoints;
  const double route_turn =
      export_route(sample().mission, sample().plan, ExportOptions{}.arc_tolerance_m, false).turn_radius_m;
  ASSERT_GT(route_turn, 5.0);
  int turning = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (i == 0 || i + 1 == got.size() || w[i].hold_s > 0.0) {
      EXPECT_EQ(acceptance[i], 2.0) << i;
      continue;
    }
    const double m_lon = 111320.0 * std::cos(got[i].y() * M_PI / 180.0), m_lat = 110540.0;
    const Eigen::Vector2d in((got[i].x() - got[i - 1].x()) * m_lon, (got[i].y() - got[i - 1].y()) * m_lat);
    const Eigen::Vector2d out((got[i + 1].x() - got[i].x()) * m_lon, (got[i + 1].y() - got[i].y()) * m_lat);
    const double theta = std::acos(std::clamp(in.dot(out) / (in.norm() * out.norm()), -1.0, 1.0));
    const double r = w[i].radius_m > 0.0 ? w[i].radius_m : route_turn;
    const double want = std::max(2.0, std::min(r * std::tan(theta / 2), 0.5 * std::min(in.norm(), out.norm())));
    EXPECT_NEAR(acceptance[i], want, 0.01 * want + 0.05) << i;  // the file's lon/lat against the plan's metres
    if (acceptance[i] > 2.5) ++turning;
  }
  EXPECT_GT(turning, 20);
}

TEST(PlanExport, RtzReadsBackWithLibxml2) {
  ScratchDir dir;
  const std::string path = exported(dir, "plan.rtz");
  xmlDocPtr doc = xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET);
  ASSERT_NE(doc, nullptr);
  const auto name = [](xmlNodePtr n) { return std::string(reinterpret_cast<const char*>(n->name)); };
  const auto attr = [](xmlNodePtr n, const char* a) {
    xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(a));
    const double d = v ? std::stod(reinterpret_cast<const char*>(v)) : NAN;
    xmlFree(v);
    return d;
  };
  xmlNodePtr root = xmlDocGetRootElement(doc);
  ASSERT_EQ(name(root), "route");
  EXPECT_STREQ(reinterpret_cast<const char*>(root->ns->href), "http://www.cirm.org/RTZ/1/0");
  std::vector<Eigen::Vector3d> got;
  for (xmlNodePtr c = root->children; c; c = c->next) {
    if (c->type != XML_ELEMENT_NODE || name(c) != "waypoints") continue;
    for (xmlNodePtr w = c->children; w; w = w->next) {
      if (w->type != XML_ELEMENT_NODE || name(w) != "waypoint") continue;  // not defaultWaypoint
      Eigen::Vector3d p(NAN, NAN, NAN);
      for (xmlNodePtr e = w->children; e; e = e->next) {
        if (e->type != XML_ELEMENT_NODE) continue;
        if (name(e) == "position") p.head<2>() = Eigen::Vector2d(attr(e, "lon"), attr(e, "lat"));
        if (name(e) != "extensions") continue;
        for (xmlNodePtr x = e->children->next->children; x; x = x->next) {
          if (x->type == XML_ELEMENT_NODE && name(x) == "depth_m") {
            xmlChar* v = xmlNodeGetContent(x);
            p.z() = std::stod(reinterpret_cast<const char*>(v));
            xmlFree(v);
          }
        }
      }
      got.push_back(p);
    }
  }
  xmlFreeDoc(doc);
  expect_waypoints(got, "rtz", {}, true);
}

TEST(PlanExport, MoosBehavioursReadBackInLocalCoordinates) {
  ScratchDir dir;
  std::ifstream in(exported(dir, "plan.bhv"));
  std::string line;
  double lat0 = NAN, lon0 = NAN;
  std::vector<Eigen::Vector3d> local;  // x, y, depth
  std::vector<int> conditions, endflags;
  std::size_t leg_start = 0;
  while (std::getline(in, line)) {
    const auto value = [&](const char* key) -> std::optional<std::string> {
      const auto at = line.find(key);
      if (at == std::string::npos) return std::nullopt;
      return line.substr(line.find('=', at) + 1);
    };
    if (line.rfind("Behavior = ", 0) == 0 && line != "Behavior = BHV_ConstantDepth") leg_start = local.size();
    if (auto v = value("LatOrigin")) lat0 = std::stod(*v);
    if (auto v = value("LongOrigin")) lon0 = std::stod(*v);
    std::optional<std::string> pts = value("  points");
    if (!pts) pts = value("  station_pt");
    if (pts) {
      std::stringstream ss(*pts);
      std::string pair;
      while (std::getline(ss, pair, ':')) {
        const auto comma = pair.find(',');
        local.emplace_back(std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1)), NAN);
      }
    }
    if (auto v = value("  depth     ")) {
      for (std::size_t i = leg_start; i < local.size(); ++i) local[i].z() = std::stod(*v);
    }
    // Legs run in order: leg N's endflag starts leg N + 1.
    const auto last_value = [&](const char* key) -> std::optional<int> {
      if (line.find(key) == std::string::npos) return std::nullopt;
      return std::stoi(line.substr(line.rfind('=') + 1));
    };
    if (auto v = last_value("condition = DG_LEG")) conditions.push_back(*v);
    if (auto v = last_value("endflag   = DG_LEG")) endflags.push_back(*v);
  }
  ASSERT_FALSE(endflags.empty());
  for (std::size_t i = 0; i < endflags.size(); ++i) EXPECT_EQ(endflags[i], static_cast<int>(i) + 2) << i;
  ASSERT_TRUE(std::isfinite(lat0) && std::isfinite(lon0));
  // Kiel lies in zone 32 by either rule; MOOSGeodesy's exceptions are tested below.
  const LocalFrame utm = LocalFrame::from_user_crs("EPSG:32632");
  const Vec2 origin = utm.from_lonlat(lon0, lat0);
  std::vector<Eigen::Vector3d> got{{lon0, lat0, sample().waypoints.front().depth_m}};  // the start is the origin
  for (const Eigen::Vector3d& p : local) {
    const Vec2 ll = utm.to_lonlat(origin + p.head<2>());
    got.emplace_back(ll.x(), ll.y(), p.z());
  }
  // Each leg holds the depth at its end waypoint, as the CSV export of the same plan gives it. A
  // dive in place without a hold is no waypoint of the helm's (a loiter reaches the depth there).
  auto csv = open_vector(exported(dir, "plan.csv"));
  std::vector<double> csv_depth;
  for (auto& f : csv->GetLayer(0)) csv_depth.push_back(f->GetFieldAsDouble("depth_m"));
  const auto& w = sample().waypoints;
  ASSERT_EQ(csv_depth.size(), w.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (i > 0 && (w[i].xy - w[i - 1].xy).norm() < 1e-6 && w[i].hold_s == 0.0) continue;
    ASSERT_LT(k, got.size());
    ASSERT_NEAR(got[k].x(), w[i].lonlat.x(), kDeg) << i;
    ASSERT_NEAR(got[k].y(), w[i].lonlat.y(), kDeg) << i;
    ASSERT_NEAR(got[k].z(), csv_depth[i], kCm) << i;
    ++k;
  }
  EXPECT_EQ(k, got.size());
  std::size_t changes = 0;  // the check means something: the plan changes depth along its legs
  for (std::size_t i = 1; i < csv_depth.size(); ++i) changes += std::abs(csv_depth[i] - csv_depth[i - 1]) > 0.5;
  EXPECT_GE(changes, 3u);
  // MOOSGeodesy's zones: Norway's 32V at 60 N 5 E (31 by the plain rule), Svalbard's 33X at 78 N 15 E.
  EXPECT_EQ(moos_local_utm(5.0, 60.0).id(), "EPSG:32632");
  EXPECT_EQ(moos_local_utm(15.0, 78.0).id(), "EPSG:32633");
  EXPECT_EQ(moos_local_utm(10.2, 54.4).id(), "EPSG:32632");
}

TEST(PlanExport, OurYamlReadsBackAsTheBasicManoeuvres) {
  ScratchDir dir;
  const MissionPlan back = read_plan_yaml(exported(dir, "plan.yaml"));
  const MissionPlan& plan = sample().plan;
  ASSERT_EQ(back.basics.size(), plan.basics.size());
  EXPECT_NEAR(back.length_m, plan.length_m, kCm);
  for (std::size_t i = 0; i < plan.basics.size(); ++i) {
    const BasicManoeuvre &a = plan.basics[i], &b = back.basics[i];
    ASSERT_EQ(a.kind, b.kind) << i;
    ASSERT_EQ(a.role, b.role) << i;
    ASSERT_LT((a.from - b.from).norm(), kCm) << i;
    ASSERT_LT((a.to - b.to).norm(), kCm) << i;
    ASSERT_NEAR(a.depth_m, b.depth_m, kCm) << i;
    ASSERT_NEAR(a.length_m, b.length_m, kCm) << i;
    ASSERT_NEAR(a.hold_s, b.hold_s, 1e-3) << i;
    if (a.kind == BasicManoeuvre::Kind::arc) {
      ASSERT_EQ(a.turn, b.turn) << i;
    }
  }
  EXPECT_EQ(back.basics.back().source + 1, sample().mission.manoeuvres.size());
  // Hostile plan files are one-line errors.
  const std::string bad = dir.write("bad.yaml", "basic_manoeuvres:\n  - {kind: spiral, from: {x: 0, y: 0}}\n");
  try {
    read_plan_yaml(bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_plan_yaml(dir.file("missing.yaml")), InputError);
}

TEST(PlanExport, WritesAreAtomicAndNeverReplaceWithoutOverwrite) {
  ScratchDir dir;
  const std::string path = dir.write("plan.gpx", "precious");
  const Sample& s = sample();
  try {
    export_plan(s.mission, s.plan, path, ExportFormat::gpx);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("`overwrite`"), std::string::npos) << e.what();
  }
  std::ifstream kept(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), {}), "precious");
  export_plan(s.mission, s.plan, path, ExportFormat::gpx, {0.5, true});
  EXPECT_GT(std::filesystem::file_size(path), 1000u);
  // A failed write leaves nothing behind, and an old file as it was: csv needs a .csv name.
  const std::string old_file = dir.write("plan.txt", "old");
  EXPECT_THROW(export_plan(s.mission, s.plan, old_file, ExportFormat::csv, {0.5, true}), InputError);
  std::ifstream old_kept(old_file);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(old_kept), {}), "old");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 2u);
  export_plan(s.mission, s.plan, dir.file("UPPER.CSV"), ExportFormat::csv);  // the extension in any case
  // Errors name the user's file, never the temporary one.
  try {
    export_plan(s.mission, s.plan, "/proc/plan.geojson", ExportFormat::geojson);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find(".tmp"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
  EXPECT_THROW(export_plan(s.mission, s.plan, dir.file("no/such/folder/plan.gpx"), ExportFormat::gpx), InputError);
  EXPECT_THROW(parse_export_format("shapefile"), InputError);
  EXPECT_THROW(export_format_for("plan.docx"), InputError);
  EXPECT_EQ(export_format_for("PLAN.RTZ"), ExportFormat::rtz);
}
