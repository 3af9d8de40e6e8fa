// The stored-obstacle database: imports, merges by hand-derived numbers,
// idempotent re-imports, a process killed mid-transaction, and bad stores.
#include <fcntl.h>
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <ogrsf_frmts.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_store.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::run_cli;
using deepguide::test::ScratchDir;

namespace {

// Detections in UTM 32N on its central meridian (9 deg E), where grid north is
// true north, so headings and offsets in metres can be derived by hand.
const std::string kHeader = "x,y,semi_major_m,semi_minor_m,orientation_deg,height_m,top_depth_m,time,contact_id\n";
constexpr double kX0 = 500000.0;
constexpr double kY0 = 6030000.0;

std::string row(double dx, double dy, double a, double b, double heading, const std::string& height,
                const std::string& top, const std::string& time, const std::string& contact) {
  std::ostringstream s;
  s.precision(12);
  s << kX0 + dx << "," << kY0 + dy << "," << a << "," << b << "," << heading << "," << height << "," << top << ","
    << time << "," << contact << "\n";
  return s.str();
}

// Mission A: four objects, none within 10 m of another, none overlapping.
std::string mission_a() {
  return kHeader + row(0, 0, 10, 4, 30, "5", "", "2024-05-01T10:00:00Z", "c1") +
         row(500, 0, 20, 20, 0, "", "30", "2024-05-01T10:05:00Z", "c2") +
         row(1000, 0, 6, 2, 135, "", "", "2024-05-01T10:10:00Z", "c3") +
         row(1016, 0, 3, 3, 0, "", "", "2024-05-01T10:11:00Z", "c4");
}

// Mission B re-sees A's objects: B1 and B4 within 10 m of c1 (one file, one
// object twice), B2 overlapping c2 with centres 30 m apart, B3 far from all,
// B5 within 10 m of both c3 (9 m) and c4 (7 m).
std::string mission_b() {
  return kHeader + row(6, 0, 14, 6, 50, "7", "", "2024-06-01T08:00:00Z", "b1") +
         row(530, 0, 15, 5, 60, "", "25", "", "b2") + row(2000, 0, 5, 5, 0, "", "", "2024-06-01T08:20:00Z", "b3") +
         row(0, 3, 12, 5, 40, "3", "", "2024-06-01T09:00:00Z", "b4") +
         row(1009, 0, 2, 2, 0, "", "", "2024-06-01T09:30:00Z", "b5");
}

ObstacleStoreOptions utm_options() {
  ObstacleStoreOptions o;
  o.local_crs = "EPSG:32632";
  o.source_crs = "EPSG:32632";
  o.import_time = "2024-07-01T00:00:00Z";
  return o;
}

// Every field and geometry of every feature of every layer, as text: equal
// snapshots mean equal stores, whatever SQLite does to the file's bytes.
std::vector<std::string> snapshot(const std::string& path) {
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << path;
  std::vector<std::string> out;
  if (!ds) return out;
  for (OGRLayer* layer : ds->GetLayers()) {
    for (auto& f : *layer) {
      std::string s = std::string(layer->GetName()) + " fid " + std::to_string(f->GetFID());
      for (int i = 0; i < f->GetFieldCount(); ++i) {
        s += std::string(" ") + f->GetFieldDefnRef(i)->GetNameRef() + "=";
        s += f->IsFieldSetAndNotNull(i) ? f->GetFieldAsString(i) : "NULL";
      }
      if (const OGRGeometry* g = f->GetGeometryRef()) {
        const OGRPoint* p = g->toPoint();
        char buf[96];
        std::snprintf(buf, sizeof buf, " POINT(%.17g %.17g)", p->getX(), p->getY());
        s += buf;
      }
      out.push_back(s);
    }
  }
  return out;
}

const StoredObstacle& by_id(const ObstacleStore& s, const std::string& id) {
  for (const auto& o : s.obstacles) {
    if (o.obstacle.id == id) return o;
  }
  throw std::runtime_error("no stored obstacle " + id);
}

double heading_of(const ObstacleStore& s, const StoredObstacle& o) {
  return std::fmod(s.frame.local_to_heading(o.obstacle.footprint.theta, o.obstacle.footprint.centre), 180.0);
}

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(ObstacleStore, NewStoreFromOneMission) {
  ScratchDir dir;
  const std::string a = dir.write("a.csv", mission_a());
  const std::string store = dir.file("store.gpkg");
  const ImportSummary s = import_detections(store, {a}, utm_options());
  EXPECT_TRUE(s.created);
  EXPECT_EQ(s.detections, 4u);
  EXPECT_EQ(s.new_obstacles, 4u);
  EXPECT_EQ(s.merged, 0u);
  EXPECT_EQ(s.already_imported, 0u);
  EXPECT_EQ(s.obstacles_in_store, 4u);
  // What `obstacles import` prints, as JSON and as text.
  const nlohmann::json j = to_json(s);
  EXPECT_EQ(j["store"], store);
  EXPECT_EQ(j["created"], true);
  EXPECT_EQ(j["new_obstacles"], 4);
  EXPECT_EQ(j["merge_distance_m"], utm_options().merge_distance_m);
  const std::string text = to_text(s);
  EXPECT_EQ(text.rfind("store              " + store + " (created)\n", 0), 0u) << text;
  EXPECT_NE(text.find("new obstacles      4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("obstacles in store 4\n"), std::string::npos) << text;

  const ObstacleStore st = read_obstacle_store(store, "EPSG:32632");
  ASSERT_EQ(st.obstacles.size(), 4u);
  ASSERT_EQ(st.detections.size(), 4u);
  const StoredObstacle& c1 = by_id(st, "a.csv/c1");
  EXPECT_NEAR(c1.obstacle.footprint.centre.x(), kX0, 1e-6);
  EXPECT_NEAR(c1.obstacle.footprint.centre.y(), kY0, 1e-6);
  EXPECT_DOUBLE_EQ(c1.obstacle.footprint.a, 10.0);
  EXPECT_DOUBLE_EQ(c1.obstacle.footprint.b, 4.0);
  EXPECT_NEAR(heading_of(st, c1), 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(c1.obstacle.height_m.value_or(-1), 5.0);
  EXPECT_FALSE(c1.obstacle.top_depth_m);
  EXPECT_EQ(c1.first_seen, "2024-05-01T10:00:00Z");
  EXPECT_EQ(c1.last_seen, "2024-05-01T10:00:00Z");
  EXPECT_EQ(c1.sightings, 1);
  EXPECT_NEAR(heading_of(st, by_id(st, "a.csv/c3")), 135.0, 1e-9);
  EXPECT_DOUBLE_EQ(by_id(st, "a.csv/c2").obstacle.top_depth_m.value_or(-1), 30.0);
  for (const StoredDetection& d : st.detections) {
    EXPECT_EQ(d.mission, "a.csv");
    EXPECT_EQ(d.source, "a.csv");
    EXPECT_EQ(d.imported_at, "2024-07-01T00:00:00Z");
    EXPECT_FALSE(d.time.empty());
  }
  // No temporary files remain next to the store.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 2u);
}

TEST(ObstacleStore, ANewStoreMustBeNamedGpkg) {
  // A GeoPackage named .geojson would mislead every other reader; nothing is created.
  ScratchDir dir;
  const std::string a = dir.write("a.csv", mission_a());
  for (const char* name : {"store.geojson", "store", "store.gpkg.tmp"}) {
    const std::string store = dir.file(name);
    deepguide::test::expect_one_line_error([&] { (void)import_detections(store, {a}, utm_options()); }, ".gpkg");
    EXPECT_FALSE(std::filesystem::exists(store)) << name;
  }
  EXPECT_TRUE(import_detections(dir.file("STORE.GPKG"), {a}, utm_options()).created);
}

TEST(ObstacleStore, SecondMissionMergesByHandDerivedValues) {
  ScratchDir dir;
  const std::string store = dir.file("store.gpkg");
  import_detections(store, {dir.write("a.csv", mission_a())}, utm_options());
  const ImportSummary s = import_detections(store, {dir.write("b.csv", mission_b())}, utm_options());
  EXPECT_FALSE(s.created);
  EXPECT_EQ(s.detections, 5u);
  EXPECT_EQ(s.new_obstacles, 1u);  // b3
  EXPECT_EQ(s.merged, 4u);         // b1, b4 -> c1; b2 -> c2; b5 -> c4
  EXPECT_EQ(s.already_imported, 0u);
  EXPECT_EQ(s.obstacles_in_store, 5u);

  const ObstacleStore st = read_obstacle_store(store, "EPSG:32632");
  ASSERT_EQ(st.obstacles.size(), 5u);
  ASSERT_EQ(st.detections.size(), 9u);

  // c1 (0,0) 10x4 @30 h5, then b1 (6,0) 14x6 @50 h7: centre (3,0), 12x5,
  // doubled-angle mean of 30 and 50 = 40, height max 7. Then b4 (0,3) 12x5 @40
  // h3 counted once against 2: centre ((2*3+0)/3, (0+3)/3) = (2,1), 12x5, 40, h7.
  const StoredObstacle& c1 = by_id(st, "a.csv/c1");
  EXPECT_NEAR(c1.obstacle.footprint.centre.x(), kX0 + 2.0, 1e-6);
  EXPECT_NEAR(c1.obstacle.footprint.centre.y(), kY0 + 1.0, 1e-6);
  EXPECT_NEAR(c1.obstacle.footprint.a, 12.0, 1e-12);
  EXPECT_NEAR(c1.obstacle.footprint.b, 5.0, 1e-12);
  EXPECT_NEAR(heading_of(st, c1), 40.0, 1e-6);
  EXPECT_DOUBLE_EQ(c1.obstacle.height_m.value_or(-1), 7.0);
  EXPECT_EQ(c1.first_seen, "2024-05-01T10:00:00Z");
  EXPECT_EQ(c1.last_seen, "2024-06-01T09:00:00Z");
  EXPECT_EQ(c1.sightings, 3);

  // c2: circle r 20 at (500,0); b2 at (530,0), 15x5 @60, 30 m away but its
  // western tip (530 - 15 sin 60, -15 cos 60) = (517.0, -7.5) lies 18.6 m from
  // c2's centre, inside it. Merge: centre (515,0), 17.5x12.5, headings 0 and 60
  // -> 30, top depth min(30, 25) = 25; b2 has no time: the import time.
  const StoredObstacle& c2 = by_id(st, "a.csv/c2");
  EXPECT_NEAR(c2.obstacle.footprint.centre.x(), kX0 + 515.0, 1e-6);
  EXPECT_NEAR(c2.obstacle.footprint.centre.y(), kY0, 1e-6);
  EXPECT_NEAR(c2.obstacle.footprint.a, 17.5, 1e-12);
  EXPECT_NEAR(c2.obstacle.footprint.b, 12.5, 1e-12);
  EXPECT_NEAR(heading_of(st, c2), 30.0, 1e-6);
  EXPECT_DOUBLE_EQ(c2.obstacle.top_depth_m.value_or(-1), 25.0);
  EXPECT_FALSE(c2.obstacle.height_m);
  EXPECT_EQ(c2.first_seen, "2024-05-01T10:05:00Z");
  EXPECT_EQ(c2.last_seen, "2024-07-01T00:00:00Z");
  EXPECT_EQ(c2.sightings, 2);

  // b5 at (1009,0) is 9 m from c3 and 7 m from c4: the nearest, c4, takes it.
  const StoredObstacle& c3 = by_id(st, "a.csv/c3");
  EXPECT_EQ(c3.sightings, 1);
  EXPECT_NEAR(c3.obstacle.footprint.centre.x(), kX0 + 1000.0, 1e-6);
  const StoredObstacle& c4 = by_id(st, "a.csv/c4");
  EXPECT_EQ(c4.sightings, 2);
  EXPECT_NEAR(c4.obstacle.footprint.centre.x(), kX0 + 1012.5, 1e-6);
  EXPECT_NEAR(c4.obstacle.footprint.a, 2.5, 1e-12);
  EXPECT_EQ(c4.last_seen, "2024-06-01T09:30:00Z");

  // b3 is far from everything: a new object.
  const StoredObstacle& b3 = by_id(st, "b.csv/b3");
  EXPECT_EQ(b3.sightings, 1);
  EXPECT_NEAR(b3.obstacle.footprint.centre.x(), kX0 + 2000.0, 1e-6);
  EXPECT_EQ(b3.first_seen, "2024-06-01T08:20:00Z");

  // Each detection row points at the object it went into.
  std::map<std::string, std::int64_t> into;
  for (const auto& d : st.detections) into[d.mission + "/" + d.contact_id] = d.object_fid;
  EXPECT_EQ(into.at("b.csv/b1"), c1.fid);
  EXPECT_EQ(into.at("b.csv/b4"), c1.fid);
  EXPECT_EQ(into.at("b.csv/b2"), c2.fid);
  EXPECT_EQ(into.at("b.csv/b5"), c4.fid);
  EXPECT_EQ(into.at("b.csv/b3"), b3.fid);
}

TEST(ObstacleStore, ReimportChangesNothing) {
  ScratchDir dir;
  const std::string store = dir.file("store.gpkg");
  const std::string a = dir.write("a.csv", mission_a());
  const std::string b = dir.write("b.csv", mission_b());
  import_detections(store, {a, b}, utm_options());
  const auto before = snapshot(store);
  const std::string bytes_before = slurp(store);
  ASSERT_EQ(before.size(), 5u + 9u);

  // Later, with another import time and from another folder: still the same detections.
  ObstacleStoreOptions later = utm_options();
  later.import_time = "2025-01-01T00:00:00Z";
  std::filesystem::create_directories(dir.path() / "copy");
  std::filesystem::copy_file(b, dir.path() / "copy" / "b.csv");
  const ImportSummary s = import_detections(store, {(dir.path() / "copy" / "b.csv").string(), a}, later);
  EXPECT_EQ(s.detections, 9u);
  EXPECT_EQ(s.already_imported, 9u);
  EXPECT_EQ(s.new_obstacles + s.merged, 0u);
  EXPECT_EQ(s.obstacles_in_store, 5u);
  EXPECT_EQ(snapshot(store), before);
  // Nothing to write means no transaction at all, so even the bytes stay.
  EXPECT_EQ(slurp(store), bytes_before);
}

// Two circles of radius 20 m: 41 m apart they miss each other by 1 m (a new
// object), 39 m apart they overlap by 1 m (merged, though the centres are
// farther apart than the merge distance).
TEST(ObstacleStore, OverlapDecidesBeyondTheMergeDistance) {
  ScratchDir dir;
  const std::string store = dir.file("s.gpkg");
  import_detections(store, {dir.write("a.csv", kHeader + row(0, 0, 20, 20, 0, "", "", "2024-05-01T10:00:00Z", "o"))},
                    utm_options());
  const ImportSummary miss = import_detections(
      store, {dir.write("b.csv", kHeader + row(41, 0, 20, 20, 0, "", "", "2024-05-02T10:00:00Z", "m"))}, utm_options());
  EXPECT_EQ(miss.new_obstacles, 1u);
  EXPECT_EQ(miss.merged, 0u);
  const ImportSummary hit = import_detections(
      store, {dir.write("c.csv", kHeader + row(-39, 0, 20, 20, 0, "", "", "2024-05-03T10:00:00Z", "h"))},
      utm_options());
  EXPECT_EQ(hit.merged, 1u);
  EXPECT_EQ(hit.obstacles_in_store, 2u);
  const ObstacleStore st = read_obstacle_store(store, "EPSG:32632");
  EXPECT_NEAR(by_id(st, "a.csv/o").obstacle.footprint.centre.x(), kX0 - 19.5, 1e-6);
  EXPECT_EQ(by_id(st, "a.csv/o").sightings, 2);
  EXPECT_NEAR(by_id(st, "b.csv/m").obstacle.footprint.centre.x(), kX0 + 41.0, 1e-6);
}

TEST(ObstacleStore, AttributeTablesAreSkippedOnlyBesideGeometry) {
  ScratchDir dir;
  // A lone layer without geometry is still an error for the reader.
  const std::string p = dir.write("nogeom.csv", "id,semi_major_m\nx,4\n");
  const std::string e = error_of([&] { load_obstacles({p}); });
  EXPECT_NE(e.find("nogeom.csv: line 2 (id 'x'): field 'geometry'"), std::string::npos) << e;
}

TEST(ObstacleStore, DuplicateWithinOneFileIsImportedOnce) {
  ScratchDir dir;
  const std::string line = row(0, 0, 10, 4, 30, "", "", "2024-05-01T10:00:00Z", "c1");
  const std::string f = dir.write("dup.csv", kHeader + line + line);
  const ImportSummary s = import_detections(dir.file("s.gpkg"), {f}, utm_options());
  EXPECT_EQ(s.detections, 2u);
  EXPECT_EQ(s.new_obstacles, 1u);
  EXPECT_EQ(s.already_imported, 1u);
  EXPECT_EQ(read_obstacle_store(dir.file("s.gpkg")).obstacles.at(0).sightings, 1);
}

TEST(ObstacleStore, GeoJsonTimesMissionAndPlainObstacleReading) {
  ScratchDir dir;
  // GDAL reads these times as date-times; +02:00 is stored as UTC.
  const std::string g = dir.write("m.geojson", R"({"type":"FeatureCollection","features":[
 {"type":"Feature","properties":{"contact_id":"k1","mission":"survey-7","time":"2024-05-01T12:00:00+02:00",
  "semi_major_m":10,"semi_minor_m":4,"orientation_deg":170},"geometry":{"type":"Point","coordinates":[10.2,54.4]}},
 {"type":"Feature","properties":{"id":"k2","time":"2024-05-01T12:00:00.250Z","semi_major_m":5},
  "geometry":{"type":"Point","coordinates":[10.21,54.4]}}]})");
  const std::string store = dir.file("s.gpkg");
  import_detections(store, {g});
  const ObstacleStore st = read_obstacle_store(store);
  ASSERT_EQ(st.obstacles.size(), 2u);
  EXPECT_EQ(by_id(st, "survey-7/k1").first_seen, "2024-05-01T10:00:00Z");
  EXPECT_EQ(by_id(st, "m.geojson/k2").first_seen, "2024-05-01T12:00:00.250Z");
  // The store is an ordinary obstacle file: load_obstacles (plan --obstacles) reads it.
  const LoadedObstacles l = load_obstacles({store});
  ASSERT_EQ(l.obstacles.ellipses.size(), 2u);
  EXPECT_EQ(l.sources.at(0).driver, "GPKG");
  EXPECT_EQ(l.obstacles.ellipses[0].id, "survey-7/k1");
  EXPECT_DOUBLE_EQ(l.obstacles.ellipses[0].footprint.a, 10.0);
  EXPECT_NEAR(l.ellipse_origins[0].heading_deg, 170.0, 1e-9);
  EXPECT_NEAR(l.ellipse_origins[0].lonlat.x(), 10.2, 1e-12);
  EXPECT_DOUBLE_EQ(l.obstacles.ellipses[1].footprint.b, 5.0);
}

TEST(ObstacleStore, NormalizeUtcTime) {
  const InputLocation w{"f.csv", "line 2", "time"};
  EXPECT_EQ(normalize_utc_time("2024-02-29T23:30:00-01:00", w), "2024-03-01T00:30:00Z");
  EXPECT_EQ(normalize_utc_time("2024-05-01 10:00:00.5Z", w), "2024-05-01T10:00:00.500Z");
  EXPECT_EQ(normalize_utc_time("1999-12-31T23:59:59+0000", w), "1999-12-31T23:59:59Z");
  for (const char* bad : {"2024-05-01T10:00:00", "2023-02-29T10:00:00Z", "2024-05-01", "yesterday",
                          "2024-05-01T24:00:00Z", "2024-05-01T10:00:00Zjunk", ""}) {
    const std::string e = error_of([&] { normalize_utc_time(bad, w); });
    EXPECT_NE(e.find("f.csv: line 2: field 'time': expected an ISO 8601 time"), std::string::npos) << bad << ": " << e;
  }
}

// A process SIGKILLed while its import transaction is open leaves the store
// exactly as it was before that import, readable, and importable again.
TEST(ObstacleStore, KilledImportLeavesThePreviousStore) {
  ScratchDir dir;
  const std::string store = dir.file("store.gpkg");
  import_detections(store, {dir.write("a.csv", mission_a())}, utm_options());
  const auto before = snapshot(store);
  ASSERT_EQ(before.size(), 8u);
  const std::string bytes_before = slurp(store);

  // 4000 new detections on a 50 m grid: 8000 rows to write (objects + detections).
  std::string big = kHeader;
  for (int i = 0; i < 4000; ++i) {
    big += row(5000.0 + 50.0 * (i % 80), 50.0 * (i / 80), 4, 2, 10, "", "", "2024-08-01T00:00:00Z",
               "n" + std::to_string(i));
  }
  const std::string big_path = dir.write("big.csv", big);
  const std::string err_path = dir.file("stderr.txt");

  // A child process imports and stops once 7000 rows are written inside the
  // open transaction, saying so in a file; then it is killed.
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // A 1 MB SQLite cache: without care the import would spill pages into the
    // store before its commit, and readers would find a hot journal.
    CPLSetConfigOption("OGR_SQLITE_CACHE", "1");
    ObstacleStoreOptions o = utm_options();
    o.on_row_written = [&](long rows) {
      if (rows != 7000) return;
      std::ofstream(err_path) << "import stalled after 7000 rows" << std::endl;
      for (;;) ::pause();
    };
    try {
      import_detections(store, {big_path}, o);
    } catch (...) {
    }
    _exit(0);
  }

  // Wait (at most two minutes on a loaded machine) for the child's marker.
  bool stalled = false;
  for (int i = 0; i < 1200 && !stalled; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stalled = slurp(err_path).find("import stalled after 7000 rows") != std::string::npos;
    int status = 0;
    if (!stalled && waitpid(pid, &status, WNOHANG) == pid) break;  // exited early: fail below
  }
  const bool journal_open = std::filesystem::exists(store + "-journal");
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(stalled) << "stderr: " << slurp(err_path);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  // The transaction had written to the file system: SQLite's rollback journal was there.
  EXPECT_TRUE(journal_open);
  // The store file itself is untouched until a commit.
  EXPECT_EQ(slurp(store), bytes_before);

  // Readable, read-only first (what `plan --obstacles` does), with no partial rows.
  EXPECT_EQ(snapshot(store), before);
  const ObstacleStore st = read_obstacle_store(store, "EPSG:32632");
  EXPECT_EQ(st.obstacles.size(), 4u);
  EXPECT_EQ(st.detections.size(), 4u);
  EXPECT_EQ(load_obstacles({store}).obstacles.size(), 4u);

  // And the same import then runs to the end.
  const ImportSummary s = import_detections(store, {big_path}, utm_options());
  EXPECT_EQ(s.new_obstacles, 4000u);
  EXPECT_EQ(s.obstacles_in_store, 4004u);
}

// ---------------------------------------------------------------- bad input

TEST(ObstacleStoreErrors, BadDetectionFilesLeaveNoStore) {
  ScratchDir dir;
  const std::string store = dir.file("store.gpkg");
  struct Case {
    std::string name, content, expect;
  };
  const std::vector<Case> cases = {
      {"garbage.geojson", "{\"type\": \"FeatureCollection\", \"features\": [", "garbage.geojson: expected"},
      {"nosize.csv", kHeader + "500000,6030000,,,,,,2024-05-01T10:00:00Z,c1\n",
       "nosize.csv: line 2: field 'semi_major_m'"},
      {"badtime.csv", kHeader + row(0, 0, 4, 2, 0, "", "", "noon", "c9"), "field 'time': expected an ISO 8601"},
      {"nozone.csv", kHeader + row(0, 0, 4, 2, 0, "", "", "2024-05-01T10:00:00", "c9"), "line 2"},
      {"poly.geojson",
       R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"id":"p"},"geometry":{"type":"Polygon","coordinates":[[[9,54.4],[9.001,54.4],[9.001,54.401],[9,54.4]]]}}]})",
       "poly.geojson: feature 0 (id 'p'): field 'geometry': expected a Point detection"},
  };
  for (const Case& c : cases) {
    const std::string path = dir.write(c.name, c.content);
    const std::string e = error_of([&] { import_detections(store, {path}, utm_options()); });
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.name << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_FALSE(std::filesystem::exists(store)) << c.name;
  }
  const std::string missing = error_of([&] { import_detections(store, {dir.file("none.csv")}, utm_options()); });
  EXPECT_NE(missing.find("none.csv: expected an existing file"), std::string::npos) << missing;
  ObstacleStoreOptions o = utm_options();
  o.merge_distance_m = -1.0;
  EXPECT_NE(
      error_of([&] { import_detections(store, {dir.write("ok.csv", mission_a())}, o); }).find("`merge_distance_m`"),
      std::string::npos);
  EXPECT_NE(error_of([&] { import_detections(store, {}, utm_options()); }).find("at least one detection file"),
            std::string::npos);
}

