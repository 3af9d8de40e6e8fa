// deepguide.plan: what `deepguide plan` does, from Python. The frame, the
// obstacles and the ends are read by the same library calls as the CLI's
// (load_obstacles, parse_position), the route by plan_route_request, so a
// route here has the CLI's length bit for bit; to_dict() is its --json.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "charts.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/route_plan_report.hpp"
#include "deepguide/render/route_plan_figure.hpp"
#include "deepguide/render/route_web_map.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

// A position as the CLI reads it: the same text, so the same double.
std::string position_text(const std::pair<double, double>& p) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g,%.17g", p.first, p.second);
  return text;
}

using EllipseRow = std::array<double, 5>;

// Rows (x, y, semi_major_m, semi_minor_m, orientation_deg), read while the
// GIL is held.
std::vector<EllipseRow> ellipse_rows(const py::array& array) {
  const auto rows = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!rows || rows.ndim() != 2 || rows.shape(1) != 5) {
    throw InputError(
        "`ellipses`: expected an array of shape (n, 5): x, y, semi_major_m, semi_minor_m, orientation_deg");
  }
  std::vector<EllipseRow> out(static_cast<std::size_t>(rows.shape(0)));
  const auto r = rows.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    for (py::ssize_t k = 0; k < 5; ++k) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = r(i, k);
  }
  return out;
}

using Rings = std::vector<std::vector<Vec2>>;

// Polygons as lists of rings ((k, 2) arrays, the outline first; or one
// array: an outline alone), read while the GIL is held.
std::vector<Rings> polygon_rings(const py::list& polygons) {
  std::vector<Rings> out;
  const auto ring_of = [](const py::handle& h, std::size_t i) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
    if (!a || a.ndim() != 2 || a.shape(1) != 2) {
      throw InputError("`polygons` item " + std::to_string(i) + ": expected rings as (k, 2) arrays of x, y");
    }
    std::vector<Vec2> ring;
    const auto r = a.unchecked<2>();
    for (py::ssize_t k = 0; k < r.shape(0); ++k) ring.emplace_back(r(k, 0), r(k, 1));
    return ring;
  };
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const py::handle item = polygons[i];
    Rings rings;
    if (py::isinstance<py::list>(item) || py::isinstance<py::tuple>(item)) {
      for (const py::handle ring : item) rings.push_back(ring_of(ring, i));
    } else {
      rings.push_back(ring_of(item, i));
    }
    out.push_back(std::move(rings));
  }
  return out;
}

// The polygons as obstacles, checked as a file's are (add_polygon_obstacle).
void add_polygons(const std::vector<Rings>& polygons, ObstacleSet& into) {
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    PolygonObstacle p;
    p.id = "polygons[" + std::to_string(i) + "]";
    for (std::size_t k = 0; k < polygons[i].size(); ++k) {
      auto& ring = k == 0 ? p.footprint.outer() : p.footprint.inners().emplace_back();
      for (const Vec2& v : polygons[i][k]) ring.push_back(to_bg(v));
      if (!ring.empty() && !(ring.front().x() == ring.back().x() && ring.front().y() == ring.back().y())) {
        ring.push_back(ring.front());  // closed, as a file's rings are
      }
    }
    add_polygon_obstacle(std::move(p), false, {"`polygons`", "polygon " + std::to_string(i), ""}, into);
  }
}

// The rows as obstacles: centres in the frame's CRS, axes and orientation as an obstacle file gives them.
std::vector<EllipticCylinder> ellipses_in(const LocalFrame& frame, const std::vector<EllipseRow>& rows) {
  std::vector<EllipticCylinder> out;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& [x, y, a, b, heading] = rows[i];
    if (!std::isfinite(x) || !std::isfinite(y)) {
      throw InputError("`ellipses` row " + std::to_string(i) + ": expected a finite x and y, got " + std::to_string(x) +
                       ", " + std::to_string(y));
    }
    EllipticCylinder e;
    e.id = "ellipses[" + std::to_string(i) + "]";
    const Vec2 centre(x, y);
    e.footprint = ellipse_from_fields(frame, centre, frame.to_lonlat(centre), a, b, heading);
    out.push_back(std::move(e));
  }
  return out;
}

