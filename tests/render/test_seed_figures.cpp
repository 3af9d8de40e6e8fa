// The seed's figures (render/seed_figures.hpp): every one written from the
// bundled data, and the numbers behind them checked independently: the
// visibility route against the exact tangent-graph optimum and its clearance,
// the quadtree route longer than it (the seed's reason for the visibility
// graph), the geometric construction turning less than the dipole method
// (Fig. 12's point), the two levels of Fig. 4 each taking part. Then the
// reactive part of Fig. 4's track in its own colour, a subset and SVG, and
// bad input (unknown figure, format, width, output folder, data) through the
// library and the CLI: one line, exit 1, nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "deepguide/render/seed_figures.hpp"
#include "deepguide/simulation/mission_run.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::run_cli;
using deepguide::test::ScratchDir;
using deepguide::test::source_file;

namespace {

SeedFigureOptions options_into(const ScratchDir& dir, const std::string& sub = "figs") {
  SeedFigureOptions o;
  o.data_root = DEEPGUIDE_SOURCE_DIR;
  o.output_dir = dir.file(sub);
  return o;
}

const WrittenSeedFigure& figure(const std::vector<WrittenSeedFigure>& all, int number) {
  for (const WrittenSeedFigure& w : all) {
    if (w.number == number) return w;
  }
  throw std::runtime_error("figure " + std::to_string(number) + " was not written");
}

std::size_t files_in(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return 0;
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

}  // namespace

TEST(SeedFigures, EveryFigureIsWrittenWithTheNumbersBehindIt) {
  ScratchDir dir;
  std::vector<int> reported;
  const auto written =
      write_seed_figures(options_into(dir), [&](const WrittenSeedFigure& w) { reported.push_back(w.number); });
  const std::vector<int> seed_order{4, 6, 7, 8, 10, 11, 12};
  EXPECT_EQ(reported, seed_order);
  ASSERT_EQ(written.size(), 7u);
  for (const WrittenSeedFigure& w : written) {
    const test::Png png(w.path);
    ASSERT_TRUE(png.ok()) << w.path;
    EXPECT_EQ(png.width(), 1200) << w.path;
    EXPECT_GT(png.height(), 400) << w.path;
    EXPECT_FALSE(w.summary.empty());
    EXPECT_EQ(std::filesystem::path(w.path).parent_path(), std::filesystem::path(dir.file("figs")));
  }
  EXPECT_EQ(files_in(dir.file("figs")), 7u) << "no temporary files left beside the figures";

  // Figs. 6 and 7 against an independent optimum: the exact tangent graph on
  // the same obstacles and margin, and the route checker on each route.
  const Scenario sc = read_scenario_file(source_file("data/scenarios/obstacle_field.yaml"));
  ObstacleSet obstacles;
  obstacles.ellipses = sc.obstacles;
  PlannerOptions exact;
  exact.margin = sc.reactive.margin_m;
  exact.graph = GraphKind::tangent;
  Planner tangent(obstacles, exact);
  const PlanOutcome optimum = tangent.solve({sc.start, sc.target, false});
  ASSERT_TRUE(optimum.result.found);
  const double best = optimum.result.exact_length_m;
  const auto& vis = figure(written, 6).facts;
  const auto& quad = figure(written, 7).facts;
  // A polygon route keeps outside the zones: never shorter than the optimum,
  // and with 2 m polygons within 1 % of it.
  EXPECT_NEAR(vis.at("optimum_m"), best, 1e-9);
  EXPECT_GE(vis.at("route_m"), best - 1e-6);
  EXPECT_LE(vis.at("route_m"), best * 1.01);
  EXPECT_GE(vis.at("min_clearance_m"), sc.reactive.margin_m - 1e-6);
  EXPECT_GE(quad.at("min_clearance_m"), sc.reactive.margin_m - 1e-6);
  // The seed's choice: the visibility graph is smaller and its route shorter.
  EXPECT_GT(quad.at("route_m"), vis.at("route_m") * 1.05);
  EXPECT_GT(quad.at("vertices"), vis.at("vertices"));
  EXPECT_GT(quad.at("waypoints"), vis.at("waypoints"));
  EXPECT_GT(quad.at("cells"), quad.at("free_cells"));
  EXPECT_EQ(quad.at("vertices"), quad.at("free_cells") + 2) << "free-cell centres, start and goal";

  // Figs. 8 and 10: a field of lines each.
  EXPECT_GE(figure(written, 8).facts.at("lines"), 20.0);
  EXPECT_GE(figure(written, 10).facts.at("lines"), 20.0);

  // Figs. 11 and 12 simulate the same runs; the geometric construction gets
  // through with its margin and asks for lower turning rates than the dipole.
  const auto& paths = figure(written, 11).facts;
  const auto& rates = figure(written, 12).facts;
  for (const char* m : {"dipole", "geometric"}) {
    const std::string k = std::string(m) + "_max_r_ref_deg_s";
    EXPECT_DOUBLE_EQ(paths.at(k), rates.at(k)) << "the same simulation, the same numbers";
  }
  EXPECT_EQ(rates.at("geometric_reached"), 1.0);
  EXPECT_EQ(rates.at("geometric_collided"), 0.0);
  EXPECT_GE(rates.at("geometric_min_clearance_m"), sc.reactive.margin_m - 0.5);  // steered by noisy contacts
  EXPECT_LT(rates.at("geometric_max_r_ref_deg_s"), rates.at("dipole_max_r_ref_deg_s") - 1.0);
  EXPECT_LT(rates.at("geometric_rms_r_ref_deg_s"), 0.5 * rates.at("dipole_rms_r_ref_deg_s"));

  // Fig. 4: the object found once, the reactive level steering for the
  // planner's 30 s, one repair, the mission completed without a collision.
  const auto& two = figure(written, 4).facts;
  EXPECT_EQ(two.at("completed"), 1.0);
  EXPECT_EQ(two.at("collided"), 0.0);
  EXPECT_EQ(two.at("found"), 1.0);
  EXPECT_EQ(two.at("replans"), 1.0);
  EXPECT_NEAR(two.at("reactive_s"), 30.0, 1.5);
  EXPECT_GT(two.at("min_clearance_m"), 0.0);
}

// Fig. 4's track: where the reactive level steered it carries the reactive
// colour, elsewhere the plan level's; the mark A is where it took over.
// What `figures` prints of each figure, and its JSON, with a path that is not
// UTF-8 (JSON must be: the caller dumps with replacement).
TEST(SeedFigures, TextAndJsonOfWrittenFigures) {
  const WrittenSeedFigure a{4, "out/fig04.png", "route 1824.2 m", {{"route_m", 1824.18}}};
  const WrittenSeedFigure b{6, "out/fig\xff.png", "laps 3", {}};
  EXPECT_EQ(to_text(a), "Fig. 4   out/fig04.png\n         route 1824.2 m\n");
  const nlohmann::json j = seed_figures_json("/data", {a, b});
  EXPECT_EQ(j["data"], "/data");
  ASSERT_EQ(j["figures"].size(), 2u);
  EXPECT_EQ(j["figures"][0]["figure"], 4);
  EXPECT_EQ(j["figures"][0]["facts"]["route_m"], 1824.18);
  EXPECT_EQ(j["figures"][1]["summary"], "laps 3");
  EXPECT_NO_THROW((void)j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace));
}

