#pragma once
// A mission as the operator writes it (the seed's mission plan: "a sequence
// of complex manoeuvres, which describe special tasks (Track, Meander, GPS
// Update)"), read from a commented YAML file (docs/MISSIONS.md,
// data/missions/).
//
// Frame: the file's `crs`, else the UTM zone of the start (docs/MISSIONS.md, "The file").
// Positions are {lon, lat} or {x, y} in that frame; depths positive down;
// speeds in knots (`speed_kn`) or m/s (`speed_mps`); headings clockwise from
// true north. Paths are relative to the file's folder. Every error is one
// line naming the file, the line (and column for YAML syntax), the key and
// what was expected.

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/planner_options.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

/// Follow waypoints in order from wherever the vehicle is.
struct TrackSpec {
  std::vector<Vec2> waypoints;
};

/// A lawnmower (the seed's Meander): parallel lines across a polygon at a
/// heading, joined by turns of `turn_radius_m`.
struct SurveySpec {
  BgPolygon area;  ///< local frame; simple (not self-intersecting)
  double line_spacing_m = 0.0;
  double heading_deg = 0.0;    ///< direction of the lines, clockwise from true north
  double turn_radius_m = 0.0;  ///< 0: the vehicle's at the survey speed
};

/// Surface where the vehicle is, hold for a GPS fix, dive again.
struct GpsUpdateSpec {
  double hold_s = 60.0;
};

/// Look at an object: align in its flow shade, or go around it.
struct IdentifyTask {
  std::string object;  ///< an obstacle's id
  enum class Mode { align, around } mode = Mode::around;
  double distance_m = 20.0;  ///< from the object's outline
};

/// Go straight to a point.
struct GotoSpec {
  Vec2 position{0.0, 0.0};
};

struct ComplexManoeuvre {
  std::string type;      ///< "track", "survey", "gps_update", "identify", "goto"
  std::string name;      ///< the file's name, else "track 1" and so on
  std::string line;      ///< where it is in the file ("line 23"), for messages
  double depth_m = 0.0;  ///< operating depth (m, positive down)
  double speed_mps = 0.0;
  std::variant<TrackSpec, SurveySpec, GpsUpdateSpec, IdentifyTask, GotoSpec> spec;
};

/// Mission control's rules: what to do where an obstacle endangers the plan
/// (mission/mission_control.hpp). Known obstacles named in `identify` are
/// gone around at `identify_distance_m`; every other one is evaded. An object
/// the sonar finds that no chart or store knew is handled as `unknown_objects`
/// says (simulate).
struct ControlRules {
  enum class Reaction { evade, identify };
  std::vector<std::string> identify;  ///< obstacle ids
  double identify_distance_m = 25.0;  ///< from the outline; at least the corridor (margin + half width)
  Reaction unknown_objects = Reaction::evade;
  /// What plans the evasions (`control.evasion_graph`): the reduced visibility
  /// graph round each evasion, or a navigation mesh kept per depth
  /// (mission/evasion_planner.hpp). visibility-full is accepted too.
  GraphKind evasion_graph = GraphKind::visibility;
};

struct Mission {
  std::string name;
  std::string source;  ///< the file
  LocalFrame frame = LocalFrame::utm_for(0.0, 0.0);
  VehicleParams vehicle;
  std::vector<std::string> charts;     ///< bathymetry rasters, S-57 cells, hazard files
  std::vector<std::string> obstacles;  ///< obstacle files
  std::string current;                 ///< "SPEED_MPS,DIR_DEG", or empty
  std::string current_file;            ///< a current field, or empty
  double margin_m = 5.0;
  double vertical_clearance_m = 2.0;
  ControlRules control;
  Vec2 start{0.0, 0.0};
  double start_depth_m = 0.0;
  std::vector<ComplexManoeuvre> manoeuvres;
};

/// Reads a mission file. Throws InputError (one line: file, line, key, what
/// was expected) for a YAML syntax error (with line and column), an unknown
/// key or manoeuvre type, a missing or bad value, a self-intersecting survey
/// area, a missing file.
Mission read_mission(const std::string& path);

}  // namespace deepguide
