// The mission figure: the sample mission's plan drawn over its chart, each
// part in the colour of its role (read back from the pixels at the middle of
// the longest line of each role), and the CLI writing it or refusing bad
// output names with no file left.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "deepguide/mission/mission_control.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

using test::colour_distance;

TEST(MissionFigure, EachPartIsDrawnInTheColourOfItsRole) {
  const Mission m = read_mission(test::source_file("data/missions/sample_mission.yaml"));
  const MissionEnvironment env = load_environment(m);
  const MissionPlan written = expand_mission(m, env.obstacles);
  const PlannedMission planned = plan_mission(m, env, written);
  MissionFigure f = mission_figure_for(m, written, planned);
  EXPECT_EQ(f.plan, &planned.plan);
  EXPECT_EQ(f.written, &written);
  EXPECT_EQ(f.conflicts.size(), planned.resolutions.size());
  EXPECT_TRUE(f.unresolved.empty());
  EXPECT_EQ(f.crs, "EPSG:32632");
  f.width_px = 900;
  ScratchDir dir;
  const std::string path = dir.file("mission.png");
  const MissionStyle style;
  const ChartLayout layout = render_mission(f, path, style);
  const test::Png png(path);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 900);
  // The middle of the longest line or arc of each role (the identification
  // laps are arcs) carries that role's colour.
  for (const auto& [role, colour] : {std::pair{BasicManoeuvre::Role::mission, style.mission},
                                     std::pair{BasicManoeuvre::Role::evasion, style.evasion},
                                     std::pair{BasicManoeuvre::Role::identification, style.identification}}) {
    const BasicManoeuvre* longest = nullptr;
    for (const BasicManoeuvre& b : planned.plan.basics) {
      if (b.role == role && b.kind != BasicManoeuvre::Kind::point && (!longest || b.length_m > longest->length_m)) {
        longest = &b;
      }
    }
    ASSERT_NE(longest, nullptr);
    const Vec2 mid = layout.view.to_pixel(longest->point_at(0.5 * longest->length_m));
    EXPECT_LE(colour_distance(png.at(mid), colour), 12) << static_cast<int>(role);
  }
  EXPECT_THROW(render_mission(MissionFigure{}, dir.file("none.png")), InputError);
}

TEST(MissionFigure, TheCliWritesItAndRefusesABadName) {
  ScratchDir dir;
  const std::string mission = test::source_file("data/missions/sample_mission.yaml");
  const auto ok = test::run_cli("render mission '" + mission + "' -o '" + dir.file("m.svg") + "' --width 600");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_GT(std::filesystem::file_size(dir.file("m.svg")), 1000u);
  const auto bad = test::run_cli("render mission '" + mission + "' -o '" + dir.file("m.bmp") + "'");
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.bmp")));
}
