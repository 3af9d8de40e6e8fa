#include "deepguide/reactive/reactive_registry.hpp"

#include <algorithm>
#include <deque>
#include <mutex>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/reactive/dipole_field.hpp"
#include "deepguide/reactive/geometric_construction.hpp"
#include "deepguide/reactive/potential_field.hpp"

namespace deepguide {
namespace {

struct Registry {
  std::mutex mutex;
  // A deque: registering another method leaves references to the entries valid.
  std::deque<ReactiveMethodEntry> entries{dipole_method_entry(), geometric_method_entry(), potential_method_entry()};
};

Registry& registry() {
  static Registry r;
  return r;
}

std::string names_of(const std::deque<ReactiveMethodEntry>& entries) {
  std::string text;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == entries.size() ? " or " : ", ") + entries[i].name;
  }
  return text;
}

const ReactiveTuning* find_tuning(const std::deque<ReactiveMethodEntry>& entries, std::string_view key) {
  for (const ReactiveMethodEntry& e : entries) {
    for (const ReactiveTuning& t : e.tuning) {
      if (t.key == key) return &t;
    }
  }
  return nullptr;
}

}  // namespace

bool ReactiveTuning::holds(double v) const { return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi); }

std::string ReactiveTuning::expected() const {
  return what + " " + (lo_closed ? ">= " : "> ") + general(lo) + " and " + (hi_closed ? "<= " : "< ") + general(hi);
}

void register_reactive_method(ReactiveMethodEntry entry) {
  if (entry.name.empty() || entry.name.find_first_of(",: ") != std::string::npos ||
      printable(entry.name, entry.name.size() + 1) != entry.name) {
    throw InputError(
        "reactive method name: expected a word of printable characters without commas, colons or spaces, got '" +
        printable(entry.name) + "'");
  }
  if (!entry.command || !entry.gradient) {
    throw InputError("reactive method '" + entry.name + "': expected a step and a gradient function");
  }
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const ReactiveMethodEntry& e : r.entries) {
    if (e.name == entry.name)
      throw InputError("reactive method '" + entry.name + "': expected a new name, it is taken");
  }
  for (const ReactiveTuning& t : entry.tuning) {
    if (find_tuning(r.entries, t.key) || !t.holds(t.fallback)) {
      throw InputError("reactive method '" + entry.name + "': tuning '" + printable(t.key) +
                       "': expected a new name with a default in its range");
    }
  }
  r.entries.push_back(std::move(entry));
}

const ReactiveMethodEntry& reactive_method_entry(const ReactiveMethod& method) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const ReactiveMethodEntry& e : r.entries) {
    if (e.name == method.name) return e;
  }
  throw InputError("`method`: expected " + names_of(r.entries) + ", got '" + printable(method.name) + "'");
}

std::vector<ReactiveMethodEntry> reactive_method_entries() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return {r.entries.begin(), r.entries.end()};
}

std::string reactive_method_names_text() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return names_of(r.entries);
}

std::optional<ReactiveMethod> parse_reactive_method(std::string_view name) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const ReactiveMethodEntry& e : r.entries) {
    if (e.name == name) return ReactiveMethod{e.name};
  }
  return std::nullopt;
}

ReactiveMethod reactive_method_named(std::string_view name, const std::string& what) {
  if (auto m = parse_reactive_method(name)) return *m;
  throw InputError(what + ": expected " + reactive_method_names_text() + ", got '" + printable(std::string(name)) +
                   "'");
}

std::vector<ReactiveMethod> reactive_methods_named(const std::vector<std::string>& names, const std::string& what) {
  std::vector<ReactiveMethod> out;
  for (const std::string& n : names) {
    ReactiveMethod m = reactive_method_named(n, what);
    if (std::find(out.begin(), out.end(), m) != out.end()) {
      throw InputError(what + ": expected each method once, got '" + printable(n) + "' twice");
    }
    out.push_back(std::move(m));
  }
  if (out.empty()) throw InputError(what + ": expected at least one method");
  return out;
}

double tuning_value(const ReactiveParams& params, std::string_view key) {
  if (const auto it = params.tuning.find(key); it != params.tuning.end()) return it->second;
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  if (const ReactiveTuning* t = find_tuning(r.entries, key)) return t->fallback;
  throw InputError("reactive tuning '" + printable(std::string(key)) + "': expected a parameter a method declares");
}

double tuning_value(const ReactiveParams& params, const ReactiveTuning& t) {
  const auto it = params.tuning.find(t.key);
  return it != params.tuning.end() ? it->second : t.fallback;
}

const ReactiveTuning* reactive_tuning(std::string_view key) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return find_tuning(r.entries, key);
}

std::vector<ReactiveTuning> reactive_tunings() {
  std::vector<ReactiveTuning> out;
  for (const ReactiveMethodEntry& e : reactive_method_entries())
    out.insert(out.end(), e.tuning.begin(), e.tuning.end());
  return out;
}

}  // namespace deepguide
