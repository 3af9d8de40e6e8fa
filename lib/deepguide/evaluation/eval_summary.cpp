#include "deepguide/evaluation/eval_summary.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {

namespace {

using RowsByScenario = std::map<std::size_t, std::map<std::string, const EvalRow*>>;

RowsByScenario by_scenario(const std::vector<EvalRow>& rows) {
  RowsByScenario out;
  for (const EvalRow& r : rows) out[r.scenario_index][r.method] = &r;
  return out;
}

// The first method of the run whose name starts with `graph` (visibility, visibility:dijkstra, ...).
std::string first_of(const std::vector<std::string>& methods, const std::string& graph) {
  for (const std::string& m : methods) {
    if (m == graph || m.rfind(graph + ":", 0) == 0) return m;
  }
  return "";
}

double median_of(std::vector<double> v) { return distribution(std::move(v)).median; }

std::string pct(int part, int whole) {
  return std::to_string(part) + " of " + std::to_string(whole) +
         (whole > 0 ? " (" + fixed(100.0 * part / whole, 1) + " %)" : "");
}

ClaimCheck visibility_claim(const EvaluationRun& run, const RowsByScenario& rows) {
  ClaimCheck c;
  c.claim = "The visibility graph costs less to compute than the quadtree graph and gives better routes";
  const std::string vis = first_of(run.manifest.methods, "visibility");
  const std::string quad = first_of(run.manifest.methods, "quadtree");
  if (vis.empty() || quad.empty()) {
    c.verdict = "not tested";
    c.evidence.push_back("the run needs a visibility and a quadtree method among its methods");
    return c;
  }
  std::vector<double> vis_ms, quad_ms, vis_size, quad_size, ratio;
  int paired = 0, vis_no_longer = 0;
  for (const auto& [index, methods] : rows) {
    const auto v = methods.find(vis), q = methods.find(quad);
    if (v == methods.end() || q == methods.end()) continue;
    const MethodRun &a = v->second->run, &b = q->second->run;
    vis_ms.push_back(a.compute_ms);
    quad_ms.push_back(b.compute_ms);
    vis_size.push_back(static_cast<double>(a.graph_vertices + a.graph_edges));
    quad_size.push_back(static_cast<double>(b.graph_vertices + b.graph_edges));
    if (a.end == "no_route" || b.end == "no_route" || a.route_length_m <= 0.0) continue;
    ++paired;
    vis_no_longer += a.route_length_m <= b.route_length_m + 1e-3;
    ratio.push_back(b.route_length_m / a.route_length_m);
  }
  const bool timed = run.manifest.timing;
  const double mv = median_of(vis_ms), mq = median_of(quad_ms);
  const double sv = median_of(vis_size), sq = median_of(quad_size);
  const bool cheaper = timed ? mv < mq : sv < sq;
  const double r = median_of(ratio);
  const bool better = paired > 0 && 2 * vis_no_longer > paired && r >= 1.0;
  if (vis_ms.empty() || paired == 0) {
    c.verdict = "not tested";
    c.evidence.push_back("no scenario where both " + vis + " and " + quad + " found a route");
    return c;
  }
  c.verdict = cheaper && better ? "holds" : "does not hold";
  if (timed) {
    c.evidence.push_back("compute time, median: " + vis + " " + fixed(mv, 2) + " ms, " + quad + " " + fixed(mq, 2) +
                         " ms (" + (mv > 0 ? fixed(mq / mv, 1) + " x" : std::string("n/a")) +
                         "): " + (cheaper ? "cheaper" : "not cheaper"));
  }
  c.evidence.push_back("graph size (vertices + edges), median: " + vis + " " + fixed(sv, 0) + ", " + quad + " " +
                       fixed(sq, 0) + (timed ? "" : std::string(": ") + (cheaper ? "smaller" : "not smaller")));
  c.evidence.push_back("route no longer than the quadtree's: " + pct(vis_no_longer, paired) +
                       " of the scenarios where both found a route");
  c.evidence.push_back("route length quadtree / visibility, median " + fixed(r, 4) + ", 95th percentile " +
                       fixed(distribution(ratio).p95, 4) + ": " + (better ? "better routes" : "not better routes"));
  return c;
}

ClaimCheck turning_claim(const EvaluationRun& run, const RowsByScenario& rows) {
  ClaimCheck c;
  c.claim = "The geometric construction needs smaller maximum reference turning rates than dipole potentials";
  const bool has = std::count(run.manifest.methods.begin(), run.manifest.methods.end(), "geometric") &&
                   std::count(run.manifest.methods.begin(), run.manifest.methods.end(), "dipole");
  if (!has) {
    c.verdict = "not tested";
    c.evidence.push_back("the run needs the geometric and dipole methods among its methods");
    return c;
  }
  std::vector<double> geo, dip;
  int paired = 0, lower = 0;
  for (const auto& [index, methods] : rows) {
    const auto g = methods.find("geometric"), d = methods.find("dipole");
    if (g == methods.end() || d == methods.end()) continue;
    ++paired;
    geo.push_back(rad_to_deg(g->second->run.max_rate_ref));
    dip.push_back(rad_to_deg(d->second->run.max_rate_ref));
    lower += g->second->run.max_rate_ref < d->second->run.max_rate_ref;
  }
  const Distribution dg = distribution(geo), dd = distribution(dip);
  if (paired == 0) {
    c.verdict = "not tested";
    c.evidence.push_back("no scenario that both geometric and dipole ran");
    return c;
  }
  const bool holds = 2 * lower > paired && dg.median < dd.median;
  c.verdict = holds ? "holds" : "does not hold";
  c.evidence.push_back("max |r_ref| lower with geometric: " + pct(lower, paired) + " scenarios");
  c.evidence.push_back("max |r_ref| median: geometric " + fixed(dg.median, 2) + " deg/s, dipole " +
                       fixed(dd.median, 2) + " deg/s; 95th percentile: geometric " + fixed(dg.p95, 2) +
                       " deg/s, dipole " + fixed(dd.p95, 2) + " deg/s");
  return c;
}

nlohmann::json dist_json(const Distribution& d) {
  return {{"count", d.count}, {"min", d.min}, {"median", d.median}, {"p95", d.p95}, {"max", d.max}, {"mean", d.mean}};
}

std::string cell(const Distribution& d, int digits) {
  if (d.count == 0) return "–";
  return fixed(d.median, digits) + " / " + fixed(d.p95, digits);
}

}  // namespace

