#pragma once
// The mission figure: the plan over the sea chart (render/chart_scene.hpp:
// depth shading, land, hazards, obstacles), each part in the colour of what
// it is for: the mission's own manoeuvres, and the evasions and
// identification laps mission control put in; the plan as written, dashed,
// under it; a ring where each conflict began and a cross where one could not
// be resolved; the start and the end; and, when given, the track a
// simulation sailed (where the reactive level steered, in its own colour)
// and the objects its sonar found, and labelled marks (the seed's point A).
// The map shows the plans and the track, padded by a tenth (at least 150 m).

#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionFigure {
  std::vector<std::string> charts;                  ///< drawn as `render chart` draws them
  std::vector<std::string> obstacles;               ///< obstacle files, drawn as further obstacles
  std::string crs;                                  ///< the mission's frame, e.g. "EPSG:32632"
  const MissionPlan* plan = nullptr;                ///< the plan to show (required)
  const MissionPlan* written = nullptr;             ///< optional: the plan as written, before mission control
  std::vector<Vec2> conflicts;                      ///< where dangers began (on the written plan)
  std::vector<Vec2> unresolved;                     ///< where a conflict could not be resolved
  std::vector<Vec2> track;                          ///< optional: the track sailed in simulation
  std::vector<bool> track_reactive;                 ///< optional, one per track point: the reactive level steered to it
  std::vector<std::pair<Vec2, std::string>> marks;  ///< optional: labelled points, e.g. {where, "A"}
  const ObstacleSet* detected = nullptr;            ///< optional: objects the sonar found that nobody knew
  std::string title;
  int width_px = 1200;
  WorldBox extent;  ///< the part to show (local frame); empty: the plans and the track, padded
};

// Light lines in a dark casing: they read on the deep blue and on the pale
// shallows of the depth shading alike.
struct MissionStyle {
  Rgba casing{0.13, 0.15, 0.16, 0.75};
  Rgba mission = rgb_hex(0xfcc419);
  Rgba evasion = rgb_hex(0xff922b);
  Rgba identification = rgb_hex(0xe599f7);
  Rgba written = rgb_hex(0xced4da);
  Rgba conflict = rgb_hex(0xff3b3b);
  Rgba track = rgb_hex(0x69db7c);
  Rgba reactive = rgb_hex(0x3bc9db);
  Rgba start = rgb_hex(0x2f9e44);
  Rgba end = rgb_hex(0x212529);
};

struct MissionRun;

/// The figure of a mission (its plan as written) and its planned version:
/// its charts, obstacle files and frame, and where each conflict began (a
/// cross where unresolved). Refers to both plans: they must outlive it.
MissionFigure mission_figure_for(const Mission& mission, const MissionPlan& written, const PlannedMission& planned);

/// The figure of a simulated run of it: the plan as it ended (with the
/// evasions planned on the way), the track sailed, coloured where the reactive
/// level steered, the objects the sonar found, and a mark "A" where the
/// reactive level first took over. With zoom_m > 0, the square of half-side
/// zoom_m around the first object found. Titled with the run's outcome.
/// Refers to `written` and `run`: they must outlive it.
MissionFigure simulated_mission_figure(const Mission& mission, const MissionPlan& written,
                                       const PlannedMission& planned, const MissionRun& run, double zoom_m = 0.0);

/// Draws the figure to `path` (.png or .svg), atomically. Throws InputError
/// for a missing plan or what render_chart refuses.
ChartLayout render_mission(const MissionFigure& figure, const std::string& path, const MissionStyle& style = {});

struct MissionFileFigure {
  std::string title;  ///< empty: "NAME: L km, T; N conflict(s), K resolved"
  int width_px = 1200;
  bool as_written = false;  ///< the plan as written, without mission control's changes
};

/// `render mission`: the mission file read, planned and drawn to `path`.
/// Throws what load_mission and render_mission throw.
ChartLayout render_mission_file(const std::string& mission, const std::string& path, const MissionFileFigure& options);

}  // namespace deepguide
