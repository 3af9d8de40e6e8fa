// Importing detections into the obstacle store: each detection merged into
// the stored obstacle it matches (within the merge distance, or
// overlapping), or added as a new one, and the store written in one
// transaction.

#include "deepguide/obstacle_files/obstacle_store.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <boost/geometry/algorithms/intersects.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <unordered_set>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_store_file.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace fs = std::filesystem;
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using namespace store_detail;

namespace {

// ---------------------------------------------------------------- records

std::string rounded(double v, double step, int decimals) {
  double r = std::round(v / step) * step;
  if (r == 0.0) r = 0.0;  // no "-0.000"
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, r);
  return buf;
}

std::string optional_text(const std::optional<double>& v) { return v ? rounded(*v, 1e-3, 3) : std::string(); }

double axis_heading_deg(double heading_deg) {
  const double h = std::fmod(wrap_360(heading_deg), 180.0);
  return h >= 180.0 ? 0.0 : h;
}

struct Detection {
  InputLocation where;
  std::string source;
  std::string mission;
  std::string contact_id;
  std::string time;  // UTC text or empty
  Millis seen_ms = 0;
  std::string key;
  EllipticCylinder obstacle;
  Eigen::Vector2d lonlat{0.0, 0.0};
  double heading_deg = 0.0;
};

std::vector<Detection> parse_detections(const LoadedObstacles& l, std::size_t first_source, Millis import_ms) {
  for (const ObstacleOrigin& o : l.polygon_origins) {
    if (o.source < first_source) continue;
    InputLocation w = o.where;
    w.field = "geometry";
    throw input_error(w, "a Point detection (a sonar contact with semi_major_m)", "a polygon");
  }
  std::vector<Detection> out;
  for (std::size_t i = 0; i < l.obstacles.ellipses.size(); ++i) {
    const ObstacleOrigin& o = l.ellipse_origins[i];
    if (o.source < first_source) continue;
    Detection d;
    d.where = o.where;
    d.source = fs::path(l.sources[o.source].path).filename().string();
    d.mission = o.extra[kMission].value_or(d.source);
    d.contact_id = o.extra[kContactId].value_or(l.obstacles.ellipses[i].id);
    if (o.extra[kTime]) {
      InputLocation w = o.where;
      w.field = "time";
      d.time = normalize_utc_time(*o.extra[kTime], w);
      d.seen_ms = *parse_iso(d.time);
    } else {
      d.seen_ms = import_ms;
    }
    d.obstacle = l.obstacles.ellipses[i];
    d.lonlat = o.lonlat;
    d.heading_deg = o.heading_deg;
    const Ellipse& e = d.obstacle.footprint;
    std::string heading = rounded(axis_heading_deg(o.heading_deg), 1e-3, 3);
    if (heading == "180.000") heading = "0.000";  // 179.9996 rounds up to the same axis as 0
    d.key = nlohmann::json::array({d.mission, d.contact_id, d.time, rounded(o.lonlat.x(), 1e-8, 8),
                                   rounded(o.lonlat.y(), 1e-8, 8), rounded(e.a, 1e-3, 3), rounded(e.b, 1e-3, 3),
                                   heading, optional_text(d.obstacle.height_m), optional_text(d.obstacle.top_depth_m)})
                .dump();
    out.push_back(std::move(d));
  }
  return out;
}

// ---------------------------------------------------------------- matching and merging

BgBox footprint_box(const Ellipse& e, double grow) {
  const double c = std::cos(e.theta), s = std::sin(e.theta);
  const double hx = std::sqrt(e.a * e.a * c * c + e.b * e.b * s * s) + grow;
  const double hy = std::sqrt(e.a * e.a * s * s + e.b * e.b * c * c) + grow;
  return {BgPoint(e.centre.x() - hx, e.centre.y() - hy), BgPoint(e.centre.x() + hx, e.centre.y() + hy)};
}

BgPolygon footprint_polygon(const Ellipse& e) {
  constexpr int kSides = 256;
  BgPolygon p;
  for (int k = 0; k < kSides; ++k) p.outer().push_back(to_bg(e.point_at(-2.0 * kPi * k / kSides)));  // clockwise
  p.outer().push_back(p.outer().front());
  return p;
}

struct Working {
  StoredObstacle stored;
  Millis first_ms = 0;
  Millis last_ms = 0;
  bool is_new = false;
  bool dirty = false;
  // A new, unmerged obstacle is written with the detection's values as read,
  // so no frame round trip touches them.
  bool as_read = false;
  Eigen::Vector2d lonlat{0.0, 0.0};
  double heading_deg = 0.0;
};

