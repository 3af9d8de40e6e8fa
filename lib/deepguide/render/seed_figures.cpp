#include "deepguide/render/seed_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/render/field_figure.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "deepguide/render/route_scene.hpp"
#include "deepguide/render/trajectory_figure.hpp"
#include "deepguide/render/turn_rate_plot.hpp"
#include "deepguide/simulation/mission_run.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;

const char* const kEncounter = "data/missions/encounter.yaml";
const char* const kEncounterUnknown = "data/missions/encounter_unknown.geojson";
const char* const kObstacleField = "data/scenarios/obstacle_field.yaml";
const char* const kOneObstacle = "data/scenarios/one_obstacle.yaml";
// Files those name in turn: checked with them, so a candidate folder holding
// only the four above is not taken for the data.
const char* const kVehicle = "data/vehicles/deepc.yaml";
const char* const kKnownObstacles = "data/sample_obstacles.geojson";

constexpr double kFig4PlanningDelay_s = 30.0;
constexpr double kFig4Zoom_m = 200.0;
constexpr double kFig6Tolerance_m = 2.0;
constexpr double kFig7MinCell_m = 4.0;
const ReactiveMethod kCompared[] = {ReactiveMethod::dipole, ReactiveMethod::geometric};

// What one drawing needs: where its inputs are, where it goes, how wide.
struct Job {
  std::string root;
  std::string path;
  int width_px = 1200;
  std::string input(const char* relative) const { return (fs::path(root) / relative).string(); }
};

std::string title(int number, const std::string& what) { return "Fig. " + std::to_string(number) + " (seed): " + what; }

// A clearance for the summaries: "none" where nothing was near (+inf).
std::string metres(double m, int digits) { return std::isfinite(m) ? fixed(m, digits) + " m" : std::string("none"); }

WrittenSeedFigure fig4_two_levels(const Job& job) {
  const LoadedMission l = load_mission(job.input(kEncounter));
  const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
  const ObstacleSet unknown = load_obstacles({job.input(kEncounterUnknown)}, {l.mission.frame.id(), ""}).obstacles;
  MissionRunOptions options;
  options.planning_delay_s = kFig4PlanningDelay_s;
  const MissionRun run = run_mission(l.mission, l.env, planned.plan, unknown, options);
  MissionFigure f = simulated_mission_figure(l.mission, l.plan, planned, run, kFig4Zoom_m);
  f.width_px = job.width_px;
  f.title = title(4, f.marks.empty() ? "the two levels of control: " + std::string(run.completed ? "" : "NOT ") +
                                           "completed, the reactive level never steered"
                                     : std::string("the reactive level reacts at A, the repaired plan is sailed") +
                                           (run.completed && !run.collided ? "" : " (NOT completed safely)"));
  render_mission(f, job.path);

  double reactive_s = 0.0;
  for (std::size_t k = 1; k < run.track.size(); ++k) {
    if (run.track[k].reactive) reactive_s += run.track[k].time_s - run.track[k - 1].time_s;
  }
  WrittenSeedFigure w;
  w.facts = {{"completed", run.completed ? 1.0 : 0.0},
             {"collided", run.collided ? 1.0 : 0.0},
             {"found", static_cast<double>(run.detected.size())},
             {"replans", static_cast<double>(run.replans)},
             {"reactive_s", reactive_s},
             {"time_s", run.time_s},
             {"min_clearance_m", run.min_clearance_m}};
  w.summary = std::string(run.completed ? "completed" : "NOT completed") + " in " + clock_text(run.time_s) + ", " +
              std::to_string(run.detected.size()) + " object(s) found, reactive level " + fixed(reactive_s, 0) +
              " s, " + std::to_string(run.replans) + " replan(s), least clearance " + metres(run.min_clearance_m, 1) +
              (run.collided ? ", COLLIDED" : "");
  return w;
}