std::vector<MethodColumn> method_columns(const RunManifest& manifest) {
  const auto count = [](int MethodStats::*field) {
    return [field](const MethodStats& x) { return std::to_string(x.*field); };
  };
  const auto dist = [](Distribution MethodStats::*field, int digits) {
    return [field, digits](const MethodStats& x) { return cell(x.*field, digits); };
  };
  const bool timing = manifest.timing;
  return {{"method", [](const MethodStats& x) { return x.method; }, false},
          {"runs", count(&MethodStats::runs)},
          {"reached", count(&MethodStats::reached)},
          {"collisions", count(&MethodStats::collisions)},
          {"unavoidable", count(&MethodStats::unavoidable)},
          {"no route", count(&MethodStats::no_route)},
          {"energy wins", count(&MethodStats::wins)},
          {"path m", dist(&MethodStats::path_length_m, 1)},
          {"planned route m", dist(&MethodStats::route_length_m, 1)},
          {"energy kJ", dist(&MethodStats::energy_kj, 1)},
          {"time s", dist(&MethodStats::time_s, 1)},
          {"min clearance m", dist(&MethodStats::min_clearance_m, 2)},
          {"max r_ref deg/s", dist(&MethodStats::max_rate_ref_deg_s, 2)},
          {"rms r_ref deg/s", dist(&MethodStats::rms_rate_ref_deg_s, 2)},
          {"compute ms", [timing](const MethodStats& x) { return timing ? cell(x.compute_ms, 2) : std::string("–"); }},
          {"graph size",
           [](const MethodStats& x) { return x.graph_size.max > 0 ? cell(x.graph_size, 0) : std::string("–"); }}};
}

