// deepguide.simulate: what `deepguide simulate` does, from Python. The
// trajectory comes as columns (the CSV's names and units, at full precision:
// vehicle_columns), which the package's Python part makes a structured array.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include <cstdio>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/render/trajectory_figure.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/simulation.hpp"
#include "deepguide/simulation/trajectory_io.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

struct Simulation {
  Scenario scenario;
  SimulationResult result;

  py::dict columns() const {
    const auto& t = result.trajectory;
    const auto n = static_cast<py::ssize_t>(t.size());
    py::array_t<double> time(n), x(n), y(n), heading(n), course(n), rate_cmd(n), rate_ref(n), rate(n), speed(n),
        clearance(n);
    py::array_t<std::int32_t> sector(n), contacts(n);
    py::array_t<bool> unreachable(n);
    py::list status;
    for (py::ssize_t i = 0; i < n; ++i) {
      const TrajectorySample& s = t[static_cast<std::size_t>(i)];
      const VehicleColumns c = vehicle_columns(s);
      time.mutable_at(i) = c.time_s, x.mutable_at(i) = c.x_m, y.mutable_at(i) = c.y_m;
      heading.mutable_at(i) = c.heading_deg, course.mutable_at(i) = c.course_cmd_deg;
      rate_cmd.mutable_at(i) = c.rate_cmd_deg_s, rate_ref.mutable_at(i) = c.rate_ref_deg_s;
      rate.mutable_at(i) = c.rate_deg_s, speed.mutable_at(i) = c.speed_mps, clearance.mutable_at(i) = c.clearance_m;
      sector.mutable_at(i) = s.sector, unreachable.mutable_at(i) = s.course_unreachable;
      contacts.mutable_at(i) = s.contacts;
      status.append(std::string(to_string(s.status)));
    }
    py::dict d;
    d["time_s"] = time, d["x_m"] = x, d["y_m"] = y, d["heading_deg"] = heading, d["course_cmd_deg"] = course;
    d["rate_cmd_deg_s"] = rate_cmd, d["rate_ref_deg_s"] = rate_ref, d["rate_deg_s"] = rate, d["speed_mps"] = speed;
    d["clearance_m"] = clearance, d["sector"] = sector, d["status"] = status, d["course_unreachable"] = unreachable;
    d["contacts"] = contacts;
    return d;
  }
  py::object to_dict() const { return from_json(simulation_json(scenario, result).dump()); }
};

}  // namespace

void bind_simulate(py::module_& m) {
  py::class_<Simulation>(m, "_Simulation")
      .def("_columns", &Simulation::columns)
      .def("to_dict", &Simulation::to_dict, "The statistics as `deepguide simulate --json` prints them.")
      .def(
          "text", [](const Simulation& s) { return simulation_text(s.scenario, s.result); },
          "The statistics as `deepguide simulate` prints them.")
      .def(
          "_render",
          [](const Simulation& s, const std::filesystem::path& path) {
            py::gil_scoped_release free;
            TrajectoryFigure figure;
            figure.map = reactive_map_for(s.scenario, s.scenario.name);
            figure.runs = {s.result};
            render_trajectory_figure(figure, path.string());
          },
          py::arg("path"))
      .def_property_readonly("end", [](const Simulation& s) { return std::string(to_string(s.result.end)); })
      .def_property_readonly("reached", [](const Simulation& s) { return s.result.stats.reached; })
      .def_property_readonly("collided", [](const Simulation& s) { return s.result.stats.collided; })
      .def_property_readonly("method", [](const Simulation& s) { return std::string(to_string(s.result.method)); });

  m.def(
      "_simulate",
      [](const std::string& scenario_file, const std::string& method, std::optional<std::uint64_t> seed) {
        const ReactiveMethod parsed = reactive_method_named(method, "`method`");
        Simulation out;
        {
          py::gil_scoped_release free;
          out.scenario = read_scenario_file(scenario_file);
          if (seed) out.scenario.sonar.seed = *seed;
          out.result = simulate(out.scenario, parsed, {true});
        }
        return out;
      },
      py::arg("scenario"), py::arg("method"), py::arg("seed") = py::none());
}

}  // namespace deepguide::python
