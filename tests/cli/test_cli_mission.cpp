// deepguide mission check, end to end on the sample mission and on bad files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "deepguide/world/local_frame.hpp"
#include "test_support.hpp"

using deepguide::test::run_cli;
using deepguide::test::ScratchDir;

TEST(CliMission, CheckListsTheSampleMissionsConflicts) {
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  const auto r = run_cli("mission check '" + mission + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("manoeuvres").get<int>(), 5);
  EXPECT_TRUE(j.at("sea_floor").get<bool>());
  const auto& conflicts = j.at("conflicts");
  ASSERT_GE(conflicts.size(), 2u);
  // In order along the mission, and the survey at 20 m meets wreck-1 (top 18.6 m).
  double last = -1.0;
  bool wreck = false;
  for (const auto& c : conflicts) {
    EXPECT_GE(c.at("along_m").get<double>(), last);
    last = c.at("along_m").get<double>();
    wreck = wreck || (c.at("with") == "wreck-1" && c.at("manoeuvre") == "deep water box");
  }
  EXPECT_TRUE(wreck) << r.out;
  const auto text = run_cli("mission check '" + mission + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("conflicts"), std::string::npos) << text.out;
}

TEST(CliMission, BadMissionsAreOneLineAndExitOne) {
  ScratchDir dir;
  const std::string header = "crs: EPSG:32632\nstart: {x: 580700, y: 6033450, depth_m: 0}\n";
  const std::string chart = deepguide::test::source_file("charts/sample_chart.tif");
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {header + "manoeuvres:\n  - hover: {depth_m: 5}\n", {"line 4", "hover"}},
      {header + "manoeuvres:\n  - track: {waypoints: [{x: 1, y: 2}\n", {"line", "column"}},
      {header + "manoeuvres:\n  - survey: {line_spacing_m: 50, area: [{x: 0, y: 0}, {x: 100, y: 100}, "
                "{x: 100, y: 0}, {x: 0, y: 100}]}\n",
       {"area", "simple polygon"}},
      // (580000, 6033300) is on the sample chart's land.
      {header + "environment: {charts: ['" + chart +
           "']}\nmanoeuvres:\n  - track: {depth_m: 5, waypoints: "
           "[{x: 580000, y: 6033300}]}\n",
       {"waypoint", "on land"}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string path = dir.write("bad" + std::to_string(k) + ".yaml", cases[k].first);
    const auto r = run_cli("mission check '" + path + "'");
    EXPECT_EQ(r.exit_code, 1) << k << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const std::string& w : cases[k].second) EXPECT_NE(r.err.find(w), std::string::npos) << k << ": " << r.err;
  }
}

