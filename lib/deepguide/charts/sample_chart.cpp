#include "deepguide/charts/sample_chart.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

// Design coordinates: metres from the raster's south-west corner (x east, y north).
struct Shoal {
  Vec2 centre;
  double radius_m;
  double crest_depth_m;
};
constexpr double kShoalBankDistance = 380.0;  // bank crest, metres off the coast
constexpr double kShoalBankWidth = 140.0;
constexpr double kHarbourDepth = 12.0;  // the basin is dredged like the channel

const Shoal kShoals[] = {
    {{1750.0, 1250.0}, 120.0, 4.5},  // Mittelgrund: a shallow shoal east of the route
    {{350.0, 1950.0}, 180.0, 9.0},
    {{1350.0, 2250.0}, 140.0, 11.0},
};

double uniform01(std::mt19937& g) { return static_cast<double>(g() >> 8) / 16777216.0; }

// Northing (design m) of the natural coastline at x: a gentle bay and a headland in the west.
double coast_y(double x) {
  return 280.0 + 60.0 * std::sin(kTwoPi * x / 1700.0 + 0.8) + 260.0 * std::exp(-std::pow((x - 150.0) / 260.0, 2));
}

bool in_box(double x, double y, double x0, double x1, double y0, double y1) {
  return x >= x0 && x <= x1 && y >= y0 && y <= y1;
}

struct Roughness {
  struct Wave {
    double kx, ky, phase, amp;
  };
  std::vector<Wave> waves;
  explicit Roughness(std::uint32_t seed) {
    std::mt19937 g(seed);
    for (int i = 0; i < 6; ++i) {
      const double wavelength = 80.0 + 320.0 * uniform01(g);
      const double dir = kTwoPi * uniform01(g);
      const double k = kTwoPi / wavelength;
      waves.push_back({k * std::cos(dir), k * std::sin(dir), kTwoPi * uniform01(g), 0.08 + 0.08 * uniform01(g)});
    }
  }
  double operator()(double x, double y) const {
    double s = 0.0;
    for (const Wave& w : waves) s += w.amp * std::sin(w.kx * x + w.ky * y + w.phase);
    return s;
  }
};

// The harbour: a basin cut into the land, two moles and an entrance facing north.
enum class Harbour { none, water, mole };
Harbour harbour_at(double x, double y) {
  if (in_box(x, y, 630.0, 660.0, 0.0, 430.0) && y >= coast_y(x) - 40.0) return Harbour::mole;
  if (in_box(x, y, 940.0, 970.0, 60.0, 430.0) || in_box(x, y, 840.0, 970.0, 400.0, 430.0)) return Harbour::mole;
  if (in_box(x, y, 660.0, 940.0, 90.0, 400.0) || in_box(x, y, 660.0, 840.0, 400.0, 430.0)) return Harbour::water;
  return Harbour::none;
}

struct Channel {
  Vec2 start, dir;
  double length, half_width, slope, depth;
};

Channel design_channel(const SampleChartLayout& l) {
  const Vec2 south_west(l.west, l.north - l.height * l.cell_m);
  const Vec2 a = l.channel_start - south_west;
  const Vec2 b = l.channel_end - south_west;
  return {a, (b - a).normalized(), (b - a).norm(), l.channel_half_width_m, 25.0, l.channel_depth_m};
}

// Depth the dredging guarantees at (x, y), 0 outside the channel.
double channel_depth(const Channel& c, const Vec2& p) {
  const Vec2 d = p - c.start;
  const double t = d.dot(c.dir);
  const double lateral = std::abs(d.x() * c.dir.y() - d.y() * c.dir.x());
  if (t < -c.slope || t > c.length + c.slope) return 0.0;
  const double beyond = std::max({lateral - c.half_width, -t, t - c.length, 0.0});
  if (beyond >= c.slope) return 0.0;
  return c.depth * (1.0 - beyond / c.slope);
}

// Natural depth (m, positive down) of the sea floor off the coast; negative on land.
double natural_depth(double x, double y, const Roughness& rough) {
  const double d = y - coast_y(x);
  if (d < 0.0) return -std::min(0.8 + 0.015 * -d + 0.3 * rough(x, y), 18.0);  // land rises inland
  const double base = 1.5 + 27.0 * (1.0 - std::exp(-d / 650.0));
  const double crest = 7.0 + std::sin(kTwoPi * x / 900.0);  // the bank's crest: 6 .. 8 m
  const double bank_base = 1.5 + 27.0 * (1.0 - std::exp(-kShoalBankDistance / 650.0));
  double depth = base - (bank_base - crest) * std::exp(-std::pow((d - kShoalBankDistance) / kShoalBankWidth, 2));
  for (const Shoal& s : kShoals) {
    const double r = (Vec2(x, y) - s.centre).norm();
    if (depth > s.crest_depth_m) depth -= (depth - s.crest_depth_m) * std::exp(-std::pow(r / s.radius_m, 2));
  }
  // Roughness fades out towards the shore so the coastline stays where it is.
  return std::max(0.3, depth + rough(x, y) * std::min(1.0, d / 100.0));
}