void merge_into(Working& w, const Detection& d) {
  const double n = static_cast<double>(w.stored.sightings);
  Ellipse& e = w.stored.obstacle.footprint;
  const Ellipse& f = d.obstacle.footprint;
  e.centre = (n * e.centre + f.centre) / (n + 1.0);
  e.a = (n * e.a + f.a) / (n + 1.0);
  e.b = (n * e.b + f.b) / (n + 1.0);
  const Vec2 doubled = n * Vec2(std::cos(2.0 * e.theta), std::sin(2.0 * e.theta)) +
                       Vec2(std::cos(2.0 * f.theta), std::sin(2.0 * f.theta));
  e.theta = 0.5 * std::atan2(doubled.y(), doubled.x());
  EllipticCylinder& o = w.stored.obstacle;
  if (o.height_m && d.obstacle.height_m) {
    o.height_m = std::max(*o.height_m, *d.obstacle.height_m);
  } else if (o.top_depth_m && d.obstacle.top_depth_m) {
    o.top_depth_m = std::min(*o.top_depth_m, *d.obstacle.top_depth_m);
  } else {
    o.height_m.reset();
    o.top_depth_m.reset();
  }
  w.first_ms = std::min(w.first_ms, d.seen_ms);
  w.last_ms = std::max(w.last_ms, d.seen_ms);
  w.stored.first_seen = format_utc(w.first_ms);
  w.stored.last_seen = format_utc(w.last_ms);
  ++w.stored.sightings;
  w.dirty = true;
  w.as_read = false;
}

void fill_feature(OGRFeature& f, const Working& w, const LocalFrame& frame) {
  const EllipticCylinder& o = w.stored.obstacle;
  const Ellipse& e = o.footprint;
  const Eigen::Vector2d ll = w.as_read ? w.lonlat : frame.to_lonlat(e.centre);
  OGRPoint point(ll.x(), ll.y());
  f.SetGeometry(&point);
  f.SetField("id", o.id.c_str());
  f.SetField("semi_major_m", e.a);
  f.SetField("semi_minor_m", e.b);
  f.SetField("orientation_deg",
             axis_heading_deg(w.as_read ? w.heading_deg : frame.local_to_heading(e.theta, e.centre)));
  for (const auto& [name, v] : {std::pair{"height_m", o.height_m}, std::pair{"top_depth_m", o.top_depth_m}}) {
    if (v) {
      f.SetField(name, *v);
    } else {
      f.SetFieldNull(f.GetFieldIndex(name));
    }
  }
  f.SetField("first_seen", w.stored.first_seen.c_str());
  f.SetField("last_seen", w.stored.last_seen.c_str());
  f.SetField("sightings", static_cast<GIntBig>(w.stored.sightings));
}

// A detection to record, and the index of the object it went into.
using Row = std::pair<const Detection*, std::size_t>;

// Each detection not imported before merged into the nearest object it
// matches (centres within d_max, or footprints that overlap), or added to
// `objects` as a new one; counted in `summary`.
std::vector<Row> match_detections(const std::vector<Detection>& detections, std::vector<Working>& objects,
                                  std::unordered_set<std::string>& keys, double d_max, ImportSummary& summary) {
  using Entry = std::pair<BgBox, std::size_t>;
  bgi::rtree<Entry, bgi::quadratic<16>> index;
  std::vector<BgBox> boxes;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    boxes.push_back(footprint_box(objects[i].stored.obstacle.footprint, 0.0));
    index.insert({boxes[i], i});
  }
  std::vector<Row> rows;
  for (const Detection& d : detections) {
    ++summary.detections;
    if (!keys.insert(d.key).second) {
      ++summary.already_imported;
      continue;
    }
    const Ellipse& f = d.obstacle.footprint;
    std::vector<Entry> candidates;
    index.query(bgi::intersects(footprint_box(f, d_max)), std::back_inserter(candidates));
    std::optional<std::size_t> best;
    double best_dist = std::numeric_limits<double>::infinity();
    std::optional<BgPolygon> mine;
    for (const Entry& c : candidates) {
      const Ellipse& e = objects[c.second].stored.obstacle.footprint;
      const double dist = (e.centre - f.centre).norm();
      if (dist > best_dist || (best && dist == best_dist && c.second > *best)) continue;
      bool match = dist <= d_max;
      if (!match) {
        if (!mine) mine = footprint_polygon(f);
        match = bg::intersects(*mine, footprint_polygon(e));
      }
      if (match) best = c.second, best_dist = dist;
    }
    if (best) {
      index.remove(Entry{boxes[*best], *best});
      merge_into(objects[*best], d);
      boxes[*best] = footprint_box(objects[*best].stored.obstacle.footprint, 0.0);
      index.insert({boxes[*best], *best});
      ++summary.merged;
      rows.emplace_back(&d, *best);
    } else {
      Working w;
      w.stored.obstacle = d.obstacle;
      w.stored.obstacle.id = d.mission + "/" + (d.contact_id.empty() ? d.where.feature : d.contact_id);
      w.stored.first_seen = w.stored.last_seen = format_utc(d.seen_ms);
      w.stored.sightings = 1;
      w.first_ms = w.last_ms = d.seen_ms;
      w.is_new = w.dirty = w.as_read = true;
      w.lonlat = d.lonlat;
      w.heading_deg = d.heading_deg;
      objects.push_back(std::move(w));
      boxes.push_back(footprint_box(d.obstacle.footprint, 0.0));
      index.insert({boxes.back(), objects.size() - 1});
      ++summary.new_obstacles;
      rows.emplace_back(&d, objects.size() - 1);
    }
  }

  return rows;
}

