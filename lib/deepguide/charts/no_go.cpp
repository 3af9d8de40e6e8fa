#include "deepguide/charts/no_go.hpp"

#include <gdal_alg.h>
#include <ogrsf_frmts.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "deepguide/charts/bathymetry_raster.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/polygon_ops.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace fs = std::filesystem;

namespace {

// Masks up to this many cells live in memory (one byte each); larger ones go
// to a compressed GeoTIFF in the temp folder.
constexpr std::size_t kMemMaskCells = std::size_t{1} << 26;
// Lines between two drops of the mask's block cache while polygonizing.
constexpr int kMaskFlushLines = 512;

void check_option(const std::string& path, const char* field, double value, const char* what) {
  if (!std::isfinite(value) || value < 0) {
    throw input_error(InputLocation{path, "", field}, std::string("a finite ") + what + " >= 0 m", general(value));
  }
}

// An OGR layer that hands each polygon GDALPolygonize emits to a function and
// keeps nothing, so the cells' outlines are never all in memory at once.
class PolygonSink final : public OGRLayer {
 public:
  explicit PolygonSink(std::function<void(const OGRPolygon&)> fn)
      : fn_(std::move(fn)), defn_(new OGRFeatureDefn("nogo")) {
    defn_->Reference();
    OGRFieldDefn value("value", OFTInteger);
    defn_->AddFieldDefn(&value);
    defn_->SetGeomType(wkbPolygon);
  }
  ~PolygonSink() override { defn_->Release(); }
  PolygonSink(const PolygonSink&) = delete;
  PolygonSink& operator=(const PolygonSink&) = delete;

  void ResetReading() override {}
  OGRFeature* GetNextFeature() override { return nullptr; }
  OGRFeatureDefn* GetLayerDefn() override { return defn_; }
  int TestCapability(const char* cap) override { return EQUAL(cap, OLCSequentialWrite) ? TRUE : FALSE; }
  /// An exception from the function, kept until GDAL has returned (it must not cross C code).
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 protected:
  OGRErr ICreateFeature(OGRFeature* feature) override {
    try {
      const OGRGeometry* g = feature->GetGeometryRef();
      if (g != nullptr && wkbFlatten(g->getGeometryType()) == wkbPolygon) fn_(*g->toPolygon());
      return OGRERR_NONE;
    } catch (...) {
      error_ = std::current_exception();
      return OGRERR_FAILURE;
    }
  }

