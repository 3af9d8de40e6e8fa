// The MOOS-IvP export and the real helm (mission/moos_helm.hpp): the phases
// a .bhv runs, a pLogger .alog read back (hand-made logs with known answers,
// and hostile ones), and a mission sailed headless by the prebuilt pHelmIvP,
// uSimMarineV22 and pMarinePIDV22 in ../shared/tools/moos-ivp (skipped with a
// message where they are absent): every phase in order to the end flag, no
// stop before it, within 5 m of the route (median) and at each phase's depth.
//
// DEEPGUIDE_MOOS_MISSION=path sails another mission (docs/MISSIONS.md's
// figures come from data/missions/sample_mission.yaml); DEEPGUIDE_MOOS_KEEP=DIR
// keeps the run's folder (the .bhv, the .moos and the .alog) there.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/moos_helm.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

struct Planned {
  Mission mission;
  MissionPlan written;
  PlannedMission planned;
  MissionPlan plan;
  ExportRoute route;
};

Planned planned(const std::string& path) {
  Mission mission = read_mission(path);
  const MissionEnvironment env = load_environment(mission);
  MissionPlan written = expand_mission(mission, env.obstacles);
  PlannedMission p = plan_mission(mission, env, written);
  MissionPlan plan = p.plan;
  ExportRoute route = export_route(mission, plan);
  return Planned{std::move(mission), std::move(written), std::move(p), std::move(plan), std::move(route)};
}

const Planned& sample() {
  static const Planned p = planned(test::source_file("data/missions/sample_mission.yaml"));
  return p;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A plan of one leg north along x = 0 to y = 100 at 10 m, then a hold.
MoosPlan one_leg() {
  MoosPlan plan{LocalFrame::from_user_crs("EPSG:32632"), Vec2(9.0, 54.0)};
  plan.phases.push_back({MoosPhase::Kind::waypoints, {Vec2(0.0, 100.0)}, 10.0, 1.5, 0.0});
  plan.phases.push_back({MoosPhase::Kind::hold, {Vec2(0.0, 100.0)}, 10.0, 0.0, 30.0});
  return plan;
}

}  // namespace

TEST(MoosHelm, PhasesHoldTheDepthOfTheirEndWaypoint) {
  const MoosPlan plan = moos_plan(sample().route);
  const std::vector<ExportWaypoint>& w = sample().route.waypoints;
  ASSERT_GE(plan.phases.size(), 5u);
  // Walk the waypoints with the phases: each leg's points are waypoints arriving at the leg's depth.
  const Vec2 origin = plan.utm.from_lonlat(plan.origin_lonlat);
  std::size_t k = 1, reaches = 0, holds = 0;
  for (const MoosPhase& p : plan.phases) {
    if (p.kind == MoosPhase::Kind::reach_depth) {
      ++reaches;
      EXPECT_GT(p.duration_s, 10.0);
      continue;  // the point's own hold (or the next leg) follows at the same place
    }
    if (p.kind == MoosPhase::Kind::hold) {
      ++holds;
      ASSERT_LT(k, w.size());
      EXPECT_DOUBLE_EQ(p.duration_s, w[k].hold_s);
      EXPECT_DOUBLE_EQ(p.depth_m, w[k].depth_m);
      ++k;
      continue;
    }
    for (const Vec2& q : p.points) {
      while (k < w.size() && (w[k].xy - w[k - 1].xy).norm() < 1e-6 && w[k].hold_s == 0.0) ++k;  // a dive in place
      ASSERT_LT(k, w.size());
      const Vec2 at = plan.utm.from_lonlat(w[k].lonlat) - origin;
      ASSERT_LT((at - q).norm(), 1e-3) << k;
      ASSERT_DOUBLE_EQ(p.depth_m, w[k].depth_m) << k;
      ++k;
    }
  }
  EXPECT_EQ(k, w.size());
  EXPECT_EQ(holds, 1u);    // the GPS fix
  EXPECT_EQ(reaches, 2u);  // up to the surface for it, and down again
  // The radii grow with the vehicle's turn: a waypoint inside the turning circle is orbited.
  EXPECT_GE(plan.slip_radius_m, sample().route.turn_radius_m);
  EXPECT_GE(plan.capture_radius_m, 3.0);
}

