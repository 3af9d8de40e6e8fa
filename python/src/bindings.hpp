#pragma once
// What each binding file adds to the module (module.cpp calls them in turn).

#include <pybind11/pybind11.h>

namespace deepguide::python {

/// deepguide.plan and the Route it returns (plan.cpp).
void bind_plan(pybind11::module_& m);

}  // namespace deepguide::python
