#include "deepguide/obstacle_files/obstacle_io.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/algorithms/is_valid.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/csv_positions.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/no_go_union.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

// One feature as read, in lon/lat (degrees) before the local frame is known.
struct GeoRecord {
  InputLocation where;
  std::int64_t fid = 0;
  std::vector<std::optional<std::string>> extra;
  std::string id;
  bool is_ellipse = false;
  Eigen::Vector2d centre;  // lon, lat
  double a = 0.0;
  double b = 0.0;
  double heading_deg = 0.0;
  std::vector<std::vector<Eigen::Vector2d>> rings;  // lon, lat; first = outer
  std::optional<double> height_m;
  std::optional<double> top_depth_m;
};

std::string describe_feature(const OGRFeature& f, const std::string& driver, const std::string& layer,
                             bool several_layers) {
  std::string s;
  if (several_layers) s = "layer '" + layer + "', ";
  // The CSV driver numbers data rows from 1; the header is line 1.
  if (driver == "CSV") {
    s += "line " + std::to_string(f.GetFID() + 1);
  } else {
    s += "feature " + std::to_string(f.GetFID());
  }
  for (const char* key : {"id", "name"}) {
    const int i = f.GetFieldIndex(key);
    if (i >= 0 && f.IsFieldSetAndNotNull(i)) {
      s += std::string(" (") + key + " '" + printable(f.GetFieldAsString(i)) + "')";
      break;
    }
  }
  return s;
}

// A numeric field: absent (no column, null or empty) -> nullopt; otherwise a
// finite number or an InputError naming the field.
// Field index by name; Shapefiles cut names to 10 characters (semi_major_m ->
// semi_major), so the cut name is accepted too.
int field_index(const OGRFeature& f, const std::string& name) {
  const int i = f.GetFieldIndex(name.c_str());
  return i >= 0 || name.size() <= 10 ? i : f.GetFieldIndex(name.substr(0, 10).c_str());
}

std::optional<double> numeric_field(const OGRFeature& f, const char* name, InputLocation where) {
  where.field = name;
  const int i = field_index(f, name);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return std::nullopt;
  const OGRFieldType type = f.GetFieldDefnRef(i)->GetType();
  double v = 0.0;
  if (type == OFTReal || type == OFTInteger || type == OFTInteger64) {
    v = f.GetFieldAsDouble(i);
  } else {
    std::string text = f.GetFieldAsString(i);
    text.erase(0, text.find_first_not_of(" \t"));
    text.erase(text.find_last_not_of(" \t") + 1);
    if (text.empty()) return std::nullopt;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (*first == '+') ++first;
    auto [ptr, ec] = std::from_chars(first, last, v);
    if (ec != std::errc() || ptr != last) throw input_error(where, "a number", "'" + text + "'");
  }
  if (!std::isfinite(v)) throw input_error(where, "a finite number", std::to_string(v));
  return v;
}

void read_vertical(const OGRFeature& f, const InputLocation& where, GeoRecord& rec) {
  rec.height_m = numeric_field(f, "height_m", where);
  rec.top_depth_m = numeric_field(f, "top_depth_m", where);
  if (rec.height_m && rec.top_depth_m) {
    InputLocation w = where;
    w.field = "height_m";
    throw input_error(w, "either height_m or top_depth_m, not both");
  }
  if (rec.height_m && *rec.height_m <= 0.0) {
    InputLocation w = where;
    w.field = "height_m";
    throw input_error(w, "a height above the sea floor > 0 m", general(*rec.height_m));
  }
  if (rec.top_depth_m && *rec.top_depth_m < 0.0) {
    InputLocation w = where;
    w.field = "top_depth_m";
    throw input_error(w, "a depth >= 0 m (positive down)", general(*rec.top_depth_m));
  }
}

