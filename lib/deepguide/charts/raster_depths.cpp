#include "deepguide/charts/raster_depths.hpp"

#include <gdal_priv.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "deepguide/charts/bathymetry_raster.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

std::vector<Vec2> raster_outline(const std::string& path, const BathymetryOptions& read, const BathymetryInfo& info,
                                 const LocalFrame& frame) {
  std::vector<Vec2> out;
  const LonLatExtent& e = info.extent;
  OGRSpatialReference src;
  src.importFromWkt(info.crs_wkt.c_str());
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference local;
  local.importFromWkt(frame.wkt().c_str());
  local.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (src.IsSame(&local)) {
    gdal::QuietErrors quiet;
    detail::OpenedBathymetry o = detail::open_bathymetry(path, read);
    const double* gt = o.geotransform;
    out.emplace_back(gt[0], gt[3]);
    out.emplace_back(gt[0] + gt[1] * info.width, gt[3] + gt[5] * info.height);
    return out;
  }
  constexpr int kSteps = 20;
  for (int i = 0; i <= kSteps; ++i) {
    const double f = static_cast<double>(i) / kSteps;
    for (const Eigen::Vector2d& ll : {Eigen::Vector2d(e.west + f * (e.east - e.west), e.south),
                                      Eigen::Vector2d(e.west + f * (e.east - e.west), e.north),
                                      Eigen::Vector2d(e.west, e.south + f * (e.north - e.south)),
                                      Eigen::Vector2d(e.east, e.south + f * (e.north - e.south))}) {
      const Vec2 p = frame.from_lonlat(ll);
      if (p.allFinite()) out.push_back(p);
    }
  }
  return out;
}

RasterDepths sample_raster_depths(const std::string& path, const BathymetryOptions& read, const LocalFrame& frame,
                                  const std::vector<Vec2>& points, int width, int height) {
  gdal::QuietErrors quiet;
  detail::OpenedBathymetry r = detail::open_bathymetry(path, read);
  const double* gt = r.geotransform;
  const int rw = r.info.width, rh = r.info.height;
  const std::size_t n = points.size();
  RasterDepths out;
  out.state.assign(n, RasterDepths::State::outside);
  out.depth_m.assign(n, 0.0);
  std::vector<double> xs(n), ys(n);
  for (std::size_t k = 0; k < n; ++k) xs[k] = points[k].x(), ys[k] = points[k].y();
  OGRSpatialReference local;
  local.importFromWkt(frame.wkt().c_str());
  local.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (!local.IsSame(r.srs.get())) {
    const gdal::TransformPtr ct = gdal::make_transform(local, *r.srs);
    if (!ct) throw InputError(path + ": expected a CRS PROJ can transform to " + frame.id() + ", got " + r.info.crs);
    std::vector<int> ok(n, 0);
    ct->Transform(static_cast<int>(n), xs.data(), ys.data(), nullptr, ok.data());
    for (std::size_t k = 0; k < n; ++k) {
      if (ok[k] == 0) xs[k] = ys[k] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  // Raster columns and rows (continuous) of every point, and the window they span.
  double c0 = INFINITY, c1 = -INFINITY, r0 = INFINITY, r1 = -INFINITY;
  for (std::size_t k = 0; k < n; ++k) {
    const double col = (xs[k] - gt[0]) / gt[1];
    const double row = (ys[k] - gt[3]) / gt[5];
    xs[k] = col;
    ys[k] = row;
    if (!(col >= 0.0 && col < rw && row >= 0.0 && row < rh)) continue;
    c0 = std::min(c0, col), c1 = std::max(c1, col), r0 = std::min(r0, row), r1 = std::max(r1, row);
  }
  if (!(c1 >= c0)) return out;  // the raster lies outside the picture
  const int x0 = static_cast<int>(c0), x1 = std::min(rw, static_cast<int>(c1) + 1);
  const int y0 = static_cast<int>(r0), y1 = std::min(rh, static_cast<int>(r1) + 1);
  const int win_w = x1 - x0, win_h = y1 - y0;
  const int bw = std::min(win_w, width + width / 2 + 1);
  const int bh = std::min(win_h, height + height / 2 + 1);
  std::vector<float> buf(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh));
  GDALRasterIOExtraArg extra;
  INIT_RASTERIO_EXTRA_ARG(extra);
  extra.eResampleAlg = GRIORA_NearestNeighbour;
  if (r.band->RasterIO(GF_Read, x0, y0, win_w, win_h, buf.data(), bw, bh, GDT_Float32, 0, 0, &extra) != CE_None) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(path + ": expected readable cells" +
                     (why.empty() ? std::string() : ", got: " + printable(why, 160)));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double col = xs[k], row = ys[k];
    if (!(col >= x0 && col < x1 && row >= y0 && row < y1)) continue;
    const int bx = std::min(bw - 1, static_cast<int>((col - x0) * bw / win_w));
    const int by = std::min(bh - 1, static_cast<int>((row - y0) * bh / win_h));
    const double v = buf[static_cast<std::size_t>(by) * bw + bx];
    if (r.is_nodata(v)) {
      out.state[k] = RasterDepths::State::no_data;
    } else {
      out.state[k] = RasterDepths::State::depth;
      out.depth_m[k] = v * r.to_depth;
    }
  }
  return out;
}

