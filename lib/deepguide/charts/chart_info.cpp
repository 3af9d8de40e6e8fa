#include "deepguide/charts/chart_info.hpp"

#include "deepguide/charts/enc_catalogue.hpp"
#include "deepguide/charts/enc_cells.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <boost/geometry/algorithms/area.hpp>
#include <boost/geometry/algorithms/union.hpp>
#include <cmath>
#include <filesystem>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/no_go.hpp"
#include "deepguide/charts/s57_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/safety_zone.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/obstacle_files/obstacle_summary.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/no_go_union.hpp"

namespace deepguide {
namespace fs = std::filesystem;
namespace bg = boost::geometry;

namespace {

void check_options(const ChartInfoOptions& o) {
  if (!std::isnan(o.depth_m) && (!std::isfinite(o.depth_m) || o.depth_m < 0.0)) {
    throw InputError("`depth_m`: expected an operating depth >= 0 m, got " + std::to_string(o.depth_m));
  }
  if (!std::isfinite(o.clearance_m) || o.clearance_m < 0.0) {
    throw InputError("`clearance_m`: expected a vertical clearance >= 0 m, got " + std::to_string(o.clearance_m));
  }
}

LocalFrame frame_for(const LonLatExtent& e, const ChartInfoOptions& o) {
  if (o.local_crs.empty()) return default_frame_for(e);
  LocalFrame frame = LocalFrame::from_user_crs(o.local_crs);
  require_true_scale(frame, e, "the charts");
  return frame;
}

// Size (east x north, m) in the local frame of a lon/lat box: the box of its corners.
void local_size(ChartInfo& info, const LocalFrame& frame) {
  const LonLatExtent& e = info.extent;
  if (std::isnan(e.west)) return;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const double lon : {e.west, e.east}) {
    for (const double lat : {e.south, e.north}) {
      const Eigen::Vector2d p = frame.from_lonlat(lon, lat);
      x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
    }
  }
  info.width_m = x1 - x0;
  info.height_m = y1 - y0;
}

// Area of the union of the footprints (m2); ellipses as polygons within 0.1 m outside.
double union_area(const ObstacleSet& set) {
  std::vector<BgPolygon> parts;
  for (const EllipticCylinder& c : set.ellipses) parts.push_back(enclosing_bg_polygon({c.footprint, 0.0}, {0.1}));
  for (const PolygonObstacle& p : set.polygons) parts.push_back(p.footprint);
  BgMultiPolygon acc;
  for (const BgPolygon& p : parts) {
    BgMultiPolygon next;
    bg::union_(acc, p, next);
    acc = std::move(next);
  }
  return bg::area(acc);
}

void raster_info(ChartInfo& info, GDALDataset& ds, const ChartInfoOptions& o) {
  BathymetryOptions read;
  read.assumed_crs = o.source_crs;
  const BathymetryInfo b = inspect_bathymetry(info.path, read);
  info.crs = b.crs;
  info.extent = b.extent;
  info.min_depth_m = b.min_depth_m;
  info.max_depth_m = b.max_depth_m;
  info.raster_width = b.width;
  info.raster_height = b.height;
  info.cell_x_m = b.pixel_x;
  info.cell_y_m = b.pixel_y;
  info.valid_fraction = b.valid_fraction;
  info.has_nodata = b.has_nodata;
  info.nodata = b.nodata;
  info.vertical_sense = std::string(to_string(b.sense_used)) + " (" + b.sense_reason + ")";
  for (int i = 1; i <= ds.GetRasterCount(); ++i) {
    GDALRasterBand* band = ds.GetRasterBand(i);
    const std::string desc = band->GetDescription();
    info.layers.push_back(
        {"band " + std::to_string(i), static_cast<std::size_t>(b.width) * b.height,
         (desc.empty() ? std::string() : printable(desc) + ", ") + GDALGetDataTypeName(band->GetRasterDataType())});
  }
  const LocalFrame frame = frame_for(info.extent, o);
  info.local_crs = frame.id();
  OGRSpatialReference srs;
  if (srs.importFromWkt(b.crs_wkt.c_str()) == OGRERR_NONE && srs.IsProjected() && info.local_crs == b.crs) {
    // The raster's own frame: its exact size, not the box around its lon/lat box.
    info.width_m = std::abs(b.pixel_x) * b.width * srs.GetLinearUnits();
    info.height_m = std::abs(b.pixel_y) * b.height * srs.GetLinearUnits();
  } else {
    local_size(info, frame);
  }
  if (!std::isnan(o.depth_m)) {
    NoGoOptions n;
    n.operating_depth_m = o.depth_m;
    n.vertical_clearance_m = o.clearance_m;
    n.bathymetry = read;
    const NoGoArea area = compute_no_go(info.path, frame, n);
    NoGoSummary s;
    s.depth_m = o.depth_m;
    s.clearance_m = o.clearance_m;
    s.area_m2 = area.area_m2;
    s.polygons = area.polygons.size();
    s.no_go_cells = area.no_go_cells;
    s.total_cells = area.total_cells;
    info.no_go = s;
  }
}

// One cell, a folder of cells or an exchange set (every cell read together,
// as the planners read them: the no-go is the set's, the better scale winning).
void s57_info(ChartInfo& info, const ChartInfoOptions& o) {
  // GDAL applies a cell's updates up to the first one missing and says
  // nothing: a broken sequence is refused here as where the cells are planned on.
  const std::vector<EncCellFiles> files = find_enc_cells({info.path});
  const bool several = files.size() > 1 || fs::is_directory(info.path) || is_enc_catalogue_name(info.path);
  info.crs = "EPSG:4326";  // S-57 positions are WGS 84 lon/lat by the standard
  auto lo = [](double a, double b) { return std::isnan(a) ? b : std::isnan(b) ? a : std::min(a, b); };
  auto hi = [](double a, double b) { return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b); };
  std::map<std::string, std::size_t> layers;
  std::vector<S57Summary> sums;
  for (const EncCellFiles& f : files) {
    S57Summary sum = summarize_s57(f.base);
    for (const auto& [name, n] : sum.layer_counts) layers[name] += n;
    for (const auto& [zoc, n] : sum.zoc_areas) info.zoc_areas[zoc] += n;
    info.min_depth_m = lo(info.min_depth_m, lo(sum.depare_min_m, sum.sounding_min_m));
    info.max_depth_m = hi(info.max_depth_m, hi(sum.depare_max_m, sum.sounding_max_m));
    info.extent = {lo(info.extent.west, sum.extent.west), hi(info.extent.east, sum.extent.east),
                   lo(info.extent.south, sum.extent.south), hi(info.extent.north, sum.extent.north)};
    sums.push_back(std::move(sum));
  }
  for (const auto& [name, n] : layers) info.layers.push_back({name, n, ""});
  S57Options so;
  so.local_crs = o.local_crs;
  const LocalFrame frame = several ? frame_for(info.extent, o) : s57_local_frame(sums.front(), so);
  info.local_crs = frame.id();
  local_size(info, frame);
  // Hazards and land as the cells hold them (s57_chart.hpp's classes), counted from the summaries.
  for (const S57Summary& sum : sums) {
    for (const char* cls : {"OBSTRN", "WRECKS", "UWTROC", "LNDARE"}) {
      const auto n = sum.layer_counts.find(cls);
      if (n == sum.layer_counts.end()) continue;
      (std::string(cls) == "LNDARE" ? info.land_features : info.hazards) += n->second;
    }
  }
  std::optional<EncNoGo> no_go;
  if (!std::isnan(o.depth_m)) {
    no_go = enc_no_go({info.path}, frame, enc_options(o.chart, o.depth_m, o.clearance_m));
  }
  if (several) {
    if (no_go) {
      for (const EncCellSummary& c : no_go->cells) {
        info.cells.push_back({c.path, c.name, c.usage_band, c.compilation_scale, c.edition, c.update_number, ""});
      }
    } else {
      for (std::size_t i = 0; i < files.size(); ++i) {
        const EncCellFiles& f = files[i];
        info.cells.push_back({f.base, fs::path(f.base).stem().string(), sums[i].usage_band, sums[i].compilation_scale,
                              sums[i].edition, sums[i].update_number, ""});
      }
      // Best scale first, as the no-go decides overlaps (enc_no_go.hpp).
      std::stable_sort(info.cells.begin(), info.cells.end(), [](const ChartCell& a, const ChartCell& b) {
        return decides_before(a.compilation_scale, a.usage_band, a.name, b.compilation_scale, b.usage_band, b.name);
      });
    }
    for (ChartCell& c : info.cells) {
      for (const EncCellFiles& f : files) {
        if (f.base == c.path) c.catalogue = f.catalogue;
      }
    }
  }
  if (no_go) {
    NoGoSummary s;
    s.depth_m = o.depth_m;
    s.clearance_m = o.clearance_m;
    // Inside the coverage: the ring of unknown water round it is the planners' fence, not chart.
    BgMultiPolygon areas;
    for (const EncNoGoFeature& f : no_go->features) {
      if (f.cls == "M_COVR") continue;
      for (const BgPolygon& p : f.area) areas.push_back(p);
      if (f.point) {
        Ellipse disc;
        disc.centre = *f.point;
        disc.a = disc.b = f.radius_m;
        areas.push_back(enclosing_bg_polygon({disc, 0.0}, {0.1}));
      }
    }
    s.area_m2 = 0.0;
    std::vector<const BgPolygon*> parts;
    for (const BgPolygon& p : areas) parts.push_back(&p);
    for (const BgPolygon& p : union_no_go({}, parts)) s.area_m2 += boost::geometry::area(p);
    s.polygons = no_go->obstacles.polygons.size();
    s.vertices = no_go->vertices;
    s.no_go_by_class = no_go->no_go_by_class;
    for (const auto& [cls, n] : no_go->passable_by_class) s.hazards_passable += n;
    info.no_go = s;
  }
}

