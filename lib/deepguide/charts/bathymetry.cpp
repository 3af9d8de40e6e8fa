#include "deepguide/charts/bathymetry.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <vector>

#include "deepguide/charts/bathymetry_raster.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/plausible_depth.hpp"
#include "deepguide/world/raster_completeness.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

std::string item(GDALMajorObject& o, const std::string& key) {
  const char* v = o.GetMetadataItem(key.c_str());
  return v != nullptr ? std::string(v) : std::string();
}

GDALDatasetUniquePtr open_raster(const std::string& path, const BathymetryOptions& options) {
  gdal::ensure_registered();
  std::error_code ec;
  // GDAL's virtual files (/vsimem/, /vsizip/ ...) are not on the file system.
  const bool virtual_file = path.rfind("/vsi", 0) == 0;
  if (!virtual_file && !fs::exists(path, ec))
    throw InputError(path + ": expected an existing bathymetry raster, found none");
  if (!virtual_file && fs::is_directory(path, ec))
    throw InputError(path + ": expected a bathymetry raster file, got a folder");
  std::vector<const char*> oo;
  for (const auto& o : options.open_options) oo.push_back(o.c_str());
  oo.push_back(nullptr);
  // A netCDF classic header is walked before GDAL reads it (current_field.cpp says why).
  if (!virtual_file) require_complete_netcdf(path);
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, oo.data());
  if (!ds || ds->GetRasterCount() == 0) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(
        path + ": expected a raster GDAL can open" +
        (why.empty() ? std::string(", got a file no raster driver recognises") : ", got: " + printable(why, 160)));
  }
  if (!virtual_file) require_complete_raster(*ds, path);
  return ds;
}

// The vertical sense the file states, with the reason; elevation by default.
std::pair<VerticalSense, std::string> detect_sense(GDALDataset& ds, GDALRasterBand& band) {
  const std::string var = item(band, "NETCDF_VARNAME");
  std::string positive = ascii_lower(item(band, "positive"));
  if (positive.empty() && !var.empty()) positive = ascii_lower(item(ds, var + "#positive"));
  if (positive == "down") return {VerticalSense::depth, "attribute positive=down"};
  if (positive == "up") return {VerticalSense::elevation, "attribute positive=up"};

  const std::string driver = ds.GetDriver() != nullptr ? ds.GetDriver()->GetDescription() : "";
  if (driver == "BAG") return {VerticalSense::elevation, "BAG specification: elevation, positive up"};

  const std::pair<const char*, std::string> names[] = {{"description", band.GetDescription()},
                                                       {"standard_name", item(band, "standard_name")},
                                                       {"long_name", item(band, "long_name")},
                                                       {"variable name", var}};
  for (const auto& [what, text] : names) {
    const std::string t = ascii_lower(text);
    if (t.empty()) continue;
    if (t.find("depth") != std::string::npos)
      return {VerticalSense::depth, std::string("band ") + what + " '" + printable(text) + "' says depth"};
    for (const char* w : {"elevation", "height", "topograph", "altitude"})
      if (t.find(w) != std::string::npos)
        return {VerticalSense::elevation, std::string("band ") + what + " '" + printable(text) + "' says elevation"};
    if (t == "z")
      return {VerticalSense::elevation, std::string("band ") + what + " 'z' (GMT grid: elevation, positive up)"};
  }
  return {VerticalSense::elevation, "the file does not say; assumed elevation, positive up (GDAL/GMT/NOAA convention)"};
}

// CF lon/lat axes (NetCDF x/y with units degrees_east/degrees_north) without a CRS.
bool has_cf_lonlat_axes(GDALDataset& ds) {
  bool east = false, north = false;
  if (char** md = ds.GetMetadata()) {
    for (char** p = md; *p != nullptr; ++p) {
      const std::string kv = ascii_lower(*p);
      if (kv.find("#units=degrees_east") != std::string::npos) east = true;
      if (kv.find("#units=degrees_north") != std::string::npos) north = true;
    }
  }
  return east && north;
}

bool same_as_nodata(double v, double nodata, GDALDataType type) {
  if (v == nodata) return true;
  // A Float32 band stores its NoData value rounded to float (e.g. 0.1).
  return type == GDT_Float32 && static_cast<float>(v) == static_cast<float>(nodata);
}

}  // namespace

