// The compiled part of the `deepguide` Python package: the library's errors
// as Python exceptions, its version, and each binding file's functions. The
// layer stays thin: every call is one the CLI makes too, so a result here
// equals the CLI's for the same inputs (tests/python).

#include <pybind11/pybind11.h>

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "bindings.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/version.hpp"

namespace py = pybind11;

namespace {

// A library message names the parameter its caller set (core/error.hpp);
// Python code set it by keyword, so the keyword is what it reads.
std::optional<std::string> keyword_of_parameter(std::string_view parameter) {
  static const std::map<std::string_view, std::string_view> keywords = {
      {"depth_m", "depth"},
      {"margin_m", "margin"},
      {"tolerance_m", "tolerance"},
      {"turn_radius_m", "turn_radius"},
      {"vertical_clearance_m", "vertical_clearance"},
      {"max_expansions", "max_expansions"},
  };
  const auto it = keywords.find(parameter);
  if (it == keywords.end()) return std::nullopt;
  return "`" + std::string(it->second) + "`";  // the replacement stands for the backquoted name
}

std::string python_message(const char* what) { return deepguide::rename_parameters(what, keyword_of_parameter); }

}  // namespace

PYBIND11_MODULE(_deepguide, m) {
  m.doc() = "deepguide's compiled core; import `deepguide`, not this module.";
  m.attr("__version__") = deepguide::kVersion;
  // Bad input is a ValueError to Python code that knows nothing of ours; the
  // others are runtime errors. Each carries the library's one line.
  static py::exception<deepguide::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<deepguide::NoRouteError> no_route(m, "NoRouteError", PyExc_RuntimeError);
  static py::exception<deepguide::ManoeuvreError> manoeuvre(m, "ManoeuvreError", PyExc_RuntimeError);
  static py::exception<deepguide::PartialError> partial(m, "PartialError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const deepguide::InputError& e) {
      input_error(python_message(e.what()).c_str());
    } catch (const deepguide::NoRouteError& e) {
      no_route(python_message(e.what()).c_str());
    } catch (const deepguide::ManoeuvreError& e) {
      manoeuvre(python_message(e.what()).c_str());
    } catch (const deepguide::PartialError& e) {
      partial(python_message(e.what()).c_str());
    }
  });
  deepguide::python::bind_charts(m);  // before plan, whose signature names Chart and CurrentField
  deepguide::python::bind_plan(m);
  deepguide::python::bind_simulate(m);
  deepguide::python::bind_evaluate(m);
  deepguide::python::bind_missions(m);
  deepguide::python::bind_checks(m);
  deepguide::python::bind_obstacles(m);
  deepguide::python::bind_figures(m);
}