void vector_info(ChartInfo& info, GDALDataset& ds, const ChartInfoOptions& o) {
  for (OGRLayer* layer : ds.GetLayers()) {
    info.layers.push_back({layer->GetName(), static_cast<std::size_t>(std::max<GIntBig>(0, layer->GetFeatureCount())),
                           OGRGeometryTypeToName(layer->GetGeomType())});
  }
  ObstacleReadOptions read{o.local_crs, o.source_crs};
  if (ds.GetLayerByName("deepguide_chart") != nullptr) {
    // A prepared chart (prepared_chart.hpp): its obstacles are what the
    // planners take; the other layers name the no-go and are not hazards.
    read.layers = {"obstacles"};
    read.repair_polygons = true;
  }
  LoadedObstacles loaded = load_obstacles({info.path}, read);
  const ObstacleSummary sum = summarize(loaded);
  info.crs = loaded.sources.empty() ? std::string() : loaded.sources.front().crs;
  info.local_crs = loaded.frame.id();
  if (sum.has_extent) {
    info.extent = {sum.west, sum.east, sum.south, sum.north};
    info.width_m = sum.max_x - sum.min_x;
    info.height_m = sum.max_y - sum.min_y;
  }
  info.hazards = loaded.obstacles.size();
  auto top = [&](const std::optional<double>& t) {
    if (!t) return;
    info.min_depth_m = std::isnan(info.min_depth_m) ? *t : std::min(info.min_depth_m, *t);
    info.max_depth_m = std::isnan(info.max_depth_m) ? *t : std::max(info.max_depth_m, *t);
  };
  for (const auto& c : loaded.obstacles.ellipses) top(c.top_depth_m);
  for (const auto& p : loaded.obstacles.polygons) top(p.top_depth_m);
  if (!std::isnan(o.depth_m)) {
    ObstacleSet left = loaded.obstacles;
    NoGoSummary s;
    s.depth_m = o.depth_m;
    s.clearance_m = o.clearance_m;
    s.hazards_passable = remove_passable(left, o.depth_m, o.clearance_m);
    s.area_m2 = union_area(left);
    s.polygons = left.size();
    info.no_go = s;
  }
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

}  // namespace

