// deepguide.read_chart, read_current and constant_current: charts and
// current fields read once by the library's readers (charts_frame,
// chart_obstacles, load_current_field), to plan on again and again, to draw
// (render_chart) and to look into (chart_info, summarize_current).

#include "charts.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/currents/current_summary.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/render/chart_web_map.hpp"
#include "deepguide/render/reactive_map.hpp"  // ellipse_outline

namespace py = pybind11;

namespace deepguide::python {

const ChartObstacles& Chart::obstacles() const {
  if (!charted) throw InputError(unread);
  return *charted;
}

py::list lonlat_outlines(const ObstacleSet& obstacles, const LocalFrame& frame) {
  const auto ring = [&](const auto& points) {
    py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
    auto o = a.template mutable_unchecked<2>();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 ll = frame.to_lonlat(Vec2(points[i].x(), points[i].y()));
      o(i, 0) = ll.x(), o(i, 1) = ll.y();
    }
    return a;
  };
  py::list out;
  for (const EllipticCylinder& e : obstacles.ellipses) {
    py::list rings;
    rings.append(ring(ellipse_outline(e.footprint, 72)));
    out.append(rings);
  }
  for (const PolygonObstacle& p : obstacles.polygons) {
    py::list rings;
    rings.append(ring(p.footprint.outer()));
    for (const auto& inner : p.footprint.inners()) rings.append(ring(inner));
    out.append(rings);
  }
  return out;
}

ChartOptions chart_options(const std::string& zoc, bool restricted_areas,
                           const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
  ChartOptions o;
  const std::optional<ZocPolicy> policy = parse_zoc_policy(zoc);
  if (!policy) throw InputError("`zoc`: expected clipped, strict or none, got '" + printable(zoc) + "'");
  o.zoc = *policy;
  o.restricted_areas = restricted_areas;
  if (unassessed_zoc) {
    o.unassessed = {std::get<0>(*unassessed_zoc), std::get<1>(*unassessed_zoc), std::get<2>(*unassessed_zoc)};
  }
  check_chart_options(o);
  return o;
}

namespace {

// Without a depth a raster's or an S-57 cell's no-go cannot be judged
// (chart_obstacles.hpp): such a chart is drawn and described, not planned on.
bool needs_depth(const std::string& path) {
  return names_enc(path) || is_prepared_chart(path) || chart_kind(path) != ChartKind::vector;
}

Chart read_chart(const std::vector<std::string>& paths, std::optional<double> depth, double clearance,
                 const std::string& crs, const std::string& src_crs, const ChartOptions& options) {
  if (paths.empty()) throw InputError("`charts`: expected at least one chart file");
  if (depth && (!std::isfinite(*depth) || *depth < 0.0)) {
    throw InputError("`depth`: expected an operating depth >= 0 m, got " + general(*depth));
  }
  if (!std::isfinite(clearance) || clearance < 0.0) {
    throw InputError("`vertical_clearance`: expected a clearance >= 0 m, got " + general(clearance));
  }
  Chart c{paths, charts_frame(paths, crs, src_crs), depth ? *depth : std::nan(""), clearance, src_crs, options, nullptr,
          ""};
  if (!depth && std::any_of(paths.begin(), paths.end(), needs_depth)) {
    c.unread =
        "`depth`: expected the operating depth the chart was read at (read_chart(..., depth=M)); its "
        "rasters' and S-57 cells' no-go depend on it";
    return c;
  }
  ChartObstacleOptions read;
  read.depth_m = c.depth_m;
  read.clearance_m = clearance;
  read.source_crs = src_crs;
  read.enc = enc_options(options);
  c.charted = std::make_shared<const ChartObstacles>(chart_obstacles(paths, c.frame, read));
  return c;
}

py::list chart_info_dicts(const Chart& c) {
  ChartInfoOptions o;
  o.depth_m = c.depth_m;
  o.clearance_m = c.clearance_m;
  o.local_crs = c.frame.wkt();
  o.source_crs = c.src_crs;
  o.chart = c.options;
  std::vector<std::string> texts;
  {
    py::gil_scoped_release free;
    for (const std::string& p : c.paths) texts.push_back(to_json(chart_info(p, o)).dump());
  }
  py::list out;
  for (const std::string& t : texts) out.append(from_json(t));
  return out;
}

void render(const Chart& c, const std::filesystem::path& path, int width, const std::string& title,
            const std::vector<std::string>& obstacles) {
  ChartRenderOptions o;
  o.charts = c.paths;
  o.obstacles = obstacles;
  o.depth_m = c.depth_m;
  o.clearance_m = c.clearance_m;
  o.chart_options = c.options;
  o.local_crs = c.frame.wkt();
  o.source_crs = c.src_crs;
  o.title = title;
  o.width_px = width;
  py::gil_scoped_release free;
  render_chart(o, path.string());
}

// Velocities (n, 2) at field coordinates (n, 2), NaN where the field does not know.
py::array_t<double> sample(const Current& c, const py::array& points, std::optional<double> time) {
  const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  if (!p || p.ndim() != 2 || p.shape(1) != 2) {
    throw InputError("`points`: expected an (n, 2) array of x, y in the field's CRS (lon, lat for a geographic one)");
  }
  const CurrentField& f = *c.field;
  double t = 0.0;
  if (time) {
    t = *time;
  } else if (!f.times_s.empty()) {
    t = f.times_s.front();
  }
  if (!std::isfinite(t)) throw InputError("`time`: expected UTC seconds since 1970, got " + general(t));
  py::array_t<double> out({p.shape(0), py::ssize_t{2}});
  auto in = p.unchecked<2>();
  auto o = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < p.shape(0); ++i) {
    const auto v = sample_native(f, Eigen::Vector2d(in(i, 0), in(i, 1)), t);
    o(i, 0) = v ? v->x() : std::nan("");
    o(i, 1) = v ? v->y() : std::nan("");
  }
  return out;
}

