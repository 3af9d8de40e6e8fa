#include "deepguide/planning/route_io.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlerror.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/obstacle_files/csv_positions.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

namespace {

void set_json_field(OGRFeature& f, const std::string& key, const nlohmann::json& v) {
  const int i = f.GetFieldIndex(key.c_str());
  if (i < 0) return;
  if (v.is_number_integer())
    f.SetField(i, static_cast<GIntBig>(v.get<long long>()));
  else if (v.is_number())
    f.SetField(i, v.get<double>());
  else if (v.is_string())
    f.SetField(i, v.get<std::string>().c_str());
  else if (v.is_boolean())
    f.SetField(i, v.get<bool>() ? 1 : 0);
  else
    f.SetFieldNull(i);
}

OGRFieldType field_type(const nlohmann::json& v) {
  if (v.is_number_integer() || v.is_boolean()) return OFTInteger64;
  if (v.is_number()) return OFTReal;
  return OFTString;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(path + ": could not " + what + (why.empty() ? std::string() : ": " + why));
}

}  // namespace

void write_route_geojson(const std::string& path, const Route& route, const LocalFrame& frame,
                         const nlohmann::json& properties, const std::vector<nlohmann::json>& waypoint_properties) {
  gdal::ensure_registered();
  AtomicOutput out(path);
  gdal::QuietErrors quiet;
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GeoJSON");
  if (driver == nullptr) fail(path, "find GDAL's GeoJSON driver");
  const gdal::MemoryOutput mem(path);  // every byte to disk checked (gdal_support.hpp)
  {
    GDALDatasetUniquePtr ds(driver->Create(mem.path().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) fail(path, "create the file");
    const auto geo = gdal::wgs84();
    // 12 decimals (~0.1 um): routes touch the zones exactly, and a route read
    // back must still pass the checker's 1 um tolerance.
    const char* options[] = {"RFC7946=YES", "COORDINATE_PRECISION=12", nullptr};
    OGRLayer* layer = ds->CreateLayer("route", geo.get(), wkbUnknown, const_cast<char**>(options));
    if (layer == nullptr) fail(path, "create the route layer");
    // One schema for both feature kinds: `kind` tells the line from the waypoints.
    nlohmann::json fields = {{"kind", ""}, {"index", 0}, {"cum_length_m", 0.0}};
    for (const auto& [key, value] : properties.items()) fields[key] = value;
    for (const nlohmann::json& w : waypoint_properties) {
      for (const auto& [key, value] : w.items()) fields.emplace(key, value);
    }
    for (const auto& [key, value] : fields.items()) {
      OGRFieldDefn fd(key.c_str(), field_type(value));
      if (layer->CreateField(&fd) != OGRERR_NONE) fail(path, "create field " + key);
    }
    std::vector<Eigen::Vector2d> lonlat;
    for (const Vec2& p : route.points) {
      lonlat.push_back(frame.to_lonlat(p));
      if (!lonlat.back().allFinite()) fail(path, "transform a waypoint to lon/lat");
    }
    {
      OGRFeature f(layer->GetLayerDefn());
      f.SetField("kind", "route");
      for (const auto& [key, value] : properties.items()) set_json_field(f, key, value);
      f.SetFieldNull(f.GetFieldIndex("index"));
      f.SetFieldNull(f.GetFieldIndex("cum_length_m"));
      OGRLineString line;
      for (const auto& ll : lonlat) line.addPoint(ll.x(), ll.y());
      f.SetGeometry(&line);
      if (layer->CreateFeature(&f) != OGRERR_NONE) fail(path, "write the route line");
    }
    double cum = 0.0;
    for (std::size_t i = 0; i < route.points.size(); ++i) {
      if (i > 0) cum += (route.points[i] - route.points[i - 1]).norm();
      OGRFeature f(layer->GetLayerDefn());
      f.SetField("kind", "waypoint");
      f.SetField("index", static_cast<GIntBig>(i));
      f.SetField("cum_length_m", cum);
      if (i < waypoint_properties.size()) {
        for (const auto& [key, value] : waypoint_properties[i].items()) set_json_field(f, key, value);
      }
      OGRPoint pt(lonlat[i].x(), lonlat[i].y());
      f.SetGeometry(&pt);
      if (layer->CreateFeature(&f) != OGRERR_NONE) fail(path, "write waypoint " + std::to_string(i));
    }
  }
  mem.save(out.temp_path().string(), path);
  out.commit();
}

namespace {

const xmlChar* xml_text(const char* s) { return reinterpret_cast<const xmlChar*>(s); }

void xml_quiet(void*, const char*, ...) {}

bool named(xmlNodePtr n, const char* local_name) {
  return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, xml_text(local_name)) == 0;
}

// An RTZ attribute as a number in [lo, hi]; InputError naming the waypoint otherwise.
double rtz_number(xmlNodePtr n, const char* attribute, double lo, double hi, const std::string& where) {
  xmlChar* v = xmlGetProp(n, xml_text(attribute));
  const std::string text = v ? reinterpret_cast<const char*>(v) : "";
  xmlFree(v);
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || !(d >= lo && d <= hi)) {
    throw InputError(where + ": field '" + attribute + "': expected a number in [" + general(lo) + ", " + general(hi) +
                     "], got '" + printable(text) + "'");
  }
  return d;
}