// mission plan|simulate --html that cannot be written: one line, exit 1,
// nothing written; over one of the mission's inputs (its chart): refused.
TEST(CliMission, AWebMapThatCannotBeWrittenIsOneLineAndNothingWritten) {
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  ScratchDir dir;
  for (const std::string command : {"mission plan", "mission simulate"}) {
    for (const auto& [html, words] : {std::pair<std::string, std::string>{dir.file("no/map.html"), "does not exist"},
                                      {dir.file("map.txt"), "ending in .html or .htm"}}) {
      const auto r = run_cli(command + " '" + mission + "' --html '" + html + "'");
      EXPECT_EQ(r.exit_code, 1) << command << ": " << r.err;
      EXPECT_NE(r.err.find("--html"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  // A page written over the mission file itself is refused.
  const std::string copy = dir.file("m.html");
  std::filesystem::copy_file(mission, copy);
  const auto over = run_cli("mission plan '" + copy + "' --html '" + copy + "'");
  EXPECT_EQ(over.exit_code, 1) << over.err;
  EXPECT_NE(over.err.find("which is the MISSION file"), std::string::npos) << over.err;
}

TEST(CliMission, PlanResolvesEveryConflictOfTheSampleAndTheCheckerPasses) {
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  const auto r = run_cli("mission plan '" + mission + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& resolutions = j.at("resolutions");
  ASSERT_GE(resolutions.size(), 2u);
  for (const auto& res : resolutions) EXPECT_TRUE(res.at("resolved").get<bool>()) << res.dump();
  EXPECT_EQ(j.at("remaining_conflicts").get<int>(), 0);
  EXPECT_TRUE(j.at("check").at("safe").get<bool>());
  EXPECT_GT(j.at("length_m").get<double>(), j.at("original_length_m").get<double>());
  const auto text = run_cli("mission plan '" + mission + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("resolved"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("check            safe"), std::string::npos) << text.out;
}

TEST(CliMission, AConflictThatCannotBeResolvedExitsThreeWithTimeAndPlace) {
  // The track ends 5 m from a rock: nothing past it to rejoin.
  ScratchDir dir;
  const deepguide::LocalFrame frame = deepguide::LocalFrame::from_user_crs("EPSG:32632");
  const Eigen::Vector2d rock = frame.to_lonlat({500405.0, 6000000.0});
  const std::string obstacles =
      dir.write("rock.geojson",
                "{\"type\": \"FeatureCollection\", \"features\": [{\"type\": \"Feature\", \"properties\": "
                "{\"id\": \"rock\", \"semi_major_m\": 3, \"semi_minor_m\": 3, \"orientation_deg\": 0}, "
                "\"geometry\": {\"type\": \"Point\", \"coordinates\": [" +
                    nlohmann::json(rock.x()).dump() + ", " + nlohmann::json(rock.y()).dump() + "]}}]}\n");
  const std::string path = dir.write(
      "m.yaml", "crs: EPSG:32632\nstart: {x: 500000, y: 6000000, depth_m: 5}\nenvironment: {obstacles: ['" + obstacles +
                    "']}\nmanoeuvres:\n  - track: {depth_m: 5, waypoints: [{x: 500400, y: 6000000}]}\n");
  const auto r = run_cli("mission plan '" + path + "'");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const char* w : {"could not be resolved", "rock", "into the mission", "mission's end"}) {
    EXPECT_NE(r.err.find(w), std::string::npos) << w << ": " << r.err;
  }
  EXPECT_NE(r.out.find("UNSOLVED"), std::string::npos) << r.out;
  // export writes nothing for it.
  const auto e = run_cli("mission export '" + path + "' -o '" + dir.file("m.plan") + "'");
  EXPECT_EQ(e.exit_code, 3) << e.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.plan")));
  // check says so too, as loudly.
  const auto c = run_cli("mission check '" + path + "'");
  EXPECT_EQ(c.exit_code, 3) << c.err;
  EXPECT_NE(c.out.find("UNAVOIDABLE"), std::string::npos) << c.out;
  EXPECT_NE(c.err.find("could not be resolved"), std::string::npos) << c.err;
}

TEST(CliMission, ACurrentStrongerThanTheVehicleIsNotCalledSafe) {
  // A 10 m/s current, the vehicle doing 2 m/s: check, plan, export and
  // simulate said "safe: 363 legs" or collided; each now exits 3 naming where.
  ScratchDir dir;
  const auto mission_with = [&](const std::string& current) {
    return dir.write("m" + current.substr(0, current.find(',')) + ".yaml",
                     "crs: EPSG:32632\nstart: {x: 500000, y: 6000000, depth_m: 5}\nenvironment: {current: '" + current +
                         "'}\nmanoeuvres:\n  - track: {depth_m: 5, speed_kn: 4, waypoints: [{x: 500400, y: 6000000}, "
                         "{x: 500400, y: 6000400}]}\n");
  };
  // Towards north: the east leg cannot be held, nor the turn's first part
  // (an arc heading east of north), while the north leg can.
  const std::string strong = mission_with("10,0");
  const auto c = run_cli("mission check '" + strong + "' --json");
  EXPECT_EQ(c.exit_code, 3) << c.err;
  EXPECT_NE(c.err.find("the 10.00 m/s current beats the vehicle on 2 basic manoeuvre(s)"), std::string::npos) << c.err;
  EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
  ASSERT_NE(c.out.find("beaten_by_current"), std::string::npos) << c.out;
  const auto j = nlohmann::json::parse(c.out);
  ASSERT_EQ(j.at("beaten_by_current").size(), 2u);
  EXPECT_EQ(j.at("beaten_by_current")[1].at("basic").get<int>(), 1);
  EXPECT_NEAR(j.at("beaten_by_current")[0].at("along_m").get<double>(), 0.0, 1e-6);
  for (const std::string& cmd : {"mission plan '" + strong + "'", "mission simulate '" + strong + "'",
                                 "mission export '" + strong + "' -o '" + dir.file("m.plan") + "'"}) {
    const auto r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 3) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("current beats the vehicle"), std::string::npos) << cmd << ": " << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.plan")));
  // 1.5 m/s across a 2.06 m/s vehicle: it crabs, and all is well.
  const auto held = run_cli("mission plan '" + mission_with("1.5,0") + "'");
  EXPECT_EQ(held.exit_code, 0) << held.err;
}

TEST(CliMission, ExportWritesEachFormatOnceAndRefusesToReplaceWithoutOverwrite) {
  ScratchDir dir;
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  for (const char* name : {"p.yaml", "p.geojson", "p.gpx", "p.kml", "p.csv", "p.plan", "p.bhv", "p.rtz"}) {
    const auto r = run_cli("mission export '" + mission + "' -o '" + dir.file(name) + "'");
    ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
    EXPECT_NE(r.out.find("wrote"), std::string::npos) << r.out;
  }
  const auto again = run_cli("mission export '" + mission + "' -o '" + dir.file("p.gpx") + "'");
  EXPECT_EQ(again.exit_code, 1) << again.err;
  EXPECT_EQ(std::count(again.err.begin(), again.err.end(), '\n'), 1) << again.err;
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(run_cli("mission export '" + mission + "' -o '" + dir.file("p.gpx") + "' --overwrite").exit_code, 0);
  const auto format = run_cli("mission export '" + mission + "' -o '" + dir.file("p.xml") + "' --format gpx");
  EXPECT_EQ(format.exit_code, 0) << format.err;
  const auto unknown = run_cli("mission export '" + mission + "' -o '" + dir.file("p.xml") + "'");
  EXPECT_EQ(unknown.exit_code, 1) << unknown.err;
  EXPECT_NE(unknown.err.find("extension"), std::string::npos) << unknown.err;
}

TEST(CliMission, SimulateSailsTheSampleAndFindsTheObjectNobodyKnew) {
  ScratchDir dir;
  const std::string mission = deepguide::test::source_file("data/missions/sample_mission.yaml");
  const std::string unknown = deepguide::test::source_file("data/missions/sample_unknown.geojson");
  const auto r = run_cli("mission simulate '" + mission + "' --unknown '" + unknown + "' --json --render '" +
                         dir.file("sim.png") + "' --zoom 120");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("completed").get<bool>());
  EXPECT_FALSE(j.at("collided").get<bool>());
  EXPECT_EQ(j.at("detected").get<int>(), 1);
  EXPECT_GE(j.at("replans").get<int>(), 1);
  EXPECT_GT(j.at("min_clearance_m").get<double>(), 3.0);
  EXPECT_TRUE(std::filesystem::exists(dir.file("sim.png")));
  const auto text = run_cli("mission simulate '" + mission + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("hold 120 s"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("reached the end"), std::string::npos) << text.out;
}

TEST(CliMission, HostileNamesArePrintedEscaped) {
  // A mission and a manoeuvre named with an ANSI escape, a newline and U+202E
  // (right-to-left override): printed raw, they recoloured the terminal, split
  // the summary line and reversed what followed.
  ScratchDir dir;
  const std::string m = dir.write(
      "m.yaml",
      "name: \"evil\\e[31mred\\nline\\u202E\"\ncrs: EPSG:32632\nstart: {x: 500000, y: 6000000, depth_m: 5}\n"
      "manoeuvres:\n  - track: {name: \"leg\\e[2J\", depth_m: 5, speed_kn: 4, waypoints: [{x: 500400, y: 6000000}]}\n");
  for (const std::string cmd : {"mission check", "mission plan"}) {
    const auto r = run_cli(cmd + " '" + m + "'");
    ASSERT_EQ(r.exit_code, 0) << cmd << ": " << r.err;
    EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << cmd << ": " << r.out;
    EXPECT_EQ(r.out.find("\xe2\x80\xae"), std::string::npos) << cmd << ": " << r.out;
    EXPECT_NE(r.out.find("mission          evil\\x1b[31mred\\x0aline\\u202e ("), std::string::npos)
        << cmd << ": " << r.out;
  }
}
