// deepguide.check_route and deepguide.identify: `deepguide check route` and
// `deepguide identify`, from Python, as reports (to_dict() is the command's
// --json). An unsafe route or a failed manoeuvre is a verdict to read, not an
// exception; bad input raises InputError.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "charts.hpp"
#include "deepguide/planning/route_file_check.hpp"
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/trajectory_io.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

struct Identification {
  Scenario scenario;
  IdentifyResult result;
};

}  // namespace

void bind_checks(py::module_& m) {
  py::class_<RouteFileCheckReport>(m, "RouteCheck", "The verdict of `deepguide check route`.")
      .def_readonly("safe", &RouteFileCheckReport::safe)
      .def_readonly("why", &RouteFileCheckReport::why, "The first crossing, or where the route comes closest.")
      .def_readonly("waypoints", &RouteFileCheckReport::waypoints)
      .def_readonly("length_m", &RouteFileCheckReport::length_m)
      .def(
          "to_dict", [](const RouteFileCheckReport& r) { return from_json(r.to_json().dump()); },
          "The command's --json.")
      .def("text", &RouteFileCheckReport::to_text)
      .def("__repr__", [](const RouteFileCheckReport& r) {
        return std::string("RouteCheck(safe=") + (r.safe ? "True" : "False") + ", why='" + r.why + "')";
      });

  m.def(
      "check_route",
      [](const std::filesystem::path& route, const std::vector<std::filesystem::path>& obstacles,
         const std::vector<std::filesystem::path>& charts, std::optional<double> depth, double margin,
         double vertical_clearance, const std::string& crs, const std::string& src_crs, const std::string& zoc,
         bool restricted_areas, const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
        RouteFileCheckOptions o;
        o.chart = chart_options(zoc, restricted_areas, unassessed_zoc);
        o.route = route.string();
        o.obstacles = path_texts(obstacles);
        o.charts = path_texts(charts);
        if (depth) o.operating_depth_m = *depth;
        o.margin_m = margin;
        o.vertical_clearance_m = vertical_clearance;
        o.crs = crs;
        o.src_crs = src_crs;
        py::gil_scoped_release free;
        return check_route_file(o);
      },
      py::arg("route"), py::kw_only(), py::arg("obstacles") = std::vector<std::filesystem::path>{},
      py::arg("charts") = std::vector<std::filesystem::path>{}, py::arg("depth") = py::none(),
      py::arg("margin") = RouteFileCheckOptions{}.margin_m,
      py::arg("vertical_clearance") = RouteFileCheckOptions{}.vertical_clearance_m, py::arg("crs") = "",
      py::arg("src_crs") = "", py::arg("zoc") = "clipped", py::arg("restricted_areas") = false,
      py::arg("unassessed_zoc") = py::none(),
      "Checks a route file (RTZ, GPX, GeoJSON, KML, ...) against obstacle files and S-57 charts at `depth`, as "
      "`deepguide check route`, with the independent checker; a route that is not safe gives safe == False.");

  py::class_<Identification>(m, "Identification", "An identification run, as `deepguide identify` makes it.")
      .def(
          "to_dict",
          [](const Identification& r) { return from_json(identification_json(r.scenario, r.result).dump()); },
          "The command's --json: statistics and mode switches.")
      .def("text", [](const Identification& r) { return identification_text(r.scenario, r.result); })
      .def_property_readonly("end", [](const Identification& r) { return std::string(to_string(r.result.end)); })
      .def_property_readonly(
          "failure",
          [](const Identification& r) -> std::optional<std::string> {
            if (r.result.failure.empty()) return std::nullopt;
            return r.result.failure;
          },
          "Why the manoeuvre failed (the command exits 3 with it), or None.")
      .def("__repr__", [](const Identification& r) {
        return "Identification(end='" + std::string(to_string(r.result.end)) + "')";
      });

  m.def(
      "identify",
      [](const std::filesystem::path& scenario, const std::string& mode) {
        Identification out;
        py::gil_scoped_release free;
        out.scenario = read_identification_scenario(scenario.string(), mode);
        out.result = simulate_identification(out.scenario, {false});
        return out;
      },
      py::arg("scenario"), py::kw_only(), py::arg("mode") = "",
      "Runs a scenario's identify section (aligning in a current, or going around the object; `mode` align or "
      "around, empty: the scenario's), as `deepguide identify`.");
}

}  // namespace deepguide::python
