#include "deepguide/planning/graph_registry.hpp"

#include <deque>
#include <mutex>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/builtin_graphs.hpp"

namespace deepguide {
namespace {

struct Registry {
  std::mutex mutex;
  // A deque: registering another graph leaves references to the entries valid.
  std::deque<GraphEntry> entries = seeded();

  static std::deque<GraphEntry> seeded() {
    const std::vector<GraphEntry> builtin = builtin_graph_entries();
    return {builtin.begin(), builtin.end()};
  }
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
  if (entry.name.empty() || entry.name.find_first_of(",: ") != std::string::npos ||
      printable(entry.name, entry.name.size() + 1) != entry.name) {
    throw InputError("graph name: expected a word of printable characters without commas, colons or spaces, got '" +
                     printable(entry.name) + "'");
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