// Figs. 6 and 7: a planning graph over the obstacle scenario and its route.
WrittenSeedFigure graph_figure(const Job& job, int number, GraphKind kind) {
  const Scenario sc = read_scenario_file(job.input(kObstacleField));
  ObstacleSet obstacles;
  obstacles.ellipses = sc.obstacles;
  PlannerOptions options;
  options.margin = sc.reactive.margin_m;
  options.graph = kind;
  if (graph_entry(kind).can.steps) {
    // A cell graph covers a work area: the box over start, target and every zone, a tenth wider: the route
    // may pass outside the obstacles' box.
    const auto [lo, hi] = footprint_box(obstacles);
    WorldBox box;
    box.extend((lo - Vec2::Constant(options.margin)).cwiseMin(sc.start).cwiseMin(sc.target));
    box.extend((hi + Vec2::Constant(options.margin)).cwiseMax(sc.start).cwiseMax(sc.target));
    box = box.padded(0.1 * std::max(box.width(), box.height()));
    options.quadtree.min_cell_m = kFig7MinCell_m;
    options.quadtree.area_min = box.min;
    options.quadtree.area_max = box.max;
  } else {
    options.tolerance = kFig6Tolerance_m;
  }
  Planner planner(obstacles, options);
  const PlanOutcome outcome = planner.solve({sc.start, sc.target, false});
  const PlanResult& r = outcome.result;
  if (!r.found) {
    throw InputError(printable(job.input(kObstacleField), 200) +
                     ": expected a route from start to target, got none: " + r.message);
  }

  RouteScene scene;
  scene.obstacles = &obstacles;
  scene.margin = options.margin;
  scene.route = r.route.points;
  scene.start = sc.start;
  scene.goal = sc.target;
  scene.graph_edges = planner.graph_edges();
  if (const auto* visibility = planner.graph().as<ZoneVisibilityGraph>()) {
    if (!visibility->zones().empty()) scene.zone_polygons = &visibility->zones();
  }
  std::size_t free_cells = 0, cells = 0;
  const QuadtreeGraph* q = planner.graph().as<QuadtreeGraph>();
  if (q != nullptr) {
    for (const auto& leaf : q->tree().leaves()) {
      auto& list = leaf.state == CellState::free ? scene.free_cells : scene.occupied_cells;
      // The root overhangs the work area; what lies beyond it is no cell of the graph.
      const auto b = q->tree().box(leaf);
      const Vec2 lo = b.min.cwiseMax(options.quadtree.area_min), hi = b.max.cwiseMin(options.quadtree.area_max);
      if (!(lo.x() < hi.x() && lo.y() < hi.y())) continue;
      list.emplace_back(lo, hi);
      ++cells;
      free_cells += leaf.state == CellState::free ? 1 : 0;
    }
  }
  const std::string sizes =
      std::to_string(r.stats.graph_vertices) + " vertices, " + std::to_string(r.stats.graph_edges) + " edges";
  const std::string route =
      "route " + fixed(r.route.length(), 1) + " m, " + std::to_string(r.route.points.size()) + " waypoints";
  scene.title = title(number, (q != nullptr ? "quadtree graph, " : "visibility graph, ") + sizes + "; " + route +
                                  " (margin " + general(options.margin) + " m)");
  render_route(scene, job.path, job.width_px);

  WrittenSeedFigure w;
  w.facts = {{"vertices", static_cast<double>(r.stats.graph_vertices)},
             {"edges", static_cast<double>(r.stats.graph_edges)},
             {"route_m", r.route.length()},
             {"waypoints", static_cast<double>(r.route.points.size())},
             {"min_clearance_m", outcome.check.min_clearance_m}};
  w.summary = sizes + ", " + route + ", least clearance " + metres(outcome.check.min_clearance_m, 2);
  if (q != nullptr) {
    w.facts["cells"] = static_cast<double>(cells);
    w.facts["free_cells"] = static_cast<double>(free_cells);
    w.summary = std::to_string(cells) + " cells (" + std::to_string(free_cells) + " free), " + w.summary;
  } else {
    // The yardstick: the exact tangent graph's optimum along the zones' curves.
    PlannerOptions exact;
    exact.margin = options.margin;
    exact.graph = GraphKind::tangent;
    const PlanOutcome best = Planner(obstacles, exact).solve({sc.start, sc.target, false});
    if (best.result.found) {
      w.facts["optimum_m"] = best.result.exact_length_m;
      w.summary += " (the exact optimum " + fixed(best.result.exact_length_m, 1) + " m)";
    }
  }
  return w;
}

// Figs. 8 and 10: one method's gradient lines round one obstacle.
WrittenSeedFigure field_figure(const Job& job, int number, const ReactiveMethod& method, const std::string& what) {
  FieldFigure figure = field_figure_for(read_scenario_file(job.input(kOneObstacle)), method);
  figure.width_px = job.width_px;
  figure.map.title = title(number, what);
  const FieldFigureGeometry g = render_field_figure(figure, job.path);
  WrittenSeedFigure w;
  w.facts = {{"lines", static_cast<double>(g.lines.size())}, {"dividing_lines", static_cast<double>(g.dividing)}};
  w.summary = std::to_string(g.lines.size()) + " gradient lines";
  return w;
}