 private:
  std::function<void(const OGRPolygon&)> fn_;
  OGRFeatureDefn* defn_;
  std::exception_ptr error_;
};

// A temporary file removed when this goes out of scope.
class TempFile {
 public:
  TempFile() {
    static std::atomic<unsigned> counter{0};
    path_ = (fs::temp_directory_path() /
             ("deepguide-nogo-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tif"))
                .string();
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Pixel corners (column, row of the raster) -> the local frame.
class PixelToFrame {
 public:
  PixelToFrame(const detail::OpenedBathymetry& raster, const LocalFrame& frame)
      : ct_(nullptr, [](OGRCoordinateTransformation*) {}) {
    std::copy(std::begin(raster.geotransform), std::end(raster.geotransform), gt_);
    OGRSpatialReference frame_srs;
    frame_srs.importFromWkt(frame.wkt().c_str());
    frame_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (!raster.srs->IsSame(&frame_srs)) {
      ct_ = gdal::make_transform(*raster.srs, frame_srs);
      if (!ct_) {
        throw InputError(raster.info.path + ": expected a CRS that converts to the local frame " + frame.id() +
                         ", got " + raster.info.crs + ", which PROJ cannot transform");
      }
    }
  }
  /// True when pixel edges bend in the frame (a different CRS), so outlines are split at every cell corner.
  bool curved() const { return ct_ != nullptr; }

  // Converts xs/ys (pixel coordinates) in place.
  void apply(std::vector<double>& xs, std::vector<double>& ys, const std::string& path) const {
    for (std::size_t i = 0; i < xs.size(); ++i) {
      xs[i] = gt_[0] + xs[i] * gt_[1];
      ys[i] = gt_[3] + ys[i] * gt_[5];
    }
    if (ct_ && !xs.empty() && !ct_->Transform(static_cast<int>(xs.size()), xs.data(), ys.data(), nullptr, nullptr)) {
      throw InputError(path + ": expected cells that convert to the local frame, got one PROJ cannot transform");
    }
  }

 private:
  double gt_[6];
  gdal::TransformPtr ct_;
};

// One ring of a polygonized outline (pixel coordinates, integral corners) in the frame.
// Points where the outline goes straight on are dropped (exact: integral corners);
// `corners` counts the ring's distinct corners.
BgPolygon::ring_type ring_to_frame(const OGRLinearRing& ring, const PixelToFrame& to_frame, const std::string& path,
                                   std::size_t& corners) {
  std::vector<double> px, py;
  const int n = ring.getNumPoints();
  // Corners only: a point between two collinear edges adds nothing.
  for (int i = 0; i + 1 < n; ++i) {  // the last point closes the ring
    const int prev = i == 0 ? n - 2 : i - 1;
    const double ax = ring.getX(prev), ay = ring.getY(prev), bx = ring.getX(i), by = ring.getY(i);
    const double cx = ring.getX(i + 1), cy = ring.getY(i + 1);
    if ((bx - ax) * (cy - by) - (by - ay) * (cx - bx) == 0.0) continue;
    px.push_back(bx);
    py.push_back(by);
  }
  corners += px.size();
  if (to_frame.curved()) {
    // Split every edge at every cell corner it passes (edges are axis-parallel, integral).
    std::vector<double> dx, dy;
    for (std::size_t i = 0; i < px.size(); ++i) {
      const std::size_t j = (i + 1) % px.size();
      const double steps = std::max(std::abs(px[j] - px[i]), std::abs(py[j] - py[i]));
      for (double k = 0; k < steps; k += 1.0) {
        dx.push_back(px[i] + (px[j] - px[i]) * (k / steps));
        dy.push_back(py[i] + (py[j] - py[i]) * (k / steps));
      }
    }
    px = std::move(dx);
    py = std::move(dy);
  }
  to_frame.apply(px, py, path);
  BgPolygon::ring_type out;
  out.reserve(px.size() + 1);
  for (std::size_t i = 0; i < px.size(); ++i) out.emplace_back(px[i], py[i]);
  if (!out.empty()) out.push_back(out.front());
  return out;
}

struct MaskProgress {
  GDALRasterBand* band = nullptr;
  int calls = 0;
};

// GDALPolygonize reports after every line of each of its two passes: drop the
// mask's cached blocks now and then, so the mask is never held in memory whole.
int CPL_STDCALL drop_mask_cache(double, const char*, void* arg) {
  auto* p = static_cast<MaskProgress*>(arg);
  if (++p->calls % kMaskFlushLines == 0) p->band->FlushCache(false);
  return TRUE;
}

}  // namespace

LocalFrame raster_local_frame(const std::string& path, const BathymetryOptions& options) {
  gdal::QuietErrors quiet;
  const detail::OpenedBathymetry raster = detail::open_bathymetry(path, options);
  return default_frame_for(raster.info.extent);
}

BgPolygon raster_coverage(const std::string& path, const LocalFrame& frame, const BathymetryOptions& options) {
  gdal::QuietErrors quiet;
  const detail::OpenedBathymetry raster = detail::open_bathymetry(path, options);
  const double* gt = raster.geotransform;
  const int w = raster.info.width, h = raster.info.height;
  OGRSpatialReference local;
  local.importFromWkt(frame.wkt().c_str());
  local.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const gdal::TransformPtr ct = gdal::make_transform(*raster.srs, local);
  if (!ct) throw InputError(path + ": expected a CRS PROJ can transform to " + frame.id());
  // Corners in pixel space, anticlockwise; each side sampled in up to 64 steps (a side in lon/lat bends in UTM).
  const double corners[5][2] = {{0, 0}, {0, double(h)}, {double(w), double(h)}, {double(w), 0}, {0, 0}};
  BgPolygon poly;
  for (int side = 0; side < 4; ++side) {
    const int steps = std::max(1, std::min(64, std::max(w, h)));
    for (int k = 0; k < steps; ++k) {
      const double f = static_cast<double>(k) / steps;
      const double px = corners[side][0] + f * (corners[side + 1][0] - corners[side][0]);
      const double py = corners[side][1] + f * (corners[side + 1][1] - corners[side][1]);
      double x = gt[0] + px * gt[1] + py * gt[2], y = gt[3] + px * gt[4] + py * gt[5];
      if (!ct->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) {
        throw InputError(path + ": expected the chart's corners inside the local frame " + frame.id());
      }
      poly.outer().emplace_back(x, y);
    }
  }
  poly.outer().push_back(poly.outer().front());
  boost::geometry::correct(poly);
  return poly;
}

NoGoArea compute_no_go(const std::string& path, const LocalFrame& frame, const NoGoOptions& options) {
  check_option(path, "operating_depth_m", options.operating_depth_m, "operating depth");
  check_option(path, "vertical_clearance_m", options.vertical_clearance_m, "vertical clearance");
  check_option(path, "simplify_tolerance_m", options.simplify_tolerance_m, "simplification tolerance");

  gdal::QuietErrors quiet;
  detail::OpenedBathymetry raster = detail::open_bathymetry(path, options.bathymetry);
  NoGoArea result;
  result.raster = raster.info;
  const int width = raster.info.width, height = raster.info.height;
  result.total_cells = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const double limit = options.operating_depth_m + options.vertical_clearance_m;
  const PixelToFrame to_frame(raster, frame);
  {
    std::vector<double> cx = {width / 2.0, width / 2.0 + 1, width / 2.0 + 1, width / 2.0};
    std::vector<double> cy = {height / 2.0, height / 2.0, height / 2.0 + 1, height / 2.0 + 1};
    to_frame.apply(cx, cy, path);
    BgPolygon cell;
    for (int i = 0; i < 4; ++i) cell.outer().emplace_back(cx[i], cy[i]);
    cell.outer().emplace_back(cx[0], cy[0]);
    bg::correct(cell);
    result.cell_area_m2 = bg::area(cell);
  }

  // 1. The mask, window by window (whole rows, so strips of the GeoTIFF mask are written whole).
  gdal::ensure_registered();
  std::unique_ptr<TempFile> mask_file;
  GDALDatasetUniquePtr mask;
  if (result.total_cells <= kMemMaskCells) {
    mask.reset(GetGDALDriverManager()->GetDriverByName("MEM")->Create("", width, height, 1, GDT_Byte, nullptr));
  } else {
    mask_file = std::make_unique<TempFile>();
    const char* create[] = {"TILED=NO", "BLOCKYSIZE=1", "COMPRESS=DEFLATE", "ZLEVEL=1", nullptr};
    mask.reset(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(mask_file->path().c_str(), width, height, 1,
                                                                        GDT_Byte, const_cast<char**>(create)));
  }
  if (!mask) {
    throw InputError(path + ": expected room for the no-go mask (" + std::to_string(width) + " x " +
                     std::to_string(height) + " cells) in " + fs::temp_directory_path().string() +
                     ", got: " + printable(gdal::QuietErrors::last_message(), 160));
  }
  double identity[6] = {0, 1, 0, 0, 0, 1};  // the outlines come in pixel corners
  mask->SetGeoTransform(identity);
  GDALRasterBand& mask_band = *mask->GetRasterBand(1);

  GDALRasterBand& band = *raster.band;
  const auto [win_w, win_h] =
      detail::scan_window(band, width, height, options.bathymetry.max_window_cells, /*whole_rows=*/true);
  std::vector<double> buf(static_cast<std::size_t>(win_w) * static_cast<std::size_t>(win_h));
  std::vector<GByte> bits(buf.size());
  for (int y = 0; y < height; y += win_h) {
    const int h = std::min(win_h, height - y);
    for (int x = 0; x < width; x += win_w) {
      const int w = std::min(win_w, width - x);
      if (band.RasterIO(GF_Read, x, y, w, h, buf.data(), w, h, GDT_Float64, 0, 0, nullptr) != CE_None) {
        const std::string why = gdal::QuietErrors::last_message();
        throw InputError(path + ": expected readable cells in the window at column " + std::to_string(x) + ", row " +
                         std::to_string(y) + (why.empty() ? std::string() : ", got: " + printable(why, 160)));
      }
      const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
      for (std::size_t i = 0; i < n; ++i) {
        const double v = buf[i];
        bool no_go;
        if (raster.is_nodata(v)) {
          no_go = options.nodata_is_no_go;
        } else {
          raster.require_plausible(v, static_cast<std::size_t>(x) + i % static_cast<std::size_t>(w),
                                   static_cast<std::size_t>(y) + i / static_cast<std::size_t>(w));
          const double depth = v * raster.to_depth;
          no_go = depth <= 0.0 || depth < limit;
        }
        bits[i] = no_go ? 1 : 0;
        result.no_go_cells += no_go ? 1 : 0;
      }
      if (mask_band.RasterIO(GF_Write, x, y, w, h, bits.data(), w, h, GDT_Byte, 0, 0, nullptr) != CE_None) {
        throw InputError(path + ": expected room for the no-go mask in " + fs::temp_directory_path().string() +
                         ", got: " + printable(gdal::QuietErrors::last_message(), 160));
      }
    }
    // Neither band's blocks are needed again: free them (GDAL's cache would
    // otherwise grow to its limit, 5% of RAM by default).
    band.FlushCache(false);
    mask_band.FlushCache(false);
  }
  buf = {};
  bits = {};

  // 2. Polygonize, and convert/simplify each polygon as GDAL emits it.
  const double tol = options.simplify_tolerance_m;
  std::vector<BgPolygon> polys;
  PolygonSink sink([&](const OGRPolygon& cells) {
    BgPolygon exact;
    exact.outer() = ring_to_frame(*cells.getExteriorRing(), to_frame, path, result.vertices_before_simplify);
    for (int i = 0; i < cells.getNumInteriorRings(); ++i)
      exact.inners().push_back(
          ring_to_frame(*cells.getInteriorRing(i), to_frame, path, result.vertices_before_simplify));
    bg::correct(exact);
    if (tol == 0) {
      polys.push_back(std::move(exact));
      return;
    }
    for (auto& p : simplify_outward(exact, tol)) polys.push_back(std::move(p));
  });
  if (result.no_go_cells > 0) {
    MaskProgress progress{&mask_band};
    const CPLErr err = GDALPolygonize(GDALRasterBand::ToHandle(&mask_band), GDALRasterBand::ToHandle(&mask_band),
                                      OGRLayer::ToHandle(&sink), 0, nullptr, drop_mask_cache, &progress);
    sink.rethrow();
    if (err != CE_None) {
      throw InputError(
          path + ": expected a mask GDAL can polygonize, got: " + printable(gdal::QuietErrors::last_message(), 160));
    }
  }
  mask.reset();
  mask_file.reset();

  // 3. Disjoint polygons for the planners.
  if (tol > 0) polys = merge_overlapping(std::move(polys));
  result.polygons.reserve(polys.size());
  for (auto& p : polys) {
    result.area_m2 += bg::area(p);
    result.vertices_after_simplify += distinct_vertices(p);
    PolygonObstacle o;
    o.id = "nogo/" + std::to_string(result.polygons.size() + 1);
    o.footprint = std::move(p);
    result.polygons.push_back(std::move(o));
  }
  return result;
}

NoGoArea compute_no_go(const SeaFloor& floor, const LocalFrame& frame, const NoGoOptions& options) {
  const std::size_t w = floor.nx() - 1, h = floor.ny() - 1;
  if (w > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      h > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw InputError("sea floor: expected a grid GDAL can hold, got " + std::to_string(floor.nx()) + " x " +
                     std::to_string(floor.ny()) + " nodes");
  }
  // Row 0 is the northern edge, as in a north-up raster.
  std::vector<float> cells(w * h);
  const auto node = [&](std::size_t i, std::size_t j) { return floor.node_depth(i, j); };
  for (std::size_t j = 0; j < h; ++j) {
    for (std::size_t i = 0; i < w; ++i) {
      const double d = std::min(std::min(node(i, j), node(i + 1, j)), std::min(node(i, j + 1), node(i + 1, j + 1)));
      // A float holds a depth to 6e-8 relative (under a micrometre at 10 m);
      // where it rounds deeper it is taken one step shallower, to stay on the no-go side.
      float f = static_cast<float>(d);
      if (static_cast<double>(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
      cells[(h - 1 - j) * w + i] = f;
    }
  }

  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  if (gtiff == nullptr) throw InputError("sea floor: expected GDAL's GTiff driver");
  static std::atomic<unsigned long> serial{0};
  const std::string path =
      "/vsimem/deepguide_sea_floor_" + std::to_string(::getpid()) + "_" + std::to_string(serial++) + ".tif";
  {
    GDALDatasetUniquePtr ds(
        gtiff->Create(path.c_str(), static_cast<int>(w), static_cast<int>(h), 1, GDT_Float32, nullptr));
    if (!ds) throw InputError("sea floor: expected room for an in-memory copy of " + std::to_string(w * h) + " cells");
    double transform[6] = {
        floor.origin().x(), floor.spacing(), 0.0, floor.origin().y() + floor.spacing() * static_cast<double>(h), 0.0,
        -floor.spacing()};
    ds->SetGeoTransform(transform);
    ds->SetProjection(frame.wkt().c_str());
    GDALRasterBand& band = *ds->GetRasterBand(1);
    band.SetDescription("depth");
    if (band.RasterIO(GF_Write, 0, 0, static_cast<int>(w), static_cast<int>(h), cells.data(), static_cast<int>(w),
                      static_cast<int>(h), GDT_Float32, 0, 0, nullptr) != CE_None) {
      VSIUnlink(path.c_str());
      throw InputError("sea floor: could not write its in-memory copy");
    }
  }
  NoGoOptions o = options;
  o.bathymetry = {};
  o.bathymetry.sense = VerticalSense::depth;
  try {
    NoGoArea area = compute_no_go(path, frame, o);
    VSIUnlink(path.c_str());
    return area;
  } catch (...) {
    VSIUnlink(path.c_str());
    throw;
  }
}

}  // namespace deepguide
