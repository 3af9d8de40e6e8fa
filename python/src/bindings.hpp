#pragma once
// What each binding file adds to the module (module.cpp calls them in turn).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

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

/// One path (str or os.PathLike) or a sequence of them, as the library's file names.
inline std::vector<std::string> one_or_more_paths(const pybind11::object& paths) {
  if (pybind11::isinstance<pybind11::str>(paths) || pybind11::hasattr(paths, "__fspath__")) {
    return {paths.cast<std::filesystem::path>().string()};
  }
  return path_texts(paths.cast<std::vector<std::filesystem::path>>());
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
/// deepguide.read_chart, read_current, constant_current (charts.cpp).
void bind_charts(pybind11::module_& m);
/// The drawings of `deepguide render` and `deepguide figures` (figures.cpp).
void bind_figures(pybind11::module_& m);

}  // namespace deepguide::python
