#pragma once
// The stored-obstacle database: one GeoPackage in which the detections from
// several missions merge. Layout and decisions are in docs/FORMATS.md,
// "Stored-obstacle database"; in short:
//
// - Layer `obstacles`: Points in EPSG:4326, an ordinary obstacle file for
//   load_obstacles (`id`, `semi_major_m`, `semi_minor_m`, `orientation_deg`,
//   `height_m`, `top_depth_m`) plus `first_seen`, `last_seen` (ISO 8601 UTC
//   text) and `sightings` (integer >= 1). Polygons a user adds are kept and
//   never merged.
// - Attribute table `detections`: one row per imported detection, with its
//   identity `key` (unique index), `mission`, `contact_id`, `time`,
//   `object_fid` (the obstacle it went into), `source`, `imported_at`.
// - Detections are read by load_obstacles (any OGR source, Points only) with
//   the optional fields `time` (ISO 8601 with Z or an offset, stored as UTC),
//   `mission` (default: the file's name) and `contact_id` (default: the
//   feature's id or name).
// - A detection without `time` counts as seen at the import time for
//   first/last seen, but its key carries no time, so a later re-import of the
//   same file is still a no-op.
// - Key: JSON array of mission, contact id, time, lon/lat as read rounded to
//   1e-8 deg (~1 mm), axes and vertical values rounded to 1 mm, orientation
//   (mod 180) to 0.001 deg. A key already in the store is skipped, so importing
//   the same detections twice changes nothing.
// - Match: a detection matches a stored obstacle when the centres lie within
//   merge_distance_m (default 10 m: an AUV's navigation drift between position
//   fixes plus the sonar's range error are several metres) in the local frame,
//   or when the footprints overlap (inscribed 256-gons, ~1e-4 of the axes
//   inside; Boost.Geometry). Several matches: the nearest centre wins (the
//   detection never joins two obstacles). Detections are taken in file order
//   against the store as it grows, so repeated contacts within one file merge.
// - Merge (running, sighting-weighted): centre and axes are the mean of the
//   stored estimate counted `sightings` times and the detection counted once;
//   the orientation likewise on the doubled angle (an axis is direction-less
//   mod 180 deg; an exact tie gives east-west). Vertically the conservative
//   value: the larger height_m, the smaller top_depth_m; mixed kinds, or either
//   filling the water column, give the whole water column.
// - One GeoPackage transaction per import; any error rolls back. Its pages
//   stay in memory until the commit (PRAGMA cache_spill = OFF), so a killed
//   import leaves the store file untouched and read-only readers unhindered.
//   A new store is created empty in a temporary file in the same folder and
//   hard-linked into place (never over an existing file), so a killed first
//   import leaves no store or an empty, valid one. An exclusive flock() on the
//   store serialises concurrent importers. A store file without any write
//   permission bit is refused as read-only, even for root.

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct ObstacleStoreOptions {
  /// Centres closer than this (m) are one object, whether or not the footprints overlap.
  double merge_distance_m = 10.0;
  /// Local frame for merging: empty = UTM zone of the centre of the store and the detections.
  std::string local_crs;
  /// CRS of detection files that carry none (CSV in UTM); empty = EPSG:4326.
  std::string source_crs;
  /// Sighting time for detections without `time`, ISO 8601; empty = now.
  std::string import_time;
  /// Called with the count of rows written so far inside the open
  /// transaction, after each (a test stops an import there to kill it).
  std::function<void(long rows)> on_row_written = nullptr;
};

struct StoredObstacle {
  std::int64_t fid = 0;
  EllipticCylinder obstacle;  ///< in ObstacleStore::frame
  std::string first_seen;     ///< ISO 8601 UTC
  std::string last_seen;
  std::int64_t sightings = 0;
};

struct StoredDetection {
  std::string key;
  std::string mission;
  std::string contact_id;
  std::string time;  ///< ISO 8601 UTC; empty when the detection had none
  std::int64_t object_fid = 0;
  std::string source;       ///< file name the detection came from
  std::string imported_at;  ///< ISO 8601 UTC
};

struct ObstacleStore {
  LocalFrame frame;
  std::vector<StoredObstacle> obstacles;    ///< ordered by fid
  std::vector<StoredDetection> detections;  ///< ordered by key
};

/// Reads and checks a store (layout above). Throws InputError naming the file,
/// layer, feature and field for anything else: not a GeoPackage, a missing
/// layer or field, a bad value.
ObstacleStore read_obstacle_store(const std::string& path, const std::string& local_crs = {});

struct ImportSummary {
  std::string store;                 ///< the store's path
  double merge_distance_m = 0.0;     ///< as imported
  bool created = false;              ///< the store did not exist before
  std::size_t detections = 0;        ///< Point detections read from the files
  std::size_t new_obstacles = 0;     ///< detections that started a new stored obstacle
  std::size_t merged = 0;            ///< detections merged into a stored obstacle
  std::size_t already_imported = 0;  ///< detections whose key the store already had (skipped)
  std::size_t obstacles_in_store = 0;
};

/// Adds the detections of `detection_paths` to the store at `store_path`
/// (created if missing) in one transaction. Throws InputError (one line) for
/// bad detections, a bad or read-only store, or bad options; the store is then
/// as it was before.
ImportSummary import_detections(const std::string& store_path, const std::vector<std::string>& detection_paths,
                                const ObstacleStoreOptions& options = {});

/// What `obstacles import` prints: the counts above, as JSON or as text.
nlohmann::json to_json(const ImportSummary& s);
std::string to_text(const ImportSummary& s);

/// An ISO 8601 date and time with a zone (Z or +-HH:MM) -> UTC text
/// "YYYY-MM-DDTHH:MM:SS[.mmm]Z". Throws InputError at `where` otherwise.
std::string normalize_utc_time(const std::string& text, const InputLocation& where);

}  // namespace deepguide