// The compared methods' results, as facts "METHOD_NAME" and a summary of
// their paths (Fig. 11) or of their turning rates (Fig. 12).
void add_runs(WrittenSeedFigure& w, const std::vector<SimulationResult>& runs, bool rates) {
  for (const SimulationResult& run : runs) {
    const std::string m(to_string(run.method));
    const SimulationStats& s = run.stats;
    w.facts[m + "_reached"] = s.reached ? 1.0 : 0.0;
    w.facts[m + "_collided"] = s.collided ? 1.0 : 0.0;
    w.facts[m + "_path_m"] = s.path_length_m;
    w.facts[m + "_min_clearance_m"] = s.min_clearance_m;
    w.facts[m + "_max_r_ref_deg_s"] = rad_to_deg(s.max_abs_rate_ref);
    w.facts[m + "_rms_r_ref_deg_s"] = rad_to_deg(s.rms_rate_ref);
    w.facts[m + "_max_r_deg_s"] = rad_to_deg(s.max_abs_rate);
    if (!w.summary.empty()) w.summary += "; ";
    if (rates) {
      w.summary += m + " max |r_ref| " + fixed(rad_to_deg(s.max_abs_rate_ref), 1) + " deg/s (RMS " +
                   fixed(rad_to_deg(s.rms_rate_ref), 2) + "), max |r| " + fixed(rad_to_deg(s.max_abs_rate), 1) +
                   " deg/s";
    } else {
      w.summary += m + " " + fixed(s.path_length_m, 0) + " m, least clearance " + metres(s.min_clearance_m, 1) +
                   (s.collided ? ", COLLIDED" : "") + (s.reached ? "" : ", target not reached");
    }
  }
}

WrittenSeedFigure fig11_paths(const Job& job) {
  TrajectoryFigure figure = trajectory_figure_for(read_scenario_file(job.input(kObstacleField)), kCompared);
  figure.width_px = job.width_px;
  figure.map.title = title(11, "paths through the obstacle scenario");
  render_trajectory_figure(figure, job.path);
  WrittenSeedFigure w;
  add_runs(w, figure.runs, false);
  return w;
}

WrittenSeedFigure fig12_turning_rates(const Job& job) {
  TurnRatePlot plot = turn_rate_plot_for(read_scenario_file(job.input(kObstacleField)), kCompared);
  plot.width_px = job.width_px;
  plot.title = title(12, "the reference turning rate r_ref (and the vehicle's r)");
  render_turn_rate_plot(plot, job.path);
  WrittenSeedFigure w;
  add_runs(w, plot.runs, true);
  return w;
}

WrittenSeedFigure draw(int number, const Job& job) {
  switch (number) {
    case 4: return fig4_two_levels(job);
    case 6: return graph_figure(job, 6, GraphKind::visibility_full);
    case 7: return graph_figure(job, 7, GraphKind::quadtree);
    case 8: return field_figure(job, 8, ReactiveMethod::dipole, "gradient lines of the harmonic dipole potential");
    case 10: return field_figure(job, 10, ReactiveMethod::geometric, "gradient lines by geometric construction");
    case 11: return fig11_paths(job);
    case 12: return fig12_turning_rates(job);
    default: break;
  }
  throw InputError("figure " + std::to_string(number) + ": not drawn here");  // seed_figure_specs() and draw() disagree
}

std::string known_numbers() {
  std::string out;
  for (const SeedFigureSpec& s : seed_figure_specs()) out += (out.empty() ? "" : ", ") + std::to_string(s.number);
  return out;
}

}  // namespace

const std::vector<SeedFigureSpec>& seed_figure_specs() {
  static const std::vector<SeedFigureSpec> specs = {
      {4,
       "fig04_two_levels",
       "route by the two levels of control: reactive reaction at A, then the repaired plan",
       {kEncounter, kEncounterUnknown, kKnownObstacles, kVehicle}},
      {6,
       "fig06_visibility_graph",
       "visibility graph over the obstacle scenario and its shortest route",
       {kObstacleField, kVehicle}},
      {7,
       "fig07_quadtree_graph",
       "quadtree graph over the same obstacles and its shortest route",
       {kObstacleField, kVehicle}},
      {8, "fig08_dipole_gradient_lines", "gradient lines of the harmonic dipole potential", {kOneObstacle, kVehicle}},
      {10, "fig10_geometric_gradient_lines", "gradient lines by geometric construction", {kOneObstacle, kVehicle}},
      {11,
       "fig11_paths",
       "paths of the dipole method and the geometric construction through the obstacle scenario",
       {kObstacleField, kVehicle}},
      {12, "fig12_turning_rates", "reference turning rate r_ref of both methods over time", {kObstacleField, kVehicle}},
  };
  return specs;
}