// Transforms a point of the layer's CRS to lon/lat and checks it.
Eigen::Vector2d to_geo(OGRCoordinateTransformation& ct, double x, double y, const InputLocation& where) {
  InputLocation w = where;
  w.field = "geometry";
  if (!std::isfinite(x) || !std::isfinite(y)) {
    throw input_error(w, "finite coordinates", "(" + general(x) + ", " + general(y) + ")");
  }
  const double x0 = x;
  const double y0 = y;
  if (!ct.Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) {
    throw input_error(w, "coordinates valid in the file's CRS", "(" + general(x0) + ", " + general(y0) + ")");
  }
  if (std::abs(y) > 90.0 || std::abs(x) > 540.0) {
    throw input_error(w, "a position on the Earth (lon/lat within +-180/+-90 after transformation)",
                      "(" + general(x) + ", " + general(y) +
                          "); a file without a CRS is read as lon/lat: "
                          "give its CRS with `src_crs`");
  }
  return {x, y};
}

void read_ellipse_fields(const OGRFeature& f, const InputLocation& where, GeoRecord& rec) {
  InputLocation w = where;
  const auto a = numeric_field(f, "semi_major_m", where);
  w.field = "semi_major_m";
  if (!a) throw input_error(w, "a semi-major axis in metres for a Point obstacle", "no value");
  // An obstacle's axes are metres to kilometres; 100 km is far beyond any
  // (and beyond what a UTM frame holds to the metre). Below a millimetre no
  // chart or sonar places anything, and the graphs square the axes: 1e-300
  // underflowed to 0 in the tangent graph (issue 39).
  constexpr double kMinAxis_m = 1e-3, kMaxAxis_m = 1e5;
  if (!(*a >= kMinAxis_m && *a <= kMaxAxis_m)) {
    throw input_error(w, "a semi-major axis of at least 1 mm and at most 100 km", general(*a));
  }
  const auto b = numeric_field(f, "semi_minor_m", where);
  w.field = "semi_minor_m";
  if (b && !(*b >= kMinAxis_m)) throw input_error(w, "a semi-minor axis of at least 1 mm", general(*b));
  if (b && *b > *a) {
    throw input_error(w, "semi_minor_m <= semi_major_m (" + general(*a) + " m)", general(*b));
  }
  const auto heading = numeric_field(f, "orientation_deg", where);
  w.field = "orientation_deg";
  if (heading && !(std::abs(*heading) <= 360.0)) {
    throw input_error(w, "a heading in degrees within +-360", general(*heading));
  }
  rec.is_ellipse = true;
  rec.a = *a;
  rec.b = b.value_or(*a);
  rec.heading_deg = heading.value_or(0.0);
}

std::vector<Eigen::Vector2d> read_ring(const OGRLinearRing& ring, OGRCoordinateTransformation& ct,
                                       const InputLocation& where) {
  std::vector<Eigen::Vector2d> out;
  out.reserve(ring.getNumPoints());
  for (int i = 0; i < ring.getNumPoints(); ++i) out.push_back(to_geo(ct, ring.getX(i), ring.getY(i), where));
  return out;
}

// A footprint every planner and checker can take: rings that neither cross
// themselves nor each other, with an area. A bow-tie has none of its own
// (Boost.Geometry measures it as two lobes of opposite sign, area ~0) and the
// planners would route through it; repairing it silently would choose the
// obstacle's shape for the operator, so it is refused with what to do.
void require_simple(const BgPolygon& footprint, const InputLocation& where) {
  namespace bg = boost::geometry;
  bg::validity_failure_type failure = bg::no_failure;
  if (bg::is_valid(footprint, failure)) return;
  const char* got = nullptr;
  switch (failure) {
    case bg::failure_self_intersections: got = "rings that cross themselves or each other (a bow-tie?)"; break;
    case bg::failure_wrong_topological_dimension:
    case bg::failure_few_points: got = "a ring without area"; break;
    case bg::failure_spikes: got = "a ring with a spike (it runs out and back along itself)"; break;
    case bg::failure_interior_rings_outside: got = "a hole outside the outer ring"; break;
    case bg::failure_nested_interior_rings: got = "a hole inside another hole"; break;
    case bg::failure_disconnected_interior: got = "holes that cut the polygon in two"; break;
    case bg::failure_intersecting_interiors: got = "holes that overlap"; break;
    case bg::failure_wrong_orientation:
      // correct() has oriented every ring with an area; one it could not is a
      // bow-tie whose lobes cancel exactly (area 0: Boost then reports the
      // orientation before the crossing) or a ring without area.
      got =
          bg::intersects(footprint) ? "rings that cross themselves or each other (a bow-tie?)" : "a ring without area";
      break;
    default: return;  // closure and duplicate points are corrected or harmless
  }
  InputLocation w = where;
  w.field = "geometry";
  throw input_error(w, "a simple polygon (repair it first, e.g. ogr2ogr -makevalid)", got);
}

