#include "deepguide/planning/prepared_graphs.hpp"

#include <chrono>
#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/planner.hpp"

namespace deepguide {

std::string prepared_graph_key(const GraphBuild& in) {
  // %a: every bit of each number, so equal keys mean equal inputs.
  return printf_text("obstacles %s; margin %a m; tolerance %a m; turn radius %a m",
                     footprint_fingerprint(in.obstacles).c_str(), in.margin, in.options.tolerance,
                     in.options.turn_radius_m);
}

const PreparedGraphRecord* find_prepared(const std::vector<PreparedGraphRecord>& kept, const std::string& graph,
                                         const std::string& key) {
  for (const PreparedGraphRecord& r : kept) {
    if (r.graph == graph && r.key == key) return &r;
  }
  return nullptr;
}

PreparedGraphsMaker graph_preparer(const std::vector<GraphKind>& graphs, const PlannerOptions& options) {
  // Named apart from the Planner's `tolerance`: beside chart prepare's own
  // --tolerance (the no-go's simplification), that name would point at the wrong flag.
  if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0) {
    throw InputError("`zone_tolerance`: expected a zone polygon tolerance > 0 m, got " + general(options.tolerance));
  }
  for (const GraphKind& kind : graphs) {
    if (!graph_entry(kind).save) {
      throw InputError("`graphs` " + kind.name + ": expected " +
                       graph_names_text([](const GraphEntry& e) { return static_cast<bool>(e.save); }) + " (the " +
                       kind.name + " graph cannot be kept in a prepared chart)");
    }
  }
  return [graphs, options](const ObstacleSet& as_read) {
    std::vector<PreparedGraphRecord> out;
    for (const GraphKind& kind : graphs) {
      PlannerOptions o = options;
      o.graph = kind;
      o.prepared = nullptr;
      const auto t0 = std::chrono::steady_clock::now();
      const Planner planner(as_read, o);
      PreparedGraphRecord r = planner.save_graph();
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      r.about = printf_text("margin %s m, %zu edges, %.1f MB, built in %.2f s", general(o.margin).c_str(),
                            planner.graph_edges().size(), static_cast<double>(r.data.size()) / 1e6, seconds);
      out.push_back(std::move(r));
    }
    return out;
  };
}

}  // namespace deepguide