TEST(MoosHelm, BehaviourNamesNeverBeginWithAnother) {
  // pHelmIvP took dg_leg_10 for a duplicate of dg_leg_1 and refused the file (MALCONFIG).
  ScratchDir dir;
  const std::string path = dir.file("plan.bhv");
  export_plan(sample().mission, sample().plan, path, ExportFormat::moos);
  std::istringstream in(slurp(path));
  std::string line;
  std::vector<std::string> names;
  while (std::getline(in, line)) {
    if (line.rfind("  name      = ", 0) == 0) names.push_back(line.substr(14));
  }
  ASSERT_GE(names.size(), 10u);
  for (std::size_t a = 0; a < names.size(); ++a) {
    for (std::size_t b = 0; b < names.size(); ++b) {
      if (a == b) continue;
      ASSERT_NE(names[b].rfind(names[a], 0), 0u) << names[a] << " begins " << names[b];
    }
  }
  const std::string text = slurp(path);
  EXPECT_NE(text.find("duration  = no-time-limit"), std::string::npos);
  EXPECT_NE(text.find("endflag   = DG_DONE = true"), std::string::npos);
  EXPECT_NE(text.find("domain = depth:0:"), std::string::npos);
}

TEST(MoosHelm, ALogReadsBackAgainstThePlan) {
  ScratchDir dir;
  // 3 m east of the leg the whole way, at 10 m when the leg ends, on to the end flag.
  std::string log = "%% a pLogger header\n%% LOGSTART 1\n0.5 DG_LEG pHelmIvP 1\n1.0 DEPLOY uTimerScript true\n";
  for (int i = 0; i <= 10; ++i) {
    const double t = 1.0 + i;
    log += std::to_string(t) + " NAV_DEPTH uSimMarineV22 " + std::to_string(i) + "\n";
    log += std::to_string(t) + " NAV_X uSimMarineV22 3\n";
    log += std::to_string(t) + " NAV_Y uSimMarineV22 " + std::to_string(10 * i) + "\n";
  }
  log +=
      "11.2 DG_LEG pHelmIvP 2\n12.0 IVPHELM_ALLSTOP pHelmIvP clear\n30.0 DG_LEG pHelmIvP 3\n"
      "30.0 DG_DONE pHelmIvP true\n30.3 IVPHELM_ALLSTOP pHelmIvP NothingToDo\n";
  const MoosLog read = read_moos_alog(dir.write("run.alog", log));
  ASSERT_EQ(read.nav.size(), 11u);
  EXPECT_DOUBLE_EQ(read.nav[4].depth, 4.0);
  const SailedReport r = compare_sailed(one_leg(), read);
  EXPECT_TRUE(r.done);
  EXPECT_TRUE(r.in_order);
  EXPECT_EQ(r.phases_run, 2u);
  EXPECT_TRUE(r.allstops_before_done.empty());  // NothingToDo comes after the end
  EXPECT_NEAR(r.median_off_m, 3.0, 1e-9);
  EXPECT_NEAR(r.max_off_m, 3.0, 1e-9);
  EXPECT_NEAR(r.worst_depth_miss_m, 0.0, 1e-9);  // 10 m at the leg's end (t = 11)
  EXPECT_NEAR(r.sailed_s, 29.0, 1e-9);
  // A stop mid-route, a skipped phase and no end flag are all seen.
  const std::string bad = log.substr(0, log.find("11.2 DG_LEG")) +
                          "5.5 IVPHELM_ALLSTOP pHelmIvP MissingDecVars:depth\n11.2 DG_LEG pHelmIvP 3\n";
  const SailedReport b = compare_sailed(one_leg(), read_moos_alog(dir.write("bad.alog", bad)));
  EXPECT_FALSE(b.done);
  EXPECT_FALSE(b.in_order);
  ASSERT_EQ(b.allstops_before_done.size(), 1u);
  EXPECT_EQ(b.allstops_before_done[0], "MissingDecVars:depth");
}