void read_polygon(const OGRPolygon& poly, OGRCoordinateTransformation& ct, const InputLocation& where, GeoRecord rec,
                  std::vector<GeoRecord>& out) {
  if (poly.IsEmpty() || poly.getExteriorRing() == nullptr || poly.getExteriorRing()->getNumPoints() < 4) {
    InputLocation w = where;
    w.field = "geometry";
    throw input_error(w, "a polygon with at least 3 distinct vertices", "an empty or degenerate ring");
  }
  rec.rings.push_back(read_ring(*poly.getExteriorRing(), ct, where));
  for (int i = 0; i < poly.getNumInteriorRings(); ++i) {
    rec.rings.push_back(read_ring(*poly.getInteriorRing(i), ct, where));
  }
  out.push_back(std::move(rec));
}

// A field as text for ObstacleOrigin::extra; dates and times as ISO 8601
// (GDAL's own text form is "YYYY/MM/DD HH:MM:SS+TZ").
std::optional<std::string> text_field(const OGRFeature& f, const std::string& name) {
  const int i = field_index(f, name);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return std::nullopt;
  const OGRFieldType type = f.GetFieldDefnRef(i)->GetType();
  std::string text;
  if (type == OFTDateTime || type == OFTDate) {
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, tz = 0;
    float sec = 0.0F;
    f.GetFieldAsDateTime(i, &y, &mo, &d, &h, &mi, &sec, &tz);
    char buf[64];
    if (type == OFTDate) {
      std::snprintf(buf, sizeof buf, "%04d-%02d-%02d", y, mo, d);
    } else {
      const int ms = static_cast<int>(std::lround(sec * 1000.0F));
      if (ms % 1000 == 0) {
        std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", y, mo, d, h, mi, ms / 1000);
      } else {
        std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03d", y, mo, d, h, mi, ms / 1000, ms % 1000);
      }
    }
    text = buf;
    // GDAL's TZFlag: 0 unknown, 1 local time, 100 UTC, 100 +- 4n = offset of n quarter hours.
    if (type == OFTDateTime && tz == 100) {
      text += "Z";
    } else if (type == OFTDateTime && tz > 1) {
      const int quarters = std::abs(tz - 100);
      std::snprintf(buf, sizeof buf, "%c%02d:%02d", tz > 100 ? '+' : '-', quarters / 4, quarters % 4 * 15);
      text += buf;
    }
  } else {
    text = f.GetFieldAsString(i);
    text.erase(0, text.find_first_not_of(" \t"));
    text.erase(text.find_last_not_of(" \t") + 1);
  }
  if (text.empty()) return std::nullopt;
  return text;
}

struct SourceRead {
  ObstacleSourceInfo info;
  std::vector<GeoRecord> records;
};

