// The library calls behind `mission check`, `mission plan`, `mission export`
// and `mission simulate`, in-process on the sample mission: text and JSON from
// one report, the one-line reasons a mission cannot be sailed, the export
// read back, and outputs that would destroy an input.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/mission_report.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/simulation/mission_run_report.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

const std::string kSample = test::source_file("data/missions/sample_mission.yaml");

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(MissionReport, CheckListsEveryConflictInTextAndJson) {
  const MissionCheckReport report = check_mission_file(kSample);
  const nlohmann::json j = report.to_json();
  ASSERT_GE(report.conflicts.size(), 2u);
  EXPECT_EQ(j.at("conflicts").size(), report.conflicts.size());
  EXPECT_EQ(j.at("manoeuvres"), 5);
  EXPECT_EQ(j.at("file"), kSample);
  const std::string text = report.to_text();
  EXPECT_NE(text.find("conflicts        " + std::to_string(report.conflicts.size()) + " (corridor "), std::string::npos)
      << text;
  // One table row per conflict: each names the obstacle it meets.
  for (const Conflict& c : report.conflicts) EXPECT_GE(count(text, c.with), 1u) << c.with << "\n" << text;
  // Mission control resolves every conflict of the sample, and there is no current to beat the vehicle.
  EXPECT_TRUE(j.at("unavoidable").empty());
  EXPECT_TRUE(j.at("beaten_by_current").empty());
  EXPECT_FALSE(report.failure().has_value());
}

TEST(MissionReport, PlanResolvesEveryConflictAndTheCheckerAgrees) {
  const MissionPlanReport report = plan_mission_file(kSample);
  const nlohmann::json j = report.to_json();
  EXPECT_TRUE(j.at("check").at("safe").get<bool>());
  EXPECT_EQ(j.at("remaining_conflicts"), 0);
  ASSERT_EQ(j.at("resolutions").size(), report.planned.resolutions.size());
  double added = 0.0;
  for (const auto& r : j.at("resolutions")) {
    EXPECT_TRUE(r.at("resolved").get<bool>()) << r;
    added += r.at("added_m").get<double>();
  }
  // Each evasion's added length is what the plan grew by.
  EXPECT_NEAR(j.at("length_m").get<double>() - j.at("original_length_m").get<double>(), added, 0.5);
  const std::string text = report.to_text();
  EXPECT_NE(text.find("check            safe: " + std::to_string(report.verdict.legs) + " legs"), std::string::npos)
      << text;
  EXPECT_EQ(count(text, "resolved"), report.planned.resolutions.size()) << text;
  EXPECT_FALSE(report.failure().has_value());
}

TEST(MissionReport, AnUnresolvedConflictIsOneLineWithItsTimeAndPlace) {
  MissionPlanReport report = plan_mission_file(kSample);
  ASSERT_FALSE(report.planned.resolutions.empty());
  Resolution& first = report.planned.resolutions.front();
  first.resolved = false;
  first.time_s = 3725.0;
  first.problem = "no way round";
  const auto why = report.failure();
  ASSERT_TRUE(why.has_value());
  EXPECT_EQ(why->rfind(kSample + ": 1 conflict(s) could not be resolved; the first, with " + first.conflict.with +
                           " at 1:02:05 into the mission, ",
                       0),
            0u)
      << *why;
  EXPECT_NE(why->find(" m deep: no way round"), std::string::npos) << *why;
  EXPECT_EQ(why->find('\n'), std::string::npos);
  // A conflict observation still finds after every one was resolved is not let pass either.
  first.resolved = true;
  report.planned.remaining.push_back(first.conflict);
  ASSERT_TRUE(report.failure().has_value());
  EXPECT_NE(report.failure()->find("1 conflict(s) remain in the planned mission"), std::string::npos);
}

TEST(MissionReport, ExportWritesThePlanAndRefusesToOverwriteTheMission) {
  test::ScratchDir dir;
  MissionExportRequest request;
  request.mission = kSample;
  request.output = dir.file("sample.gpx");
  const MissionExportReport report = export_mission_file(request);
  EXPECT_EQ(report.format, ExportFormat::gpx);
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_EQ(read_route_waypoints(request.output).size(), report.waypoints);
  EXPECT_EQ(report.to_text(request.output).rfind("wrote " + request.output + " (gpx): ", 0), 0u);
  // As written, the sample's conflicts are said, not hidden.
  request.as_written = true;
  request.options.overwrite = true;
  EXPECT_FALSE(export_mission_file(request).warnings.empty());
  // The mission file as the output: refused, and the mission is untouched.
  const auto before = std::filesystem::file_size(kSample);
  request.output = kSample;
  request.format = ExportFormat::gpx;
  EXPECT_THROW(export_mission_file(request), InputError);
  EXPECT_EQ(std::filesystem::file_size(kSample), before);
}

TEST(MissionReport, SimulationFindsTheObjectNobodyKnew) {
  MissionRunRequest request;
  request.mission = kSample;
  request.unknown = {test::source_file("data/missions/sample_unknown.geojson")};
  const MissionRunReport report = simulate_mission_file(request);
  const nlohmann::json j = report.to_json();
  EXPECT_TRUE(j.at("completed").get<bool>());
  EXPECT_EQ(j.at("detected"), 1);
  EXPECT_EQ(j.at("events").size(), report.run.events.size());
  const std::string text = report.to_text();
  EXPECT_EQ(text.rfind("mission          ", 0), 0u) << text;
  EXPECT_NE(text.find("completed in "), std::string::npos) << text;
  EXPECT_FALSE(report.failure().has_value());
  // Drawing the run over a mission file itself is refused before anything is sailed.
  request.outputs = {{"--render", kSample}};
  EXPECT_THROW(simulate_mission_file(request), InputError);
}