TEST(SeedFigures, TheReactivePartOfTheTrackHasItsOwnColour) {
  const LoadedMission l = load_mission(source_file("data/missions/encounter.yaml"));
  const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
  const ObstacleSet unknown =
      load_obstacles({source_file("data/missions/encounter_unknown.geojson")}, {l.mission.frame.id(), ""}).obstacles;
  MissionRunOptions options;
  options.planning_delay_s = 30.0;
  const MissionRun run = run_mission(l.mission, l.env, planned.plan, unknown, options);
  const MissionFigure f = simulated_mission_figure(l.mission, l.plan, planned, run, 200.0);
  ASSERT_EQ(f.track_reactive.size(), f.track.size());
  ASSERT_EQ(f.marks.size(), 1u);
  EXPECT_EQ(f.marks.front().second, "A");
  const auto begin = std::find(f.track_reactive.begin(), f.track_reactive.end(), true);
  ASSERT_NE(begin, f.track_reactive.end()) << "the reactive level steered";
  ASSERT_NE(begin, f.track_reactive.begin()) << "the plan level steered first";
  const auto first = static_cast<std::size_t>(begin - f.track_reactive.begin());
  std::size_t last = first;
  while (last + 1 < f.track.size() && f.track_reactive[last + 1]) ++last;
  ASSERT_GT(last, first + 10) << "the reactive level steered for a while";
  EXPECT_LT((f.marks.front().first - f.track[first - 1]).norm(), 1e-9);
  EXPECT_NE(f.title.find("completed in " + clock_text(run.time_s)), std::string::npos) << f.title;

  ScratchDir dir;
  const std::string path = dir.file("fig4.png");
  const MissionStyle style;
  const ChartLayout layout = render_mission(f, path, style);
  const test::Png png(path);
  ASSERT_TRUE(png.ok());
  const Vec2 reactive_mid = layout.view.to_pixel(f.track[(first + last) / 2]);
  EXPECT_LE(test::colour_distance(png.at(reactive_mid), style.reactive), 40);
  // Well before A, the plan level steered.
  ASSERT_GT(first, 60u);
  const Vec2 before = layout.view.to_pixel(f.track[first - 60]);
  ASSERT_GT(before.x(), layout.map.x + 2.0) << "60 s before A is on the map";
  ASSERT_LT(before.y(), layout.map.y + layout.map.height - 2.0);
  EXPECT_LE(test::colour_distance(png.at(before), style.track), 40);
  EXPECT_THROW(
      {
        MissionFigure bad = f;
        bad.track_reactive.pop_back();
        render_mission(bad, dir.file("bad.png"));
      },
      InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}

TEST(SeedFigures, ASubsetInSvgInTheSeedsOrder) {
  ScratchDir dir;
  SeedFigureOptions o = options_into(dir, "a/b");  // nested folders are made
  o.only = {12, 8, 12};
  o.extension = "svg";
  o.width_px = 800;
  const auto written = write_seed_figures(o);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0].number, 8);
  EXPECT_EQ(written[1].number, 12);
  EXPECT_EQ(std::filesystem::path(written[0].path).filename(), "fig08_dipole_gradient_lines.svg");
  std::ifstream in(written[1].path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("width=\"800"), std::string::npos);
  EXPECT_EQ(files_in(dir.file("a/b")), 2u);
}