// A geometry column and coordinate columns: GDAL takes the geometry and drops
// the others without a word, though they may disagree.
void refuse_two_places_for_positions(const std::string& path, const gdal::CsvPositionColumns& columns) {
  if (columns.geometry.empty() || (columns.x.empty() && columns.y.empty())) return;
  throw InputError(path + ": line 1: expected the positions in one place, a " +
                   gdal::joined_names(gdal::csv_geometry_names(), "/") + " column or x/y columns, got both '" +
                   columns.geometry + "' and '" + (!columns.x.empty() ? columns.x : columns.y) +
                   "': which one holds the position is not known");
}

SourceRead read_source(const std::string& path, const ObstacleReadOptions& options) {
  SourceRead result;
  result.info.path = path;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing file, found none");

  gdal::QuietErrors quiet;
  std::vector<std::string> csv_options;
  gdal::CsvPositionColumns columns;  // a CSV's
  std::vector<const char*> open_options;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".csv") {
    columns = gdal::csv_position_columns(path);
    refuse_two_places_for_positions(path, columns);
    csv_options = gdal::csv_open_options(columns, false);
    for (const std::string& o : csv_options) open_options.push_back(o.c_str());
  }
  open_options.push_back(nullptr);
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, open_options.data());
  if (!ds) {
    std::string why = gdal::QuietErrors::last_message();
    throw InputError(path +
                     ": expected a vector file GDAL can read (GeoJSON, GeoPackage, Shapefile, "
                     "CSV, ...)" +
                     (why.empty() ? std::string() : ", got: " + why));
  }
  result.info.driver = ds->GetDriver() != nullptr ? ds->GetDriver()->GetDescription() : "";
  // GDAL opens a file whose CRS it cannot resolve and silently falls back to
  // WGS 84 (GeoJSON) or none; that would misplace every obstacle, so refuse.
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty()) {
    const bool crs = why.find("crs") != std::string::npos || why.find("PROJ") != std::string::npos ||
                     why.find("CRS") != std::string::npos || why.find("SRS") != std::string::npos;
    throw InputError(path +
                     (crs ? ": field 'crs': expected a coordinate reference system GDAL knows, got: "
                          : ": expected a readable vector file, got: ") +
                     why);
  }

  const auto geo = gdal::wgs84();
  std::unique_ptr<OGRSpatialReference> assumed;
  if (!options.source_crs.empty()) {
    assumed = gdal::srs_from_user_input(options.source_crs);
    if (!assumed) {
      throw InputError("`src_crs`: expected a known coordinate reference system such as EPSG:4326, got '" +
                       options.source_crs + "'");
    }
  }
  const bool several_layers = ds->GetLayerCount() > 1;
  bool any_spatial = false;
  for (OGRLayer* layer : ds->GetLayers()) any_spatial = any_spatial || layer->GetGeomType() != wkbNone;
  std::vector<std::string> crs_names;
  for (OGRLayer* layer : ds->GetLayers()) {
    if (any_spatial && layer->GetGeomType() == wkbNone) continue;
    if (!options.layers.empty() &&
        std::find(options.layers.begin(), options.layers.end(), layer->GetName()) == options.layers.end()) {
      continue;
    }
    const OGRSpatialReference* layer_srs = layer->GetSpatialRef();
    std::unique_ptr<OGRSpatialReference> srs;
    std::string crs_name;
    if (layer_srs != nullptr) {
      srs.reset(layer_srs->Clone());
      srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
      crs_name = gdal::srs_id(*srs);
    } else if (assumed) {
      srs.reset(assumed->Clone());
      crs_name = gdal::srs_id(*srs) + " (from `src_crs`)";
    } else {
      srs = gdal::wgs84();
      crs_name = "none in file, read as EPSG:4326";
    }
    if (std::find(crs_names.begin(), crs_names.end(), crs_name) == crs_names.end()) {
      crs_names.push_back(crs_name);
    }
    auto ct = gdal::make_transform(*srs, *geo);
    if (!ct) {
      throw InputError(path + ": layer '" + layer->GetName() + "': field 'crs': expected a CRS that can be " +
                       "transformed to WGS 84, got '" + crs_name + "'");
    }
    for (auto& feature : *layer) {
      InputLocation where{path, describe_feature(*feature, result.info.driver, layer->GetName(), several_layers), ""};
      GeoRecord rec;
      rec.where = where;
      rec.fid = feature->GetFID();
      for (const std::string& name : options.extra_fields) rec.extra.push_back(text_field(*feature, name));
      for (const char* key : {"id", "name"}) {
        const int i = feature->GetFieldIndex(key);
        if (i >= 0 && feature->IsFieldSetAndNotNull(i)) {
          rec.id = feature->GetFieldAsString(i);
          break;
        }
      }
      const OGRGeometry* g = feature->GetGeometryRef();
      InputLocation gw = where;
      gw.field = "geometry";
      if ((g == nullptr || g->IsEmpty()) && columns.geometry.empty() && columns.has_xy()) {
        // GDAL leaves a CSV row's point unset for a blank, "nan" or "inf" coordinate.
        throw input_error(where, "fields '" + columns.x + "', '" + columns.y + "' holding two finite numbers",
                          "a blank or a coordinate that is not finite");
      }
      if (g == nullptr || g->IsEmpty()) {
        throw input_error(gw, "a Point or Polygon geometry with finite coordinates", "an empty or missing geometry");
      }
      read_vertical(*feature, where, rec);
      switch (wkbFlatten(g->getGeometryType())) {
        case wkbPoint: {
          read_ellipse_fields(*feature, where, rec);
          const auto* p = g->toPoint();
          rec.centre = to_geo(*ct, p->getX(), p->getY(), where);
          result.records.push_back(std::move(rec));
          ++result.info.ellipses;
          break;
        }
        case wkbPolygon:
          read_polygon(*g->toPolygon(), *ct, where, std::move(rec), result.records);
          ++result.info.polygons;
          break;
        case wkbMultiPolygon:
          for (const OGRPolygon* part : *g->toMultiPolygon()) {
            read_polygon(*part, *ct, where, rec, result.records);
            ++result.info.polygons;
          }
          break;
        default: throw input_error(gw, "a Point or Polygon geometry", OGRGeometryTypeToName(g->getGeometryType()));
      }
    }
  }
  for (std::size_t i = 0; i < crs_names.size(); ++i) result.info.crs += (i ? ", " : "") + crs_names[i];
  return result;
}