std::string locate_seed_data(const std::vector<std::string>& candidates) {
  std::string why;
  for (const std::string& c : candidates) {
    if (c.empty()) continue;
    std::string missing;
    for (const SeedFigureSpec& s : seed_figure_specs()) {
      for (const std::string& in : s.inputs) {
        std::error_code ec;
        if (missing.empty() && !fs::is_regular_file(fs::path(c) / in, ec)) missing = in;
      }
    }
    if (missing.empty()) return c;
    why += (why.empty() ? "" : "; ") + printable(c, 200) + " lacks " + missing;
  }
  throw InputError("the bundled data: expected a folder holding data/scenarios and data/missions (`data_root`), got " +
                   (why.empty() ? std::string("no candidate") : why));
}

std::vector<WrittenSeedFigure> write_seed_figures(const SeedFigureOptions& options,
                                                  const std::function<void(const WrittenSeedFigure&)>& on_written) {
  if (options.extension != "png" && options.extension != "svg") {
    throw InputError("figure format: expected png or svg, got '" + printable(options.extension) + "'");
  }
  if (options.width_px < kMinImageWidth || options.width_px > kMaxImageWidth) {
    throw InputError("figure width: expected " + std::to_string(kMinImageWidth) + " to " +
                     std::to_string(kMaxImageWidth) + " px, got " + std::to_string(options.width_px));
  }
  std::vector<const SeedFigureSpec*> chosen;
  for (int n : options.only) {
    const auto& specs = seed_figure_specs();
    const auto it = std::find_if(specs.begin(), specs.end(), [n](const SeedFigureSpec& s) { return s.number == n; });
    if (it == specs.end()) {
      throw InputError("figure " + std::to_string(n) + ": expected one of the seed's figures " + known_numbers());
    }
    if (std::find(chosen.begin(), chosen.end(), &*it) == chosen.end()) chosen.push_back(&*it);
  }
  if (options.only.empty()) {
    for (const SeedFigureSpec& s : seed_figure_specs()) chosen.push_back(&s);
  }
  std::sort(chosen.begin(), chosen.end(), [](const auto* a, const auto* b) { return a->number < b->number; });
  // Every input is checked before anything is drawn: a missing file names itself at once.
  (void)locate_seed_data({options.data_root});

  std::error_code ec;
  const fs::path out(options.output_dir);
  const std::string shown = printable(options.output_dir, 200);
  if (options.output_dir.empty()) throw InputError("the figures' folder: expected a folder (-o DIR), got nothing");
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    throw InputError(shown + ": expected a folder for the figures, got a file");
  }
  const bool made = !fs::exists(out, ec);
  fs::create_directories(out, ec);
  if (ec) throw InputError(shown + ": cannot make the figures' folder: " + ec.message());

  // All or nothing: the figures are drawn into a folder of their own inside
  // the output folder (so the renames stay on one file system) and moved out
  // only when every one has been drawn. On an error that folder goes, and so
  // does the output folder when this call made it.
  remove_stale_temporaries(out);
  const fs::path staging = temporary_path(out, "deepguide-figures");
  struct Cleanup {
    fs::path staging, out;
    bool made;
    bool armed = true;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(staging, ignored);
      if (armed && made) fs::remove(out, ignored);  // only if empty
    }
  } cleanup{staging, out, made};
  fs::create_directory(staging, ec);
  if (ec) throw InputError(shown + ": cannot write the figures there: " + ec.message());

  std::vector<WrittenSeedFigure> written;
  for (const SeedFigureSpec* s : chosen) {
    const std::string file = s->stem + "." + options.extension;
    const Job job{options.data_root, (staging / file).string(), options.width_px};
    WrittenSeedFigure w = draw(s->number, job);
    w.number = s->number;
    w.path = (out / file).string();
    written.push_back(std::move(w));
  }
  for (const WrittenSeedFigure& w : written) {
    fs::rename(staging / fs::path(w.path).filename(), w.path, ec);
    if (ec) throw InputError(printable(w.path, 200) + ": cannot put the figure in place: " + ec.message());
  }
  cleanup.armed = false;
  if (on_written) {
    for (const WrittenSeedFigure& w : written) on_written(w);
  }
  return written;
}

std::string to_text(const WrittenSeedFigure& w) {
  return printf_text("Fig. %-3d %s\n         %s\n", w.number, w.path.c_str(), w.summary.c_str());
}

nlohmann::json seed_figures_json(const std::string& data_root, const std::vector<WrittenSeedFigure>& figures) {
  nlohmann::json list = nlohmann::json::array();
  for (const WrittenSeedFigure& w : figures) {
    list.push_back({{"figure", w.number}, {"file", w.path}, {"summary", w.summary}, {"facts", w.facts}});
  }
  return {{"data", data_root}, {"figures", list}};
}

}  // namespace deepguide