WebMercatorDepths raster_depths_web_mercator(const std::string& path, const std::string& source_crs, int max_px) {
  BathymetryOptions read;
  read.assumed_crs = source_crs;
  const BathymetryInfo info = inspect_bathymetry(path, read);  // the file's checks, its CRS and vertical sense
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr src = gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_READONLY);
  if (!src) throw InputError(path + ": expected a raster GDAL can open");
  const double aspect = static_cast<double>(info.width) / std::max(1, info.height);
  const int w = aspect >= 1.0 ? max_px : std::max(1, static_cast<int>(max_px * aspect));
  const int h = aspect >= 1.0 ? std::max(1, static_cast<int>(max_px / aspect)) : max_px;
  const int out_w = std::min(w, std::max(info.width, 2)), out_h = std::min(h, std::max(info.height, 2));
  std::vector<std::string> args{"-of",
                                "MEM",
                                "-t_srs",
                                "EPSG:3857",
                                "-s_srs",
                                info.crs_wkt,
                                "-r",
                                "bilinear",
                                "-ts",
                                std::to_string(out_w),
                                std::to_string(out_h),
                                "-dstnodata",
                                "nan",
                                "-ot",
                                "Float64"};
  if (info.has_nodata) args.insert(args.end(), {"-srcnodata", std::to_string(info.nodata)});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* options = GDALWarpAppOptionsNew(argv.data(), nullptr);
  GDALDatasetH in = GDALDataset::ToHandle(src.get());
  int failed = 0;
  const GDALDatasetUniquePtr warped(GDALDataset::FromHandle(GDALWarp("", nullptr, 1, &in, options, &failed)));
  GDALWarpAppOptionsFree(options);
  if (!warped || failed)
    throw InputError(path + ": could not warp the raster into Web Mercator (" + gdal::QuietErrors::last_message() +
                     ")");
  WebMercatorDepths out;
  const int W = out.width = warped->GetRasterXSize(), H = out.height = warped->GetRasterYSize();
  std::vector<double>& z = out.depth_m;
  z.resize(static_cast<std::size_t>(W) * static_cast<std::size_t>(H));
  if (warped->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, W, H, z.data(), W, H, GDT_Float64, 0, 0) != CE_None) {
    throw InputError(path + ": could not read the warped raster");
  }
  const bool elevation = info.sense_used == VerticalSense::elevation;
  for (double& v : z) {
    if (!std::isfinite(v) || (info.has_nodata && v == info.nodata)) {
      v = std::numeric_limits<double>::quiet_NaN();
    } else if (elevation) {
      v = -v;
    }
  }
  // The corners of Web Mercator's box, in lon/lat: where Leaflet puts the grid.
  std::array<double, 6> gt{};
  warped->GetGeoTransform(gt.data());
  const auto mercator = gdal::srs_from_user_input("EPSG:3857");
  const auto lonlat = gdal::wgs84();
  const std::unique_ptr<OGRCoordinateTransformation> to(
      OGRCreateCoordinateTransformation(mercator.get(), lonlat.get()));
  std::array<double, 2> xs{gt[0], gt[0] + gt[1] * W}, ys{gt[3] + gt[5] * H, gt[3]};
  if (!to || !to->Transform(2, xs.data(), ys.data())) throw InputError(path + ": could not place the depth image");
  out.bounds = {xs[0], xs[1], ys[0], ys[1]};
  return out;
}

}  // namespace deepguide
