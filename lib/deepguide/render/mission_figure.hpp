#pragma once
// The mission figure: the plan over the sea chart (render/chart_scene.hpp:
// depth shading, land, hazards, obstacles), each part in the colour of what
// it is for: the mission's own manoeuvres, and the evasions and
// identification laps mission control put in; the plan as written, dashed,
// under it; a ring where each conflict began and a cross where one could not
// be resolved; the start and the end; and, when given, the track a
// simulation sailed and the objects its sonar found.
// The map shows the plans and the track, padded by a tenth (at least 150 m).

#include <string>
#include <vector>

#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide {

struct MissionFigure {
  std::vector<std::string> charts;     ///< drawn as `render chart` draws them
  std::vector<std::string> obstacles;  ///< obstacle files, drawn as further obstacles
  std::string crs;                     ///< the mission's frame, e.g. "EPSG:32632"
  const MissionPlan* plan = nullptr;   ///< the plan to show (required)
  const MissionPlan* written = nullptr;  ///< optional: the plan as written, before mission control
  std::vector<Vec2> conflicts;         ///< where dangers began (on the written plan)
  std::vector<Vec2> unresolved;        ///< where a conflict could not be resolved
  std::vector<Vec2> track;             ///< optional: the track sailed in simulation
  const ObstacleSet* detected = nullptr;  ///< optional: objects the sonar found that nobody knew
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
  Rgba start = rgb_hex(0x2f9e44);
  Rgba end = rgb_hex(0x212529);
};

/// Draws the figure to `path` (.png or .svg), atomically. Throws InputError
/// for a missing plan or what render_chart refuses.
ChartLayout render_mission(const MissionFigure& figure, const std::string& path, const MissionStyle& style = {});

}  // namespace deepguide
