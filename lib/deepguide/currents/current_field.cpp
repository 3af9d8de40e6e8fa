#include "deepguide/currents/current_field.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_reading.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/raster_completeness.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace current_detail {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

Axis ascending_axis(std::vector<double> values, const std::string& path, const std::string& name) {
  Axis a;
  for (double v : values) {
    if (!std::isfinite(v))
      throw InputError(path + ": axis '" + printable(name) + "': expected finite coordinates, got NaN or infinity");
  }
  if (values.size() >= 2 && values[1] < values[0]) {
    std::reverse(values.begin(), values.end());
    a.reversed = true;
  }
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (!(values[i] > values[i - 1])) {
      throw InputError(path + ": axis '" + printable(name) + "': expected strictly monotonic coordinates, got " +
                       fixed(values[i - 1], 6) + " then " + fixed(values[i], 6));
    }
  }
  a.values = std::move(values);
  return a;
}

// ------------------------------------------------------------------ multidimensional reading

void set_extent(CurrentField& f, const OGRSpatialReference& srs) {
  if (f.geographic) {
    f.extent = {f.x.front(), f.x.back(), f.y.front(), f.y.back()};
    return;
  }
  auto geo = gdal::wgs84();
  auto ct = gdal::make_transform(srs, *geo);
  double w, s, e, n;
  if (!ct || !ct->TransformBounds(f.x.front(), f.y.front(), f.x.back(), f.y.back(), &w, &s, &e, &n, 21)) {
    throw InputError(f.source + ": expected a field extent that converts to lon/lat from " + f.crs +
                     ", got one PROJ cannot transform");
  }
  f.extent = {w, e, s, n};
}

void set_crs(CurrentField& f, const OGRSpatialReference& srs, const std::string& source) {
  f.crs = gdal::srs_id(srs);
  f.crs_source = source;
  f.geographic = srs.IsGeographic();
  char* wkt = nullptr;
  if (srs.exportToWkt(&wkt) == OGRERR_NONE && wkt != nullptr) f.crs_wkt = wkt;
  CPLFree(wkt);
}

void check_size(const std::string& path, std::size_t nx, std::size_t ny, std::size_t steps, const CurrentOptions& o) {
  const double cells = static_cast<double>(nx) * static_cast<double>(ny);
  if (cells > static_cast<double>(o.max_cells_per_step) ||
      cells * static_cast<double>(std::max<std::size_t>(steps, 1)) > static_cast<double>(o.max_total_cells)) {
    throw InputError(path + ": expected a current field of at most " + std::to_string(o.max_cells_per_step) +
                     " nodes per time step and " + std::to_string(o.max_total_cells) + " in all, got " +
                     std::to_string(nx) + " x " + std::to_string(ny) + " nodes x " + std::to_string(steps) +
                     " step(s); cut the work area out first (e.g. gdal_translate -projwin or ncks)");
  }
}

}  // namespace current_detail

namespace {

using current_detail::ascending_axis;
using current_detail::Axis;
using current_detail::check_size;
using current_detail::set_crs;
using current_detail::set_extent;
using current_detail::trim;
using current_detail::Unpack;

CurrentField load_two_band(GDALDataset& ds, const std::string& path, const CurrentOptions& options) {
  if (ds.GetRasterCount() != 2) {
    throw InputError(path +
                     ": expected a two-band raster (band 1 u east, band 2 v north, m/s) or a NetCDF file with u/v " +
                     "variables, got a raster with " + std::to_string(ds.GetRasterCount()) + " band(s)");
  }
  CurrentField f;
  f.source = path;
  f.driver = ds.GetDriver() != nullptr ? ds.GetDriver()->GetDescription() : "";
  f.u_name = "band 1";
  f.v_name = "band 2";
  f.depth_m = options.depth_m;
  f.depth_levels = "no depth axis";
  std::unique_ptr<OGRSpatialReference> srs;
  if (const OGRSpatialReference* file_srs = ds.GetSpatialRef(); file_srs != nullptr && !file_srs->IsEmpty()) {
    srs.reset(file_srs->Clone());
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    set_crs(f, *srs, "file");
  } else if (!options.assumed_crs.empty()) {
    srs = gdal::srs_from_user_input(options.assumed_crs);
    if (!srs)
      throw InputError(path + ": assumed CRS: expected a CRS OSR knows, got '" + printable(options.assumed_crs) + "'");
    set_crs(f, *srs, "assumed (option)");
  } else {
    throw InputError(path +
                     ": expected a raster with a CRS, got none; give the CRS it uses (`src_crs`, e.g. EPSG:4326)");
  }
  double gt[6];
  if (ds.GetGeoTransform(gt) != CE_None)
    throw InputError(path + ": expected a georeferenced raster (a geotransform), got none");
  if (gt[2] != 0.0 || gt[4] != 0.0) throw InputError(path + ": expected a north-up raster, got a rotated geotransform");
  const std::size_t nx = static_cast<std::size_t>(ds.GetRasterXSize()),
                    ny = static_cast<std::size_t>(ds.GetRasterYSize());
  check_size(path, nx, ny, 1, options);
  std::vector<double> xs(nx), ys(ny);
  for (std::size_t i = 0; i < nx; ++i) xs[i] = gt[0] + (static_cast<double>(i) + 0.5) * gt[1];
  for (std::size_t j = 0; j < ny; ++j) ys[j] = gt[3] + (static_cast<double>(j) + 0.5) * gt[5];
  const Axis ax = ascending_axis(xs, path, "x (columns)");
  const Axis ay = ascending_axis(ys, path, "y (rows)");
  f.x = ax.values;
  f.y = ay.values;
  for (int b = 1; b <= 2; ++b) {
    GDALRasterBand& band = *ds.GetRasterBand(b);
    std::vector<double> buf(nx * ny);
    if (band.RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), buf.data(), static_cast<int>(nx),
                      static_cast<int>(ny), GDT_Float64, 0, 0, nullptr) != CE_None) {
      throw InputError(path + ": band " + std::to_string(b) +
                       ": expected readable cells, got: " + printable(gdal::QuietErrors::last_message(), 160));
    }
    Unpack unpack;
    int has = 0;
    unpack.fill = band.GetNoDataValue(&has);
    unpack.has_fill = has != 0;
    unpack.float32 = band.GetRasterDataType() == GDT_Float32;
    int ok = 0;
    const double s = band.GetScale(&ok);
    if (ok) unpack.scale = s;
    const double o = band.GetOffset(&ok);
    if (ok) unpack.offset = o;
    std::vector<double>& out = b == 1 ? f.u : f.v;
    out.resize(nx * ny);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t si = ax.reversed ? nx - 1 - i : i, sj = ay.reversed ? ny - 1 - j : j;
        out[j * nx + i] = unpack(buf[sj * nx + si]);
      }
  }
  set_extent(f, *srs);
  return f;
}

}  // namespace