// A planned route: the report the CLI prints, with the frame it is in.
struct Route {
  std::shared_ptr<const RoutePlanReport> report;
  LocalFrame frame;

  py::array_t<double> xy() const {
    const auto& pts = report->route.points;
    py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < pts.size(); ++i) o(i, 0) = pts[i].x(), o(i, 1) = pts[i].y();
    return out;
  }
  py::array_t<double> lonlat() const {
    const auto& pts = report->route.points;
    py::array_t<double> out({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Vec2 ll = frame.to_lonlat(pts[i]);
      o(i, 0) = ll.x(), o(i, 1) = ll.y();
    }
    return out;
  }
  // The obstacles' footprints (a chart's no-go polygons among them) in
  // lon/lat: per obstacle a list of rings, the outline first, then its holes.
  py::list outlines() const { return lonlat_outlines(report->obstacles, frame); }
  py::object to_dict() const { return from_json(report->to_json().dump()); }
  std::string repr() const {
    char text[200];
    std::snprintf(text, sizeof text, "Route(length_m=%.2f, waypoints=%zu, graph='%s', crs='%s')",
                  report->route.length(), report->route.points.size(), to_string(report->options.graph).c_str(),
                  frame.id().c_str());
    return text;
  }
};

struct PlanArgs {
  std::pair<double, double> start, goal;
  std::vector<std::string> obstacles, charts;
  std::optional<Chart> chart;  ///< charts read once (read_chart), instead of `charts`
  std::optional<py::array> ellipses;
  std::optional<py::list> polygons;
  std::string crs, src_crs;
  std::optional<std::string> graph;
  std::string search, cost;
  double margin = 5.0, tolerance = 0.0;
  std::optional<double> depth, turn_radius, vertical_clearance;
  std::optional<std::string> zoc;
  std::optional<bool> restricted_areas;
  std::optional<std::tuple<double, double, double>> unassessed_zoc;
  bool escape = false;
  std::string vehicle, speed, current;
  std::shared_ptr<const CurrentField> current_field;  ///< a field read once (read_current), instead of `current`
  std::size_t max_expansions = 0;
  std::optional<double> start_heading, goal_heading;  // deg, clockwise from true north
  std::string current_const, depart;
};

// A chart read once fixes what the request would read it with; a keyword
// that asks otherwise is a mistake to say, not to ignore.
void take_chart(const Chart& c, const PlanArgs& a, RoutePlanRequest& r) {
  const auto differs = [](const char* keyword, const std::string& asked, const std::string& read) {
    return InputError(std::string(keyword) + ": " + asked + ", but the chart was read with " + read +
                      "; read it again with read_chart(...) to plan so");
  };
  const std::string depth = std::isnan(c.depth_m) ? "no depth" : general(c.depth_m) + " m";
  if (a.depth && !(*a.depth == c.depth_m)) throw differs("`depth`", general(*a.depth) + " m", depth);
  if (a.vertical_clearance && *a.vertical_clearance != c.clearance_m) {
    throw differs("`vertical_clearance`", general(*a.vertical_clearance) + " m", general(c.clearance_m) + " m");
  }
  if (!a.src_crs.empty() && a.src_crs != c.src_crs) throw differs("`src_crs`", a.src_crs, "'" + c.src_crs + "'");
  ChartOptions asked = c.options;
  if (a.zoc) asked.zoc = parse_zoc_policy(*a.zoc).value_or(c.options.zoc);
  if (a.restricted_areas) asked.restricted_areas = *a.restricted_areas;
  if (a.unassessed_zoc) {
    asked.unassessed = {std::get<0>(*a.unassessed_zoc), std::get<1>(*a.unassessed_zoc), std::get<2>(*a.unassessed_zoc)};
  }
  if (const std::string d = chart_options_difference(c.options, asked); !d.empty()) {
    throw InputError("`zoc`, `restricted_areas`, `unassessed_zoc`: the chart was read with " + d +
                     "; read it again with read_chart(...) to plan so");
  }
  r.charted = c.charted ? c.charted : throw InputError(c.unread);
  r.charts = c.paths;
  r.depth_m = c.depth_m;
  r.vertical_clearance_m = c.clearance_m;
  r.src_crs = c.src_crs;
  r.chart = c.options;
}

