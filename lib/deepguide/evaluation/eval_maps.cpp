#include "deepguide/evaluation/eval_maps.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/evaluation/eval_method.hpp"
#include "deepguide/render/scenario_web_map.hpp"

namespace deepguide {

namespace {

constexpr std::size_t kCollisionsPerMethod = 5;
constexpr std::size_t kPages = 20;

}  // namespace

std::vector<EvaluationMap> write_evaluation_maps(const Suite& suite, const EvaluationRun& run, const std::string& dir) {
  // Which scenarios, and why: per method its least clearance, then its collisions.
  std::map<std::size_t, std::string> chosen;  // scenario index -> why
  const auto choose = [&](std::size_t index, const std::string& why) {
    if (chosen.size() >= kPages && !chosen.count(index)) return;
    std::string& reasons = chosen[index];
    reasons += (reasons.empty() ? "" : "; ") + why;
  };
  for (const std::string& method : run.manifest.methods) {
    const EvalRow* closest = nullptr;
    std::size_t collisions = 0;
    for (const EvalRow& r : run.rows) {
      if (r.method != method || !std::isfinite(r.run.min_clearance_m) || r.run.end == "no_route") continue;
      if (closest == nullptr || r.run.min_clearance_m < closest->run.min_clearance_m) closest = &r;
    }
    if (closest != nullptr) {
      choose(closest->scenario_index,
             "least clearance of " + method + " (" + fixed(closest->run.min_clearance_m, 2) + " m)");
    }
    for (const EvalRow& r : run.rows) {
      if (r.method == method && r.run.collided && collisions++ < kCollisionsPerMethod) {
        choose(r.scenario_index, method + " collided");
      }
    }
  }
  std::vector<EvalMethod> methods;
  for (const std::string& m : run.manifest.methods) methods.push_back(parse_eval_method(m));
  // The folder is this run's: an earlier run's pages go.
  const std::filesystem::path folder = std::filesystem::path(dir) / "maps";
  std::error_code ec;
  std::filesystem::remove_all(folder, ec);
  std::filesystem::create_directories(folder, ec);
  if (ec) throw InputError(folder.string() + ": could not make the folder for the maps (" + ec.message() + ")");
  std::vector<EvaluationMap> out;
  for (const auto& [index, why] : chosen) {
    const Scenario scenario = load_suite_scenario(suite, index);
    std::vector<ScenarioTrack> tracks;
    for (const EvalMethod& m : methods) {
      const MethodRun r = run_method(scenario, m, true);
      tracks.push_back({m.name, r.end, r.note, r.collided, r.min_clearance_m, r.path_length_m, r.route, r.track});
    }
    const std::string id = suite.scenarios.at(index).id;
    const std::string file = "maps/" + id + ".html";
    write_web_map(scenario_web_map(scenario, id + ": " + why, tracks), (std::filesystem::path(dir) / file).string());
    out.push_back({id, file, why});
  }
  return out;
}

}  // namespace deepguide