// RTZ 1.0-1.2: <route><waypoints><waypoint id name><position lat lon/>. Real files use several
// namespaces (http://www.cirm.org/RTZ/1/0, https://cirm.org/rtz-xml-schemas): elements are matched
// by their local names.
std::vector<RouteFileWaypoint> read_rtz(const std::string& path) {
  xmlSetGenericErrorFunc(nullptr, xml_quiet);
  refuse_special_file(path);  // libxml2 would wait on a named pipe for ever
  std::unique_ptr<xmlDoc, decltype(&xmlFreeDoc)> doc(xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET), &xmlFreeDoc);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    throw InputError(path + (e ? ": line " + std::to_string(e->line) : std::string()) +
                     ": expected an RTZ route (XML), could not parse it");
  }
  xmlNodePtr root = xmlDocGetRootElement(doc.get());
  if (root == nullptr || !named(root, "route")) throw InputError(path + ": expected an RTZ <route> element at the top");
  std::vector<RouteFileWaypoint> out;
  for (xmlNodePtr list = root->children; list; list = list->next) {
    if (!named(list, "waypoints")) continue;
    for (xmlNodePtr w = list->children; w; w = w->next) {
      if (!named(w, "waypoint")) continue;
      xmlChar* id = xmlGetProp(w, xml_text("id"));
      xmlChar* name = xmlGetProp(w, xml_text("name"));
      const std::string where = path + ": line " + std::to_string(xmlGetLineNo(w)) + ": waypoint " +
                                (id ? printable(reinterpret_cast<const char*>(id)) : std::to_string(out.size() + 1));
      RouteFileWaypoint p;
      if (name) p.name = reinterpret_cast<const char*>(name);
      xmlFree(id);
      xmlFree(name);
      xmlNodePtr pos = w->children;
      while (pos && !named(pos, "position")) pos = pos->next;
      if (pos == nullptr) throw InputError(where + ": expected a <position lat lon>");
      p.lonlat = Vec2(rtz_number(pos, "lon", -180.0, 180.0, where), rtz_number(pos, "lat", -90.0, 90.0, where));
      out.push_back(std::move(p));
    }
  }
  if (out.size() < 2)
    throw InputError(path + ": expected an RTZ route with at least 2 waypoints, got " + std::to_string(out.size()));
  return out;
}

