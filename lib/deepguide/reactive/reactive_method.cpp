// Names of the methods and statuses, and the dispatch to the method files.

#include "deepguide/reactive/reactive_method.hpp"

#include <algorithm>
#include <stdexcept>

#include "deepguide/core/error.hpp"

#include "deepguide/reactive/dipole_field.hpp"
#include "deepguide/reactive/geometric_construction.hpp"
#include "deepguide/reactive/potential_field.hpp"

namespace deepguide {

std::string_view to_string(ReactiveMethod method) {
  switch (method) {
    case ReactiveMethod::dipole: return "dipole";
    case ReactiveMethod::geometric: return "geometric";
    case ReactiveMethod::potential: return "potential";
  }
  return "?";
}

std::optional<ReactiveMethod> parse_reactive_method(std::string_view name) {
  for (ReactiveMethod m : {ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential}) {
    if (to_string(m) == name) return m;
  }
  return std::nullopt;
}

ReactiveMethod reactive_method_named(std::string_view name, const std::string& what) {
  if (const auto m = parse_reactive_method(name)) return *m;
  throw InputError(what + ": expected dipole, geometric or potential, got '" + printable(std::string(name)) + "'");
}

std::vector<ReactiveMethod> reactive_methods_named(const std::vector<std::string>& names, const std::string& what) {
  std::vector<ReactiveMethod> out;
  for (const std::string& n : names) {
    const ReactiveMethod m = reactive_method_named(n, what);
    if (std::find(out.begin(), out.end(), m) != out.end()) {
      throw InputError(what + ": expected each method once, got '" + printable(n) + "' twice");
    }
    out.push_back(m);
  }
  if (out.empty()) throw InputError(what + ": expected at least one method");
  return out;
}

std::string_view to_string(ReactiveStatus status) {
  switch (status) {
    case ReactiveStatus::ok: return "ok";
    case ReactiveStatus::arrived: return "arrived";
    case ReactiveStatus::leaving_zone: return "leaving_zone";
    case ReactiveStatus::target_in_zone: return "target_in_zone";
    case ReactiveStatus::stalled: return "stalled";
  }
  return "?";
}

ReactiveCommand reactive_command(ReactiveMethod method, const ReactiveParams& params, ReactiveMemory& memory,
                                 const ReactiveInput& input) {
  switch (method) {
    case ReactiveMethod::dipole: return dipole_command(params, memory, input);
    case ReactiveMethod::geometric: return geometric_command(params, memory, input);
    case ReactiveMethod::potential: return potential_command(params, memory, input);
  }
  throw std::invalid_argument("reactive_command: unknown method");
}

Vec2 reactive_gradient(ReactiveMethod method, const ReactiveParams& params, const Vec2& point, const Vec2& target,
                       std::span<const Ellipse> objects) {
  switch (method) {
    case ReactiveMethod::dipole: return dipole_gradient(params, point, target, objects);
    case ReactiveMethod::geometric: return geometric_gradient(params, point, target, objects);
    case ReactiveMethod::potential: return potential_gradient(params, point, target, objects);
  }
  throw std::invalid_argument("reactive_gradient: unknown method");
}

}  // namespace deepguide