TEST(SeedFigures, BadInputIsOneLineAndWritesNothing) {
  ScratchDir dir;
  SeedFigureOptions o = options_into(dir);
  o.only = {6, 5};
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"figure 5", "4, 6, 7, 8, 10, 11, 12"});
  o.only = {};
  o.extension = "jpg";
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"png or svg", "jpg"});
  o.extension = "png";
  o.width_px = 50;
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"width", "50"});
  o.width_px = 1200;
  EXPECT_FALSE(std::filesystem::exists(dir.file("figs"))) << "nothing made before the input was checked";

  const std::string file = dir.write("taken", "not a folder");
  o.output_dir = file;
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"taken", "got a file"});

  // Data without the figures' inputs: each candidate named with what it lacks.
  o.output_dir = dir.file("figs");
  o.data_root = dir.path().string();
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {dir.path().string().c_str(), "lacks data/"});
  test::expect_error(test::error_of([&] {
                       locate_seed_data({"/nonexistent-deepguide", dir.path().string()});
                     }),
                     {"/nonexistent-deepguide lacks data/missions/encounter.yaml", "`data_root`"});
  EXPECT_EQ(locate_seed_data({"/nonexistent-deepguide", DEEPGUIDE_SOURCE_DIR}), DEEPGUIDE_SOURCE_DIR);
  EXPECT_FALSE(std::filesystem::exists(dir.file("figs")));

  // A broken input file: its reader's one-line error, and no figure at all,
  // not even those drawn before it; the folder the call made goes too, and a
  // folder that was there stays with what it held.
  std::filesystem::create_directories(dir.path() / "root" / "data");
  std::filesystem::copy(source_file("data"), dir.path() / "root" / "data", std::filesystem::copy_options::recursive);
  dir.write("root/data/scenarios/obstacle_field.yaml", "name: broken\nstart: {x: 0}\n");
  o.data_root = dir.file("root");
  o.only = {8, 11};
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"obstacle_field.yaml", "start"});
  EXPECT_FALSE(std::filesystem::exists(dir.file("figs")));
  std::filesystem::create_directories(dir.path() / "kept");
  dir.write("kept/mine.txt", "mine");
  o.output_dir = dir.file("kept");
  test::expect_error(test::error_of([&] { write_seed_figures(o); }), {"obstacle_field.yaml", "start"});
  EXPECT_EQ(files_in(dir.file("kept")), 1u) << "only what was there before";
  o.only = {8};
  ASSERT_EQ(write_seed_figures(o).size(), 1u) << "the other inputs are fine";
  EXPECT_EQ(files_in(dir.file("kept")), 2u);
}

TEST(SeedFiguresCli, WritesTheChosenFiguresAndRefusesBadInput) {
  ScratchDir dir;
  const std::string out = dir.file("out");
  test::RunResult r = run_cli("figures -o '" + out + "' --only 10,8 --width 600");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Fig. 8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Fig. 10"), std::string::npos) << r.out;
  EXPECT_LT(r.out.find("Fig. 8"), r.out.find("Fig. 10"));
  const test::Png png(out + "/fig10_geometric_gradient_lines.png");
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 600);

  r = run_cli("figures -o '" + out + "' --only 6 --json --data '" + std::string(DEEPGUIDE_SOURCE_DIR) + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("figures").size(), 1u);
  EXPECT_EQ(j["figures"][0]["figure"], 6);
  EXPECT_GT(j["figures"][0]["facts"]["route_m"].get<double>(), 600.0);

  for (const std::string& bad :
       {std::string("--only 9"), std::string("--format gif"), std::string("--data /nonexistent-deepguide")}) {
    r = run_cli("figures -o '" + dir.file("bad") + "' " + bad);
    EXPECT_EQ(r.exit_code, 1) << bad << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad"))) << bad;
  }
  r = run_cli("figures");
  EXPECT_EQ(r.exit_code, 2) << "-o is required";
}
