#include "deepguide/charts/no_go_export.hpp"

#include <chrono>
#include <optional>

#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"

namespace deepguide {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void from_cells(const NoGoExportRequest& r, NoGoExportReport& out) {
  EncNoGoOptions opts = enc_options(r.chart, r.nogo.operating_depth_m, r.nogo.vertical_clearance_m);
  opts.simplify_tolerance_m = r.nogo.simplify_tolerance_m;
  const auto t0 = std::chrono::steady_clock::now();
  const EncNoGo no_go = enc_no_go(
      r.charts, r.crs.empty() ? std::nullopt : std::optional<LocalFrame>(LocalFrame::from_user_crs(r.crs)), opts);
  out.seconds = seconds_since(t0);
  write_obstacles(r.output, no_go.obstacles, no_go.frame);
  out.from_cells = true;
  out.local_crs = no_go.frame.id();
  out.local_crs_name = no_go.frame.name();
  out.cells = no_go.cells;
  out.required_depth_m = no_go.required_depth_m;
  out.no_go_by_class = no_go.no_go_by_class;
  out.passable_by_class = no_go.passable_by_class;
  out.zoc_areas = no_go.zoc_areas;
  out.polygons = no_go.obstacles.polygons.size();
  out.discs = no_go.obstacles.ellipses.size();
  out.vertices = no_go.vertices;
}

void from_raster(const NoGoExportRequest& r, NoGoExportReport& out) {
  const std::string& raster = r.charts.front();
  NoGoOptions opts = r.nogo;
  opts.nodata_is_no_go = r.nodata_is_no_go;
  opts.bathymetry.assumed_crs = r.src_crs;
  opts.bathymetry.sense = r.sense;
  const LocalFrame frame =
      r.crs.empty() ? raster_local_frame(raster, opts.bathymetry) : LocalFrame::from_user_crs(r.crs);
  const auto t0 = std::chrono::steady_clock::now();
  NoGoArea area = compute_no_go(raster, frame, opts);
  out.seconds = seconds_since(t0);
  ObstacleSet set;
  set.polygons = std::move(area.polygons);
  write_obstacles(r.output, set, frame);
  area.polygons.clear();
  out.local_crs = frame.id();
  out.local_crs_name = frame.name();
  out.polygons = set.polygons.size();
  out.area = std::move(area);
}

}  // namespace

NoGoExportReport export_no_go(const NoGoExportRequest& request) {
  obstacle_format_for(request.output);  // a bad extension before the work
  NoGoExportReport out;
  out.request = request;
  if (request.charts.empty()) throw InputError("charts: expected a bathymetry raster or S-57 cells");
  if (names_enc(request.charts.front()) || request.charts.size() > 1) {
    from_cells(request, out);
  } else {
    from_raster(request, out);
  }
  return out;
}

nlohmann::json NoGoExportReport::to_json() const {
  if (from_cells) {
    nlohmann::json list = nlohmann::json::array();
    for (const EncCellSummary& c : cells) {
      list.push_back({{"path", c.path},
                      {"name", c.name},
                      {"scale", c.compilation_scale},
                      {"usage_band", c.usage_band},
                      {"edition", c.edition},
                      {"updates", c.update_number}});
    }
    return {{"cells", list},
            {"output", request.output},
            {"local_crs", local_crs},
            {"required_depth_m", required_depth_m},
            {"no_go_by_class", no_go_by_class},
            {"passable_by_class", passable_by_class},
            {"zones_of_confidence", zoc_areas},
            {"zoc", to_string(request.chart.zoc)},
            {"restricted_areas", request.chart.restricted_areas},
            {"polygons", polygons},
            {"discs", discs},
            {"vertices", vertices},
            {"seconds", seconds}};
  }
  return {{"raster", request.charts.front()},
          {"output", request.output},
          {"local_crs", local_crs},
          {"operating_depth_m", request.nogo.operating_depth_m},
          {"vertical_clearance_m", request.nogo.vertical_clearance_m},
          {"simplify_tolerance_m", request.nogo.simplify_tolerance_m},
          {"width", area.raster.width},
          {"height", area.raster.height},
          {"total_cells", area.total_cells},
          {"no_go_cells", area.no_go_cells},
          {"cell_area_m2", area.cell_area_m2},
          {"polygons", polygons},
          {"area_m2", area.area_m2},
          {"vertices_before_simplify", area.vertices_before_simplify},
          {"vertices_after_simplify", area.vertices_after_simplify},
          {"seconds", seconds}};
}

std::string NoGoExportReport::to_text() const {
  const NoGoOptions& o = request.nogo;
  std::string text;
  if (from_cells) {
    for (const EncCellSummary& c : cells) {
      text += report_line("cell", c.name + "  1:" + std::to_string(c.compilation_scale) + ", band " +
                                      std::to_string(c.usage_band) + ", edition " + c.edition + ", update " +
                                      std::to_string(c.update_number));
    }
    text += report_line("local frame", local_crs + " (" + local_crs_name + ")");
    text += report_line("rule", "charted depth less its zone of confidence < " + fixed(o.operating_depth_m, 2) +
                                    " m (operating) + " + fixed(o.vertical_clearance_m, 2) + " m (clearance)" +
                                    (request.chart.zones_of_confidence() ? "" : " (zones ignored)"));
    std::string classes;
    for (const auto& [cls, n] : no_go_by_class)
      classes += (classes.empty() ? "" : ", ") + cls + " " + std::to_string(n);
    text += report_line("no-go", classes);
    text += report_line("planners", std::to_string(polygons) + " polygon(s) with " + std::to_string(vertices) +
                                        " corners, " + std::to_string(discs) + " disc(s) (tolerance " +
                                        fixed(o.simplify_tolerance_m, 2) + " m, outward only)");
  } else {
    const BathymetryInfo& r = area.raster;
    text += report_line("raster", request.charts.front() + "  [" + r.driver + ", " + r.crs + "] " +
                                      std::to_string(r.width) + " x " + std::to_string(r.height) + " cells");
    text += report_line("local frame", local_crs + " (" + local_crs_name + ")");
    text +=
        report_line("rule", "depth < " + fixed(o.operating_depth_m, 2) + " m (operating) + " +
                                fixed(o.vertical_clearance_m, 2) + " m (clearance), land, " +
                                (request.nodata_is_no_go ? "and cells without data" : "cells without data are water"));
    const double pct = area.total_cells > 0
                           ? 100.0 * static_cast<double>(area.no_go_cells) / static_cast<double>(area.total_cells)
                           : 0.0;
    text += report_line("no-go cells", std::to_string(area.no_go_cells) + " of " + std::to_string(area.total_cells) +
                                           " (" + fixed(pct, 1) + "%), " + fixed(area.cell_area_m2, 1) + " m2 each");
    text += report_line("polygons", std::to_string(polygons) + ", area " + fixed(area.area_m2, 1) + " m2");
    text +=
        report_line("vertices", std::to_string(area.vertices_before_simplify) + " before, " +
                                    std::to_string(area.vertices_after_simplify) + " after simplification (tolerance " +
                                    fixed(o.simplify_tolerance_m, 2) + " m, outward only)");
  }
  text += report_line("time", fixed(seconds, 2) + " s");
  text += report_line("wrote", request.output);
  return text;
}

}  // namespace deepguide
