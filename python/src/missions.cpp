// Missions from Python: `deepguide mission check|plan|export|simulate`. Each
// returns the report the command prints (to_dict() its --json, text() its
// text) with `failure`, the one line the command exits 3 with, or None: a
// mission that cannot be sailed is a report to read, not an exception.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "charts.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/mission/mission_report.hpp"
#include "deepguide/simulation/mission_run_report.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

// The reports share what Python sees of them.
template <class Report>
void bind_report(py::module_& m, const char* name, const char* doc) {
  py::class_<Report>(m, name, doc)
      .def(
          "to_dict", [](const Report& r) { return from_json(r.to_json().dump()); }, "The command's --json.")
      .def("text", &Report::to_text, "What the command prints.")
      .def_property_readonly("failure", &Report::failure,
                             "Why the mission cannot be sailed (the line the command exits 3 with), or None.")
      .def("__repr__", [name](const Report& r) {
        return std::string(name) + "(file='" + r.file +
               "', failure=" + (r.failure() ? "'" + *r.failure() + "'" : "None") + ")";
      });
}

}  // namespace

void bind_missions(py::module_& m) {
  bind_report<MissionCheckReport>(m, "MissionCheck", "What `deepguide mission check` reports.");
  bind_report<MissionPlanReport>(m, "MissionPlan", "What `deepguide mission plan` reports.");
  bind_report<MissionRunReport>(m, "MissionRun", "What `deepguide mission simulate` reports.");
  // The track sailed, as columns the package's Python part makes a structured array.
  py::type::of<MissionRunReport>().attr("_track_columns") = py::cpp_function(
      [](const MissionRunReport& r) {
        const auto& t = r.run.track;
        const auto n = static_cast<py::ssize_t>(t.size());
        py::array_t<double> time(n), x(n), y(n), lon(n), lat(n), depth(n), heading(n), along(n);
        py::array_t<bool> reactive(n);
        for (py::ssize_t i = 0; i < n; ++i) {
          const MissionSample& s = t[static_cast<std::size_t>(i)];
          const Vec2 ll = r.loaded.mission.frame.to_lonlat(s.position);
          time.mutable_at(i) = s.time_s, x.mutable_at(i) = s.position.x(), y.mutable_at(i) = s.position.y();
          lon.mutable_at(i) = ll.x(), lat.mutable_at(i) = ll.y(), depth.mutable_at(i) = s.depth_m;
          heading.mutable_at(i) = math_rad_to_heading_deg(s.heading), along.mutable_at(i) = s.along_m;
          reactive.mutable_at(i) = s.reactive;
        }
        py::dict d;
        d["time_s"] = time, d["x_m"] = x, d["y_m"] = y, d["lon"] = lon, d["lat"] = lat, d["depth_m"] = depth;
        d["heading_deg"] = heading, d["along_m"] = along, d["reactive"] = reactive;
        return d;
      },
      py::is_method(py::type::of<MissionRunReport>()));

  m.def(
      "mission_check",
      [](const std::filesystem::path& mission, const std::string& zoc, bool restricted_areas,
         const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
        const ChartOptions chart = chart_options(zoc, restricted_areas, unassessed_zoc);
        py::gil_scoped_release free;
        return check_mission_file(mission.string(), chart);
      },
      py::arg("mission"), py::kw_only(), py::arg("zoc") = "clipped", py::arg("restricted_areas") = false,
      py::arg("unassessed_zoc") = py::none(), "The plan as written and its conflicts, as `deepguide mission check`.");
  m.def(
      "mission_plan",
      [](const std::filesystem::path& mission, const std::string& zoc, bool restricted_areas,
         const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
        const ChartOptions chart = chart_options(zoc, restricted_areas, unassessed_zoc);
        py::gil_scoped_release free;
        return plan_mission_file(mission.string(), chart);
      },
      py::arg("mission"), py::kw_only(), py::arg("zoc") = "clipped", py::arg("restricted_areas") = false,
      py::arg("unassessed_zoc") = py::none(),
      "Every conflict evaded or identified and the plan checked, as `deepguide mission plan`.");
  m.def(
      "mission_export",
      [](const std::filesystem::path& mission, const std::filesystem::path& output, bool as_written,
         const std::string& zoc, bool restricted_areas,
         const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
        MissionExportRequest request;
        request.chart = chart_options(zoc, restricted_areas, unassessed_zoc);
        request.mission = mission.string();
        request.output = output.string();
        request.as_written = as_written;
        py::gil_scoped_release free;
        return export_mission_file(request).to_text(request.output);
      },
      py::arg("mission"), py::arg("output"), py::kw_only(), py::arg("as_written") = false, py::arg("zoc") = "clipped",
      py::arg("restricted_areas") = false, py::arg("unassessed_zoc") = py::none(),
      "Plans the mission and writes it in the format of `output`'s extension, as `deepguide mission export`; "
      "returns the line the command prints.");
  m.def(
      "mission_simulate",
      [](const std::filesystem::path& mission, const std::vector<std::filesystem::path>& unknown, std::uint64_t seed,
         double planning_delay, const std::string& zoc, bool restricted_areas,
         const std::optional<std::tuple<double, double, double>>& unassessed_zoc) {
        MissionRunRequest request;
        request.chart = chart_options(zoc, restricted_areas, unassessed_zoc);
        request.mission = mission.string();
        request.unknown = path_texts(unknown);
        request.options.seed = seed;
        request.options.planning_delay_s = planning_delay;
        py::gil_scoped_release free;
        return simulate_mission_file(request);
      },
      py::arg("mission"), py::kw_only(), py::arg("unknown") = std::vector<std::filesystem::path>{},
      py::arg("seed") = MissionRunOptions{}.seed, py::arg("planning_delay") = MissionRunOptions{}.planning_delay_s,
      py::arg("zoc") = "clipped", py::arg("restricted_areas") = false, py::arg("unassessed_zoc") = py::none(),
      "Sails the planned mission in simulation, with objects nobody knew (`unknown` obstacle files), as "
      "`deepguide mission simulate`.");
}

}  // namespace deepguide::python
