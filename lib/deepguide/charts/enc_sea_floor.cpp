#include "deepguide/charts/enc_sea_floor.hpp"

#include <gdal_alg.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "deepguide/core/error.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

namespace {

constexpr double kLand = -1.0;  // what a node no vehicle can reach at any depth gets
constexpr std::size_t kMaxNodes = std::size_t{1} << 26;

std::unique_ptr<OGRGeometry> ogr_area(const BgMultiPolygon& area) {
  auto mp = std::make_unique<OGRMultiPolygon>();
  for (const BgPolygon& p : area) {
    OGRPolygon op;
    auto ring = [&](const auto& r) {
      OGRLinearRing lr;
      for (const BgPoint& q : r) lr.addPoint(q.x(), q.y());
      op.addRing(&lr);
    };
    ring(p.outer());
    for (const auto& in : p.inners()) ring(in);
    mp->addGeometry(&op);
  }
  return mp;
}

}  // namespace

SeaFloor enc_sea_floor(const std::vector<std::string>& charts, const LocalFrame& frame, const Vec2& lo, const Vec2& hi,
                       double spacing, EncNoGoOptions options) {
  if (!std::isfinite(spacing) || spacing <= 0.0) {
    throw InputError("sea floor spacing: expected a spacing > 0 m, got " + std::to_string(spacing));
  }
  if (!lo.allFinite() || !hi.allFinite() || !(hi.x() > lo.x()) || !(hi.y() > lo.y())) {
    throw InputError("sea floor: expected a box with some area");
  }
  const std::size_t nx = static_cast<std::size_t>(std::ceil((hi.x() - lo.x()) / spacing)) + 1;
  const std::size_t ny = static_cast<std::size_t>(std::ceil((hi.y() - lo.y()) / spacing)) + 1;
  if (nx * ny > kMaxNodes) {
    throw InputError("sea floor: expected at most " + std::to_string(kMaxNodes) + " nodes, got " +
                     std::to_string(nx * ny) + " (a larger spacing, or a smaller area)");
  }
  // Every depth too shallow: each feature comes back with its least depth.
  options.operating_depth_m = 1e4;
  options.vertical_clearance_m = 0.0;
  options.planner_obstacles = false;
  const EncNoGo judged = enc_no_go(charts, frame, options);

  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  if (mem == nullptr) throw InputError("sea floor: GDAL has no MEM driver");
  GDALDatasetUniquePtr ds(mem->Create("", static_cast<int>(nx), static_cast<int>(ny), 1, GDT_Float64, nullptr));
  if (!ds) throw InputError("sea floor: GDAL could not make a grid of " + std::to_string(nx * ny) + " nodes");
  // Node (i, j) is the centre of pixel (i, ny - 1 - j): rows run north to south.
  const double top = lo.y() + static_cast<double>(ny - 1) * spacing + 0.5 * spacing;
  double gt[6] = {lo.x() - 0.5 * spacing, spacing, 0.0, top, 0.0, -spacing};
  ds->SetGeoTransform(gt);
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->Fill(std::numeric_limits<double>::quiet_NaN());

  struct Burn {
    std::unique_ptr<OGRGeometry> geometry;
    double value;
  };
  std::vector<Burn> burns;
  for (const EncNoGoFeature& f : judged.features) {
    if (f.cls == "M_COVR") continue;  // unknown water stays without data
    const double value = std::isnan(f.least_depth_m) ? kLand : f.least_depth_m;
    if (f.point) {
      // A 32-gon whose chords lie outside the disc (radius / cos(pi / 32)).
      OGRPoint c(f.point->x(), f.point->y());
      std::unique_ptr<OGRGeometry> disc(c.Buffer(f.radius_m / std::cos(M_PI / 32.0), 8));
      if (!disc) throw InputError("sea floor: GEOS could not make the disc of " + f.id);
      burns.push_back({std::move(disc), value});
    } else if (!f.area.empty()) {
      burns.push_back({ogr_area(f.area), value});
    }
  }
  // Deepest first: a shallower burn overwrites, so each pixel keeps the shallowest touching it.
  std::stable_sort(burns.begin(), burns.end(), [](const Burn& a, const Burn& b) { return a.value > b.value; });
  std::vector<OGRGeometryH> geoms;
  std::vector<double> values;
  for (const Burn& b : burns) {
    geoms.push_back(OGRGeometry::ToHandle(b.geometry.get()));
    values.push_back(b.value);
  }
  int band_list = 1;
  char* opts[] = {const_cast<char*>("ALL_TOUCHED=TRUE"), nullptr};
  if (!geoms.empty() &&
      GDALRasterizeGeometries(GDALDataset::ToHandle(ds.get()), 1, &band_list, static_cast<int>(geoms.size()),
                              geoms.data(), nullptr, nullptr, values.data(), opts, nullptr, nullptr) != CE_None) {
    throw InputError("sea floor: GDAL could not rasterize the charts: " + gdal::QuietErrors::last_message());
  }
  std::vector<double> pixels(nx * ny);
  if (band->RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), pixels.data(), static_cast<int>(nx),
                     static_cast<int>(ny), GDT_Float64, 0, 0, nullptr) != CE_None) {
    throw InputError("sea floor: GDAL could not read the grid back");
  }
  // Nodes south to north; each the shallowest of its 3 x 3 neighbours (no data counting as 0).
  auto at = [&](std::ptrdiff_t i, std::ptrdiff_t j) {
    i = std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(nx) - 1);
    j = std::clamp<std::ptrdiff_t>(j, 0, static_cast<std::ptrdiff_t>(ny) - 1);
    const double v =
        pixels[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(ny) - 1 - j) * nx + static_cast<std::size_t>(i)];
    return std::isnan(v) ? 0.0 : v;
  };
  std::vector<double> depths(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      double m = std::numeric_limits<double>::infinity();
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          m = std::min(m, at(static_cast<std::ptrdiff_t>(i) + di, static_cast<std::ptrdiff_t>(j) + dj));
        }
      }
      depths[j * nx + i] = m;
    }
  }
  return SeaFloor(lo, spacing, nx, ny, std::move(depths));
}

}  // namespace deepguide