// Every line and point of an OGR source, in WGS 84, in the order of its layers and features.
std::vector<RouteFilePart> read_ogr_parts(const std::string& path) {
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  // A CSV's waypoints from its WKT column (lon and lat kept as fields, to
  // agree with it: `mission export` writes both), else from its lon and lat
  // columns. A route file carries no CRS: x/y columns would be read as degrees.
  const bool csv = ascii_lower(std::filesystem::path(path).extension().string()) == ".csv";
  gdal::CsvPositionColumns columns;
  std::vector<std::string> csv_options;
  if (csv) {
    columns = gdal::csv_position_columns(path);
    if (columns.geometry.empty() && (columns.x == "x" || columns.x == "easting")) {
      throw InputError(path + ": line 1: column '" + columns.x +
                       "': expected the waypoints in lon and lat columns (WGS 84 degrees) or a WKT column");
    }
    csv_options = gdal::csv_open_options(columns, true);
  }
  std::vector<const char*> open_options;
  for (const std::string& o : csv_options) open_options.push_back(o.c_str());
  open_options.push_back(nullptr);
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, open_options.data());
  if (!ds) fail(path, "open it as a vector file (GeoJSON, GPX, KML, RTZ, ...)");
  const auto geo = gdal::wgs84();
  std::vector<RouteFilePart> parts;
  for (OGRLayer* layer : ds->GetLayers()) {
    std::unique_ptr<OGRSpatialReference> srs;
    if (layer->GetSpatialRef() != nullptr) {
      srs.reset(layer->GetSpatialRef()->Clone());
      srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    } else {
      srs = gdal::wgs84();
    }
    auto ct = gdal::make_transform(*srs, *geo);
    if (!ct) fail(path, "transform its CRS to WGS 84");
    for (auto& feature : *layer) {
      const OGRGeometry* g = feature->GetGeometryRef();
      // A CSV row is a waypoint: one without a position is a hole in the route, not a row to skip.
      const bool unplaced = g == nullptr || g->IsEmpty() ||
                            (wkbFlatten(g->getGeometryType()) == wkbPoint &&
                             !(std::isfinite(g->toPoint()->getX()) && std::isfinite(g->toPoint()->getY())));
      if (csv && unplaced) {
        const std::string line = path + ": line " + std::to_string(feature->GetFID() + 1);
        if (!columns.geometry.empty())
          throw InputError(line + ": field '" + columns.geometry + "': expected a WKT POINT");
        if (!columns.has_xy()) {
          throw InputError(path + ": line 1: expected a WKT column, or lon and lat columns, holding the waypoints");
        }
        const auto text = [&](const std::string& name) {
          const int i = feature->GetFieldIndex(name.c_str());
          // GDAL leaves a blank, "nan" or "inf" unset in a coordinate column.
          return i >= 0 && feature->IsFieldSetAndNotNull(i) ? "'" + printable(feature->GetFieldAsString(i)) + "'"
                                                            : std::string("no finite number");
        };
        throw InputError(line + ": fields '" + columns.x + "', '" + columns.y +
                         "': expected two finite numbers (degrees), got " + text(columns.x) + " and " +
                         text(columns.y));
      }
      if (g == nullptr) continue;
      const std::string where = std::string(layer->GetName()) + " feature " + std::to_string(feature->GetFID());
      // A part from a line string or a point; `k` numbers the members of a multi-geometry.
      const auto add = [&](const OGRGeometry* member, const std::string& label) {
        RouteFilePart part{label, {}, wkbFlatten(member->getGeometryType()) == wkbPoint};
        const auto take = [&](double x, double y, int i) {
          if (!std::isfinite(x) || !std::isfinite(y) || !ct->Transform(1, &x, &y)) {
            throw InputError(path + ": " + label + ": vertex " + std::to_string(i) +
                             ": field 'geometry': expected finite coordinates");
          }
          part.points.push_back({Vec2(x, y), {}});
        };
        if (part.is_point) {
          const OGRPoint* pt = member->toPoint();
          if (pt->IsEmpty()) return;
          take(pt->getX(), pt->getY(), 0);
          // A CSV of waypoints with a WKT column and lon, lat columns (as
          // `mission export` writes): GDAL takes the WKT, so both must agree.
          const int lon = feature->GetFieldIndex("lon"), lat = feature->GetFieldIndex("lat");
          if (lon >= 0 && lat >= 0 && feature->IsFieldSetAndNotNull(lon) && feature->IsFieldSetAndNotNull(lat)) {
            const Vec2 fields(feature->GetFieldAsDouble(lon), feature->GetFieldAsDouble(lat));
            const Vec2& geometry = part.points.back().lonlat;
            if (!((fields - geometry).cwiseAbs().maxCoeff() <= 1e-7)) {
              throw InputError(path + ": " + label + ": fields 'lon', 'lat' (" + general(fields.x()) + ", " +
                               general(fields.y()) + ") disagree with its geometry (" + general(geometry.x()) + ", " +
                               general(geometry.y()) + "): expected one position");
            }
          }
        } else {
          const OGRLineString* line = member->toLineString();
          for (int i = 0; i < line->getNumPoints(); ++i) take(line->getX(i), line->getY(i), i);
          if (part.points.size() < 2) {
            throw InputError(path + ": " + label + ": expected a route line with at least 2 points");
          }
        }
        parts.push_back(std::move(part));
      };
      switch (wkbFlatten(g->getGeometryType())) {
        case wkbLineString:
        case wkbPoint: add(g, where); break;
        case wkbMultiLineString:
        case wkbMultiPoint: {
          const OGRGeometryCollection* c = g->toGeometryCollection();
          for (int k = 0; k < c->getNumGeometries(); ++k) {
            add(c->getGeometryRef(k), where + " part " + std::to_string(k + 1));
          }
          break;
        }
        default: break;  // areas are not routes
      }
    }
  }
  return parts;
}

}  // namespace

std::vector<RouteFilePart> read_route_parts(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": expected an existing route file, found none");
  if (ascii_lower(std::filesystem::path(path).extension().string()) == ".rtz")
    return {{"route", read_rtz(path), false}};
  std::vector<RouteFilePart> parts = read_ogr_parts(path);
  if (parts.empty()) throw InputError(path + ": expected a route line or points, found none");
  // Waypoints without a line (a CSV of waypoints, a GPX of marks) are a route
  // in file order: checking each point alone would call its legs safe unseen.
  const bool has_line = std::any_of(parts.begin(), parts.end(), [](const RouteFilePart& p) { return !p.is_point; });
  if (!has_line && parts.size() >= 2) {
    RouteFilePart line{"the " + std::to_string(parts.size()) + " points in file order", {}, false};
    for (RouteFilePart& p : parts) line.points.push_back(std::move(p.points.front()));
    return {std::move(line)};
  }
  return parts;
}

std::vector<RouteFileWaypoint> read_route_waypoints(const std::string& path) {
  for (RouteFilePart& part : read_route_parts(path)) {
    if (!part.is_point) return std::move(part.points);
  }
  throw InputError(path + ": expected a LineString feature (the route line), found none");
}

Route route_in_frame(const std::vector<RouteFileWaypoint>& waypoints, const LocalFrame& frame,
                     const std::string& where) {
  Route route;
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const Vec2 p = frame.from_lonlat(waypoints[i].lonlat);
    if (!p.allFinite()) {
      throw InputError(where + ": waypoint " + std::to_string(i + 1) + ": expected a position inside the local frame " +
                       frame.id());
    }
    route.points.push_back(p);
  }
  return route;
}

Route read_route(const std::string& path, const LocalFrame& frame) {
  return route_in_frame(read_route_waypoints(path), frame, path);
}

}  // namespace deepguide