EvaluationSummary summarize(const EvaluationRun& run) {
  EvaluationSummary s;
  const RowsByScenario rows = by_scenario(run.rows);
  std::map<std::string, int> wins;
  for (const auto& [index, methods] : rows) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [name, r] : methods) {
      if (r->run.reached && !r->run.collided) best = std::min(best, r->run.energy_j);
    }
    for (const auto& [name, r] : methods) {
      if (r->run.reached && !r->run.collided && r->run.energy_j <= best + 1.0) ++wins[name];
    }
  }
  for (const std::string& name : run.manifest.methods) {
    MethodStats m;
    m.method = name;
    std::vector<double> path, route, energy, time, clearance, max_ref, rms_ref, ms, size;
    for (const EvalRow& r : run.rows) {
      if (r.method != name) continue;
      const MethodRun& x = r.run;
      ++m.runs;
      m.reached += x.reached;
      m.collisions += x.collided;
      m.unavoidable += x.collided && x.unavoidable;
      if (x.end == "no_route") {
        ++m.no_route;
      } else {
        m.other_ends += x.end != "reached";
        path.push_back(x.path_length_m);
        energy.push_back(x.energy_j / 1000.0);
        time.push_back(x.time_s);
        if (std::isfinite(x.min_clearance_m)) clearance.push_back(x.min_clearance_m);
        max_ref.push_back(rad_to_deg(x.max_rate_ref));
        rms_ref.push_back(rad_to_deg(x.rms_rate_ref));
        if (x.route_length_m > 0.0) route.push_back(x.route_length_m);
      }
      ms.push_back(x.compute_ms);
      size.push_back(static_cast<double>(x.graph_vertices + x.graph_edges));
    }
    m.wins = wins[name];
    m.path_length_m = distribution(path);
    m.route_length_m = distribution(route);
    m.energy_kj = distribution(energy);
    m.time_s = distribution(time);
    m.min_clearance_m = distribution(clearance);
    m.max_rate_ref_deg_s = distribution(max_ref);
    m.rms_rate_ref_deg_s = distribution(rms_ref);
    m.compute_ms = distribution(ms);
    m.graph_size = distribution(size);
    s.methods.push_back(m);
  }
  s.claims.push_back(visibility_claim(run, rows));
  s.claims.push_back(turning_claim(run, rows));
  return s;
}

std::string outputs_line(const EvaluationRun& run, const std::string& dir, bool with_report) {
  std::string line = "wrote " + dir + "/rows.csv, run.json, results.json and summary.md" +
                     (with_report ? ", report.html and its figures" : "") + " (" + std::to_string(run.rows.size()) +
                     " rows";
  if (run.resumed > 0 && run.computed > 0) line += ", " + std::to_string(run.resumed) + " kept from the earlier run";
  return line + ")";
}

std::string skipped_line(const EvaluationRun& run) {
  if (run.manifest.skipped.empty()) return {};
  const SkippedRun& first = run.manifest.skipped.front();
  return std::to_string(run.manifest.skipped.size()) + " run(s) skipped, the first: " + first.scenario +
         (first.method.empty() ? "" : " with " + first.method) + ": " + first.error;
}

std::string summary_markdown(const EvaluationRun& run, const EvaluationSummary& s) {
  const RunManifest& m = run.manifest;
  std::ostringstream o;
  o << "# Evaluation of suite " << m.suite << "\n\n";
  std::size_t scenarios = 0;
  for (std::size_t i = 0; i < m.scenarios; ++i) {
    scenarios += static_cast<std::size_t>(i % static_cast<std::size_t>(m.shard.count)) ==
                 static_cast<std::size_t>(m.shard.index - 1);
  }
  o << scenarios << " scenarios"
    << (m.shard.count > 1 ? " (shard " + std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count) + ")" : "")
    << ", " << m.methods.size() << " methods, " << run.rows.size() << " runs";
  if (!m.skipped.empty()) o << ", " << m.skipped.size() << " skipped";
  o << ".\n\nEach cell: median / 95th percentile. Path, energy, time, clearance and turning rates are the "
       "vehicle's, simulated; a planner's route, within the vehicle's turning radius, is sailed by path following.\n\n";
  const std::vector<MethodColumn> columns = method_columns(m);
  o << "|";
  for (const MethodColumn& c : columns) o << " " << c.header << " |";
  o << "\n|";
  for (const MethodColumn& c : columns) o << (c.numeric ? "---:|" : "---|");
  o << "\n";
  for (const MethodStats& x : s.methods) {
    o << "|";
    for (const MethodColumn& c : columns) o << " " << c.cell(x) << " |";
    o << "\n";
  }
  o << "\n## The seed's claims\n\n";
  for (const ClaimCheck& c : s.claims) {
    o << "- **" << c.claim << "**: " << c.verdict << ".\n";
    for (const std::string& e : c.evidence) o << "  - " << e << "\n";
  }
  if (!m.skipped.empty()) {
    o << "\n## Skipped\n\n";
    for (const SkippedRun& k : m.skipped) {
      o << "- " << k.scenario << (k.method.empty() ? "" : " with " + k.method) << ": " << k.error << "\n";
    }
  }
  return o.str();
}

