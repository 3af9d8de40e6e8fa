#include "deepguide/charts/s57_chart.hpp"

#include <ogrsf_frmts.h>

#include <algorithm>
#include <boost/geometry/algorithms/correct.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_reader.hpp"
#include "deepguide/charts/s57_unknown_objects.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/plausible_depth.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

// Opens `path` with the S57 driver only, the update handling set per dataset
// (open option UPDATES), never through a process-wide config option. The
// caller keeps a QuietErrors alive while it reads, and calls check_read().
GDALDatasetUniquePtr open_cell(const std::string& path, bool apply_updates) {
  gdal::ensure_registered();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing S-57 cell (*.000), found none");
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": expected an S-57 cell file (*.000), got a folder");
  const char* drivers[] = {"S57", nullptr};
  const char* open_options[] = {apply_updates ? "UPDATES=APPLY" : "UPDATES=IGNORE", nullptr};
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, open_options);
  if (!ds) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(path + ": expected an S-57 ENC cell GDAL's S57 driver can read" +
                     (why.empty() ? std::string(", got a file it does not recognise") : ", got: " + why));
  }
  refuse_unknown_object_classes(*ds, path);
  return ds;
}

// GDAL reports some damage only while features are read.
void check_read(const std::string& path) {
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty()) {
    throw InputError(path + ": expected a complete S-57 cell, got: " + why);
  }
}

void grow(LonLatExtent& e, const OGREnvelope& env) {
  auto lo = [](double a, double b) { return std::isnan(a) ? b : std::min(a, b); };
  auto hi = [](double a, double b) { return std::isnan(a) ? b : std::max(a, b); };
  e.west = lo(e.west, env.MinX);
  e.east = hi(e.east, env.MaxX);
  e.south = lo(e.south, env.MinY);
  e.north = hi(e.north, env.MaxY);
}

std::optional<double> real_field(const OGRFeature& f, const char* name) {
  const int i = f.GetFieldIndex(name);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return std::nullopt;
  const double v = f.GetFieldAsDouble(i);
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

std::string string_field(const OGRFeature& f, const char* name) {
  const int i = f.GetFieldIndex(name);
  return i >= 0 && f.IsFieldSetAndNotNull(i) ? f.GetFieldAsString(i) : std::string();
}

void min_max(double& lo, double& hi, double v) {
  lo = std::isnan(lo) ? v : std::min(lo, v);
  hi = std::isnan(hi) ? v : std::max(hi, v);
}

}  // namespace

S57Summary summarize_s57(const std::string& path, bool apply_updates) {
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr ds = open_cell(path, apply_updates);
  S57Summary s;
  bool has_coverage = false;
  LonLatExtent all;
  for (OGRLayer* layer : ds->GetLayers()) {
    const std::string name = layer->GetName();
    std::size_t count = 0;
    for (auto& f : *layer) {
      ++count;
      const OGRGeometry* g = f->GetGeometryRef();
      OGREnvelope env;
      if (g != nullptr && !g->IsEmpty()) {
        g->getEnvelope(&env);
        grow(all, env);
      }
      if (name == "DSID") {
        s.edition = string_field(*f, "DSID_EDTN");
        s.update_number = std::atoi(string_field(*f, "DSID_UPDN").c_str());
        s.issue_date = string_field(*f, "DSID_ISDT");
        s.usage_band = std::atoi(string_field(*f, "DSID_INTU").c_str());
        s.compilation_scale = std::atol(string_field(*f, "DSPM_CSCL").c_str());
      } else if (name == "M_COVR" && g != nullptr && !g->IsEmpty()) {
        grow(s.extent, env);
        has_coverage = true;
      } else if (name == "M_QUAL") {
        const std::string zoc = string_field(*f, "CATZOC");
        static const char* const letters[] = {"A1", "A2", "B", "C", "D", "U"};
        const int k = std::atoi(zoc.c_str());
        ++s.zoc_areas[k >= 1 && k <= 6 ? letters[k - 1] : "unknown"];
      } else if (name == "DEPARE") {
        const std::string where = path + ": " + name + "/" + string_field(*f, "RCID");
        for (const char* field : {"DRVAL1", "DRVAL2"}) {
          if (const auto d = real_field(*f, field)) {
            require_plausible_depth(*d, where + " " + field);
            min_max(s.depare_min_m, s.depare_max_m, *d);
          }
        }
      } else if (name == "SOUNDG" && g != nullptr) {
        // Without SPLIT_MULTIPOINT a SOUNDG feature is a 3-D multipoint whose
        // z is the sounding's depth (m, positive down).
        auto add = [&](const OGRPoint& p) {
          ++s.soundings;
          require_plausible_depth(p.getZ(), path + ": " + name + "/" + string_field(*f, "RCID") + " (a sounding)");
          min_max(s.sounding_min_m, s.sounding_max_m, p.getZ());
        };
        if (wkbFlatten(g->getGeometryType()) == wkbMultiPoint) {
          for (const OGRPoint* p : *g->toMultiPoint()) add(*p);
        } else if (wkbFlatten(g->getGeometryType()) == wkbPoint) {
          add(*g->toPoint());
        }
      }
    }
    s.layer_counts[name] = count;
  }
  check_read(path);
  if (!has_coverage) s.extent = all;
  if (std::isnan(s.extent.west)) throw InputError(path + ": expected an S-57 cell with features, got none");
  return s;
}

