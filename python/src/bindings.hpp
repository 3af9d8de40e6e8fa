#pragma once
// What each binding file adds to the module (module.cpp calls them in turn).

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>
#include <vector>

namespace deepguide::python {

/// A JSON text the library made (a report's --json) as Python objects.
inline pybind11::object from_json(const std::string& text) {
  return pybind11::module_::import("json").attr("loads")(text);
}

/// Paths from Python (str or os.PathLike) as the library's file names.
inline std::vector<std::string> path_texts(const std::vector<std::filesystem::path>& paths) {
  std::vector<std::string> out;
  for (const auto& p : paths) out.push_back(p.string());
  return out;
}

/// deepguide.plan and the Route it returns (plan.cpp).
void bind_plan(pybind11::module_& m);
/// deepguide.simulate's compiled part (simulate.cpp).
void bind_simulate(pybind11::module_& m);
/// deepguide.generate_suite and deepguide.evaluate's compiled part (evaluate.cpp).
void bind_evaluate(pybind11::module_& m);
/// deepguide.mission_check, mission_plan, mission_export and mission_simulate (missions.cpp).
void bind_missions(pybind11::module_& m);
/// deepguide.check_route and deepguide.identify (checks.cpp).
void bind_checks(pybind11::module_& m);
/// deepguide.read_obstacles (obstacles.cpp).
void bind_obstacles(pybind11::module_& m);

}  // namespace deepguide::python