nlohmann::json results_json(const EvaluationRun& run, const EvaluationSummary& s) {
  nlohmann::json rows = nlohmann::json::array();
  for (const EvalRow& r : run.rows) {
    const MethodRun& x = r.run;
    nlohmann::json j = {{"scenario_index", r.scenario_index},
                        {"scenario", r.scenario},
                        {"method", r.method},
                        {"end", x.end},
                        {"reached", x.reached},
                        {"collided", x.collided},
                        {"unavoidable", x.unavoidable},
                        {"route_length_m", x.route_length_m},
                        {"path_length_m", x.path_length_m},
                        {"energy_kj", x.energy_j / 1000.0},
                        {"time_s", x.time_s},
                        {"max_rate_ref_deg_s", rad_to_deg(x.max_rate_ref)},
                        {"rms_rate_ref_deg_s", rad_to_deg(x.rms_rate_ref)},
                        {"max_rate_deg_s", rad_to_deg(x.max_rate)},
                        {"rms_rate_deg_s", rad_to_deg(x.rms_rate)},
                        {"heading_reversals", x.heading_reversals},
                        {"compute_ms", x.compute_ms},
                        {"graph_vertices", x.graph_vertices},
                        {"graph_edges", x.graph_edges}};
    // JSON has no infinity: no obstacles, no clearance.
    j["min_clearance_m"] = std::isfinite(x.min_clearance_m) ? nlohmann::json(x.min_clearance_m) : nlohmann::json();
    if (!x.note.empty()) j["note"] = x.note;
    rows.push_back(j);
  }
  nlohmann::json methods = nlohmann::json::array();
  for (const MethodStats& x : s.methods) {
    methods.push_back({{"method", x.method},
                       {"runs", x.runs},
                       {"reached", x.reached},
                       {"collisions", x.collisions},
                       {"unavoidable_collisions", x.unavoidable},
                       {"no_route", x.no_route},
                       {"energy_wins", x.wins},
                       {"path_length_m", dist_json(x.path_length_m)},
                       {"route_length_m", dist_json(x.route_length_m)},
                       {"energy_kj", dist_json(x.energy_kj)},
                       {"time_s", dist_json(x.time_s)},
                       {"min_clearance_m", dist_json(x.min_clearance_m)},
                       {"max_rate_ref_deg_s", dist_json(x.max_rate_ref_deg_s)},
                       {"rms_rate_ref_deg_s", dist_json(x.rms_rate_ref_deg_s)},
                       {"compute_ms", dist_json(x.compute_ms)},
                       {"graph_size", dist_json(x.graph_size)}});
  }
  nlohmann::json claims = nlohmann::json::array();
  for (const ClaimCheck& c : s.claims)
    claims.push_back({{"claim", c.claim}, {"verdict", c.verdict}, {"evidence", c.evidence}});
  nlohmann::json skipped = nlohmann::json::array();
  for (const SkippedRun& k : run.manifest.skipped) {
    skipped.push_back({{"scenario", k.scenario}, {"method", k.method}, {"error", k.error}});
  }
  return {{"suite", run.manifest.suite},
          {"scenarios", run.manifest.scenarios},
          {"methods", run.manifest.methods},
          {"skipped", skipped},
          {"summary", methods},
          {"claims", claims},
          {"rows", rows}};
}

void write_results(const std::string& dir, const EvaluationRun& run) {
  const EvaluationSummary s = summarize(run);
  const std::filesystem::path d(dir);
  write_text_file(d / "results.json", results_json(run, s).dump(1) + "\n", "results");
  write_text_file(d / "summary.md", summary_markdown(run, s), "summary");
}

}  // namespace deepguide