Eigen::Vector2d to_local_checked(const LocalFrame& frame, const Eigen::Vector2d& lonlat, const InputLocation& where) {
  const Eigen::Vector2d xy = frame.from_lonlat(lonlat);
  if (!xy.allFinite()) {
    InputLocation w = where;
    w.field = "geometry";
    throw input_error(w, "a position inside the area of the local frame " + frame.id(),
                      "lon " + general(lonlat.x()) + ", lat " + general(lonlat.y()));
  }
  return xy;
}

}  // namespace

Ellipse ellipse_from_fields(const LocalFrame& frame, const Eigen::Vector2d& centre, const Eigen::Vector2d& lonlat,
                            double semi_major_m, double semi_minor_m, double orientation_deg) {
  // Where the frame stretches the axes they are made frame metres; where it
  // shrinks them (at most 0.05 %) they stay as given, as every other size
  // from a chart does.
  const double scale = std::max(1.0, frame.scale_at(lonlat).greatest);
  const double k = std::isfinite(scale) ? scale : 1.0;
  return Ellipse{centre, semi_major_m * k, semi_minor_m * k, frame.heading_to_local(orientation_deg, centre)};
}

void add_polygon_obstacle(PolygonObstacle p, bool repair, const InputLocation& where, ObstacleSet& into) {
  boost::geometry::correct(p.footprint);
  if (repair && !boost::geometry::is_valid(p.footprint)) {
    // A repair that leaves no area is refused as before: never an obstacle dropped in silence.
    // The parts are GEOS's valid polygons; two holes touching at a vertex may stay that Boost
    // reads as crossing (Kachemak at 7 m, enc/25), which the planners take as they are.
    const std::vector<BgPolygon> parts = union_no_go({}, {&p.footprint});
    if (parts.empty()) require_simple(p.footprint, where);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      PolygonObstacle part = p;
      part.footprint = parts[k];
      if (k > 0) part.id += "#" + std::to_string(k + 1);
      into.polygons.push_back(std::move(part));
    }
    return;
  }
  require_simple(p.footprint, where);
  into.polygons.push_back(std::move(p));
}

