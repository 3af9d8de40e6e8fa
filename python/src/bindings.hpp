#pragma once
// What each binding file adds to the module (module.cpp calls them in turn).

#include <pybind11/pybind11.h>

namespace deepguide::python {

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
