#pragma once
// A mission as a web map (render/web_map.hpp): `mission plan --html` and
// `mission simulate --html`.
//
// Layers, each switchable:
//  - obstacles: what the mission knows (obstacle files, charted hazards and
//    no-go), each with its id; a click lists every one under it;
//  - zones: their safety zones at the mission's margin;
//  - written: the plan as written, before mission control (off at first);
//  - legs: the plan between its exported waypoints, coloured by role
//    (mission, evasion, identification), each with its manoeuvre, length,
//    depth and speed;
//  - waypoints: the waypoints `mission export` writes (name, position,
//    depth, speed, hold, turn radius, distance and time along, role,
//    manoeuvre), listed in the table too;
//  - conflicts: where each danger began, with the obstacle, the reaction
//    and whether it was resolved (and why not);
//  - track (simulate): the track sailed, a sample a second, where the
//    reactive level steered in its own colour; objects the sonar found.

#include "deepguide/core/api.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/render/web_map.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionRun;

/// The map of a loaded mission and its planned version; with `run`, the
/// track sailed in simulation and what its sonar found (on the run's plan);
/// `as_written`: the plan as written is the one drawn (`mission check`),
/// its conflicts where they begin on it.
WebMap mission_web_map(const LoadedMission& loaded, const PlannedMission& planned, const MissionRun* run = nullptr,
                       bool as_written = false);

}  // namespace deepguide
