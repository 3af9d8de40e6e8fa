// The statuses' names, and each step sent to its method through the registry.

#include "deepguide/reactive/reactive_method.hpp"

#include "deepguide/reactive/reactive_registry.hpp"

namespace deepguide {

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

ReactiveCommand reactive_command(const ReactiveMethod& method, const ReactiveParams& params, ReactiveMemory& memory,
                                 const ReactiveInput& input) {
  return reactive_method_entry(method).command(params, memory, input);
}

Vec2 reactive_gradient(const ReactiveMethod& method, const ReactiveParams& params, const Vec2& point,
                       const Vec2& target, std::span<const Ellipse> objects) {
  return reactive_method_entry(method).gradient(params, point, target, objects);
}

}  // namespace deepguide
