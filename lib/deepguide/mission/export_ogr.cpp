// Routes through GDAL's vector drivers: GeoJSON (the route format of
// planning/route_io.hpp), GPX (its route_points layer, so each point keeps
// its name, elevation and extension fields), KML (the LIBKML driver, which
// writes altitudeMode and typed ExtendedData) and CSV (a WKT column).
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide::detail {
namespace {

[[noreturn]] void fail(const ExportInput& in, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(in.destination + ": could not " + what + (why.empty() ? std::string() : ": " + why));
}

// The per-waypoint fields every format but GPX's standard elements carries.
struct Field {
  const char* name;
  OGRFieldType type;
};
constexpr Field kWaypointFields[] = {{"depth_m", OFTReal},  {"speed_mps", OFTReal},  {"hold_s", OFTReal},
                                     {"radius_m", OFTReal}, {"along_m", OFTReal},    {"time_s", OFTReal},
                                     {"role", OFTString},   {"manoeuvre", OFTString}};

void set_waypoint_fields(OGRFeature& f, const ExportWaypoint& w) {
  f.SetField("depth_m", w.depth_m);
  f.SetField("speed_mps", w.speed_mps);
  f.SetField("hold_s", w.hold_s);
  f.SetField("radius_m", w.radius_m);
  f.SetField("along_m", w.along_m);
  f.SetField("time_s", w.time_s);
  f.SetField("role", w.role.c_str());
  f.SetField("manoeuvre", w.manoeuvre.c_str());
}

std::string description(const ExportWaypoint& w) {
  std::string d = w.role;
  if (!w.manoeuvre.empty()) d += " (" + w.manoeuvre + ")";
  return d + ": depth " + fixed(w.depth_m, 2) + " m, " + fixed(w.speed_mps, 2) + " m/s" +
         (w.hold_s > 0.0 ? ", hold " + fixed(w.hold_s, 0) + " s" : std::string());
}

void write_geojson(const std::string& path, const ExportInput& in) {
  const ExportRoute& r = in.route;
  Route route;
  std::vector<nlohmann::json> points;
  for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
    const ExportWaypoint& w = r.waypoints[i];
    route.points.push_back(w.xy);
    route.depth_m.push_back(w.depth_m);
    points.push_back(i < r.waypoint_properties.size() ? r.waypoint_properties[i] : nlohmann::json::object());
    points.back().update({{"name", w.name},
                          {"depth_m", w.depth_m},
                          {"speed_mps", w.speed_mps},
                          {"hold_s", w.hold_s},
                          {"radius_m", w.radius_m},
                          {"along_m", w.along_m},
                          {"time_s", w.time_s},
                          {"role", w.role},
                          {"manoeuvre", w.manoeuvre}});
    if (w.manoeuvre.empty()) points.back().erase("manoeuvre");
  }
  nlohmann::json properties = r.properties;
  properties["name"] = r.name;
  properties["crs"] = r.frame.id();
  properties["length_m"] = r.length_m;
  if (r.turn_radius_m > 0.0) properties["turn_radius_m"] = r.turn_radius_m;
  write_route_geojson(path, route, r.frame, properties, points);
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

void add_field(OGRLayer* layer, const char* name, OGRFieldType type, const ExportInput& in) {
  OGRFieldDefn fd(name, type);
  if (layer->CreateField(&fd) != OGRERR_NONE) fail(in, std::string("create field ") + name);
}

// Altitude = -depth: below the sea surface (0 - 0 is +0, not -0).
double altitude(const ExportWaypoint& w) { return 0.0 - w.depth_m; }

void write_gpx(const std::string& path, const ExportInput& in) {
  GDALDatasetUniquePtr ds =
      create(path, "GPX", in,
             {"GPX_USE_EXTENSIONS=YES", "GPX_EXTENSIONS_NS=dg", "GPX_EXTENSIONS_NS_URL=https://deepguide.dev/gpx/1"});
  const auto geo = gdal::wgs84();
  OGRLayer* layer = ds->CreateLayer("route_points", geo.get(), wkbPoint, nullptr);
  if (layer == nullptr) fail(in, "create the GPX route");
  for (const char* name : {"depth_m", "speed_mps", "hold_s", "radius_m"}) add_field(layer, name, OFTReal, in);
  for (const ExportWaypoint& w : in.route.waypoints) {
    OGRFeature f(layer->GetLayerDefn());
    f.SetField("route_fid", 0);
    f.SetField("route_name", in.route.name.c_str());
    f.SetField("name", w.name.c_str());
    f.SetField("desc", description(w).c_str());
    f.SetField("ele", altitude(w));
    f.SetField("depth_m", w.depth_m);
    f.SetField("speed_mps", w.speed_mps);
    f.SetField("hold_s", w.hold_s);
    f.SetField("radius_m", w.radius_m);
    OGRPoint p(w.lonlat.x(), w.lonlat.y());
    f.SetGeometry(&p);
    if (layer->CreateFeature(&f) != OGRERR_NONE) fail(in, "write a GPX route point");
  }
}

void write_kml(const std::string& path, const ExportInput& in) {
  GDALDatasetUniquePtr ds = create(path, "LIBKML", in);
  const auto geo = gdal::wgs84();
  OGRLayer* route = ds->CreateLayer("route", geo.get(), wkbLineString25D, nullptr);
  if (route == nullptr) fail(in, "create the KML route");
  add_field(route, "name", OFTString, in);
  add_field(route, "description", OFTString, in);
  add_field(route, "altitudeMode", OFTString, in);
  add_field(route, "length_m", OFTReal, in);
  {
    OGRFeature f(route->GetLayerDefn());
    f.SetField("name", in.route.name.c_str());
    f.SetField("description", ("deepguide route; altitude = -depth (m); planned in " + in.route.frame.id()).c_str());
    f.SetField("altitudeMode", "absolute");
    f.SetField("length_m", in.route.length_m);
    OGRLineString line;
    for (const ExportWaypoint& w : in.route.waypoints) line.addPoint(w.lonlat.x(), w.lonlat.y(), altitude(w));
    f.SetGeometry(&line);
    if (route->CreateFeature(&f) != OGRERR_NONE) fail(in, "write the KML route");
  }
  OGRLayer* points = ds->CreateLayer("waypoints", geo.get(), wkbPoint25D, nullptr);
  if (points == nullptr) fail(in, "create the KML waypoints");
  add_field(points, "name", OFTString, in);
  add_field(points, "description", OFTString, in);
  add_field(points, "altitudeMode", OFTString, in);
  for (const Field& field : kWaypointFields) add_field(points, field.name, field.type, in);
  for (const ExportWaypoint& w : in.route.waypoints) {
    OGRFeature f(points->GetLayerDefn());
    f.SetField("name", w.name.c_str());
    f.SetField("description", description(w).c_str());
    f.SetField("altitudeMode", "absolute");
    set_waypoint_fields(f, w);
    OGRPoint p(w.lonlat.x(), w.lonlat.y(), altitude(w));
    f.SetGeometry(&p);
    if (points->CreateFeature(&f) != OGRERR_NONE) fail(in, "write a KML waypoint");
  }
}

void write_csv(const std::string& path, const ExportInput& in) {
  // GDAL's CSV driver makes a folder of files for any other name.
  if (ascii_lower(std::filesystem::path(path).extension().string()) != ".csv") {
    throw InputError(in.destination + ": expected a .csv file name for the csv format");
  }
  // No SRS on the layer: GDAL would write a .prj beside the temporary file.
  // The WKT column is WGS 84 lon/lat by the header; the crs column names x_m, y_m's frame.
  GDALDatasetUniquePtr ds = create(path, "CSV", in);
  const char* layer_options[] = {"GEOMETRY=AS_WKT", nullptr};
  OGRLayer* layer = ds->CreateLayer("waypoints", nullptr, wkbPoint25D, const_cast<char**>(layer_options));
  if (layer == nullptr) fail(in, "create the CSV table");
  add_field(layer, "name", OFTString, in);
  for (const char* name : {"lon", "lat", "x_m", "y_m"}) add_field(layer, name, OFTReal, in);
  add_field(layer, "crs", OFTString, in);
  for (const Field& field : kWaypointFields) add_field(layer, field.name, field.type, in);
  const std::string crs = in.route.frame.id();
  for (const ExportWaypoint& w : in.route.waypoints) {
    OGRFeature f(layer->GetLayerDefn());
    f.SetField("name", w.name.c_str());
    f.SetField("lon", w.lonlat.x());
    f.SetField("lat", w.lonlat.y());
    f.SetField("x_m", w.xy.x());
    f.SetField("y_m", w.xy.y());
    f.SetField("crs", crs.c_str());
    set_waypoint_fields(f, w);
    OGRPoint p(w.lonlat.x(), w.lonlat.y(), altitude(w));
    f.SetGeometry(&p);
    if (layer->CreateFeature(&f) != OGRERR_NONE) fail(in, "write a CSV row");
  }
}

}  // namespace

void write_plan_ogr(const std::string& path, ExportFormat format, const ExportInput& in) {
  gdal::QuietErrors quiet;
  if (format == ExportFormat::geojson) return write_geojson(path, in);  // route_io writes through memory itself
  // GDAL writes in memory; every byte to disk is then checked (gdal_support.hpp).
  const gdal::MemoryOutput mem(path);
  switch (format) {
    case ExportFormat::gpx: write_gpx(mem.path(), in); break;
    case ExportFormat::kml: write_kml(mem.path(), in); break;
    case ExportFormat::csv: write_csv(mem.path(), in); break;
    default: throw InputError(in.destination + ": " + to_string(format) + " is not a GDAL format");
  }
  mem.save(path, in.destination);
}

}  // namespace deepguide::detail
