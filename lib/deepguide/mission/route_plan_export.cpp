#include "deepguide/mission/route_plan_export.hpp"

#include <filesystem>

#include "deepguide/mission/route_export.hpp"

namespace deepguide {

void write_route_plan(const RoutePlanReport& report, const std::string& path) {
  const ExportFormat format = route_file_format(path);
  const RoutePlanRequest& r = report.request;
  for (std::size_t k = 0; report.replay && k < report.replay->repairs.size(); ++k) {
    if (report.repair_files[k].empty()) continue;
    const Repair& repair = report.replay->repairs[k];
    RouteExportSettings settings;
    settings.name = std::filesystem::path(report.repair_files[k]).stem().string();
    settings.margin_m = r.margin_m;
    ExportRoute exported = export_route(Route{repair.route}, report.frame, report.vehicle, settings);
    exported.properties = {{"repair", k + 1}, {"along_m", repair.along_m}, {"length_m", repair.cost}};
    write_route_file(exported, report.repair_files[k], format, {.overwrite = true});
  }
  RouteExportSettings settings;
  settings.name = std::filesystem::path(path).stem().string();
  settings.depth_m = std::isnan(r.depth_m) ? 0.0 : r.depth_m;
  for (const PricedLeg& leg : report.priced.legs) {
    settings.leg_speeds_mps.push_back(leg.cost.speed_mps);
    if (report.priced.feasible) settings.leg_times_s.push_back(leg.cost.time_s);
  }
  settings.margin_m = r.margin_m;
  settings.turn_radius_m = report.options.turn_radius_m;
  if (!std::isnan(r.depth_m)) settings.safety_depth_m = r.depth_m + r.vertical_clearance_m;
  if (report.timed) settings.depart_utc_s = report.model->depart_s;
  ExportRoute exported = export_route(report.route, report.frame, report.vehicle, settings);
  exported.properties = report.route_properties();
  exported.waypoint_properties = report.waypoint_properties();
  write_route_file(exported, path, format, {.overwrite = true});
}

}  // namespace deepguide