LocalFrame s57_local_frame(const S57Summary& summary, const S57Options& options) {
  if (options.local_crs.empty()) return default_frame_for(summary.extent);
  LocalFrame frame = LocalFrame::from_user_crs(options.local_crs, "`local_crs`");
  require_true_scale(frame, summary.extent, "the cell");
  return frame;
}

S57Hazards s57_hazards(const std::string& path, const LocalFrame& frame, const S57Options& options) {
  if (!std::isfinite(options.point_hazard_radius_m) || options.point_hazard_radius_m <= 0.0) {
    throw InputError("point hazard radius: expected a radius > 0 m, got " + general(options.point_hazard_radius_m));
  }
  // The one S-57 reader the charts' no-go uses too (enc_reader.hpp); the
  // rules here are the obstacle file's (the header's decisions).
  static const char* const kClasses[] = {"OBSTRN", "WRECKS", "UWTROC", "LNDARE"};
  EncReadRequest request;
  request.classes = {std::begin(kClasses), std::end(kClasses)};
  request.apply_updates = options.apply_updates;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing S-57 cell (*.000), found none");
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": expected an S-57 cell file (*.000), got a folder");
  const EncCells read = read_enc_cells(find_enc_cells({path}), frame, request);
  const EncCell& cell = read.cells.front();
  S57Hazards out;
  for (const char* cls : kClasses) {
    const auto counted = cell.layer_counts.find(cls);
    out.features_read[cls] = counted == cell.layer_counts.end() ? 0 : counted->second;
    std::size_t with_geometry = 0;
    for (const EncFeature& f : cell.features) {
      if (f.cls != cls) continue;
      ++with_geometry;
      const std::string id = f.cls + "/" + std::to_string(f.rcid);
      auto part_id = [&](std::size_t k) { return k == 0 ? id : id + "#" + std::to_string(k + 1); };
      std::optional<double> top;
      if (f.cls != "LNDARE" && !std::isnan(f.valsou)) top = std::max(f.valsou, 0.0);  // < 0: dries
      for (std::size_t k = 0; k < f.points.size(); ++k) {
        EllipticCylinder c;
        c.id = part_id(k);
        c.footprint.centre = f.points[k];
        c.footprint.a = c.footprint.b = options.point_hazard_radius_m;
        c.footprint.theta = 0.0;
        c.top_depth_m = top;
        out.obstacles.ellipses.push_back(std::move(c));
      }
      for (std::size_t k = 0; k < f.areas.size(); ++k) {
        PolygonObstacle p;
        p.id = part_id(k);
        p.top_depth_m = top;
        p.footprint = f.areas[k];
        out.obstacles.polygons.push_back(std::move(p));
      }
      if (!f.lines.empty()) ++out.skipped_lines;
    }
    // A feature without any geometry is not among the reader's features.
    out.skipped_empty += out.features_read[cls] - std::min(out.features_read[cls], with_geometry);
  }
  if (!std::isnan(options.operating_depth_m)) {
    out.removed_by_depth = remove_passable(out.obstacles, options.operating_depth_m, options.vertical_clearance_m);
  }
  return out;
}

}  // namespace deepguide
