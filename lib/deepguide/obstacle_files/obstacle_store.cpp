#include "deepguide/obstacle_files/obstacle_store.hpp"

#include <ogrsf_frmts.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_store_file.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace store_detail {
// ---------------------------------------------------------------- times

// A stored time: an ISO 8601 time with a zone (core/utc_time.hpp), in milliseconds.
std::optional<Millis> parse_iso(const std::string& s) {
  const std::optional<double> t = parse_iso8601(s, true);
  if (!t) return std::nullopt;
  return static_cast<Millis>(std::llround(*t * 1000.0));
}

std::string format_utc(Millis ms) { return deepguide::format_utc(static_cast<double>(ms) / 1000.0, true); }

Millis checked_time(const std::string& text, const InputLocation& where) {
  return *parse_iso(normalize_utc_time(text, where));
}

// ---------------------------------------------------------------- store layout

struct FieldSpec {
  const char* name;
  OGRFieldType type;
  OGRFieldType alt;
  const char* type_name;
};

const FieldSpec kObstacleFields[] = {
    {"id", OFTString, OFTString, "text"},
    {"semi_major_m", OFTReal, OFTReal, "real"},
    {"semi_minor_m", OFTReal, OFTReal, "real"},
    {"orientation_deg", OFTReal, OFTReal, "real"},
    {"height_m", OFTReal, OFTReal, "real"},
    {"top_depth_m", OFTReal, OFTReal, "real"},
    {"first_seen", OFTString, OFTString, "text"},
    {"last_seen", OFTString, OFTString, "text"},
    {"sightings", OFTInteger64, OFTInteger, "integer"},
};
const FieldSpec kDetectionFields[] = {
    {"key", OFTString, OFTString, "text"},
    {"mission", OFTString, OFTString, "text"},
    {"contact_id", OFTString, OFTString, "text"},
    {"time", OFTString, OFTString, "text"},
    {"object_fid", OFTInteger64, OFTInteger, "integer"},
    {"source", OFTString, OFTString, "text"},
    {"imported_at", OFTString, OFTString, "text"},
};

void check_layer(GDALDataset& ds, const std::string& path, const char* name, bool spatial, const FieldSpec* fields,
                 std::size_t n_fields) {
  OGRLayer* layer = ds.GetLayerByName(name);
  const InputLocation where{path, std::string("layer '") + name + "'", ""};
  if (layer == nullptr) {
    throw input_error(where,
                      std::string("the obstacle store's ") + (spatial ? "Point layer" : "attribute table") +
                          " (a GeoPackage written by 'deepguide obstacles import')",
                      "none");
  }
  if (spatial) {
    if (wkbFlatten(layer->GetGeomType()) != wkbPoint) {
      throw input_error(where, "a Point layer", OGRGeometryTypeToName(layer->GetGeomType()));
    }
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    const std::string id = srs != nullptr ? gdal::srs_id(*srs) : "none";
    if (id != "EPSG:4326") throw input_error(where, "CRS EPSG:4326", id);
  }
  OGRFeatureDefn* defn = layer->GetLayerDefn();
  for (std::size_t k = 0; k < n_fields; ++k) {
    const FieldSpec& f = fields[k];
    InputLocation w = where;
    w.field = f.name;
    const int i = defn->GetFieldIndex(f.name);
    if (i < 0) throw input_error(w, std::string("a ") + f.type_name + " field of the obstacle store", "none");
    const OGRFieldType t = defn->GetFieldDefn(i)->GetType();
    if (t != f.type && t != f.alt) {
      throw input_error(w, std::string("a ") + f.type_name + " field", OGRFieldDefn::GetFieldTypeName(t));
    }
  }
}

GDALDatasetUniquePtr open_store(const std::string& path, bool update) {
  gdal::QuietErrors quiet;
  const char* const drivers[] = {"GPKG", nullptr};
  GDALDatasetUniquePtr ds =
      gdal::open_dataset(path, GDAL_OF_VECTOR | (update ? GDAL_OF_UPDATE : GDAL_OF_READONLY), drivers);
  if (!ds) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(path + ": expected a GeoPackage obstacle store, got " +
                     (why.empty() ? std::string("a file that is not a GeoPackage") : "'" + printable(why, 160) + "'"));
  }
  check_layer(*ds, path, kObstacleLayer, true, kObstacleFields, std::size(kObstacleFields));
  check_layer(*ds, path, kDetectionLayer, false, kDetectionFields, std::size(kDetectionFields));
  return ds;
}

void check_writable(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw InputError(path + ": expected a readable obstacle store, got: " + std::strerror(errno));
  }
  // Root may write anywhere; a store without any write bit was still meant to stay as it is.
  if ((st.st_mode & 0222) == 0 || ::access(path.c_str(), W_OK) != 0) {
    throw InputError(path + ": expected a writable obstacle store, got a read-only file");
  }
}