const char* to_string(ChartKind kind) {
  switch (kind) {
    case ChartKind::raster: return "bathymetry raster";
    case ChartKind::s57: return "S-57 cell";
    case ChartKind::vector: return "hazard file";
  }
  return "?";
}

namespace {

// Opens `path` as any raster or vector dataset, with the messages chart_kind promises.
GDALDatasetUniquePtr open_chart(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing chart file, found none");
  if (fs::is_directory(path, ec)) throw InputError(path + ": expected a chart file, got a folder");
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  // A *.000 file is an S-57 base cell, read by the S57 driver alone: a
  // damaged cell must not be taken up by another driver as another format
  // (the soak fed GDAL's OpenJUMP driver a cell with XML in it, and it leaked).
  const char* const s57_only[] = {"S57", nullptr};
  const bool cell_name = ascii_lower(fs::path(path).extension().string()) == ".000";
  // The cell and its updates are checked before GDAL reads them: GDAL applies
  // a damaged update half-way (and leaks doing it).
  // An update alone (*.001 ..) is refused there too, naming its base cell.
  if (names_enc(path)) (void)find_enc_cells({path});
  GDALDatasetUniquePtr ds =
      gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_VECTOR | GDAL_OF_READONLY, cell_name ? s57_only : nullptr);
  if (!ds) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(path +
                     (cell_name ? ": expected an S-57 ENC cell GDAL's S57 driver can read, got "
                                : ": expected a chart GDAL can open (raster, S-57 cell or vector file), got ") +
                     (why.empty() ? std::string("a file no driver recognises") : printable(why, 160)));
  }
  return ds;
}