EllipseFields ellipse_fields(const LocalFrame& frame, const Ellipse& footprint) {
  const Eigen::Vector2d lonlat = frame.to_lonlat(footprint.centre);
  const double scale = std::max(1.0, frame.scale_at(lonlat).greatest);
  const double k = std::isfinite(scale) ? scale : 1.0;
  const double heading = std::fmod(frame.local_to_heading(footprint.theta, footprint.centre), 180.0);
  return {lonlat, footprint.a / k, footprint.b / k, heading < 0.0 ? heading + 180.0 : heading};
}

LoadedObstacles load_obstacles(const std::vector<std::string>& paths, const ObstacleReadOptions& options) {
  gdal::ensure_registered();
  // Fail on a bad --crs before reading anything.
  std::optional<LocalFrame> frame;
  if (!options.local_crs.empty()) frame = LocalFrame::from_user_crs(options.local_crs, "`local_crs`");

  std::vector<SourceRead> sources;
  std::vector<Eigen::Vector2d> positions;
  for (const std::string& path : paths) {
    sources.push_back(read_source(path, options));
    for (const GeoRecord& r : sources.back().records) {
      if (r.is_ellipse) positions.push_back(r.centre);
      for (const auto& ring : r.rings) positions.insert(positions.end(), ring.begin(), ring.end());
    }
  }
  positions.insert(positions.end(), options.work_area_lonlat.begin(), options.work_area_lonlat.end());
  const LonLatExtent extent = extent_of(positions);
  if (!frame) {
    const Eigen::Vector2d at = options.fallback_lonlat.value_or(Eigen::Vector2d(0.0, 0.0));
    frame = default_frame_for(!extent.empty() ? extent : LonLatExtent{at.x(), at.x(), at.y(), at.y()});
  } else if (!extent.empty()) {
    require_true_scale(*frame, extent,
                       paths.size() == 1 ? printable(paths.front(), 240) : std::string("the obstacles"));
  }

  LoadedObstacles out{{}, *frame, {}};
  for (SourceRead& src : sources) {
    for (const GeoRecord& r : src.records) {
      ObstacleOrigin origin{out.sources.size(), r.fid, r.where, r.centre, r.heading_deg, r.extra};
      (r.is_ellipse ? out.ellipse_origins : out.polygon_origins).push_back(std::move(origin));
      if (r.is_ellipse) {
        EllipticCylinder c;
        c.id = r.id;
        c.footprint =
            ellipse_from_fields(*frame, to_local_checked(*frame, r.centre, r.where), r.centre, r.a, r.b, r.heading_deg);
        c.height_m = r.height_m;
        c.top_depth_m = r.top_depth_m;
        out.obstacles.ellipses.push_back(std::move(c));
      } else {
        PolygonObstacle p;
        p.id = r.id;
        p.height_m = r.height_m;
        p.top_depth_m = r.top_depth_m;
        for (std::size_t k = 0; k < r.rings.size(); ++k) {
          auto& ring = k == 0 ? p.footprint.outer() : p.footprint.inners().emplace_back();
          for (const auto& ll : r.rings[k]) ring.push_back(to_bg(to_local_checked(*frame, ll, r.where)));
        }
        add_polygon_obstacle(std::move(p), options.repair_polygons, r.where, out.obstacles);
      }
    }
    out.sources.push_back(std::move(src.info));
  }
  return out;
}

}  // namespace deepguide