// ------------------------------------------------------------------ public

CurrentField load_current_field(const std::string& path, const CurrentOptions& options) {
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing current field file, found none");
  if (fs::is_directory(path, ec)) throw InputError(path + ": expected a current field file, got a folder");
  if (!(std::isfinite(options.depth_m) && options.depth_m >= 0)) {
    throw InputError(path + ": depth: expected a depth >= 0 m, got " + fixed(options.depth_m, 3));
  }
  // Before GDAL sees it: the netCDF library, given a classic header whose
  // counts were damaged, allocated 12.8 GB and took 56 s to give up (found by
  // fuzz/fuzz_current_nc); the header walk refuses such a file at once.
  require_complete_netcdf(path);
  // Only the drivers of the formats docs/FORMATS.md lists: GDAL probes a file
  // with every driver it has, and each is a parser a damaged file can reach.
  static const char* const multidim[] = {"netCDF", "HDF5", "Zarr", nullptr};
  static const char* const two_band[] = {"GTiff", "netCDF", "HDF5Image", "Zarr", "GRIB", "ENVI", "EHdr", nullptr};
  {
    GDALDatasetUniquePtr md = gdal::open_dataset(path, GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY, multidim);
    if (md) return current_detail::load_multidim(*md, path, options);
  }
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_READONLY, two_band);
  if (!ds || ds->GetRasterCount() == 0) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(
        path + ": expected a current field GDAL can open (NetCDF with u/v or a two-band raster)" +
        (why.empty() ? std::string(", got a file no driver recognises") : ", got: " + printable(why, 160)));
  }
  require_complete_raster(*ds, path);
  return load_two_band(*ds, path, options);
}

CurrentField parse_constant_current(const std::string& text, const std::string& what) {
  const std::string expected =
      "SPEED_MPS,DIR_DEG (speed >= 0 m/s, direction it sets towards, clockwise from true north)";
  const auto comma = text.find(',');
  double v[2] = {0.0, 0.0};
  bool ok = comma != std::string::npos && text.find(',', comma + 1) == std::string::npos;
  for (int i = 0; ok && i < 2; ++i) {
    const std::string part = trim(i == 0 ? text.substr(0, comma) : text.substr(comma + 1));
    const char* first = part.data();
    const char* last = part.data() + part.size();
    if (first < last && *first == '+') ++first;
    auto [ptr, e] = std::from_chars(first, last, v[i]);
    ok = e == std::errc() && ptr == last && std::isfinite(v[i]);
  }
  if (!ok) throw InputError(what + ": expected " + expected + ", got '" + printable(text) + "'");
  if (v[0] < 0) throw InputError(what + ": expected a speed >= 0 m/s, got " + printable(text));
  CurrentField f;
  f.source = what;
  f.driver = "constant";
  f.constant = true;
  f.crs = "EPSG:4326";
  f.crs_source = "constant (true north)";
  f.geographic = true;
  f.depth_levels = "constant";
  f.constant_velocity = v[0] * vector_of_course_deg(v[1]);
  // sin(180 deg) is not 0 in doubles: keep the exact axis directions exact.
  for (int i = 0; i < 2; ++i)
    if (std::abs(f.constant_velocity[i]) < 1e-15 * v[0]) f.constant_velocity[i] = 0.0;
  return f;
}

}  // namespace deepguide
