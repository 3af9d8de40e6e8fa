// No-go benchmark: a synthetic N x N bathymetry GeoTIFF (default 20000 x 20000,
// 5 m cells, Float32, 256 x 256 tiles, ZSTD) made here through GDAL in a temp
// folder, turned into no-go polygons by compute_no_go; prints the time, the
// polygon and vertex counts and the peak memory, then deletes the file.
//
// The seabed (depth, positive down): a 45 m plain with broad swells (+-25 m)
// and ripples (+-10 m) that make shoals, a sinuous 30 m deep channel across
// it, and six islands rising above the surface; at 30 m operating depth and
// 2 m clearance about a third of the cells are no-go, in many shoals with
// holes, so the polygons are not trivial.
//
// The raster is written in a forked child, so the parent's peak RSS
// (getrusage ru_maxrss) is that of compute_no_go alone.
//
// Run: build/bench/bench_no_go [--size N] [--depth M] [--clearance M] [--tolerance M] [--keep]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/charts/no_go.hpp"
#include "deepguide/core/error.hpp"

namespace {

namespace fs = std::filesystem;
constexpr double kCell = 5.0;  // m
constexpr double kX0 = 400000, kY0 = 6100000;

struct Args {
  int size = 20000;
  double depth = 30, clearance = 2, tolerance = 5;
  bool keep = false;
};

double peak_rss_mib(int who) {
  rusage u{};
  getrusage(who, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: KiB
}

// Depth (m, positive down) at (x, y) metres from the raster's north-west corner.
// Separable terms are precomputed per row and per column by the caller.
void write_seabed(const std::string& path, int n) {
  GDALAllRegister();
  const char* co[] = {"TILED=YES",    "BLOCKXSIZE=256", "BLOCKYSIZE=256", "COMPRESS=ZSTD",
                      "ZSTD_LEVEL=1", "BIGTIFF=YES",    nullptr};
  GDALDatasetUniquePtr ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), n, n, 1, GDT_Float32,
                                                                                   const_cast<char**>(co)));
  if (!ds) {
    std::fprintf(stderr, "bench_no_go: cannot create %s\n", path.c_str());
    std::exit(1);
  }
  double gt[6] = {kX0, kCell, 0, kY0, 0, -kCell};
  ds->SetGeoTransform(gt);
  OGRSpatialReference srs;
  srs.importFromEPSG(32632);
  ds->SetSpatialRef(&srs);
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetDescription("depth");

  const double two_pi = 2 * std::numbers::pi, side = n * kCell;
  // Islands: centre (fraction of the side), radius (m), height above the plain (m).
  const double islands[6][4] = {{0.2, 0.3, 900, 90},   {0.7, 0.2, 1500, 110},  {0.5, 0.55, 600, 70},
                                {0.85, 0.8, 1200, 95}, {0.3, 0.85, 2000, 120}, {0.6, 0.75, 400, 60}};
  std::vector<double> sx(n), cx(n), s2x(n), c2x(n);
  for (int c = 0; c < n; ++c) {
    const double x = (c + 0.5) * kCell;
    sx[c] = std::sin(two_pi * x / 23000);
    s2x[c] = std::sin(two_pi * x / 7000);
    c2x[c] = std::cos(two_pi * x / 7000);
    cx[c] = 0.5 * side + 0.08 * side * std::sin(two_pi * x / 30000);  // channel's centre line (y)
  }
  const int rows = 256;
  std::vector<float> strip(static_cast<std::size_t>(n) * rows);
  std::vector<double> gx(n);
  for (int r0 = 0; r0 < n; r0 += rows) {
    const int h = std::min(rows, n - r0);
    for (int r = 0; r < h; ++r) {
      const double y = (r0 + r + 0.5) * kCell;
      const double cy = std::cos(two_pi * y / 17000), s2y = std::sin(two_pi * y / 7000),
                   c2y = std::cos(two_pi * y / 7000);
      float* row = strip.data() + static_cast<std::size_t>(r) * n;
      for (int c = 0; c < n; ++c) {
        const double swell = 25 * sx[c] * cy;
        const double ripple = 10 * (s2x[c] * c2y + c2x[c] * s2y);  // sin((x + y) 2 pi / 7 km)
        const double dc = y - cx[c];
        const double channel = std::abs(dc) < 2000 ? 30 * std::exp(-dc * dc / (2 * 400.0 * 400.0)) : 0.0;
        row[c] = static_cast<float>(45 + swell + ripple + channel);
      }
      for (const auto& isl : islands) {
        const double iy = y - isl[1] * side, rad = isl[2];
        if (std::abs(iy) > 4 * rad) continue;
        const double ey = std::exp(-iy * iy / (2 * rad * rad));
        const int c0 = std::max(0, static_cast<int>((isl[0] * side - 4 * rad) / kCell));
        const int c1 = std::min(n, static_cast<int>((isl[0] * side + 4 * rad) / kCell) + 1);
        for (int c = c0; c < c1; ++c) {
          const double ix = (c + 0.5) * kCell - isl[0] * side;
          row[c] -= static_cast<float>(isl[3] * ey * std::exp(-ix * ix / (2 * rad * rad)));
        }
      }
    }
    if (band->RasterIO(GF_Write, 0, r0, n, h, strip.data(), n, h, GDT_Float32, 0, 0, nullptr) != CE_None) {
      std::fprintf(stderr, "bench_no_go: write failed at row %d\n", r0);
      std::exit(1);
    }
    band->FlushCache(false);  // keep the writer's memory small too
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  CLI::App app{"bench_no_go: a synthetic GeoTIFF polygonized into its no-go area; time and peak RSS"};
  app.add_option("--size", a.size, "Raster side (cells)")->check(CLI::Range(2, 200000))->capture_default_str();
  app.add_option("--depth", a.depth, "Operating depth (m)")->capture_default_str();
  app.add_option("--clearance", a.clearance, "Vertical clearance (m)")->capture_default_str();
  app.add_option("--tolerance", a.tolerance, "Polygon simplification tolerance (m)")->capture_default_str();
  app.add_flag("--keep", a.keep, "Keep the GeoTIFF");
  deepguide::bench::parse_or_exit(app, argc, argv);
  const fs::path dir = fs::temp_directory_path() / ("deepguide-bench-nogo-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "seabed.tif").string();

  const auto t0 = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    write_seabed(path, a.size);
    std::_Exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "bench_no_go: writing the raster failed\n");
    return 1;
  }
  const double write_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double file_mib = static_cast<double>(fs::file_size(path)) / (1024.0 * 1024.0);
  std::fprintf(stderr, "bench_no_go: wrote %s (%d x %d, %.0f MiB) in %.1f s, peak RSS %.0f MiB\n", path.c_str(), a.size,
               a.size, file_mib, write_s, peak_rss_mib(RUSAGE_CHILDREN));

  deepguide::NoGoOptions o;
  o.operating_depth_m = a.depth;
  o.vertical_clearance_m = a.clearance;
  o.simplify_tolerance_m = a.tolerance;
  int rc = 0;
  try {
    const double before_mib = peak_rss_mib(RUSAGE_SELF);
    const auto t1 = std::chrono::steady_clock::now();
    const deepguide::NoGoArea area =
        deepguide::compute_no_go(path, deepguide::LocalFrame::from_user_crs("EPSG:32632"), o);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    const double cpu = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                       1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
    std::printf(
        "| cells | no-go cells | polygons | vertices before | vertices after | area km2 | tolerance m | "
        "time s | CPU s | peak RSS MiB |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::printf("| %d x %d | %zu (%.1f%%) | %zu | %zu | %zu | %.2f | %.1f | %.1f | %.1f | %.0f |\n", a.size, a.size,
                area.no_go_cells, 100.0 * static_cast<double>(area.no_go_cells) / static_cast<double>(area.total_cells),
                area.polygons.size(), area.vertices_before_simplify, area.vertices_after_simplify, area.area_m2 / 1e6,
                a.tolerance, s, cpu, peak_rss_mib(RUSAGE_SELF));
    std::fprintf(stderr, "bench_no_go: peak RSS before compute_no_go %.0f MiB; raster written in %.1f s\n", before_mib,
                 write_s);
  } catch (const deepguide::InputError& e) {
    std::fprintf(stderr, "bench_no_go: %s\n", e.what());
    rc = 1;
  }
  if (!a.keep)
    fs::remove_all(dir);
  else
    std::fprintf(stderr, "bench_no_go: kept %s\n", path.c_str());
  return rc;
}