TEST(MoosHelm, HostileLogsAreOneLineErrors) {
  ScratchDir dir;
  EXPECT_THROW(read_moos_alog(dir.file("missing.alog")), InputError);
  EXPECT_THROW(read_moos_alog(dir.write("empty.alog", "%% nothing\n")), InputError);
  try {
    read_moos_alog(dir.write("bad.alog", "1.0 NAV_X uSimMarineV22 east\n"));
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("NAV_X"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(MoosHelm, TheRealHelmSailsTheExportToItsEnd) {
  const auto tools = std::filesystem::path(DEEPGUIDE_SOURCE_DIR) / ".." / "shared" / "tools" / "moos-ivp";
  if (!std::filesystem::exists(tools / "bin" / "pHelmIvP")) {
    GTEST_SKIP() << "the MOOS-IvP binaries are absent (" << tools.lexically_normal().string()
                 << "): skipping the run with the real helm";
  }
  const char* other = std::getenv("DEEPGUIDE_MOOS_MISSION");
  const std::string mission_file = other ? std::string(other) : test::source_file("data/missions/moos_check.yaml");
  const Planned p = planned(mission_file);
  const MoosPlan plan = moos_plan(p.route);
  ScratchDir dir;
  // Issue 39: the mission's name goes into the .bhv (its first line); the helm reads the file whatever
  // an exportable name holds: markup, braces, MOOS's own separators and comment marks, CJK, an emoji,
  // a right-to-left override.
  Mission named = p.mission;
  named.name = "<a href=\"x\">&amp;</a> ]] {dg} = , // # %s \u822a\u8def \U0001F6A2 \u202Eevil";
  export_plan(named, p.plan, dir.file("mission.bhv"), ExportFormat::moos);
  ASSERT_NE(slurp(dir.file("mission.bhv")).find(named.name), std::string::npos);
  double deepest = 0.0;
  for (const ExportWaypoint& w : p.route.waypoints) deepest = std::max(deepest, w.depth_m);
  MoosCommunityOptions options;
  std::random_device rd;
  options.port = 9100 + static_cast<int>(rd() % 800);  // beside another community on this machine
  { std::ofstream(dir.file("mission.moos")) << moos_community(plan, deepest, p.route.max_speed_mps, options); }
  // pAntler runs until told; stop it once the helm posts the end flag (or after 15 simulated
  // minutes per kilometre, at the warp, and a margin).
  const int limit_s = 60 + static_cast<int>(p.plan.length_m / 1000.0 * 900.0 / options.time_warp);
  const std::string bin = (tools / "bin").string(), lib = (tools / "lib").string();
  std::ofstream(dir.file("sail.sh"))
      << "cd '" << dir.path().string() << "' || exit 2\nexport PATH='" << (tools / "bin").string()
      << "':$PATH LD_LIBRARY_PATH='" << (tools / "lib").string() << "'\ntimeout -s INT " << limit_s
      << " pAntler mission.moos >antler.out 2>&1 &\npid=$!\nfor i in $(seq 1 " << limit_s << "); do\n  sleep 1\n"
      << "  if grep -qE '^[0-9.]+ +DG_DONE +pHelmIvP +true' sail/sail.alog 2>/dev/null; then sleep 2; break; fi\n"
      << "  kill -0 $pid 2>/dev/null || break\ndone\nkill -INT $pid 2>/dev/null\nwait $pid\nexit 0\n";
  ASSERT_EQ(std::system(("bash '" + dir.file("sail.sh") + "' >/dev/null 2>&1").c_str()), 0);
  ASSERT_TRUE(std::filesystem::exists(dir.file("sail/sail.alog"))) << slurp(dir.file("antler.out")).substr(0, 2000);
  const MoosLog log = read_moos_alog(dir.file("sail/sail.alog"));
  const SailedReport r = compare_sailed(plan, log);
  if (const char* keep = std::getenv("DEEPGUIDE_MOOS_KEEP")) {
    // The track the helm sailed over the plan, in the mission's frame (docs/images/moos_sailed.png).
    MissionFigure figure = mission_figure_for(p.mission, p.written, p.planned);
    const Vec2 origin = plan.utm.from_lonlat(plan.origin_lonlat);
    for (const MoosLog::Nav& s : log.nav) {
      if (log.deploy_s && s.t < *log.deploy_s) continue;
      figure.track.push_back(p.mission.frame.from_lonlat(plan.utm.to_lonlat(origin + Vec2(s.x, s.y))));
    }
    char title[200];
    std::snprintf(title, sizeof title, "%s sailed by pHelmIvP + uSimMarineV22: median %.1f m off the route, %.0f s",
                  p.mission.name.c_str(), r.median_off_m, r.sailed_s);
    figure.title = title;
    render_mission(figure, dir.file("sailed.png"));
    std::filesystem::copy(dir.path(), keep,
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  }
  std::printf(
      "sailed %s: %zu phases, done %d, in order %d, %.0f s; off the route median %.2f m, 95th %.2f m, "
      "max %.2f m; worst depth miss %.2f m (phase %zu)\n",
      mission_file.c_str(), plan.phases.size(), r.done, r.in_order, r.sailed_s, r.median_off_m, r.p95_off_m,
      r.max_off_m, r.worst_depth_miss_m, r.worst_depth_phase);
  ASSERT_FALSE(log.helm_states.empty());
  for (const std::string& s : log.helm_states) EXPECT_NE(s, "MALCONFIG");
  EXPECT_TRUE(r.done);
  EXPECT_TRUE(r.in_order) << r.phases_run << " of " << plan.phases.size() << " phases ended";
  EXPECT_TRUE(r.allstops_before_done.empty()) << r.allstops_before_done.front();
  EXPECT_LT(r.median_off_m, 5.0);
  EXPECT_LT(r.worst_depth_miss_m, 1.0) << "phase " << r.worst_depth_phase;
}