Route plan(const PlanArgs& a) {
  if (a.obstacles.empty() && a.charts.empty() && !a.chart && !a.ellipses && !a.polygons) {
    throw InputError("`obstacles`: expected obstacle files, `charts`, `ellipses` or `polygons` (or several of them)");
  }
  if ((a.ellipses || a.polygons) && a.crs.empty() && !a.chart) {
    throw InputError("`crs`: expected the CRS the `ellipses` and `polygons` arrays are in, e.g. 'EPSG:32632'");
  }
  if (a.zoc && !parse_zoc_policy(*a.zoc)) {
    throw InputError("`zoc`: expected clipped, strict or none, got '" + printable(*a.zoc) + "'");
  }
  if ((!a.current.empty() || a.current_field) && !a.current_const.empty()) {
    throw InputError("`current`: expected a field (a file or a CurrentField) or `current_const`, not both");
  }
  const std::vector<EllipseRow> rows = a.ellipses ? ellipse_rows(*a.ellipses) : std::vector<EllipseRow>{};
  const std::vector<Rings> polygons = a.polygons ? polygon_rings(*a.polygons) : std::vector<Rings>{};
  RoutePlanRequest r;
  r.charts = a.charts;
  r.src_crs = a.src_crs;
  r.margin_m = a.margin;
  r.tolerance_m = a.tolerance;
  r.turn_radius_m = a.turn_radius;
  if (a.depth) r.depth_m = *a.depth;
  if (a.vertical_clearance) r.vertical_clearance_m = *a.vertical_clearance;
  if (a.zoc) r.chart.zoc = *parse_zoc_policy(*a.zoc);
  if (a.restricted_areas) r.chart.restricted_areas = *a.restricted_areas;
  if (a.unassessed_zoc) {
    r.chart.unassessed = {std::get<0>(*a.unassessed_zoc), std::get<1>(*a.unassessed_zoc),
                          std::get<2>(*a.unassessed_zoc)};
  }
  check_chart_options(r.chart);
  if (a.chart) take_chart(*a.chart, a, r);
  r.problem.escape = a.escape;
  r.search = parse_search(a.search);
  r.cost = parse_cost_kind(a.cost);
  r.vehicle = a.vehicle;
  r.speed = a.speed;
  r.current_file = a.current;
  if (a.current_field) {
    r.current = a.current_field;
    r.current_source = a.current_field->source;
  }
  r.max_expansions = a.max_expansions;
  r.graph = a.graph ? parse_graph_kind(*a.graph)
                    : default_plan_graph(r.charts, r.cost, false, a.start_heading || a.goal_heading);
  if (graph_entry(r.graph).can.in_depth) {
    throw InputError("`graph` " + r.graph.name + ": routes in depth are not in the Python module yet");
  }
  const std::string from = position_text(a.start), to = position_text(a.goal);
  // As the CLI: the frame is `crs`, else the UTM zone of the obstacles, else
  // of the start (then lon, lat). A chart read once brings its own frame.
  py::gil_scoped_release free;
  ObstacleReadOptions read{a.crs, a.src_crs};
  if (a.chart) {
    if (!a.crs.empty() && LocalFrame::from_user_crs(a.crs, "`crs`").id() != a.chart->frame.id()) {
      throw InputError("`crs`: " + a.crs + ", but the chart was read in " + a.chart->frame.id() +
                       "; read it again with read_chart(..., crs=...) to plan so");
    }
    read.local_crs = a.chart->frame.wkt();
  } else if (a.crs.empty()) {
    read.fallback_lonlat = parse_lonlat(from, "`start`");
  }
  LoadedObstacles loaded = load_obstacles(a.obstacles, read);
  const LocalFrame frame = a.chart ? a.chart->frame : loaded.frame;
  r.obstacles = std::move(loaded.obstacles);
  for (EllipticCylinder& e : ellipses_in(frame, rows)) r.obstacles.ellipses.push_back(std::move(e));
  add_polygons(polygons, r.obstacles);
  r.problem.start = parse_position(from, "`start`", frame, !a.crs.empty());
  r.problem.goal = parse_position(to, "`goal`", frame, !a.crs.empty());
  if (a.start_heading) r.problem.start_heading = frame.heading_to_local(*a.start_heading, r.problem.start);
  if (a.goal_heading) r.problem.goal_heading = frame.heading_to_local(*a.goal_heading, r.problem.goal);
  if (!a.current_const.empty()) {
    r.current = std::make_shared<const CurrentField>(parse_constant_current(a.current_const, "`current_const`"));
    r.current_source = "current_const " + a.current_const;
  }
  if (!a.depart.empty()) r.depart_s = parse_utc(a.depart, "`depart`");
  auto report = std::make_shared<const RoutePlanReport>(plan_route_request(frame, r));
  if (const auto why = report->stop_reason()) throw NoRouteError(*why);
  return Route{std::move(report), frame};
}

}  // namespace