// The changed obstacles and the detections' rows, in one transaction: all
// or nothing.
void write_import(GDALDataset& ds, std::vector<Working>& objects, const std::vector<Row>& rows, const LocalFrame& frame,
                  const std::string& imported_at, const std::string& store_path, const ObstacleStoreOptions& options) {
  OGRLayer* obstacle_layer = ds.GetLayerByName(kObstacleLayer);
  OGRLayer* detection_layer = ds.GetLayerByName(kDetectionLayer);
  long rows_written = 0;
  auto row_written = [&] {
    ++rows_written;
    if (options.on_row_written) options.on_row_written(rows_written);
  };
  gdal::QuietErrors quiet;
  auto fail = [&](const std::string& what) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(store_path + ": could not " + what + " (nothing was imported)" +
                     (why.empty() ? "" : ": " + printable(why, 160)));
  };
  // Keep the open transaction's pages in memory: the store file then changes
  // only at commit, and a process killed before leaves a journal SQLite has
  // not yet marked valid, which read-only readers may ignore. With spills a
  // "hot" journal would lock them out until a writer rolled it back.
  if (OGRLayer* r = ds.ExecuteSQL("PRAGMA cache_spill = OFF", nullptr, nullptr)) ds.ReleaseResultSet(r);
  if (ds.StartTransaction() != OGRERR_NONE) fail("start a transaction");
  try {
    for (Working& w : objects) {
      if (!w.dirty) continue;
      OGRFeatureUniquePtr f(w.is_new ? OGRFeature::CreateFeature(obstacle_layer->GetLayerDefn())
                                     : obstacle_layer->GetFeature(w.stored.fid));
      if (!f) fail("read stored obstacle " + std::to_string(w.stored.fid));
      fill_feature(*f, w, frame);
      if (w.is_new) {
        if (obstacle_layer->CreateFeature(f.get()) != OGRERR_NONE) fail("add an obstacle");
        w.stored.fid = f->GetFID();
      } else if (obstacle_layer->SetFeature(f.get()) != OGRERR_NONE) {
        fail("update obstacle " + std::to_string(w.stored.fid));
      }
      row_written();
    }
    for (const auto& [d, object] : rows) {
      OGRFeature f(detection_layer->GetLayerDefn());
      f.SetField("key", d->key.c_str());
      f.SetField("mission", d->mission.c_str());
      f.SetField("contact_id", d->contact_id.c_str());
      if (d->time.empty()) {
        f.SetFieldNull(f.GetFieldIndex("time"));
      } else {
        f.SetField("time", d->time.c_str());
      }
      f.SetField("object_fid", static_cast<GIntBig>(objects[object].stored.fid));
      f.SetField("source", d->source.c_str());
      f.SetField("imported_at", imported_at.c_str());
      if (detection_layer->CreateFeature(&f) != OGRERR_NONE) fail("record detection '" + printable(d->key) + "'");
      row_written();
    }
    if (ds.CommitTransaction() != OGRERR_NONE) fail("commit the import");
  } catch (...) {
    ds.RollbackTransaction();
    throw;
  }
}

}  // namespace