py::dict grid(const Current& c) {
  const CurrentField& f = *c.field;
  const auto vector = [](const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); };
  const auto steps = static_cast<py::ssize_t>(f.steps());
  const auto cube = [&](const std::vector<double>& v) {
    return py::array_t<double>({steps, static_cast<py::ssize_t>(f.ny()), static_cast<py::ssize_t>(f.nx())}, v.data());
  };
  py::dict d;
  d["x"] = vector(f.x), d["y"] = vector(f.y), d["times_s"] = vector(f.times_s);
  d["u"] = cube(f.u), d["v"] = cube(f.v);
  return d;
}

}  // namespace

void bind_charts(py::module_& m) {
  py::class_<Chart>(m, "Chart",
                    "Charts read once into one frame at one depth (read_chart): plan on them with "
                    "plan(..., charts=chart), draw them, look into them. Immutable, so threads may share it.")
      .def_property_readonly(
          "crs", [](const Chart& c) { return c.frame.id(); }, "The frame the chart was read into, e.g. 'EPSG:32605'.")
      .def_property_readonly(
          "depth",
          [](const Chart& c) -> std::optional<double> {
            if (std::isnan(c.depth_m)) return std::nullopt;
            return c.depth_m;
          },
          "The operating depth it was read at (m), or None.")
      .def_property_readonly(
          "vertical_clearance", [](const Chart& c) { return c.clearance_m; }, "Water kept above the sea floor (m).")
      .def_property_readonly(
          "paths", [](const Chart& c) { return c.paths; }, "The chart files, as given.")
      .def_property_readonly(
          "files",
          [](const Chart& c) {
            py::list out;
            for (const ChartFileObstacles& f : c.obstacles().files) {
              py::dict d;
              d["path"] = f.path, d["kind"] = f.kind, d["obstacles"] = f.obstacles, d["passed_over"] = f.passed_over;
              out.append(d);
            }
            return out;
          },
          "Per chart file: its kind, the obstacles taken from it and the hazards the vehicle passes over.")
      .def("__len__", [](const Chart& c) { return c.obstacles().obstacles.size(); })
      .def(
          "outlines", [](const Chart& c) { return lonlat_outlines(c.obstacles().obstacles, c.frame); },
          "The no-go at the depth (land, shoals, hazards' discs) in lon, lat: per polygon a list of (k, 2) rings, "
          "its outline first, then its holes.")
      .def("info", &chart_info_dicts, "Per chart file what `deepguide chart info --json` prints.")
      .def("_render", &render, py::arg("path"), py::arg("width"), py::arg("title"), py::arg("obstacles"))
      .def(
          "to_html",
          [](const Chart& c) {
            const ChartObstacles& read = c.obstacles();
            if (!read.enc) {
              throw InputError("to_html: expected S-57 charts (cells, folders, exchange sets, prepared charts)");
            }
            std::string title;
            for (const std::string& p : c.paths)
              title += (title.empty() ? "" : ", ") + std::filesystem::path(p).filename().string();
            py::gil_scoped_release free;
            return web_map_html(chart_web_map(*read.enc, c.depth_m, title + " at " + general(c.depth_m) + " m"));
          },
          "The chart as `render chart --html` writes it: one web page that works offline (depth areas, land, the "
          "no-go with its reasons, hazards, soundings, zones of confidence, cells; docs/WEB_MAP.md). S-57 charts.")
      .def("__repr__", [](const Chart& c) {
        std::string out = "Chart(paths=" + std::to_string(c.paths.size()) + ", crs='" + c.frame.id() + "'";
        out += std::isnan(c.depth_m) ? ", depth=None" : ", depth=" + general(c.depth_m);
        if (c.charted) out += ", obstacles=" + std::to_string(c.charted->obstacles.size());
        return out + ")";
      });

  m.def(
      "read_chart",
      [](const py::object& charts, std::optional<double> depth, double vertical_clearance, const std::string& crs,
         const std::string& src_crs, const std::string& zoc, bool restricted_areas,
         std::optional<std::tuple<double, double, double>> unassessed_zoc) {
        const ChartOptions options = chart_options(zoc, restricted_areas, unassessed_zoc);
        const std::vector<std::string> paths = one_or_more_paths(charts);
        py::gil_scoped_release free;
        return read_chart(paths, depth, vertical_clearance, crs, src_crs, options);
      },
      py::arg("charts"), py::kw_only(), py::arg("depth") = py::none(), py::arg("vertical_clearance") = 2.0,
      py::arg("crs") = "", py::arg("src_crs") = "", py::arg("zoc") = "clipped", py::arg("restricted_areas") = false,
      py::arg("unassessed_zoc") = py::none(),
      R"(Reads charts (one path or several) once, as `plan --chart` reads them: bathymetry rasters, S-57 cells, folders and exchange
sets (read together, the better scale winning), prepared charts (`deepguide chart prepare`) and hazard files.

depth: the operating depth (m); the no-go is what is shallower than depth + vertical_clearance. Without it
the chart can be drawn and described but not planned on (a raster's or a cell's no-go depends on it).
crs: the frame (default: the first chart's UTM zone); src_crs: the CRS of a raster that carries none.
zoc (clipped, strict, none), restricted_areas, unassessed_zoc (depth_m, fraction, position_m): as the CLI's
--zoc, --restricted and --unassessed-zoc (docs/CHARTS.md).
Raises InputError for a missing or unreadable chart or a bad option.)");

  py::class_<Current>(m, "CurrentField",
                      "A current field read once (read_current, constant_current); plan(..., current=field). "
                      "Immutable, so threads may share it.")
      .def_property_readonly(
          "crs", [](const Current& c) { return c.field->crs; }, "The field's own CRS, e.g. 'EPSG:4326'.")
      .def_property_readonly(
          "geographic", [](const Current& c) { return c.field->geographic; },
          "True when x, y are longitude, latitude (degrees).")
      .def_property_readonly(
          "steady", [](const Current& c) { return c.field->steady(); }, "True when the field does not change in time.")
      .def_property_readonly(
          "source", [](const Current& c) { return c.field->source; }, "The file it was read from.")
      .def(
          "summary", [](const Current& c) { return from_json(to_json(summarize_current(*c.field)).dump()); },
          "Its grid, times, depth taken and range of values, as a dict.")
      .def("grid", &grid,
           "The nodes: x, y (the field's CRS, ascending), times_s (UTC seconds) and u, v (m/s along x and y, NaN "
           "unknown) as arrays of shape (steps, len(y), len(x)); empty for a constant field.")
      .def("at", &sample, py::arg("points"), py::kw_only(), py::arg("time") = py::none(),
           "The velocity (m/s along the field CRS's x and y: east and north for a geographic field) at `points`, an "
           "(n, 2) array in the field's CRS, at `time` (UTC seconds; default the first step), bilinear between nodes "
           "as the planner and the simulator sample it; NaN where the field does not know.")
      .def("__repr__", [](const Current& c) {
        const CurrentField& f = *c.field;
        return "CurrentField(source='" + f.source + "', crs='" + f.crs + "', steps=" + std::to_string(f.steps()) + ")";
      });

  m.def(
      "read_current",
      [](const std::filesystem::path& path, double depth, const std::string& u_variable, const std::string& v_variable,
         const std::string& src_crs) {
        CurrentOptions o;
        o.depth_m = depth;
        o.u_variable = u_variable;
        o.v_variable = v_variable;
        o.assumed_crs = src_crs;
        py::gil_scoped_release free;
        return Current{std::make_shared<const CurrentField>(load_current_field(path.string(), o))};
      },
      py::arg("path"), py::kw_only(), py::arg("depth") = 0.0, py::arg("u_variable") = "", py::arg("v_variable") = "",
      py::arg("src_crs") = "",
      "Reads a current field (NetCDF u/v, or a two-band raster) at `depth` (m), as `plan --current` does; "
      "`u_variable`/`v_variable` name its variables when they are not found by their standard names, `src_crs` "
      "its CRS when it carries none. Raises InputError naming the file.");
  m.def(
      "constant_current",
      [](double speed, double direction) {
        const std::string text = general(speed, 17) + "," + general(direction, 17);
        CurrentField field = parse_constant_current(text, "`speed`, `direction`");
        field.source = "constant_current(" + general(speed) + ", " + general(direction) + ")";
        return Current{std::make_shared<const CurrentField>(std::move(field))};
      },
      py::arg("speed"), py::arg("direction"),
      "A current the same everywhere and always: `speed` m/s setting towards `direction` (degrees clockwise from "
      "true north), as `plan --current-const SPEED,DIR`.");
}

}  // namespace deepguide::python
