// deepguide mission check MISSION.yaml [--json]: the mission's complex
// manoeuvres as basic ones, and what endangers them (docs/MISSIONS.md).

#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission_environment.hpp"

namespace deepguide::app {
namespace {

struct MissionOptions {
  std::string mission;
  bool json = false;
};

const char* kind_name(BasicManoeuvre::Kind kind) {
  switch (kind) {
    case BasicManoeuvre::Kind::line: return "line";
    case BasicManoeuvre::Kind::arc: return "arc";
    case BasicManoeuvre::Kind::point: return "point";
  }
  return "?";
}

}  // namespace

void register_mission(CLI::App& app) {
  CLI::App* mission = app.add_subcommand("mission", "Mission plans: check (basic manoeuvres and conflicts)");
  mission->require_subcommand(1);
  auto o = std::make_shared<MissionOptions>();
  CLI::App* check = mission->add_subcommand(
      "check", "Read a mission, expand it into basic manoeuvres and list the obstacles and shoals that endanger them");
  check->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  check->add_flag("--json", o->json, "Print the result as JSON");
  check->callback([o] {
    const Mission m = read_mission(o->mission);
    const MissionEnvironment env = load_environment(m);
    check_positions(m, env);
    const MissionPlan plan = expand_mission(m, env.obstacles);
    ObservationOptions observe;
    observe.margin_m = m.margin_m;
    observe.vertical_clearance_m = m.vertical_clearance_m;
    const std::vector<Conflict> conflicts = observe_collisions(plan, env.obstacles, env.floor.get(), observe);
    double time_s = 0.0;
    for (const BasicManoeuvre& b : plan.basics) time_s += b.hold_s + (b.speed_mps > 0.0 ? b.length_m / b.speed_mps : 0.0);
    const auto lonlat = [&](const Vec2& p) { return m.frame.to_lonlat(p); };
    if (o->json) {
      nlohmann::json j = {{"mission", m.name},           {"file", o->mission},
                          {"crs", m.frame.id()},          {"manoeuvres", m.manoeuvres.size()},
                          {"basic_manoeuvres", plan.basics.size()}, {"length_m", plan.length_m},
                          {"time_s", time_s},             {"obstacles", env.obstacles.size()},
                          {"sea_floor", env.floor != nullptr}, {"warnings", plan.warnings}};
      nlohmann::json list = nlohmann::json::array();
      for (const Conflict& c : conflicts) {
        const Vec2 ll = lonlat(c.where);
        list.push_back({{"along_m", c.along_m},
                        {"manoeuvre", m.manoeuvres[plan.basics[c.basic].source].name},
                        {"basic", c.basic},
                        {"basics", c.last_basic - c.basic + 1},
                        {"kind", kind_name(plan.basics[c.basic].kind)},
                        {"with", c.with},
                        {"depth_m", c.depth_m},
                        {"lon", ll.x()},
                        {"lat", ll.y()}});
      }
      j["conflicts"] = list;
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::printf("mission          %s (%s, %s)\n", m.name.c_str(), o->mission.c_str(), m.frame.id().c_str());
    std::printf("manoeuvres       %zu complex, %zu basic; %.0f m, %.0f s (%.1f h) at their speeds and holds\n",
                m.manoeuvres.size(), plan.basics.size(), plan.length_m, time_s, time_s / 3600.0);
    std::printf("environment      %zu obstacle(s), %s\n", env.obstacles.size(),
                env.floor ? "a sea floor from the chart" : "no sea floor (no bathymetry chart)");
    for (const std::string& w : plan.warnings) std::printf("warning          %s\n", w.c_str());
    std::printf("%4s %-40s %6s %10s %9s\n", "#", "manoeuvre", "basics", "from m", "length m");
    for (std::size_t i = 0; i < m.manoeuvres.size(); ++i) {
      std::size_t count = 0;
      double from = -1.0, length = 0.0;
      for (const BasicManoeuvre& b : plan.basics) {
        if (b.source != i) continue;
        if (count++ == 0) from = b.start_m;
        length += b.length_m;
      }
      std::printf("%4zu %-40s %6zu %10.0f %9.0f\n", i + 1, (m.manoeuvres[i].type + " '" + m.manoeuvres[i].name + "'").substr(0, 40).c_str(),
                  count, from, length);
    }
    if (conflicts.empty()) {
      std::printf("conflicts        none: no obstacle or shoal endangers the plan\n");
      return;
    }
    std::printf("conflicts        %zu (corridor %.1f m = margin + half the width; %.1f m over tops and the floor)\n",
                conflicts.size(), m.margin_m + observe.half_width_m, m.vertical_clearance_m);
    std::printf("%9s  %-28s %-10s %-24s %7s  %s\n", "along m", "manoeuvre", "basic", "with", "depth m", "lon, lat");
    for (const Conflict& c : conflicts) {
      const Vec2 ll = lonlat(c.where);
      const BasicManoeuvre& b = plan.basics[c.basic];
      const std::string basics = c.last_basic > c.basic ? std::to_string(c.last_basic - c.basic + 1) + " basics"
                                                        : std::string(kind_name(b.kind));
      std::printf("%9.0f  %-28s %-10s %-24s %7.1f  %.5f, %.5f\n", c.along_m,
                  m.manoeuvres[b.source].name.substr(0, 28).c_str(), basics.c_str(), c.with.substr(0, 24).c_str(),
                  c.depth_m, ll.x(), ll.y());
    }
  });
}

}  // namespace deepguide::app