ImportSummary import_detections(const std::string& store_path, const std::vector<std::string>& detection_paths,
                                const ObstacleStoreOptions& options) {
  gdal::ensure_registered();
  if (!std::isfinite(options.merge_distance_m) || options.merge_distance_m < 0.0) {
    throw InputError("`merge_distance_m`: expected a distance >= 0 m, got " + std::to_string(options.merge_distance_m));
  }
  if (detection_paths.empty()) throw InputError(store_path + ": expected at least one detection file to import");
  Millis import_ms = 0;
  if (options.import_time.empty()) {
    using namespace std::chrono;
    import_ms = duration_cast<seconds>(system_clock::now().time_since_epoch()).count() * 1000;
  } else {
    import_ms = checked_time(options.import_time, {"`import_time`", "", ""});
  }
  std::error_code ec;
  for (const std::string& p : detection_paths) {
    if (fs::exists(p, ec) && fs::exists(store_path, ec) && fs::equivalent(p, store_path, ec)) {
      throw InputError(p + ": expected a detection file, got the store itself");
    }
  }
  ObstacleReadOptions read;
  read.local_crs = options.local_crs;
  read.source_crs = options.source_crs;
  read.extra_fields = kExtraFields;

  ImportSummary summary;
  summary.store = store_path;
  summary.merge_distance_m = options.merge_distance_m;
  if (!fs::exists(store_path, ec)) {
    // The store is a GeoPackage: a new one named .geojson (or anything but
    // .gpkg) would be a GeoPackage that every other tool misreads.
    if (ascii_lower(fs::path(store_path).extension().string()) != ".gpkg") {
      throw InputError(store_path +
                       ": expected a new obstacle store's name to end in .gpkg (it is a GeoPackage), got '" +
                       printable(fs::path(store_path).extension().string()) + "'");
    }
    // Check every detection before a new store appears on disk.
    parse_detections(load_obstacles(detection_paths, read), 0, import_ms);
    summary.created = create_store(store_path);
  }
  if (fs::is_directory(store_path, ec))
    throw InputError(store_path + ": expected an obstacle store file, got a folder");
  check_writable(store_path);
  const StoreLock lock(store_path);
  GDALDatasetUniquePtr ds = open_store(store_path, true);  // also rolls back what a killed import left

  std::vector<std::string> paths{store_path};
  paths.insert(paths.end(), detection_paths.begin(), detection_paths.end());
  const LoadedObstacles loaded = load_obstacles(paths, read);
  const LocalFrame& frame = loaded.frame;
  const std::vector<Detection> detections = parse_detections(loaded, 1, import_ms);

  std::vector<Working> objects;
  for (StoredObstacle& s : parse_stored(loaded)) {
    Working w;
    w.first_ms = *parse_iso(s.first_seen);
    w.last_ms = *parse_iso(s.last_seen);
    w.stored = std::move(s);
    objects.push_back(std::move(w));
  }
  std::unordered_set<std::string> keys;
  for (StoredDetection& d : read_detection_rows(*ds)) keys.insert(std::move(d.key));

  const std::vector<Row> rows = match_detections(detections, objects, keys, options.merge_distance_m, summary);
  if (!rows.empty()) write_import(*ds, objects, rows, frame, format_utc(import_ms), store_path, options);
  summary.obstacles_in_store = static_cast<std::size_t>(ds->GetLayerByName(kObstacleLayer)->GetFeatureCount());
  return summary;
}

nlohmann::json to_json(const ImportSummary& s) {
  return {{"store", s.store},
          {"created", s.created},
          {"detections", s.detections},
          {"new_obstacles", s.new_obstacles},
          {"merged", s.merged},
          {"already_imported", s.already_imported},
          {"obstacles_in_store", s.obstacles_in_store},
          {"merge_distance_m", s.merge_distance_m}};
}

std::string to_text(const ImportSummary& s) {
  std::string t = printf_text("store              %s%s\n", s.store.c_str(), s.created ? " (created)" : "");
  t += printf_text("detections read    %zu\n", s.detections);
  t += printf_text("new obstacles      %zu\n", s.new_obstacles);
  t += printf_text("merged             %zu (merge distance %g m, or overlapping footprints)\n", s.merged,
                   s.merge_distance_m);
  t += printf_text("already imported   %zu (skipped)\n", s.already_imported);
  t += printf_text("obstacles in store %zu\n", s.obstacles_in_store);
  return t;
}

}  // namespace deepguide
