#include "deepguide/render/chart_web_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/render/obstacle_web_layers.hpp"
#include "deepguide/render/raster_web_image.hpp"
#include "deepguide/render/reactive_map.hpp"  // ellipse_outline

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

json metres(double v) { return std::round(v * 100.0) / 100.0; }

// Point hazards by kind: rocks, wrecks, obstructions, piles and structures.
const char* hazard_fill(const std::string& cls) {
  if (cls == "UWTROC") return "#5f3dc4";
  if (cls == "WRECKS") return "#d9480f";
  if (cls == "OBSTRN") return "#c2255c";
  return "#495057";
}

json feature_properties(const EncNoGoFeature& f) {
  json props{{"record", f.id}, {"cell", f.cell}, {"class", f.cls}, {"why", f.reason}};
  if (std::isfinite(f.charted_depth_m)) props["charted depth (m)"] = metres(f.charted_depth_m);
  if (std::isfinite(f.least_depth_m)) props["least depth (m)"] = metres(f.least_depth_m);
  if (f.point) props["radius (m)"] = metres(f.radius_m);
  return props;
}

}  // namespace

WebMapLayer enc_no_go_layer(const EncNoGo& enc, double operating_depth_m) {
  const WebMapGeometry to{&enc.frame};
  WebMapLayer layer =
      web_map_layer("no_go", "No-go at " + general(operating_depth_m) + " m, by feature (click for why)", "#c92a2a",
                    "#e03131", 0.18, 1.0);
  layer.explained = true;
  layer.hatched = true;  // as ECDIS and paper charts mark what a vessel must keep out of
  layer.fill_opacity = 0.6;
  for (const EncNoGoFeature& f : enc.features) {
    if (f.point) {
      layer.features.push_back(web_map_feature(to.disc(*f.point, f.radius_m), feature_properties(f)));
    } else if (!f.area.empty()) {
      layer.features.push_back(web_map_feature(to.multipolygon(f.area), feature_properties(f)));
    }
  }
  return layer;
}

WebMap chart_web_map(const EncNoGo& enc, double operating_depth_m, const std::string& title) {
  const WebMapGeometry to{&enc.frame};
  WebMap map;
  map.title = title;
  map.subtitle = std::to_string(enc.cells.size()) + " cell(s), no-go shallower than " + general(enc.required_depth_m) +
                 " m (depth " + general(operating_depth_m) + " m and its clearance), frame " + enc.frame.id();

  WebMapLayer cells = web_map_layer("cells", "Cells (where each decides)", "#343a40", "#343a40", 0.0, 1.5);
  cells.dash = "8 4";
  for (const EncChartArea& a : enc.cell_areas) {
    json props{{"cell", a.cell}};
    const auto it =
        std::find_if(enc.cells.begin(), enc.cells.end(), [&](const EncCellSummary& c) { return c.name == a.cell; });
    if (it != enc.cells.end()) {
      props["usage band"] = it->usage_band;
      props["scale"] = "1:" + std::to_string(it->compilation_scale);
      props["edition"] = it->edition;
      props["update"] = it->update_number;
    }
    cells.features.push_back(web_map_feature(to.multipolygon(a.area), std::move(props)));
  }

  WebMapLayer depths = web_map_layer("depth_areas", "Depth areas (shaded by DRVAL1)", "#74a9cf", "#8cc2e6", 0.9, 0.5);
  for (const EncChartArea& a : enc.depth_areas) {
    json props{{"record", a.id}, {"cell", a.cell}};
    if (std::isfinite(a.depth_m)) props["DRVAL1 (m)"] = metres(a.depth_m);
    json style{{"fillColor", std::isfinite(a.depth_m) ? depth_band_fill(a.depth_m) : "#d9d9d9"}};
    depths.features.push_back(web_map_feature(to.multipolygon(a.area), std::move(props), std::move(style)));
  }

  WebMapLayer land = web_map_layer("land", "Land", "#a68a5b", "#f1e3c6", 1.0, 0.8);
  WebMapLayer hazards =
      web_map_layer("hazards", "Hazards (rocks, wrecks, obstructions, piles)", "#212529", "#495057", 0.9, 1.0);
  hazards.point_radius_px = 4.0;
  WebMapLayer soundings =
      web_map_layer("soundings", "Soundings that are no-go (from zoom 12 in)", "#1864ab", "#1864ab", 0.9, 0.5);
  soundings.point_radius_px = 2.0;
  soundings.min_zoom = 12.0;  // a sounding every few pixels: from about 1:150,000 in
  for (const EncNoGoFeature& f : enc.features) {
    if (f.cls == "LNDARE") {  // areas, and the points of islets and rocks that show
      land.features.push_back(
          web_map_feature(f.point ? to.point(*f.point) : to.multipolygon(f.area), feature_properties(f)));
    } else if (f.point && f.cls == "SOUNDG") {
      soundings.features.push_back(web_map_feature(to.point(*f.point), feature_properties(f)));
    } else if (f.point) {
      hazards.features.push_back(
          web_map_feature(to.point(*f.point), feature_properties(f), json{{"fillColor", hazard_fill(f.cls)}}));
    }
  }

  WebMapLayer zones =
      web_map_layer("zones_of_confidence", "Zones of confidence (CATZOC)", "#2b8a3e", "#2b8a3e", 0.05, 1.0);
  zones.dash = "3 3";
  zones.shown = false;
  static constexpr std::array<const char*, 7> kLetters{"none", "A1", "A2", "B", "C", "D", "U"};
  for (const EncChartArea& z : enc.zones) {
    json props{{"zone", z.id}, {"cell", z.cell}};
    props["CATZOC"] = z.catzoc >= 1 && z.catzoc <= 6 ? kLetters[static_cast<std::size_t>(z.catzoc)] : "none";
    zones.features.push_back(web_map_feature(to.multipolygon(z.area), std::move(props)));
  }

  map.layers = {std::move(depths),  std::move(land),      enc_no_go_layer(enc, operating_depth_m),
                std::move(hazards), std::move(soundings), std::move(zones),
                std::move(cells)};
  if (!enc.cell_areas.empty()) {  // the frame's grid over the cells
    Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
    for (const EncChartArea& a : enc.cell_areas) {
      for (const BgPolygon& p : a.area) {
        for (const auto& v : p.outer()) lo = lo.cwiseMin(Vec2(v.x(), v.y())), hi = hi.cwiseMax(Vec2(v.x(), v.y()));
      }
    }
    map.layers.push_back(frame_grid_layer(enc.frame, lo, hi));
  }
  map.table.title = "Cells, best scale first";
  map.table.columns = {"cell", "usage band", "scale", "edition", "update"};
  for (const EncCellSummary& c : enc.cells) {
    map.table.rows.push_back(
        {c.name, c.usage_band, "1:" + std::to_string(c.compilation_scale), c.edition, c.update_number});
  }
  return map;
}

