#pragma once
// The reactive methods, by name: what `simulate --method`, `evaluate
// --methods`, the figures, mission control and the identification's evasive
// mode find a method by. Each entry carries the method's step and its
// gradient, the parameters of its own it reads from ReactiveParams::tuning
// (names, defaults, ranges: the scenario reader, the writer and validate take
// them from here), and the one phrase the help shows.
//
// A new method needs no edit elsewhere: its step and gradient functions, its
// parameters and memory in its own file pair, and its entry given to
// register_reactive_method before the first run (a test's or a program's
// start-up). docs/ARCHITECTURE.md works one through;
// tests/reactive/test_toy_reactive_method.cpp is one. The built-in methods
// come in by the same door (dipole_field, geometric_construction,
// potential_field: each file's *_method_entry).

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/reactive/reactive_method.hpp"

namespace DEEPGUIDE_API deepguide {

/// One of a method's own parameters: its name in ReactiveParams::tuning and
/// in the scenario file's `reactive:` mapping, its default and its range
/// lo < v (lo <= v when lo_closed) and v < hi (v <= hi when hi_closed).
struct ReactiveTuning {
  std::string key;
  double fallback = 0.0;
  double lo = 0.0, hi = 0.0;
  bool lo_closed = false, hi_closed = true;
  std::string what;  ///< e.g. "a distance in metres", for messages

  bool holds(double v) const;
  /// "a distance in metres > 0 and <= 10000", for messages.
  std::string expected() const;
};

struct ReactiveMethodEntry {
  std::string name;                 ///< what --method and evaluate's methods call it
  std::string help;                 ///< one phrase, e.g. "the seed's geometric construction"
  std::uint32_t colour = 0x000000;  ///< 0xRRGGBB: its track in the figures
  std::vector<ReactiveTuning> tuning;
  /// One control step (reactive_command's contract); keeps its state in the memory.
  std::function<ReactiveCommand(const ReactiveParams&, ReactiveMemory&, const ReactiveInput&)> command;
  /// The memoryless gradient direction (reactive_gradient's contract).
  std::function<Vec2(const ReactiveParams&, const Vec2& point, const Vec2& target, std::span<const Ellipse> objects)>
      gradient;
};

/// Adds a method. Throws InputError for an empty name, one with a comma,
/// colon or space, one already taken (a graph's name included is the
/// caller's to avoid: evaluate tries reactive names first), a missing step or
/// gradient, or a tuning name another method declares.
void register_reactive_method(ReactiveMethodEntry entry);
/// The entry of `method`; InputError "`method`: expected dipole, ... or
/// potential, got 'X'" otherwise.
const ReactiveMethodEntry& reactive_method_entry(const ReactiveMethod& method);
/// Every entry, the built-in ones first, then in the order they were registered.
std::vector<ReactiveMethodEntry> reactive_method_entries();
/// "dipole, geometric or potential": the names, for messages and help.
std::string reactive_method_names_text();

/// The method called `name`; nullopt when no entry has it.
std::optional<ReactiveMethod> parse_reactive_method(std::string_view name);
/// The method `name` names, given as `what` (an option or a parameter, e.g.
/// "--method"); throws InputError "WHAT: expected dipole, geometric or
/// potential, got 'NAME'".
ReactiveMethod reactive_method_named(std::string_view name, const std::string& what);
/// Methods by name, each once and at least one; throws InputError naming `what`.
std::vector<ReactiveMethod> reactive_methods_named(const std::vector<std::string>& names, const std::string& what);

/// The tuning `key` of `params`: its value there, else the default its method
/// declares. Throws InputError for a key no method declares.
double tuning_value(const ReactiveParams& params, std::string_view key);
/// The tuning `t` of `params`: its value there, else t's default (what a
/// method reads its own parameters with, no registry lookup per step).
double tuning_value(const ReactiveParams& params, const ReactiveTuning& t);
/// The declaration of tuning `key` (it lives as long as the program), or null
/// when no method declares it.
const ReactiveTuning* reactive_tuning(std::string_view key);
/// Every declared tuning, the methods' in registry order.
std::vector<ReactiveTuning> reactive_tunings();

}  // namespace deepguide
