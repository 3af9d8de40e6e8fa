// The plan through GDAL's vector drivers: GeoJSON (the route format of
// planning/route_io.hpp), GPX, KML and CSV.
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide::detail {
namespace {

[[noreturn]] void fail(const ExportInput& in, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(in.destination + ": could not " + what + (why.empty() ? std::string() : ": " + why));
}

void write_geojson(const std::string& path, const ExportInput& in) {
  Route route;
  std::vector<nlohmann::json> points;
  for (std::size_t i = 0; i < in.waypoints.size(); ++i) {
    const ExportWaypoint& w = in.waypoints[i];
    route.points.push_back(w.xy);
    route.depth_m.push_back(w.depth_m);
    points.push_back({{"depth_m", w.depth_m},     {"speed_mps", w.speed_mps}, {"hold_s", w.hold_s},
                      {"along_m", w.along_m},     {"time_s", w.time_s},       {"role", role_name(w.role)},
                      {"manoeuvre", w.manoeuvre}});
  }
  const nlohmann::json properties = {{"mission", in.mission.name},
                                     {"crs", in.mission.frame.id()},
                                     {"length_m", in.plan.length_m},
                                     {"time_s", in.waypoints.back().time_s + in.waypoints.back().hold_s}};
  write_route_geojson(path, route, in.mission.frame, properties, points);
}

GDALDatasetUniquePtr create(const std::string& path, const char* driver_name, const ExportInput& in,
                            std::vector<const char*> options = {}) {
  gdal::ensure_registered();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
  if (driver == nullptr) fail(in, std::string("find GDAL's ") + driver_name + " driver");
  options.push_back(nullptr);
  GDALDatasetUniquePtr ds(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, const_cast<char**>(options.data())));
  if (!ds) fail(in, "create the file");
  return ds;
}

OGRLineString line_of(const ExportInput& in) {
  OGRLineString line;
  for (const ExportWaypoint& w : in.waypoints) line.addPoint(w.lonlat.x(), w.lonlat.y(), 0.0 - w.depth_m);  // 0 - 0 is +0, not -0
  return line;
}

void add_field(OGRLayer* layer, const char* name, OGRFieldType type, const ExportInput& in) {
  OGRFieldDefn fd(name, type);
  if (layer->CreateField(&fd) != OGRERR_NONE) fail(in, std::string("create field ") + name);
}

void write_gpx(const std::string& path, const ExportInput& in) {
  GDALDatasetUniquePtr ds = create(path, "GPX", in);
  const auto geo = gdal::wgs84();
  OGRLayer* layer = ds->CreateLayer("routes", geo.get(), wkbLineString25D, nullptr);
  if (layer == nullptr) fail(in, "create the GPX route");
  OGRFeature f(layer->GetLayerDefn());
  f.SetField("name", in.mission.name.c_str());
  f.SetField("desc", ("deepguide plan in " + in.mission.frame.id() + "; ele = -depth (m)").c_str());
  OGRLineString line = line_of(in);
  f.SetGeometry(&line);
  if (layer->CreateFeature(&f) != OGRERR_NONE) fail(in, "write the GPX route");
}

void write_kml(const std::string& path, const ExportInput& in) {
  GDALDatasetUniquePtr ds = create(path, "KML", in);
  const auto geo = gdal::wgs84();
  OGRLayer* route = ds->CreateLayer("route", geo.get(), wkbLineString25D, nullptr);
  if (route == nullptr) fail(in, "create the KML route");
  {
    OGRFeature f(route->GetLayerDefn());
    f.SetField("Name", in.mission.name.c_str());
    f.SetField("Description", "deepguide plan; altitude = -depth (m)");
    OGRLineString line = line_of(in);
    f.SetGeometry(&line);
    if (route->CreateFeature(&f) != OGRERR_NONE) fail(in, "write the KML route");
  }
  OGRLayer* points = ds->CreateLayer("waypoints", geo.get(), wkbPoint25D, nullptr);
  if (points == nullptr) fail(in, "create the KML waypoints");
  for (std::size_t i = 0; i < in.waypoints.size(); ++i) {
    const ExportWaypoint& w = in.waypoints[i];
    OGRFeature f(points->GetLayerDefn());
    char text[160];
    std::snprintf(text, sizeof text, "depth %.2f m, speed %.2f m/s, hold %.0f s, %.0f s into the mission (%s)",
                  w.depth_m, w.speed_mps, w.hold_s, w.time_s, role_name(w.role));
    f.SetField("Name", std::to_string(i + 1).c_str());
    f.SetField("Description", text);
    OGRPoint p(w.lonlat.x(), w.lonlat.y(), 0.0 - w.depth_m);
    f.SetGeometry(&p);
    if (points->CreateFeature(&f) != OGRERR_NONE) fail(in, "write a KML waypoint");
  }
}

void write_csv(const std::string& path, const ExportInput& in) {
  // GDAL's CSV driver makes a folder of files for any other name.
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".csv") {
    throw InputError(in.destination + ": expected a .csv file name for the csv format");
  }
  GDALDatasetUniquePtr ds = create(path, "CSV", in);
  OGRLayer* layer = ds->CreateLayer("waypoints", nullptr, wkbNone, nullptr);
  if (layer == nullptr) fail(in, "create the CSV table");
  add_field(layer, "index", OFTInteger, in);
  for (const char* name : {"lon", "lat", "x", "y", "depth_m", "speed_mps", "hold_s", "along_m", "time_s"}) {
    add_field(layer, name, OFTReal, in);
  }
  add_field(layer, "role", OFTString, in);
  add_field(layer, "manoeuvre", OFTString, in);
  for (std::size_t i = 0; i < in.waypoints.size(); ++i) {
    const ExportWaypoint& w = in.waypoints[i];
    OGRFeature f(layer->GetLayerDefn());
    f.SetField("index", static_cast<int>(i));
    f.SetField("lon", w.lonlat.x());
    f.SetField("lat", w.lonlat.y());
    f.SetField("x", w.xy.x());
    f.SetField("y", w.xy.y());
    f.SetField("depth_m", w.depth_m);
    f.SetField("speed_mps", w.speed_mps);
    f.SetField("hold_s", w.hold_s);
    f.SetField("along_m", w.along_m);
    f.SetField("time_s", w.time_s);
    f.SetField("role", role_name(w.role));
    f.SetField("manoeuvre", w.manoeuvre.c_str());
    if (layer->CreateFeature(&f) != OGRERR_NONE) fail(in, "write a CSV row");
  }
}

}  // namespace

void write_plan_ogr(const std::string& path, ExportFormat format, const ExportInput& in) {
  gdal::QuietErrors quiet;
  switch (format) {
    case ExportFormat::geojson: write_geojson(path, in); return;
    case ExportFormat::gpx: write_gpx(path, in); return;
    case ExportFormat::kml: write_kml(path, in); return;
    case ExportFormat::csv: write_csv(path, in); return;
    default: break;
  }
  throw InputError(in.destination + ": " + to_string(format) + " is not a GDAL format");
}

}  // namespace deepguide::detail