const char* to_string(VerticalSense sense) {
  switch (sense) {
    case VerticalSense::elevation: return "elevation";
    case VerticalSense::depth: return "depth";
    case VerticalSense::automatic: return "automatic";
  }
  return "?";
}

namespace {

// Numbers in a netCDF attribute as GDAL shows it: "{-5475,-89}" or "-89".
std::vector<double> numbers_in(const std::string& text) {
  std::vector<double> out;
  const char* p = text.c_str();
  while (*p != 0) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end != p) {
      out.push_back(v);
      p = end;
    } else {
      ++p;
    }
  }
  return out;
}

}  // namespace

namespace detail {

// The range the file states for its cells. Only where the band is not packed
// (scale 1, offset 0): CF gives valid_range in packed and actual_range in
// unpacked units, and GDAL hands out the packed values.
void read_stated_range(GDALRasterBand& band, OpenedBathymetry& r) {
  int has_scale = 0, has_offset = 0;
  const double scale = band.GetScale(&has_scale), offset = band.GetOffset(&has_offset);
  if (has_scale != 0) r.unpack_scale = scale;
  if (has_offset != 0) r.unpack_offset = offset;
  if (r.unpack_scale != 1.0 || r.unpack_offset != 0.0) return;
  for (const char* key : {"actual_range", "valid_range"}) {
    const std::vector<double> v = numbers_in(item(band, key));
    if (v.size() == 2 && std::isfinite(v[0]) && std::isfinite(v[1]) && v[0] <= v[1]) {
      r.stated_min = v[0], r.stated_max = v[1], r.stated_from = key;
      return;
    }
  }
  const std::vector<double> lo = numbers_in(item(band, "valid_min")), hi = numbers_in(item(band, "valid_max"));
  if (lo.size() == 1 && std::isfinite(lo[0])) r.stated_min = lo[0], r.stated_from = "valid_min";
  if (hi.size() == 1 && std::isfinite(hi[0]))
    r.stated_max = hi[0], r.stated_from = lo.size() == 1 ? "valid_min/valid_max" : "valid_max";
}

bool OpenedBathymetry::is_nodata(double value) const {
  return std::isnan(value) || (info.has_nodata && same_as_nodata(value, info.nodata, type));
}

void OpenedBathymetry::require_plausible(double value, std::size_t column, std::size_t row) const {
  const std::string cell =
      info.path + ": the cell at column " + std::to_string(column) + ", row " + std::to_string(row);
  // The stated range went through text (GDAL's metadata) and may hold a
  // float32 bound: compared with a margin far below any damage that matters.
  const double slack = 1e-6 * std::max({1.0, std::abs(stated_min), std::abs(stated_max)});
  if (value < stated_min - slack || value > stated_max + slack) {
    throw InputError(cell + " holds " + general(value) + ", outside the file's own " + stated_from + " " +
                     general(stated_min) + " .. " + general(stated_max) + ": expected an undamaged file");
  }
  require_plausible_depth((value * unpack_scale + unpack_offset) * to_depth, cell);
}

namespace {
// GEBCO's global grid (86 400 x 43 200, 3.7e9 cells) fits; a block is a
// strip or tile, megabytes in every real file.
constexpr double kMaxRasterCells = 4e9;
constexpr double kMaxRasterBlockBytes = 256.0 * 1048576.0;
}  // namespace

OpenedBathymetry open_bathymetry(const std::string& path, const BathymetryOptions& options) {
  OpenedBathymetry r;
  r.dataset = open_raster(path, options);
  GDALDataset* ds = r.dataset.get();
  BathymetryInfo& info = r.info;
  info.path = path;
  info.driver = ds->GetDriver() != nullptr ? ds->GetDriver()->GetDescription() : "";
  info.width = ds->GetRasterXSize();
  info.height = ds->GetRasterYSize();
  if (options.band < 1 || options.band > ds->GetRasterCount()) {
    throw InputError(path + ": expected band " + std::to_string(options.band) + ", got a raster with " +
                     std::to_string(ds->GetRasterCount()) + " band(s)");
  }
  r.band = ds->GetRasterBand(options.band);
  GDALRasterBand& band = *r.band;
  {
    // A header GDAL took for a raster (any driver may claim a damaged or
    // foreign file) can state sizes no bathymetry has: GDAL then allocates
    // a block of that size on the first read (the fuzzing soak: 4.7 GB for a
    // 217-byte file the NGS geoid driver opened). Refused before reading.
    int bx = 0, by = 0;
    band.GetBlockSize(&bx, &by);
    const double block_bytes = static_cast<double>(std::max(bx, 0)) * std::max(by, 0) *
                               std::max(GDALGetDataTypeSizeBytes(band.GetRasterDataType()), 1);
    const double cells = static_cast<double>(info.width) * static_cast<double>(info.height);
    if (block_bytes > kMaxRasterBlockBytes || cells > kMaxRasterCells) {
      throw InputError(path + ": expected a bathymetry raster of at most " + general(kMaxRasterCells) +
                       " cells read in blocks of at most " + general(kMaxRasterBlockBytes / 1048576.0) + " MiB, got " +
                       std::to_string(info.width) + " x " + std::to_string(info.height) + " cells in blocks of " +
                       fixed(block_bytes / 1048576.0, 0) + " MiB (a damaged header?)");
    }
  }
  {
    // A damaged file (e.g. a GeoTIFF cut short) may open but fail on its
    // first and last cells, or report errors (not warnings) while opening:
    // say so before a missing CRS or the like would mislead.
    double probe = 0;
    if (band.RasterIO(GF_Read, 0, 0, 1, 1, &probe, 1, 1, GDT_Float64, 0, 0, nullptr) != CE_None ||
        band.RasterIO(GF_Read, info.width - 1, info.height - 1, 1, 1, &probe, 1, 1, GDT_Float64, 0, 0, nullptr) !=
            CE_None ||
        !gdal::QuietErrors::last_message().empty()) {
      const std::string why = gdal::QuietErrors::last_message();
      throw InputError(path + ": expected a raster GDAL can read, got a damaged one" +
                       (why.empty() ? std::string() : ": " + printable(why, 160)));
    }
  }

  // CRS: the file's, CF lon/lat axes, or the assumed one.
  std::unique_ptr<OGRSpatialReference>& srs = r.srs;
  if (const OGRSpatialReference* file_srs = ds->GetSpatialRef(); file_srs != nullptr && !file_srs->IsEmpty()) {
    srs.reset(file_srs->Clone());
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    info.crs_source = "file";
  } else if (has_cf_lonlat_axes(*ds)) {
    srs = gdal::wgs84();
    info.crs_source = "CF lon/lat axes (degrees_east/degrees_north)";
  } else if (!options.assumed_crs.empty()) {
    srs = gdal::srs_from_user_input(options.assumed_crs);
    if (!srs)
      throw InputError(path + ": assumed CRS: expected a CRS OSR knows, got '" + printable(options.assumed_crs) + "'");
    info.crs_source = "assumed (option)";
  } else {
    throw InputError(path +
                     ": expected a raster with a CRS, got none; give the CRS it uses (`src_crs`, e.g. EPSG:4326)");
  }
  info.crs = gdal::srs_id(*srs);
  {
    char* wkt = nullptr;
    if (srs->exportToWkt(&wkt) == OGRERR_NONE && wkt != nullptr) info.crs_wkt = wkt;
    CPLFree(wkt);
  }

  double* gt = r.geotransform;
  if (ds->GetGeoTransform(gt) != CE_None) {
    throw InputError(path + ": expected a georeferenced raster (a geotransform), got none");
  }
  if (gt[2] != 0.0 || gt[4] != 0.0) {
    throw InputError(path + ": expected a north-up raster, got a rotated geotransform");
  }
  info.pixel_x = gt[1];
  info.pixel_y = gt[5];
  {
    const double x0 = gt[0], x1 = gt[0] + gt[1] * info.width;
    const double y0 = gt[3], y1 = gt[3] + gt[5] * info.height;
    auto geo = gdal::wgs84();
    auto ct = gdal::make_transform(*srs, *geo);
    double w, s, e, n;
    if (!ct || !ct->TransformBounds(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1), &w, &s, &e,
                                    &n, 21)) {
      throw InputError(path + ": expected a raster extent that converts to lon/lat from " + info.crs + ", got " +
                       "one PROJ cannot transform");
    }
    info.extent = {w, e, s, n};
  }