TEST(ObstacleStoreErrors, BadDetectionsInASecondFileRollBackNothingWritten) {
  ScratchDir dir;
  const std::string store = dir.file("store.gpkg");
  import_detections(store, {dir.write("a.csv", mission_a())}, utm_options());
  const auto before = snapshot(store);
  const std::string bad = dir.write("bad.csv", kHeader + row(0, 0, 4, 8, 0, "", "", "", "x"));  // b > a
  const std::string e = error_of([&] {
    import_detections(store, {dir.write("b.csv", mission_b()), bad}, utm_options());
  });
  EXPECT_NE(e.find("bad.csv: line 2: field 'semi_minor_m'"), std::string::npos) << e;
  EXPECT_EQ(snapshot(store), before);
}

TEST(ObstacleStoreErrors, StoresThatAreNotObstacleStores) {
  ScratchDir dir;
  const std::string det = dir.write("a.csv", mission_a());
  // Text with a .gpkg name.
  const std::string text = dir.write("text.gpkg", "not a database\n");
  std::string e = error_of([&] { import_detections(text, {det}, utm_options()); });
  EXPECT_NE(e.find("text.gpkg: expected a GeoPackage obstacle store"), std::string::npos) << e;
  EXPECT_EQ(slurp(text), "not a database\n");
  // A GeoJSON file given as the store.
  const std::string json = dir.write("store.geojson", R"({"type":"FeatureCollection","features":[]})");
  e = error_of([&] { import_detections(json, {det}, utm_options()); });
  EXPECT_NE(e.find("store.geojson: expected a GeoPackage obstacle store"), std::string::npos) << e;
  // A GeoPackage of plain obstacles (obstacles convert): the store's fields are missing.
  const std::string plain = dir.file("plain.gpkg");
  const LoadedObstacles l = load_obstacles({det}, {"EPSG:32632", "EPSG:32632"});
  write_obstacles(plain, l.obstacles, l.frame);
  e = error_of([&] { import_detections(plain, {det}, utm_options()); });
  EXPECT_NE(e.find("plain.gpkg: layer 'obstacles': expected a Point layer"), std::string::npos) << e;
  // A GeoPackage of something else entirely.
  const std::string roads = dir.file("roads.gpkg");
  {
    GDALAllRegister();
    GDALDatasetUniquePtr ds(
        GetGDALDriverManager()->GetDriverByName("GPKG")->Create(roads.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    ds->CreateLayer("roads", nullptr, wkbLineString, nullptr);
  }
  e = error_of([&] { import_detections(roads, {det}, utm_options()); });
  EXPECT_NE(e.find("roads.gpkg: layer 'obstacles': expected the obstacle store's Point layer"), std::string::npos) << e;
  e = error_of([&] { read_obstacle_store(roads); });
  EXPECT_NE(e.find("roads.gpkg: layer 'obstacles'"), std::string::npos) << e;
  // The store given as a detection file too.
  const std::string store = dir.file("s.gpkg");
  import_detections(store, {det}, utm_options());
  e = error_of([&] { import_detections(store, {store}, utm_options()); });
  EXPECT_NE(e.find("expected a detection file, got the store itself"), std::string::npos) << e;
}

TEST(ObstacleStoreErrors, MissingFieldAndBadValuesInTheStore) {
  ScratchDir dir;
  const std::string det = dir.write("a.csv", mission_a());
  const std::string store = dir.file("s.gpkg");
  import_detections(store, {det}, utm_options());
  GDALAllRegister();
  {
    GDALDatasetUniquePtr ds(GDALDataset::Open(store.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    OGRLayer* layer = ds->GetLayerByName("obstacles");
    OGRFeatureUniquePtr f(layer->GetFeature(1));
    f->SetField("sightings", 0);
    ASSERT_EQ(layer->SetFeature(f.get()), OGRERR_NONE);
  }
  std::string e = error_of([&] { read_obstacle_store(store); });
  EXPECT_NE(e.find("s.gpkg: layer 'obstacles', feature 1 (id 'a.csv/c1'): field 'sightings': expected a whole "
                   "number of sightings >= 1, got '0'"),
            std::string::npos)
      << e;
  {
    GDALDatasetUniquePtr ds(GDALDataset::Open(store.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    OGRLayer* layer = ds->GetLayerByName("obstacles");
    OGRFeatureUniquePtr f(layer->GetFeature(1));
    f->SetField("sightings", 2);
    f->SetField("first_seen", "last tuesday");
    ASSERT_EQ(layer->SetFeature(f.get()), OGRERR_NONE);
  }
  e = error_of([&] { import_detections(store, {dir.write("b.csv", mission_b())}, utm_options()); });
  EXPECT_NE(e.find("feature 1 (id 'a.csv/c1'): field 'first_seen': expected an ISO 8601"), std::string::npos) << e;
  {
    GDALDatasetUniquePtr ds(GDALDataset::Open(store.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    ASSERT_EQ(ds->GetLayerByName("detections")->DeleteField(1), OGRERR_NONE);  // mission
  }
  e = error_of([&] { import_detections(store, {det}, utm_options()); });
  EXPECT_NE(e.find("s.gpkg: layer 'detections': field 'mission': expected a text field"), std::string::npos) << e;
}

TEST(ObstacleStoreErrors, ReadOnlyStoreIsRefusedAndUntouched) {
  ScratchDir dir;
  const std::string store = dir.file("s.gpkg");
  import_detections(store, {dir.write("a.csv", mission_a())}, utm_options());
  const std::string bytes = slurp(store);
  ASSERT_EQ(::chmod(store.c_str(), 0444), 0);
  const std::string e = error_of([&] { import_detections(store, {dir.write("b.csv", mission_b())}, utm_options()); });
  EXPECT_NE(e.find("s.gpkg: expected a writable obstacle store, got a read-only file"), std::string::npos) << e;
  EXPECT_EQ(slurp(store), bytes);
  EXPECT_EQ(read_obstacle_store(store).obstacles.size(), 4u);  // still readable
  ::chmod(store.c_str(), 0644);
}

// ---------------------------------------------------------------- the CLI

TEST(ObstacleStoreCli, ImportTwiceWithJson) {
  ScratchDir dir;
  const std::string a = dir.write("a.csv", mission_a());
  const std::string store = dir.file("store.gpkg");
  const std::string args = "obstacles import '" + a + "' --store '" + store + "' --src-crs EPSG:32632 --json";
  const auto r1 = run_cli(args);
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  const auto j1 = nlohmann::json::parse(r1.out);
  EXPECT_TRUE(j1.at("created").get<bool>());
  EXPECT_EQ(j1.at("new_obstacles").get<int>(), 4);
  EXPECT_DOUBLE_EQ(j1.at("merge_distance_m").get<double>(), 10.0);
  const auto before = snapshot(store);
  const auto r2 = run_cli(args);
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const auto j2 = nlohmann::json::parse(r2.out);
  EXPECT_FALSE(j2.at("created").get<bool>());
  EXPECT_EQ(j2.at("already_imported").get<int>(), 4);
  EXPECT_EQ(j2.at("obstacles_in_store").get<int>(), 4);
  EXPECT_EQ(snapshot(store), before);
  // Text output, and a merge distance large enough to join c3 and c4 (16 m apart) from another mission.
  const std::string c = dir.write("c.csv", kHeader + row(1008, 0, 3, 3, 0, "", "", "2024-09-01T00:00:00Z", "z"));
  const auto r3 =
      run_cli("obstacles import '" + c + "' --store '" + store + "' --src-crs EPSG:32632 --merge-distance 20");
  ASSERT_EQ(r3.exit_code, 0) << r3.err;
  EXPECT_NE(r3.out.find("merged             1"), std::string::npos) << r3.out;
  EXPECT_NE(r3.out.find("obstacles in store 4"), std::string::npos) << r3.out;
  // The store plans like any obstacle file.
  const auto info = run_cli("obstacles info --json '" + store + "'");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out).at("count").get<int>(), 4);
}

TEST(ObstacleStoreCli, BadInputExitsOneWithOneLine) {
  ScratchDir dir;
  const std::string a = dir.write("a.csv", mission_a());
  const std::string text = dir.write("text.gpkg", "hello\n");
  auto r = run_cli("obstacles import '" + a + "' --store '" + text + "' --src-crs EPSG:32632");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("text.gpkg: expected a GeoPackage obstacle store"), std::string::npos) << r.err;

  const std::string bad = dir.write("bad.csv", kHeader + "500000,6030000,abc,,,,,,\n");
  r = run_cli("obstacles import '" + bad + "' --store '" + dir.file("s.gpkg") + "' --src-crs EPSG:32632");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("bad.csv: line 2: field 'semi_major_m': expected a number, got 'abc'"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("s.gpkg")));

  r = run_cli("obstacles import '" + a + "' --store '" + dir.file("s.gpkg") + "' --merge-distance nan");
  EXPECT_NE(r.exit_code, 0);
  r = run_cli("obstacles import '" + a + "'");  // no --store: usage
  EXPECT_EQ(r.exit_code, 2);
}
