// Writing obstacles: GeoJSON, GeoPackage or CSV through OGR, written
// whole or not at all (core/atomic_file.hpp).

#include "deepguide/obstacle_files/obstacle_io.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace fs = std::filesystem;

ObstacleFormat obstacle_format_for(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".geojson" || ext == ".json") return ObstacleFormat::geojson;
  if (ext == ".gpkg") return ObstacleFormat::geopackage;
  if (ext == ".csv") return ObstacleFormat::csv;
  throw InputError(path + ": expected an output extension .geojson, .json, .gpkg or .csv, got '" + ext + "'");
}

namespace {

void set_optional(OGRFeature& f, const char* name, const std::optional<double>& v) {
  if (v) {
    f.SetField(name, *v);
  } else {
    f.SetFieldNull(f.GetFieldIndex(name));
  }
}

void fail_write(const std::string& path, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(path + ": could not " + what + (why.empty() ? std::string() : ": " + why));
}

}  // namespace

void write_obstacles(const std::string& path, const ObstacleSet& obstacles, const LocalFrame& frame) {
  gdal::ensure_registered();
  const ObstacleFormat format = obstacle_format_for(path);
  AtomicOutput out(path);
  gdal::QuietErrors quiet;
  const char* driver_name = format == ObstacleFormat::geojson      ? "GeoJSON"
                            : format == ObstacleFormat::geopackage ? "GPKG"
                                                                   : "CSV";
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
  if (driver == nullptr) fail_write(path, std::string("find GDAL's ") + driver_name + " driver");
  const gdal::MemoryOutput mem(path);  // every byte to disk checked (gdal_support.hpp)
  {
    GDALDatasetUniquePtr ds(driver->Create(mem.path().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) fail_write(path, "create the file");
    const auto geo = gdal::wgs84();
    std::vector<const char*> layer_options;
    if (format == ObstacleFormat::geojson) {
      // RFC 7946 defaults to 7 decimals (~1 cm); 12 keep round trips below a micrometre.
      layer_options = {"RFC7946=YES", "COORDINATE_PRECISION=12"};
    } else if (format == ObstacleFormat::csv) {
      layer_options = {"GEOMETRY=AS_WKT", "CREATE_CSVT=NO"};
    }
    layer_options.push_back(nullptr);
    OGRLayer* layer = ds->CreateLayer("obstacles", geo.get(), wkbUnknown, const_cast<char**>(layer_options.data()));
    if (layer == nullptr) fail_write(path, "create the obstacles layer");
    OGRFieldDefn id_field("id", OFTString);
    layer->CreateField(&id_field);
    for (const char* name : {"semi_major_m", "semi_minor_m", "orientation_deg", "height_m", "top_depth_m"}) {
      OGRFieldDefn fd(name, OFTReal);
      if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
    }
    const auto to_ll = [&](const Vec2& xy) {
      const Eigen::Vector2d ll = frame.to_lonlat(xy);
      if (!ll.allFinite()) fail_write(path, "transform a position to lon/lat");
      return ll;
    };
    for (const EllipticCylinder& c : obstacles.ellipses) {
      OGRFeature f(layer->GetLayerDefn());
      f.SetField("id", c.id.c_str());
      const Eigen::Vector2d ll = to_ll(c.footprint.centre);
      f.SetGeometry(std::make_unique<OGRPoint>(ll.x(), ll.y()).get());
      // The reader's fields back (ellipse_fields): true metres, the axis in [0, 180).
      const EllipseFields fields = ellipse_fields(frame, c.footprint);
      f.SetField("semi_major_m", fields.semi_major_m);
      f.SetField("semi_minor_m", fields.semi_minor_m);
      f.SetField("orientation_deg", fields.orientation_deg);
      set_optional(f, "height_m", c.height_m);
      set_optional(f, "top_depth_m", c.top_depth_m);
      if (layer->CreateFeature(&f) != OGRERR_NONE) fail_write(path, "write obstacle '" + c.id + "'");
    }
    for (const PolygonObstacle& p : obstacles.polygons) {
      OGRFeature f(layer->GetLayerDefn());
      f.SetField("id", p.id.c_str());
      OGRPolygon poly;
      auto add_ring = [&](const auto& ring) {
        OGRLinearRing r;
        // Boost rings are clockwise; write counter-clockwise outer rings as RFC 7946 asks.
        for (auto it = ring.rbegin(); it != ring.rend(); ++it) {
          const Eigen::Vector2d ll = to_ll(to_eigen(*it));
          r.addPoint(ll.x(), ll.y());
        }
        poly.addRing(&r);
      };
      add_ring(p.footprint.outer());
      for (const auto& inner : p.footprint.inners()) add_ring(inner);
      f.SetGeometry(&poly);
      for (const char* name : {"semi_major_m", "semi_minor_m", "orientation_deg"})
        f.SetFieldNull(f.GetFieldIndex(name));
      set_optional(f, "height_m", p.height_m);
      set_optional(f, "top_depth_m", p.top_depth_m);
      if (layer->CreateFeature(&f) != OGRERR_NONE) fail_write(path, "write obstacle '" + p.id + "'");
    }
  }  // closes (flushes) the dataset before the rename
  if (CPLGetLastErrorType() >= CE_Failure && !gdal::QuietErrors::last_message().empty()) {
    fail_write(path, "finish the file");
  }
  mem.save(out.temp_path().string(), path);
  out.commit();
}

}  // namespace deepguide
