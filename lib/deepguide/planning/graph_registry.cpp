#include "deepguide/planning/graph_registry.hpp"

#include <deque>
#include <mutex>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {

struct Registry {
  std::mutex mutex;
  // A deque: registering another graph leaves references to the entries valid.
  std::deque<GraphEntry> entries{
      {GraphKind::visibility.name,
       "reduced polygon graph",
       {.weighs_cost = true, .open_water_grid = true, .turn_radius = true},
       {}},
      {GraphKind::visibility_full.name,
       "the seed's",
       {.weighs_cost = true, .open_water_grid = true, .turn_radius = true},
       {}},
      {GraphKind::tangent.name, "exact, curved", {.turn_radius = true}, {}},
      // The quadtree keeps a turning radius only with --smooth (planner.cpp says why).
      {GraphKind::quadtree.name,
       "free cells' centres, the seed's Fig. 7",
       {.weighs_cost = true, .turn_radius = true},
       {}},
      {GraphKind::octree.name, "a route in depth over the sea floor", {.in_depth = true}, {}},
  };
};

Registry& registry() {
  static Registry r;
  return r;
}

template <class Entries>
std::string names_of(const Entries& entries) {
  std::string text;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == entries.size() ? " or " : ", ") + entries[i].name;
  }
  return text;
}

}  // namespace

void register_graph(GraphEntry entry) {
  if (entry.name.empty() || entry.name.find_first_of(",: ") != std::string::npos) {
    throw InputError("graph name: expected a word without commas, colons or spaces, got '" + printable(entry.name) +
                     "'");
  }
  if (!entry.build) throw InputError("graph '" + entry.name + "': expected a build function");
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const GraphEntry& e : r.entries) {
    if (e.name == entry.name) throw InputError("graph '" + entry.name + "': expected a new name, it is taken");
  }
  r.entries.push_back(std::move(entry));
}

const GraphEntry& graph_entry(const GraphKind& kind) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  for (const GraphEntry& e : r.entries) {
    if (e.name == kind.name) return e;
  }
  throw InputError("`graph`: expected " + names_of(r.entries) + ", got '" + printable(kind.name) + "'");
}

std::vector<GraphEntry> graph_entries() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  return {r.entries.begin(), r.entries.end()};
}

std::string graph_names_text(const std::function<bool(const GraphEntry&)>& which) {
  std::vector<GraphEntry> entries = graph_entries();
  if (which) std::erase_if(entries, [&](const GraphEntry& e) { return !which(e); });
  return names_of(entries);
}

std::string graph_help_text() {
  const std::vector<GraphEntry> entries = graph_entries();
  std::string text;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == entries.size() ? ", or " : ", ") + entries[i].name + " (" + entries[i].help + ")";
  }
  return text;
}

}  // namespace deepguide