// Multiples of 1/32 m (about 3 cm): exact in a float with the low mantissa
// bytes zero, which DEFLATE then squeezes (the file is committed).
double round_q(double v) { return std::round(v * 32.0) / 32.0; }

}  // namespace

const SampleChartLayout& sample_chart_layout() {
  static const SampleChartLayout layout;
  return layout;
}

float SampleChart::at(int col, int row) const {
  const SampleChartLayout& l = sample_chart_layout();
  return elevation.at(static_cast<std::size_t>(row) * static_cast<std::size_t>(l.width) +
                      static_cast<std::size_t>(col));
}

SampleChart make_sample_chart(const SampleChartOptions& options) {
  const SampleChartLayout& l = sample_chart_layout();
  const Roughness rough(options.seed);
  const Channel channel = design_channel(l);
  const double w = l.width * l.cell_m;
  const double h = l.height * l.cell_m;

  SampleChart chart;
  chart.elevation.resize(static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height));
  for (int row = 0; row < l.height; ++row) {
    const double y = h - (row + 0.5) * l.cell_m;
    for (int col = 0; col < l.width; ++col) {
      const double x = (col + 0.5) * l.cell_m;
      float& cell = chart.elevation[static_cast<std::size_t>(row) * l.width + col];
      // The survey ended short of the north-east corner: no data there.
      if ((w - x) + (h - y) < 260.0) {
        cell = l.nodata;
        continue;
      }
      double depth = natural_depth(x, y, rough);
      switch (harbour_at(x, y)) {
        case Harbour::mole: depth = -3.0; break;
        case Harbour::water: depth = kHarbourDepth; break;
        case Harbour::none: break;
      }
      if (depth > 0.0) depth = std::max(depth, channel_depth(channel, {x, y}));
      cell = static_cast<float>(round_q(-depth));
    }
  }

  // Hazards: positions in design metres, then shifted to EPSG:32632. Tops lie
  // a stated height above the sea floor (wrecks) or at a stated depth (rocks, areas).
  const Vec2 south_west(l.west, l.north - h);
  auto floor_depth = [&](const Vec2& p) {
    const int col = std::clamp(static_cast<int>(p.x() / l.cell_m), 0, l.width - 1);
    const int row = std::clamp(static_cast<int>((h - p.y()) / l.cell_m), 0, l.height - 1);
    return -static_cast<double>(chart.at(col, row));
  };
  auto point = [&](std::string id, std::string kind, std::string name, Vec2 p, double a, double b, double orient,
                   double top) {
    SampleHazard z;
    z.id = std::move(id);
    z.kind = std::move(kind);
    z.name = std::move(name);
    z.position = south_west + p;
    z.semi_major_m = a;
    z.semi_minor_m = b;
    z.orientation_deg = orient;
    z.top_depth_m = top;
    chart.hazards.push_back(std::move(z));
  };
  auto wreck = [&](std::string id, std::string name, Vec2 p, double a, double b, double orient, double height) {
    point(std::move(id), "wreck", std::move(name), p, a, b, orient, round_q(floor_depth(p) - height));
  };
  wreck("wreck-1", "Wreck of the Anna (1952)", {1500.0, 1600.0}, 45.0, 9.0, 65.0, 6.0);
  wreck("wreck-2", "Wreck, unknown", {900.0, 2200.0}, 30.0, 7.0, 140.0, 4.0);
  wreck("wreck-3", "Wreck of a barge", {1900.0, 560.0}, 25.0, 6.0, 10.0, 3.0);
  point("rock-1", "rock", "Rock off the headland", {300.0, 720.0}, 8.0, 8.0, 0.0, 1.8);
  point("rock-2", "rock", "Rock on the Mittelgrund", {1760.0, 1260.0}, 6.0, 6.0, 0.0, 2.5);
  point("rock-3", "rock", "Rock on the bank", {2200.0, 450.0}, 10.0, 7.0, 35.0, 3.0);
  point("rock-4", "rock", "Rock east of the channel", {1250.0, 520.0}, 5.0, 5.0, 0.0, 4.0);
  auto area = [&](std::string id, std::string kind, std::string name, std::vector<Vec2> ring, double top) {
    SampleHazard z;
    z.id = std::move(id);
    z.kind = std::move(kind);
    z.name = std::move(name);
    for (const Vec2& p : ring) z.ring.push_back(south_west + p);
    z.top_depth_m = top;
    Vec2 c(0.0, 0.0);
    for (const Vec2& p : z.ring) c += p;
    z.position = c / static_cast<double>(z.ring.size());
    chart.hazards.push_back(std::move(z));
  };
  area("foul-1", "foul ground", "Foul ground off the headland",
       {{180, 840}, {420, 800}, {480, 960}, {300, 1040}, {160, 980}}, 3.0);
  area("spoil-1", "spoil ground", "Disused spoil ground", {{420, 1480}, {720, 1440}, {760, 1680}, {440, 1720}}, 15.0);
  return chart;
}