void bind_plan(py::module_& m) {
  py::class_<Route>(m, "Route", "A route `plan` found, with what the CLI reports about it.")
      .def_property_readonly("xy", &Route::xy, "Waypoints in the planning frame (metres), an (n, 2) float64 array.")
      .def_property_readonly("lonlat", &Route::lonlat, "Waypoints as longitude, latitude (degrees, WGS 84), (n, 2).")
      .def_property_readonly(
          "length_m", [](const Route& r) { return r.report->route.length(); }, "Length of the route (m).")
      .def_property_readonly(
          "crs", [](const Route& r) { return r.frame.id(); }, "The planning frame, e.g. 'EPSG:32632'.")
      .def_property_readonly(
          "graph", [](const Route& r) { return to_string(r.report->options.graph); }, "The graph that planned it.")
      .def("outlines", &Route::outlines,
           "The footprints of the obstacles it was planned among (a chart's no-go polygons too), in lon, lat: per "
           "obstacle a list of (k, 2) rings, its outline first, then its holes (opposite turning), to draw the "
           "route over.")
      .def("to_dict", &Route::to_dict, "The report as `deepguide plan --json` prints it (the same keys).")
      .def(
          "text", [](const Route& r) { return r.report->to_text(); }, "The report as `deepguide plan` prints it.")
      .def(
          "_render",
          [](const Route& r, const std::filesystem::path& path, bool draw_graph) {
            py::gil_scoped_release free;
            render_route_plan(*r.report, path.string(), draw_graph);
          },
          py::arg("path"), py::arg("draw_graph"))
      .def(
          "to_html",
          [](const Route& r) {
            py::gil_scoped_release free;
            return web_map_html(route_web_map(*r.report));
          },
          "The route as `plan --html` writes it: one web page that works offline, to zoom and click (the chart's "
          "no-go with its reasons, obstacles, zones, legs, waypoints; docs/WEB_MAP.md). In a notebook: "
          "IPython.display.HTML(route.to_html()), or write it to a file.")
      .def("__repr__", &Route::repr);

  m.def(
      "plan",
      [](std::pair<double, double> start, std::pair<double, double> goal,
         const std::vector<std::filesystem::path>& obstacles, const py::object& charts,
         std::optional<py::array> ellipses, std::optional<py::list> polygons, std::string crs, std::string src_crs,
         std::optional<std::string> graph, std::string search, std::string cost, double margin, double tolerance,
         std::optional<double> depth, std::optional<double> turn_radius, std::optional<double> vertical_clearance,
         std::optional<std::string> zoc, std::optional<bool> restricted_areas,
         std::optional<std::tuple<double, double, double>> unassessed_zoc, bool escape, std::string vehicle,
         std::string speed, const py::object& current, std::size_t max_expansions, std::optional<double> start_heading,
         std::optional<double> goal_heading, std::string current_const, std::string depart) {
        PlanArgs a;
        a.start = start;
        a.goal = goal;
        a.obstacles = path_texts(obstacles);
        if (py::isinstance<Chart>(charts)) {
          a.chart = charts.cast<Chart>();
        } else if (!charts.is_none()) {
          a.charts = one_or_more_paths(charts);
        }
        if (py::isinstance<Current>(current)) {
          a.current_field = current.cast<Current>().field;
        } else if (!current.is_none()) {
          a.current = current.cast<std::filesystem::path>().string();
        }
        a.ellipses = std::move(ellipses);
        a.polygons = std::move(polygons);
        a.crs = std::move(crs);
        a.src_crs = std::move(src_crs);
        a.graph = std::move(graph);
        a.search = std::move(search);
        a.cost = std::move(cost);
        a.margin = margin;
        a.tolerance = tolerance;
        a.depth = depth;
        a.turn_radius = turn_radius;
        a.vertical_clearance = vertical_clearance;
        a.zoc = std::move(zoc);
        a.restricted_areas = restricted_areas;
        a.unassessed_zoc = unassessed_zoc;
        a.escape = escape;
        a.vehicle = std::move(vehicle);
        a.speed = std::move(speed);
        a.max_expansions = max_expansions;
        a.start_heading = start_heading;
        a.goal_heading = goal_heading;
        a.current_const = std::move(current_const);
        a.depart = std::move(depart);
        return plan(a);
      },
      py::arg("start"), py::arg("goal"), py::kw_only(), py::arg("obstacles") = std::vector<std::filesystem::path>{},
      py::arg("charts") = py::none(), py::arg("ellipses") = py::none(), py::arg("polygons") = py::none(),
      py::arg("crs") = "", py::arg("src_crs") = "", py::arg("graph") = py::none(), py::arg("search") = "astar",
      py::arg("cost") = "length", py::arg("margin") = 5.0, py::arg("tolerance") = PlannerOptions{}.tolerance,
      py::arg("depth") = py::none(), py::arg("turn_radius") = py::none(), py::arg("vertical_clearance") = py::none(),
      py::arg("zoc") = py::none(), py::arg("restricted_areas") = py::none(), py::arg("unassessed_zoc") = py::none(),
      py::arg("escape") = false, py::arg("vehicle") = "", py::arg("speed") = "cruise", py::arg("current") = py::none(),
      py::arg("max_expansions") = 0, py::arg("start_heading") = py::none(), py::arg("goal_heading") = py::none(),
      py::arg("current_const") = "", py::arg("depart") = "",
      R"(The shortest (or fastest, or most economical) safe route from `start` to `goal`, as `deepguide plan`.

start, goal: (lon, lat) in degrees, or (x, y) in `crs` when `crs` is given.
obstacles: obstacle files; charts: a Chart (read_chart: read once, planned on again and again; then `ellipses`
and `polygons` are in its frame) or chart files: bathymetry rasters, S-57 cells or folders, prepared charts,
hazard files, read with `zoc`, `restricted_areas` and `unassessed_zoc` as read_chart reads them.
ellipses: an (n, 5) array of x, y, semi_major_m, semi_minor_m, orientation_deg (clockwise from true north) in `crs`.
polygons: a list of polygons in `crs`, each a list of (k, 2) rings (the outline first, then holes) or one ring.
graph: a graph of the registry (deepguide.graphs()); None: what `plan` takes by default.
margin, tolerance, depth, turn_radius, vertical_clearance (default 2): metres, as the CLI's flags.
start_heading, goal_heading: degrees clockwise from true north (with a turn_radius; the tangent graph).
cost: length, time or energy, in `current` (a CurrentField, or a field's file read at `depth`) or
`current_const` ("SPEED_MPS,DIR_DEG"),
departing at `depart` (ISO 8601, UTC by default).
The GIL is released while it plans, so threads plan in parallel.
Raises InputError (bad input), NoRouteError (no safe route).)");

  m.def(
      "graphs",
      [] {
        std::vector<std::string> names;
        for (const GraphEntry& e : graph_entries()) names.push_back(e.name);
        return names;
      },
      "The graph kinds `plan` takes, by name.");
}

}  // namespace deepguide::python
