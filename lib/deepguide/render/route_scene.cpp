#include "deepguide/render/route_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "deepguide/render/plot_furniture.hpp"  // add_arrow, draw_figure_title

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;

// Design units (at 1200 px wide); multiplied by RouteLayout::unit.
constexpr double kSide = 24.0;       // left/right margin
constexpr double kTitleBand = 52.0;  // title band height
constexpr double kFooter = 100.0;    // footer height
constexpr double kScaleBarMax = 250.0;
constexpr double kLegendX = 330.0;  // legend left edge, from the image's left

bool finite(const Vec2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

void require_finite(const Vec2& p, const char* what) {
  if (!finite(p)) throw InputError(std::string("route chart: expected finite coordinates for the ") + what);
}

/// Bounding box of an ellipse grown by d on every side (the zone's box).
WorldBox ellipse_box(const Ellipse& e, double d) {
  const double c = std::cos(e.theta);
  const double s = std::sin(e.theta);
  const double hx = std::hypot(e.a * c, e.b * s) + d;
  const double hy = std::hypot(e.a * s, e.b * c) + d;
  WorldBox box;
  box.extend(e.centre - Vec2(hx, hy));
  box.extend(e.centre + Vec2(hx, hy));
  return box;
}

template <class Ring>
void extend_ring(WorldBox& box, const Ring& ring, const char* what) {
  for (const BgPoint& p : ring) {
    const Vec2 v = to_eigen(p);
    require_finite(v, what);
    box.extend(v);
  }
}

WorldBox content_box(const RouteScene& scene) {
  const double d = std::max(0.0, scene.margin);
  WorldBox box;
  if (scene.obstacles != nullptr) {
    for (const EllipticCylinder& c : scene.obstacles->ellipses) {
      const Ellipse& e = c.footprint;
      if (!finite(e.centre) || !std::isfinite(e.a) || !std::isfinite(e.b) || !std::isfinite(e.theta) || !(e.a > 0.0) ||
          !(e.b > 0.0)) {
        throw InputError("route chart: obstacle '" + c.id + "': expected a finite ellipse with positive axes");
      }
      box.extend(ellipse_box(e, d));
    }
    for (const PolygonObstacle& p : scene.obstacles->polygons) {
      WorldBox pb;
      extend_ring(pb, p.footprint.outer(), "polygon obstacle");
      box.extend(pb.padded(d));
    }
  }
  if (scene.zone_polygons != nullptr) {
    for (const BgPolygon& p : *scene.zone_polygons) extend_ring(box, p.outer(), "zone polygons");
  }
  for (const auto& [a, b] : scene.graph_edges) {
    require_finite(a, "graph edges");
    require_finite(b, "graph edges");
    box.extend(a);
    box.extend(b);
  }
  if (scene.detected != nullptr) {
    for (const EllipticCylinder& c : scene.detected->ellipses) box.extend(ellipse_box(c.footprint, d));
    for (const PolygonObstacle& p : scene.detected->polygons) {
      WorldBox pb;
      extend_ring(pb, p.footprint.outer(), "detected obstacle");
      box.extend(pb.padded(d));
    }
  }
  for (const auto* line : {&scene.route, &scene.track}) {
    for (const Vec2& p : *line) {
      require_finite(p, "route");
      box.extend(p);
    }
  }
  for (const auto& line : scene.repaired_routes) {
    for (const Vec2& p : line) {
      require_finite(p, "repaired route");
      box.extend(p);
    }
  }
  if (scene.start) {
    require_finite(*scene.start, "start");
    box.extend(*scene.start);
  }
  if (scene.goal) {
    require_finite(*scene.goal, "goal");
    box.extend(*scene.goal);
  }
  return box;
}

// ---------------------------------------------------------------- drawing

struct Painter {
  Canvas& canvas;
  const RouteScene& scene;
  const RouteLayout& layout;
  const RouteStyle& style = scene.style;
  double u = layout.unit;

  Vec2 px(const Vec2& w) const { return layout.view.to_pixel(w); }

  template <class Ring>
  std::vector<Vec2> ring_px(const Ring& ring) const {
    std::vector<Vec2> out;
    out.reserve(ring.size());
    for (const BgPoint& p : ring) out.push_back(px(to_eigen(p)));
    return out;
  }

  std::vector<std::vector<Vec2>> polygon_px(const BgPolygon& p) const {
    std::vector<std::vector<Vec2>> rings{ring_px(p.outer())};
    for (const auto& inner : p.inners()) rings.push_back(ring_px(inner));
    return rings;
  }

  /// Enough samples that chords stay within a fraction of a pixel.
  int samples(double radius_m) const {
    const double perimeter_px = 2.0 * kPi * radius_m * layout.view.scale();
    return std::clamp(static_cast<int>(std::ceil(perimeter_px / 3.0)), 72, 2048);
  }

  std::vector<Vec2> ellipse_px(const Ellipse& e) const {
    const int n = samples(e.a);
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) out.push_back(px(e.point_at(2.0 * kPi * i / n)));
    return out;
  }

  /// The exact boundary of the ellipse's safety zone: the offset curve
  /// p(t) + d n(t), which is not an ellipse.
  std::vector<Vec2> offset_px(const Ellipse& e, double d) const {
    const int n = samples(e.a + d);
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * kPi * i / n;
      out.push_back(px(e.point_at(t) + d * e.normal_at(t)));
    }
    return out;
  }

  Stroke zone_stroke() const { return {style.safety_zone, 1.5 * u, {7.0 * u, 4.0 * u}}; }
  Rgba zone_fill() const { return {style.safety_zone.r, style.safety_zone.g, style.safety_zone.b, 0.10}; }
  Stroke zone_polygon_stroke() const { return {style.zone_polygon, 1.0 * u, {}}; }
  Stroke graph_stroke() const { return {style.graph_edge, std::max(1.0, 0.8 * u), {}, false}; }
  Stroke route_stroke() const { return {style.route, 3.2 * u, {}}; }
  Rgba track_band() const { return {style.track.r, style.track.g, style.track.b, 0.35}; }

  void start_marker(const Vec2& c) const {
    canvas.circle(c, 8.0 * u, style.start, Stroke{style.background, 2.0 * u, {}});
  }
  void goal_marker(const Vec2& c) const {
    const double r = 10.0 * u;
    canvas.shape({c + Vec2(0, -r), c + Vec2(r, 0), c + Vec2(0, r), c + Vec2(-r, 0)}, style.goal,
                 Stroke{style.background, 2.0 * u, {}});
  }
  void waypoint(const Vec2& c) const { canvas.circle(c, 3.2 * u, style.background, Stroke{style.route, 1.6 * u, {}}); }

  // ------------------------------------------------------------ map

  void map() {
    canvas.fill_rect(layout.map, style.sea);
    canvas.clip(layout.map);
    if (scene.current) current_arrows();
    const double d = scene.margin;
    const ObstacleSet* obs = scene.obstacles;

    // Safety zones: a light fill first, so the graph and outlines stay on top.
    std::vector<std::vector<Vec2>> ellipse_zones;
    std::vector<std::vector<std::vector<Vec2>>> polygon_zones;
    if (obs != nullptr && d > 0.0) {
      for (const EllipticCylinder& c : obs->ellipses) ellipse_zones.push_back(offset_px(c.footprint, d));
      // A polygon's zone, polygon (+) disc(d), as Boost.Geometry's round
      // buffer within a third of a pixel of the exact curve.
      const ZoneOptions zone{d, std::max(0.3 / layout.view.scale(), 1e-6)};
      for (const PolygonObstacle& p : obs->polygons) {
        for (const BgPolygon& part : polygon_zone(p.footprint, zone)) polygon_zones.push_back(polygon_px(part));
      }
    }
    for (const auto& ring : ellipse_zones) canvas.fill_rings({ring}, zone_fill());
    for (const auto& rings : polygon_zones) canvas.fill_rings(rings, zone_fill());

    if (!scene.free_cells.empty() || !scene.occupied_cells.empty()) cells();
    if (!scene.graph_edges.empty()) {
      std::vector<std::pair<Vec2, Vec2>> edges;
      edges.reserve(scene.graph_edges.size());
      for (const auto& [a, b] : scene.graph_edges) edges.emplace_back(px(a), px(b));
      canvas.stroke_segments(edges, graph_stroke());
    }
    if (scene.zone_polygons != nullptr) {
      for (const BgPolygon& p : *scene.zone_polygons) {
        for (const auto& ring : polygon_px(p)) canvas.stroke_polyline(ring, zone_polygon_stroke(), true);
      }
    }
    for (const auto& ring : ellipse_zones) canvas.stroke_polyline(ring, zone_stroke(), true);
    for (const auto& rings : polygon_zones) {
      for (const auto& ring : rings) canvas.stroke_polyline(ring, zone_stroke(), true);
    }

    if (obs != nullptr) {
      for (const EllipticCylinder& c : obs->ellipses) canvas.fill_rings({ellipse_px(c.footprint)}, style.obstacle);
      for (const PolygonObstacle& p : obs->polygons) canvas.fill_rings(polygon_px(p.footprint), style.obstacle);
    }

    if (scene.detected != nullptr) detected_obstacles(*scene.detected);
    // The track sailed as a broad, light band under the routes (a highlighter).
    if (scene.track.size() >= 2) {
      std::vector<Vec2> line;
      for (const Vec2& p : scene.track) line.push_back(px(p));
      canvas.stroke_polyline(line, Stroke{track_band(), 9.0 * u, {}});
    }
    for (const auto& repaired : scene.repaired_routes) {
      std::vector<Vec2> line;
      for (const Vec2& p : repaired) line.push_back(px(p));
      canvas.stroke_polyline(line, Stroke{style.repaired, 2.2 * u, {6.0 * u, 4.0 * u}});
    }
    if (scene.route.size() >= 2) {
      std::vector<Vec2> line;
      line.reserve(scene.route.size());
      for (const Vec2& p : scene.route) line.push_back(px(p));
      // A white casing keeps the route readable over the graph.
      canvas.stroke_polyline(line, Stroke{style.background, 6.0 * u, {}});
      canvas.stroke_polyline(line, route_stroke());
      for (std::size_t i = 1; i + 1 < line.size(); ++i) waypoint(line[i]);
      leg_labels(line);
    }
    if (obs != nullptr && scene.label_obstacles) labels(*obs);
    if (scene.detected != nullptr && scene.label_obstacles) labels(*scene.detected);
    if (scene.start) start_marker(px(*scene.start));
    if (scene.goal) goal_marker(px(*scene.goal));
    canvas.unclip();
    canvas.stroke_rect(layout.map, Stroke{style.frame, 1.0 * u, {}});
  }

  /// Obstacles the sonar reported: zone and footprint in their own colour.
  void detected_obstacles(const ObstacleSet& set) {
    const Rgba fill{style.detected.r, style.detected.g, style.detected.b, 0.12};
    const Stroke outline{style.detected, 1.5 * u, {7.0 * u, 4.0 * u}};
    const double d = scene.margin;
    const ZoneOptions zone{d, std::max(0.3 / layout.view.scale(), 1e-6)};
    for (const EllipticCylinder& c : set.ellipses) {
      if (d > 0.0) {
        const std::vector<Vec2> ring = offset_px(c.footprint, d);
        canvas.fill_rings({ring}, fill);
        canvas.stroke_polyline(ring, outline, true);
      }
      canvas.fill_rings({ellipse_px(c.footprint)}, style.detected);
    }
    for (const PolygonObstacle& p : set.polygons) {
      if (d > 0.0) {
        for (const BgPolygon& part : polygon_zone(p.footprint, zone)) {
          const auto rings = polygon_px(part);
          canvas.fill_rings(rings, fill);
          for (const auto& ring : rings) canvas.stroke_polyline(ring, outline, true);
        }
      }
      canvas.fill_rings(polygon_px(p.footprint), style.detected);
    }
  }

  /// Quadtree cells: occupied ones shaded, every one outlined (hairlines).
  void cells() {
    const auto corners = [&](const std::pair<Vec2, Vec2>& c) {
      return std::vector<Vec2>{px(c.first), px(Vec2(c.second.x(), c.first.y())), px(c.second),
                               px(Vec2(c.first.x(), c.second.y()))};
    };
    for (const auto& c : scene.occupied_cells) canvas.fill_rings({corners(c)}, style.occupied_cell);
    std::vector<std::pair<Vec2, Vec2>> lines;
    for (const auto* list : {&scene.free_cells, &scene.occupied_cells}) {
      for (const auto& c : *list) {
        const std::vector<Vec2> q = corners(c);
        for (int k = 0; k < 4; ++k) lines.emplace_back(q[k], q[(k + 1) % 4]);
      }
    }
    canvas.stroke_segments(lines, Stroke{style.cell, std::max(0.6, 0.5 * u), {}, false});
  }

  /// The current on a lattice over the map, sampled at the lattice points
  /// world positions; arrow length = spacing x speed / fastest.
  void current_arrows() {
    const double spacing = 55.0 * u;
    std::vector<std::pair<Vec2, Vec2>> samples;  // pixel centre, current
    double fastest = 0.0;
    for (double y = layout.map.y + spacing / 2.0; y < layout.map.y + layout.map.height; y += spacing) {
      for (double x = layout.map.x + spacing / 2.0; x < layout.map.x + layout.map.width; x += spacing) {
        const std::optional<Vec2> c = scene.current(layout.view.to_world(Vec2(x, y)));
        if (!c || !c->allFinite() || c->norm() == 0.0) continue;
        samples.emplace_back(Vec2(x, y), *c);
        fastest = std::max(fastest, c->norm());
      }
    }
    std::vector<std::pair<Vec2, Vec2>> arrows;
    for (const auto& [at, c] : samples) {
      add_arrow(arrows, at, c.normalized(), std::max(0.15, c.norm() / fastest) * 0.8 * spacing);
    }
    canvas.stroke_segments(arrows, Stroke{style.current, 1.3 * u, {}});
  }

  /// Each leg's label along its middle, on the left of the direction of travel.
  void leg_labels(const std::vector<Vec2>& line) {
    const double size = 11.5 * u;
    for (std::size_t i = 0; i + 1 < line.size() && i < scene.leg_labels.size(); ++i) {
      const Vec2 a = line[i], b = line[i + 1];
      const double len = (b - a).norm();
      const double w = canvas.text_width(scene.leg_labels[i], size);
      if (len < w + 20.0 * u) continue;        // too short on the map to carry it
      Vec2 normal(-(b - a).y(), (b - a).x());  // pixel rows grow downwards: this is to the right...
      normal = -normal / len;                  // ...so flip it to the left of travel
      const Vec2 mid = 0.5 * (a + b) + 12.0 * u * normal;
      const TextAlign align = normal.x() < -0.3  ? TextAlign::right
                              : normal.x() > 0.3 ? TextAlign::left
                                                 : TextAlign::centre;
      canvas.text_with_halo(mid + Vec2(0.0, 4.0 * u), scene.leg_labels[i], size, style.route, style.sea, 2.5 * u,
                            align);
    }
  }

  /// Each obstacle's id to the right of its zone, as error messages name them.
  void labels(const ObstacleSet& obs) {
    const double d = std::max(0.0, scene.margin);
    auto label = [&](const std::string& id, const WorldBox& zone) {
      const Vec2 at = px(Vec2(zone.max.x(), zone.centre().y()));
      canvas.text_with_halo(at + Vec2(5.0 * u, 4.5 * u), id, 12.5 * u, style.text, style.sea, 2.5 * u);
    };
    for (const EllipticCylinder& c : obs.ellipses) label(c.id, ellipse_box(c.footprint, d));
    for (const PolygonObstacle& p : obs.polygons) {
      WorldBox box;
      for (const BgPoint& q : p.footprint.outer()) box.extend(to_eigen(q));
      label(p.id, box.padded(d));
    }
  }

  // ------------------------------------------------------------ title, footer

  void title() {
    const std::string text = scene.title.empty() ? std::string("deepguide route") : scene.title;
    draw_figure_title(canvas, text, layout.width, u, style.text, 22.0, 35.0);
  }

  FurnitureColors furniture() const { return {style.text, style.background, style.frame}; }

  void scale_bar() {
    draw_scale_bar(canvas, layout.view.scale(), kSide * u, layout.footer.y + 44.0 * u, kScaleBarMax * u, u,
                   furniture());
  }

  enum class Swatch {
    obstacle,
    zone,
    zone_polygon,
    graph,
    route,
    start,
    goal,
    current,
    cell,
    detected,
    repaired,
    track
  };

  void swatch(Swatch kind, double x, double y) {
    const double sw = 30.0 * u;
    const Vec2 mid(x + sw / 2.0, y);
    const auto small_box = [&](const Rgba& fill) {
      canvas.fill_rings(
          {{{x + 4 * u, y - 6 * u}, {x + sw - 4 * u, y - 6 * u}, {x + sw - 4 * u, y + 6 * u}, {x + 4 * u, y + 6 * u}}},
          fill);
    };
    switch (kind) {
      case Swatch::obstacle: small_box(style.obstacle); break;
      case Swatch::zone: {
        const std::vector<Vec2> box{{x, y - 8 * u}, {x + sw, y - 8 * u}, {x + sw, y + 8 * u}, {x, y + 8 * u}};
        canvas.fill_rings({box}, zone_fill());
        canvas.stroke_polyline(box, Stroke{style.safety_zone, 1.5 * u, {5.0 * u, 3.0 * u}}, true);
        break;
      }
      case Swatch::zone_polygon:
        canvas.stroke_polyline({{x, y}, {x + sw, y}}, Stroke{style.zone_polygon, 1.6 * u, {}});
        break;
      case Swatch::graph: canvas.stroke_polyline({{x, y}, {x + sw, y}}, Stroke{style.graph_edge, 1.6 * u, {}}); break;
      case Swatch::route:
        canvas.stroke_polyline({{x, y}, {x + sw, y}}, route_stroke());
        waypoint(mid);
        break;
      case Swatch::start: start_marker(mid); break;
      case Swatch::goal: goal_marker(mid); break;
      case Swatch::detected: small_box(style.detected); break;
      case Swatch::repaired:
        canvas.stroke_polyline({{x, y}, {x + sw, y}}, Stroke{style.repaired, 2.2 * u, {6.0 * u, 4.0 * u}});
        break;
      case Swatch::track: canvas.stroke_polyline({{x, y}, {x + sw, y}}, Stroke{track_band(), 9.0 * u, {}}); break;
      case Swatch::cell: {
        const std::vector<Vec2> box{
            {x + 4 * u, y - 7 * u}, {x + sw - 4 * u, y - 7 * u}, {x + sw - 4 * u, y + 7 * u}, {x + 4 * u, y + 7 * u}};
        canvas.fill_rings({box}, style.occupied_cell);
        canvas.stroke_polyline(box, Stroke{style.cell, 1.0 * u, {}}, true);
        break;
      }
      case Swatch::current: {
        std::vector<std::pair<Vec2, Vec2>> arrow;
        add_arrow(arrow, mid, Vec2(1.0, 0.0), sw);
        canvas.stroke_segments(arrow, Stroke{style.current, 1.3 * u, {}});
        break;
      }
    }
  }

  /// Two rows; each column is one group (obstacles, planner, route, ends),
  /// as wide as its longest label.
  void legend() {
    struct Entry {
      Swatch kind;
      std::string label;
    };
    std::vector<std::vector<Entry>> columns(5);
    const bool has_obstacles = scene.obstacles != nullptr && !scene.obstacles->empty();
    if (has_obstacles) columns[0].push_back({Swatch::obstacle, "obstacle"});
    if (has_obstacles && scene.margin > 0.0) {
      columns[0].push_back({Swatch::zone, "safety zone (" + general(scene.margin) + " m)"});
    }
    if (scene.zone_polygons != nullptr) columns[1].push_back({Swatch::zone_polygon, "zone polygon"});
    if (!scene.graph_edges.empty()) columns[1].push_back({Swatch::graph, "graph edge"});
    if (!scene.occupied_cells.empty()) columns[1].push_back({Swatch::cell, "occupied cell"});
    if (scene.route.size() >= 2) columns[2].push_back({Swatch::route, "route, waypoints"});
    if (scene.current) {
      columns[2].push_back({Swatch::current, scene.current_label.empty() ? "current" : scene.current_label});
    }
    if (scene.detected != nullptr && !scene.detected->empty()) {
      columns[4].push_back({Swatch::detected, "reported by the sonar"});
    }
    if (!scene.repaired_routes.empty()) columns[4].push_back({Swatch::repaired, "repaired route"});
    if (scene.track.size() >= 2) columns[2].push_back({Swatch::track, "track sailed"});
    if (scene.start) columns[3].push_back({Swatch::start, "start"});
    if (scene.goal) columns[3].push_back({Swatch::goal, "goal"});

    const double size = 14.5 * u;
    double x = kLegendX * u;
    for (const auto& column : columns) {
      if (column.empty()) continue;
      double widest = 0.0;
      for (std::size_t row = 0; row < column.size(); ++row) {
        const double y = layout.footer.y + (30.0 + 30.0 * static_cast<double>(row)) * u;  // row centre
        swatch(column[row].kind, x, y);
        canvas.text({x + 38.0 * u, y + 5.0 * u}, column[row].label, size, style.text);
        widest = std::max(widest, canvas.text_width(column[row].label, size));
      }
      x += 38.0 * u + widest + 26.0 * u;
    }
  }

  /// North is up: the map's y axis is the local frame's northing, so this is
  /// GRID north. True north differs from it by the meridian convergence (about
  /// a degree in most of a UTM zone), noted below the arrow when known.
  void north_arrow() {
    std::string note = "grid north";
    if (scene.true_north_deg) {
      char buf[64];
      const double t = *scene.true_north_deg;
      std::snprintf(buf, sizeof buf, "true N %.1f\u00b0 %s", std::abs(t), t < 0.0 ? "W" : "E");
      note = std::string("grid N; ") + buf;
    }
    draw_north_arrow(canvas, layout.width - kSide * u - 42.0 * u, layout.footer.y + 24.0 * u, u, 0.0, note,
                     layout.width - kSide * u, furniture());
  }
};

}  // namespace