  int has_nodata = 0;
  const double nodata = band.GetNoDataValue(&has_nodata);
  info.has_nodata = has_nodata != 0;
  if (info.has_nodata) info.nodata = nodata;
  r.type = band.GetRasterDataType();
  read_stated_range(band, r);

  if (options.sense == VerticalSense::automatic) {
    std::tie(info.sense_used, info.sense_reason) = detect_sense(*ds, band);
  } else {
    info.sense_used = options.sense;
    info.sense_reason = "given as an option";
  }
  r.to_depth = info.sense_used == VerticalSense::elevation ? -1.0 : 1.0;
  return r;
}

// The band is never read whole: windows of whole natural blocks, at most
// max_cells cells each (at least one block), so any raster that GDAL can read
// by blocks fits in memory.
WindowSize scan_window(GDALRasterBand& band, int raster_width, int raster_height, std::size_t max_cells,
                       bool whole_rows) {
  int bx = 0, by = 0;
  band.GetBlockSize(&bx, &by);
  bx = std::clamp(bx, 1, raster_width);
  by = std::clamp(by, 1, raster_height);
  const std::size_t block_cells = static_cast<std::size_t>(bx) * static_cast<std::size_t>(by);
  std::size_t blocks_per_window = std::max<std::size_t>(1, max_cells / block_cells);
  // Grow the window along x first (whole rows of blocks), then along y.
  const std::size_t blocks_x = (static_cast<std::size_t>(raster_width) + bx - 1) / bx;
  if (whole_rows) blocks_per_window = std::max(blocks_per_window, blocks_x);
  const std::size_t kx = std::min(blocks_per_window, blocks_x);
  const std::size_t ky = std::max<std::size_t>(1, blocks_per_window / kx);
  return {static_cast<int>(std::min<std::size_t>(kx * bx, raster_width)),
          static_cast<int>(std::min<std::size_t>(ky * by, raster_height))};
}

}  // namespace detail