namespace {

[[noreturn]] void fail_write(const std::string& path, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(path + ": could not " + what +
                   (why.empty() ? std::string() : " (GDAL: " + printable(why, 160) + ")"));
}

void write_raster(const std::string& path, const fs::path& temp, const SampleChart& chart) {
  const SampleChartLayout& l = sample_chart_layout();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (driver == nullptr) fail_write(path, "find GDAL's GTiff driver");
  const char* options[] = {"TILED=YES",   "BLOCKXSIZE=256", "BLOCKYSIZE=256", "COMPRESS=DEFLATE",
                           "PREDICTOR=3", "ZLEVEL=9",       nullptr};
  GDALDatasetUniquePtr ds(driver->Create(temp.c_str(), l.width, l.height, 1, GDT_Float32, const_cast<char**>(options)));
  if (!ds) fail_write(path, "create the GeoTIFF");
  double gt[6] = {l.west, l.cell_m, 0.0, l.north, 0.0, -l.cell_m};
  OGRSpatialReference srs;
  srs.importFromEPSG(l.epsg);
  if (ds->SetGeoTransform(gt) != CE_None || ds->SetSpatialRef(&srs) != CE_None) fail_write(path, "georeference");
  ds->SetMetadataItem("TIFFTAG_IMAGEDESCRIPTION",
                      "deepguide sample chart: SYNTHETIC elevation (m, positive up), Kiel Bight. Not for navigation.");
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetDescription("elevation");
  band->SetUnitType("m");
  band->SetNoDataValue(l.nodata);
  if (band->RasterIO(GF_Write, 0, 0, l.width, l.height, const_cast<float*>(chart.elevation.data()), l.width, l.height,
                     GDT_Float32, 0, 0, nullptr) != CE_None) {
    fail_write(path, "write the cells");
  }
  ds.reset();  // flushes and closes
  if (!gdal::QuietErrors::last_message().empty()) fail_write(path, "finish the GeoTIFF");
}

void write_hazards(const std::string& path, const fs::path& temp, const SampleChart& chart) {
  const SampleChartLayout& l = sample_chart_layout();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GPKG");
  if (driver == nullptr) fail_write(path, "find GDAL's GPKG driver");
  GDALDatasetUniquePtr ds(driver->Create(temp.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  if (!ds) fail_write(path, "create the GeoPackage");
  OGRSpatialReference srs;
  srs.importFromEPSG(l.epsg);
  OGRLayer* layer = ds->CreateLayer("hazards", &srs, wkbUnknown, nullptr);
  if (layer == nullptr) fail_write(path, "create the hazards layer");
  for (const char* name : {"id", "kind", "name"}) {
    OGRFieldDefn fd(name, OFTString);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
  }
  for (const char* name : {"semi_major_m", "semi_minor_m", "orientation_deg", "top_depth_m"}) {
    OGRFieldDefn fd(name, OFTReal);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
  }
  for (const SampleHazard& z : chart.hazards) {
    OGRFeature f(layer->GetLayerDefn());
    f.SetField("id", z.id.c_str());
    f.SetField("kind", z.kind.c_str());
    f.SetField("name", z.name.c_str());
    f.SetField("top_depth_m", z.top_depth_m);
    if (z.ring.empty()) {
      f.SetField("semi_major_m", z.semi_major_m);
      f.SetField("semi_minor_m", z.semi_minor_m);
      f.SetField("orientation_deg", z.orientation_deg);
      OGRPoint p(z.position.x(), z.position.y());
      f.SetGeometry(&p);
    } else {
      OGRLinearRing ring;
      for (const Vec2& p : z.ring) ring.addPoint(p.x(), p.y());
      ring.closeRings();
      OGRPolygon poly;
      poly.addRing(&ring);
      f.SetGeometry(&poly);
    }
    if (layer->CreateFeature(&f) != OGRERR_NONE) fail_write(path, "write hazard '" + z.id + "'");
  }
  ds.reset();  // flushes and closes
  if (!gdal::QuietErrors::last_message().empty()) fail_write(path, "finish the GeoPackage");
}

}  // namespace

SampleChartFiles write_sample_chart(const std::string& dir, const SampleChartOptions& options) {
  if (options.name.empty() || options.name.find_first_of("/\\") != std::string::npos || options.name[0] == '.') {
    throw InputError("`name`: expected a file name without folders, got '" + printable(options.name) + "'");
  }
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(dir + ": expected an existing folder to write the chart into");
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  const SampleChart chart = make_sample_chart(options);
  SampleChartFiles files;
  files.raster = (fs::path(dir) / (options.name + ".tif")).string();
  files.hazards = (fs::path(dir) / (options.name + "_hazards.gpkg")).string();
  files.hazard_count = chart.hazards.size();
  // Both complete before either is renamed into place.
  AtomicOutput raster(files.raster);
  AtomicOutput hazards(files.hazards);
  write_raster(files.raster, raster.temp_path(), chart);
  write_hazards(files.hazards, hazards.temp_path(), chart);
  raster.commit();
  hazards.commit();
  return files;
}

}  // namespace deepguide