RouteLayout route_layout(const RouteScene& scene, int width_px) {
  if (width_px < kMinImageWidth || width_px > kMaxImageWidth) {
    throw InputError("image width: expected " + std::to_string(kMinImageWidth) + " to " +
                     std::to_string(kMaxImageWidth) + " pixels, got " + std::to_string(width_px));
  }
  if (!std::isfinite(scene.margin)) throw InputError("route chart: expected a finite margin");
  const WorldBox content = content_box(scene);
  if (content.empty()) {
    throw InputError("route chart: expected something to draw (obstacles, a route, a start or a goal)");
  }
  const double span = std::max(content.width(), content.height());
  RouteLayout l;
  l.extent = content.padded(span > 0.0 ? 0.05 * span : 10.0);
  l.width = width_px;
  l.unit = width_px / 1200.0;
  const double u = l.unit;
  l.map.x = kSide * u;
  l.map.y = kTitleBand * u;
  l.map.width = width_px - 2.0 * kSide * u;
  // The map takes the content's aspect ratio, within limits; the view then
  // centres the content along the looser axis.
  const double aspect = std::clamp(l.extent.height() / l.extent.width(), 0.45, 1.5);
  l.map.height = std::round(l.map.width * aspect);
  l.footer = {0.0, l.map.y + l.map.height, static_cast<double>(width_px), kFooter * u};
  l.height = static_cast<int>(std::ceil(l.footer.y + l.footer.height));
  l.view = ViewTransform(l.extent, l.map);
  return l;
}

void render_route(const RouteScene& scene, const std::string& path, int width_px) {
  image_format_for(path);  // the extension first: the cheapest mistake to report
  RouteLayout layout;
  try {
    layout = route_layout(scene, width_px);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  Canvas canvas(path, layout.width, layout.height);
  canvas.fill_rect({0.0, 0.0, static_cast<double>(layout.width), static_cast<double>(layout.height)},
                   scene.style.background);
  Painter painter{canvas, scene, layout};
  painter.map();
  painter.title();
  painter.scale_bar();
  painter.legend();
  painter.north_arrow();
  canvas.finish();
}

double true_north_deg(const LocalFrame& frame, const Vec2& at) {
  // Clockwise angle from the map's up (grid north) to true north.
  return 90.0 - frame.true_north_angle(at) * 180.0 / std::numbers::pi;
}

std::string route_title(const std::string& name, const Route& route, double margin, const LocalFrame& frame) {
  char buf[160];
  std::snprintf(buf, sizeof buf, ": %.1f m, %zu waypoints, margin %g m  (%s)", route.length(), route.points.size(),
                margin, frame.id().c_str());
  return name + buf;
}

}  // namespace deepguide