ChartKind kind_of(GDALDataset& ds, const std::string& path) {
  const std::string driver = ds.GetDriver() != nullptr ? ds.GetDriver()->GetDescription() : "";
  if (driver == "S57") return ChartKind::s57;
  if (ds.GetRasterCount() > 0) return ChartKind::raster;
  if (ds.GetLayerCount() > 0) return ChartKind::vector;
  throw InputError(path + ": expected a chart (raster bands or vector layers), got a " + driver + " file with neither");
}

}  // namespace

ChartKind chart_kind(const std::string& path) {
  GDALDatasetUniquePtr ds = open_chart(path);
  return kind_of(*ds, path);
}

ChartInfo chart_info(const std::string& path, const ChartInfoOptions& options) {
  check_options(options);
  ChartInfo info;
  info.path = path;
  std::error_code ec;
  if (fs::is_directory(path, ec) || is_enc_catalogue_name(path)) {
    // A folder of S-57 cells or an exchange set: its cells read together.
    info.kind = ChartKind::s57;
    info.driver = "S57";
    s57_info(info, options);
    return info;
  }
  GDALDatasetUniquePtr ds = open_chart(path);
  info.driver = ds->GetDriver() != nullptr ? ds->GetDriver()->GetDescription() : "";
  info.kind = kind_of(*ds, path);
  switch (info.kind) {
    case ChartKind::s57:
      ds.reset();
      s57_info(info, options);
      break;
    case ChartKind::raster: raster_info(info, *ds, options); break;
    case ChartKind::vector: vector_info(info, *ds, options); break;
  }
  return info;
}

nlohmann::json to_json(const ChartInfo& info) {
  nlohmann::json j;
  j["path"] = info.path;
  j["kind"] = to_string(info.kind);
  j["driver"] = info.driver;
  j["crs"] = info.crs;
  j["local_crs"] = info.local_crs;
  nlohmann::json layers = nlohmann::json::array();
  for (const ChartLayer& l : info.layers)
    layers.push_back({{"name", l.name}, {"features", l.features}, {"detail", l.detail}});
  j["layers"] = layers;
  j["extent"] = {{"west", number_or_null(info.extent.west)},
                 {"east", number_or_null(info.extent.east)},
                 {"south", number_or_null(info.extent.south)},
                 {"north", number_or_null(info.extent.north)}};
  j["width_m"] = info.width_m;
  j["height_m"] = info.height_m;
  j["min_depth_m"] = number_or_null(info.min_depth_m);
  j["max_depth_m"] = number_or_null(info.max_depth_m);
  j["hazards"] = info.hazards;
  if (info.kind == ChartKind::s57) {
    j["land_features"] = info.land_features;
    j["zones_of_confidence"] = info.zoc_areas;
    if (!info.cells.empty()) {
      nlohmann::json cells = nlohmann::json::array();
      for (const ChartCell& c : info.cells) {
        cells.push_back({{"name", c.name},
                         {"path", c.path},
                         {"usage_band", c.usage_band},
                         {"compilation_scale", c.compilation_scale},
                         {"edition", c.edition},
                         {"update", c.update_number},
                         {"catalogue", c.catalogue.empty() ? nlohmann::json() : nlohmann::json(c.catalogue)}});
      }
      j["cells"] = cells;
    }
  }
  if (info.kind == ChartKind::raster) {
    j["raster"] = {{"width", info.raster_width},
                   {"height", info.raster_height},
                   {"cell_x", info.cell_x_m},
                   {"cell_y", info.cell_y_m},
                   {"valid_fraction", info.valid_fraction},
                   {"nodata", info.has_nodata ? number_or_null(info.nodata) : nlohmann::json()},
                   {"vertical_sense", info.vertical_sense}};
  }
  if (info.no_go) {
    const NoGoSummary& n = *info.no_go;
    nlohmann::json g = {
        {"depth_m", n.depth_m}, {"clearance_m", n.clearance_m}, {"area_m2", n.area_m2}, {"polygons", n.polygons}};
    if (info.kind == ChartKind::raster) {
      g["no_go_cells"] = n.no_go_cells;
      g["total_cells"] = n.total_cells;
    } else {
      g["hazards_passable"] = n.hazards_passable;
    }
    if (info.kind == ChartKind::s57) {
      g["no_go_by_class"] = n.no_go_by_class;
      g["planner_vertices"] = n.vertices;
    }
    j["no_go"] = g;
  }
  return j;
}

