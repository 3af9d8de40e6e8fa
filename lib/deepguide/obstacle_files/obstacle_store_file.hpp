#pragma once
// Library-internal: the obstacle store's file (a GeoPackage of two layers)
// as its reader (obstacle_store.cpp) and its importer (obstacle_import.cpp)
// share it: layer names, times, opening and creating the file, and the
// lock that serialises importers. Not installed: it names GDAL's types.

#include <fcntl.h>
#include <gdal_priv.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_store.hpp"

namespace deepguide::store_detail {

inline constexpr const char* kObstacleLayer = "obstacles";
inline constexpr const char* kDetectionLayer = "detections";

// Extra fields asked of load_obstacles: the store's first three, the detections' last three.
inline const std::vector<std::string> kExtraFields = {"first_seen", "last_seen", "sightings",
                                                      "time",       "mission",   "contact_id"};
enum ExtraIndex { kFirstSeen, kLastSeen, kSightings, kTime, kMission, kContactId };

using Millis = std::int64_t;  // milliseconds since 1970-01-01T00:00:00Z

/// A stored time: an ISO 8601 time with a zone (core/utc_time.hpp), in milliseconds.
std::optional<Millis> parse_iso(const std::string& s);
std::string format_utc(Millis ms);
/// `text` as a time, or an InputError naming `where`.
Millis checked_time(const std::string& text, const InputLocation& where);

/// The store at `path`, its layers checked (and, for update, what a killed
/// import left rolled back); InputError naming the file otherwise.
GDALDatasetUniquePtr open_store(const std::string& path, bool update);
/// InputError unless the store (or the folder for a new one) can be written.
void check_writable(const std::string& path);
/// Creates an empty store at `path`; true when it did.
bool create_store(const std::string& path);

/// The stored obstacles of `l` (the store read as an obstacle file), by fid.
std::vector<StoredObstacle> parse_stored(const LoadedObstacles& l);
/// The detections recorded in the store, by key.
std::vector<StoredDetection> read_detection_rows(GDALDataset& ds);

// Serialises importers: SQLite's own locks would let two of them read the
// same state and then both write.
class StoreLock {
 public:
  explicit StoreLock(const std::string& path) : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {
    if (fd_ < 0) throw InputError(path + ": expected a readable obstacle store, got: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX) != 0) {
      const int e = errno;
      ::close(fd_);
      throw InputError(path + ": could not lock the obstacle store: " + std::strerror(e));
    }
  }
  ~StoreLock() { ::close(fd_); }
  StoreLock(const StoreLock&) = delete;
  StoreLock& operator=(const StoreLock&) = delete;

 private:
  int fd_;
};

}  // namespace deepguide::store_detail