void write_chart_web_map(const ChartRenderOptions& options, const std::string& path) {
  check_web_map_path(path, "--html");
  if (std::isnan(options.depth_m)) throw InputError("--html: expected --depth (the web map shows the no-go at it)");
  if (!std::isfinite(options.depth_m) || options.depth_m < 0.0) {
    throw InputError("--depth: expected an operating depth >= 0 m, got " + general(options.depth_m));
  }
  if (!std::isfinite(options.clearance_m) || options.clearance_m < 0.0) {
    throw InputError("--vertical-clearance: expected a clearance >= 0 m, got " + general(options.clearance_m));
  }
  std::vector<std::string> enc, others, rasters;
  for (const std::string& chart : options.charts) {
    if (reads_as_enc(chart)) {
      enc.push_back(chart);
    } else {
      others.push_back(chart);
      if (chart_kind(chart) == ChartKind::raster) rasters.push_back(chart);
    }
  }
  const LocalFrame frame = charts_frame(options.charts, options.local_crs, options.source_crs);
  std::string title = options.title;
  if (title.empty()) {
    for (const std::string& chart : options.charts) {
      title += (title.empty() ? "" : ", ") + std::filesystem::path(chart).filename().string();
    }
    title += " at " + general(options.depth_m) + " m";
  }
  WebMap map;
  if (!enc.empty()) {
    map =
        chart_web_map(chart_no_go(enc, frame, enc_options(options.chart_options, options.depth_m, options.clearance_m)),
                      options.depth_m, title);
  } else {
    map.title = title;
    map.subtitle = "no-go shallower than " + general(options.depth_m + options.clearance_m) + " m, frame " + frame.id();
  }
  // Rasters: their depth shading under the layers; rasters and hazard files: their no-go at the depth.
  for (const std::string& raster : rasters) map.images.push_back(raster_depth_image(raster, options.source_crs));
  if (!others.empty()) {
    ChartObstacleOptions read;
    read.depth_m = options.depth_m;
    read.clearance_m = options.clearance_m;
    read.source_crs = options.source_crs;
    const ChartObstacles charted = chart_obstacles(others, frame, read);
    const WebMapGeometry to{&frame};
    WebMapLayer layer = web_map_layer(
        "raster_no_go", "No-go at " + general(options.depth_m) + " m from rasters and hazard files (click for which)",
        "#c92a2a", "#e03131", 0.6, 1.0);
    layer.explained = true;
    layer.hatched = true;
    for (const PolygonObstacle& p : charted.obstacles.polygons) {
      layer.features.push_back(web_map_feature(to.polygon(p.footprint), {{"no-go", p.id}}));
    }
    for (const EllipticCylinder& e : charted.obstacles.ellipses) {
      layer.features.push_back(web_map_feature(to.outline(ellipse_outline(e.footprint, 72)), {{"hazard", e.id}}));
    }
    map.layers.push_back(std::move(layer));
  }
  write_web_map(map, path);
}

}  // namespace deepguide