// Creates an empty store unless one exists. The hard link never replaces a
// store another importer created meanwhile.
bool create_store(const std::string& path) {
  AtomicOutput out(path);
  gdal::QuietErrors quiet;
  auto fail = [&](const std::string& what) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(path + ": could not create the obstacle store: " + what + (why.empty() ? "" : ": " + why));
  };
  {
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
    if (driver == nullptr) fail("GDAL has no GPKG driver");
    GDALDatasetUniquePtr ds(driver->Create(out.temp_path().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!ds) fail("create the file");
    const auto geo = gdal::wgs84();
    const char* options[] = {"FID=fid", nullptr};
    OGRLayer* obstacles = ds->CreateLayer(kObstacleLayer, geo.get(), wkbPoint, const_cast<char**>(options));
    OGRLayer* detections = ds->CreateLayer(kDetectionLayer, nullptr, wkbNone, const_cast<char**>(options));
    if (obstacles == nullptr || detections == nullptr) fail("create the layers");
    for (const auto& [layer, fields, n] : {std::tuple{obstacles, kObstacleFields, std::size(kObstacleFields)},
                                           std::tuple{detections, kDetectionFields, std::size(kDetectionFields)}}) {
      for (std::size_t k = 0; k < n; ++k) {
        OGRFieldDefn fd(fields[k].name, fields[k].type);
        if (layer->CreateField(&fd) != OGRERR_NONE) fail(std::string("create field ") + fields[k].name);
      }
    }
    ds->ExecuteSQL("CREATE UNIQUE INDEX detections_key ON detections(key)", nullptr, nullptr);
    if (!gdal::QuietErrors::last_message().empty()) fail("index the detection keys");
  }
  if (::link(out.temp_path().c_str(), path.c_str()) != 0) {
    if (errno == EEXIST) return false;
    throw InputError(path + ": could not create the obstacle store: " + std::strerror(errno));
  }
  return true;  // the temporary name goes with `out`; the store keeps the inode
}

std::vector<StoredObstacle> parse_stored(const LoadedObstacles& l) {
  std::vector<StoredObstacle> out;
  for (std::size_t i = 0; i < l.obstacles.ellipses.size(); ++i) {
    const ObstacleOrigin& o = l.ellipse_origins[i];
    if (o.source != 0) continue;
    StoredObstacle s;
    s.fid = o.fid;
    s.obstacle = l.obstacles.ellipses[i];
    for (const auto& [index, name, target] :
         {std::tuple{kFirstSeen, "first_seen", &s.first_seen}, std::tuple{kLastSeen, "last_seen", &s.last_seen}}) {
      InputLocation w = o.where;
      w.field = name;
      if (!o.extra[index]) throw input_error(w, "an ISO 8601 UTC time", "no value");
      *target = normalize_utc_time(*o.extra[index], w);
    }
    InputLocation w = o.where;
    w.field = "sightings";
    const std::string text = o.extra[kSightings].value_or("");
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), s.sightings);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || s.sightings < 1) {
      throw input_error(w, "a whole number of sightings >= 1", text.empty() ? "no value" : "'" + printable(text) + "'");
    }
    if (*parse_iso(s.first_seen) > *parse_iso(s.last_seen)) {
      w.field = "last_seen";
      throw input_error(w, "a time not before first_seen (" + s.first_seen + ")", s.last_seen);
    }
    out.push_back(std::move(s));
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.fid < y.fid; });
  return out;
}

std::vector<StoredDetection> read_detection_rows(GDALDataset& ds) {
  OGRLayer* layer = ds.GetLayerByName(kDetectionLayer);
  std::vector<StoredDetection> out;
  layer->ResetReading();
  for (auto& f : *layer) {
    StoredDetection d;
    auto text = [&](const char* name) {
      const int i = f->GetFieldIndex(name);
      return f->IsFieldSetAndNotNull(i) ? std::string(f->GetFieldAsString(i)) : std::string();
    };
    d.key = text("key");
    d.mission = text("mission");
    d.contact_id = text("contact_id");
    d.time = text("time");
    d.object_fid = f->GetFieldAsInteger64("object_fid");
    d.source = text("source");
    d.imported_at = text("imported_at");
    out.push_back(std::move(d));
  }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
  return out;
}

}  // namespace store_detail

using namespace store_detail;

std::string normalize_utc_time(const std::string& text, const InputLocation& where) {
  const auto ms = parse_iso(text);
  if (!ms) {
    throw input_error(where, "an ISO 8601 time with a zone, e.g. 2024-05-01T12:30:00Z", "'" + printable(text) + "'");
  }
  return format_utc(*ms);
}

ObstacleStore read_obstacle_store(const std::string& path, const std::string& local_crs) {
  gdal::ensure_registered();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": expected an existing obstacle store, found none");
  GDALDatasetUniquePtr ds = open_store(path, false);
  ObstacleReadOptions options;
  options.local_crs = local_crs;
  options.extra_fields = kExtraFields;
  const LoadedObstacles loaded = load_obstacles({path}, options);
  ObstacleStore store{loaded.frame, parse_stored(loaded), read_detection_rows(*ds)};
  return store;
}

}  // namespace deepguide