BathymetryInfo inspect_bathymetry(const std::string& path, const BathymetryOptions& options) {
  gdal::QuietErrors quiet;  // GDAL's warnings (e.g. BAG cornerPoints) are not printed
  detail::OpenedBathymetry opened = detail::open_bathymetry(path, options);
  BathymetryInfo info = opened.info;
  GDALRasterBand& band = *opened.band;
  const double to_depth = opened.to_depth;
  const auto [win_w, win_h] = detail::scan_window(band, info.width, info.height, options.max_window_cells);

  std::vector<double> buf(static_cast<std::size_t>(win_w) * static_cast<std::size_t>(win_h));
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int y = 0; y < info.height; y += win_h) {
    const int h = std::min(win_h, info.height - y);
    for (int x = 0; x < info.width; x += win_w) {
      const int w = std::min(win_w, info.width - x);
      if (band.RasterIO(GF_Read, x, y, w, h, buf.data(), w, h, GDT_Float64, 0, 0, nullptr) != CE_None) {
        const std::string why = gdal::QuietErrors::last_message();
        throw InputError(path + ": expected readable cells in the window at column " + std::to_string(x) + ", row " +
                         std::to_string(y) + (why.empty() ? std::string() : ", got: " + printable(why, 160)));
      }
      ++info.windows_read;
      const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
      for (std::size_t i = 0; i < n; ++i) {
        const double v = buf[i];
        if (opened.is_nodata(v)) continue;
        opened.require_plausible(v, static_cast<std::size_t>(x) + i % static_cast<std::size_t>(w),
                                 static_cast<std::size_t>(y) + i / static_cast<std::size_t>(w));
        ++info.valid_cells;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  const double cells = static_cast<double>(info.width) * static_cast<double>(info.height);
  info.valid_fraction = cells > 0 ? static_cast<double>(info.valid_cells) / cells : 0.0;
  if (info.valid_cells > 0) {
    info.min_depth_m = std::min(lo * to_depth, hi * to_depth);
    info.max_depth_m = std::max(lo * to_depth, hi * to_depth);
  }
  return info;
}

}  // namespace deepguide