namespace {

std::string range(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return "-";
  return printf_text("%.2f .. %.2f m", lo, hi);
}

}  // namespace

std::string to_text(const ChartInfo& c) {
  std::string t;
  t += printf_text("%s  [%s, %s, %s]\n", c.path.c_str(), c.cells.empty() ? to_string(c.kind) : "S-57 cells",
                   c.driver.c_str(), c.crs.c_str());
  for (const ChartCell& cell : c.cells) {
    t += printf_text("  cell           %-9s", cell.name.c_str());
    if (cell.compilation_scale > 0) t += printf_text(" band %d, 1:%ld,", cell.usage_band, cell.compilation_scale);
    t += printf_text(" edition %s, update %d%s\n", cell.edition.c_str(), cell.update_number,
                     cell.catalogue.empty() ? "" : " (from its catalogue, CRC checked)");
  }
  for (const ChartLayer& l : c.layers) {
    t += printf_text("  layer          %-14s %zu %s%s%s\n", l.name.c_str(), l.features,
                     c.kind == ChartKind::raster ? "cells" : "feature(s)", l.detail.empty() ? "" : ", ",
                     l.detail.c_str());
  }
  if (std::isfinite(c.extent.west)) {
    t += printf_text("extent           lon %.6f .. %.6f, lat %.6f .. %.6f\n", c.extent.west, c.extent.east,
                     c.extent.south, c.extent.north);
    t += printf_text("                 %.1f m x %.1f m (east x north, %s)\n", c.width_m, c.height_m,
                     c.local_crs.c_str());
  }
  if (c.kind == ChartKind::raster) {
    t += printf_text("raster           %d x %d cells of %g x %g, %.1f %% valid", c.raster_width, c.raster_height,
                     c.cell_x_m, std::abs(c.cell_y_m), 100.0 * c.valid_fraction);
    if (c.has_nodata) t += printf_text(", NoData %g", c.nodata);
    t += printf_text("\nvertical         %s\n", c.vertical_sense.c_str());
  }
  t += printf_text("depth range      %s%s\n", range(c.min_depth_m, c.max_depth_m).c_str(),
                   c.kind == ChartKind::vector ? " (hazard tops)" : "");
  t += printf_text("hazards          %zu", c.hazards);
  if (c.kind == ChartKind::s57) t += printf_text(" (+ %zu land area feature(s))", c.land_features);
  t += "\n";
  if (c.kind == ChartKind::s57) {
    t += printf_text("zones of conf.   ");
    if (c.zoc_areas.empty()) t += printf_text("none (M_QUAL absent: depths and positions taken as unassessed)");
    const char* sep = "";
    for (const auto& [zoc, n] : c.zoc_areas) {
      t += printf_text("%sCATZOC %s: %zu area(s)", sep, zoc.c_str(), n);
      sep = ", ";
    }
    t += "\n";
  }
  if (c.no_go) {
    const NoGoSummary& n = *c.no_go;
    t += printf_text("no-go at %g m    %.0f m2 (clearance %g m), %zu polygon(s)", n.depth_m, n.area_m2, n.clearance_m,
                     n.polygons);
    if (c.kind == ChartKind::raster) {
      t += printf_text(
          ", %zu of %zu cells (%.1f %%)", n.no_go_cells, n.total_cells,
          n.total_cells > 0 ? 100.0 * static_cast<double>(n.no_go_cells) / static_cast<double>(n.total_cells) : 0.0);
    } else {
      t += printf_text(", %zu %s passed over", n.hazards_passable,
                       c.kind == ChartKind::s57 ? "feature(s)" : "hazard(s)");
    }
    t += "\n";
    if (!n.no_go_by_class.empty()) {
      t += printf_text("no-go by class   ");
      const char* sep = "";
      for (const auto& [cls, k] : n.no_go_by_class) {
        t += printf_text("%s%s %zu", sep, cls.c_str(), k);
        sep = ", ";
      }
      t += printf_text(" (%zu polygon corners for the planners)\n", n.vertices);
    }
  }
  return t;
}

}  // namespace deepguide
