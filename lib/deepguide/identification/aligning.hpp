#pragma once
// Aligning to an object in a current (the seed's Figs. 13-14): a guidance
// unit. Vehicle position, course and the current in; course over ground and
// speed through the water out, with the mode (lee_goal.hpp for the areas).
//
// e the lee direction (the current's set; in still water the near side, fixed
// at the first call), g the held point: the lee goal point on the safety
// ellipse plus hold_buffer_m along e.
//   evasive      the reactive geometric method round the object and the
//                other obstacles it is given, with the zone margin standoff +
//                hold_buffer (the method runs along a zone's edge within
//                millimetres: at the standoff itself the vehicle came 3 mm
//                inside it), towards the approach point
//                a = g + approach_m e down the axis. Round the object and
//                into the shade from downstream, so that the vehicle faces
//                upstream when it starts to hold (no U-turn next to the object).
//   positioning  from the moment the vehicle is in the shade facing upstream,
//                or within approach_radius_m of a; back to evasive only when
//                it leaves the shade.
//                In a current: the ground velocity u = -k (p - g), at most
//                max_approach_mps, made good by the water velocity w = u - c:
//                the HEADING set-point is the direction of w and the speed
//                |w| (autopilot heading mode). Near g, w is about -c: the bow
//                stays into the current. A course-over-ground set-point (the
//                direction of u) is ill-defined there: one that swung with a
//                tiny u made the heading weave by +-13 degrees, and holding
//                the course at -c below |u| = 0.05 m/s lost the sideways
//                part of u, leaving the vehicle 1.6-2 m off the axis.
//                In still water: bow to the object (a heading set-point too),
//                speed k x (distance along the axis), a line of sight towards
//                the axis; the vehicle has no astern, so it creeps in and
//                coasts.
//                k = 1 / (4 T_u) makes the loop critically damped with the
//                vehicle's 20 s speed lag; twice that oscillates in still water.
// Slack water (the current below slack_fraction of the strongest seen, which
// was a current): the positioning mode holds the approach point instead of
// g. A tide that turns sets the vehicle towards the object as the lee side
// flips; holding at g, bow to the object, it passed 3.1 m from a wreck in a
// test (10 m standoff). From the approach point it goes round in evasive mode.
// A current at least as fast as the vehicle: overpowered, full speed into it.

#include <optional>
#include <span>

#include "deepguide/core/api.hpp"
#include "deepguide/identification/lee_goal.hpp"
#include "deepguide/reactive/reactive_method.hpp"

namespace DEEPGUIDE_API deepguide {

struct AlignParams {
  double standoff_m = 10.0;                      ///< safety margin round the object; the goal lies on this zone, > 0
  double still_mps = 0.05;                       ///< a current below this is still water, >= 0
  double speed_mps = 4.0 * 1852.0 / 3600.0;      ///< evasive mode's speed through the water, > 0
  double max_speed_mps = 6.0 * 1852.0 / 3600.0;  ///< the vehicle's, a cap on the positioning speed, > 0
  double position_gain_per_s = 0.0125;           ///< k of the position loop, > 0 (header)
  double max_approach_mps = 1.0;                 ///< cap on the positioning ground speed, > 0
  double lookahead_m = 20.0;                     ///< line of sight towards the current's axis, > 0
  /// The held point lies this far beyond the lee goal point along the axis,
  /// so that the position loop's small overshoot stays outside the standoff, >= 0.
  double hold_buffer_m = 1.0;
  double approach_m = 50.0;         ///< the approach point lies this far down the axis from the goal, > 0
  double approach_radius_m = 10.0;  ///< positioning starts within this of the approach point (or facing upstream), > 0
  /// Slack water: a current below this fraction of the strongest seen (which
  /// was above still_mps) is a tide about to turn, and the vehicle waits at
  /// the approach point instead of the held point. In [0, 1); 0 never backs off.
  double slack_fraction = 0.25;
};

/// Throws InputError naming the first bad field.
void validate(const AlignParams& params);

struct AlignMemory {
  AlignArea mode = AlignArea::evasive;
  std::optional<Vec2> direction;  ///< the lee direction, fixed at the first call
  ReactiveMemory reactive;        ///< the evasive mode's side latch
  int switches = 0;               ///< mode changes so far
  double strongest = 0.0;         ///< the strongest current seen (m/s), for slack water
};

struct AlignCommand {
  double course = 0.0;      ///< course over ground, or the heading when is_heading; math rad
  bool is_heading = false;  ///< `course` is a heading set-point (positioning in a current)
  double speed_mps = 0.0;   ///< through the water
  AlignArea mode = AlignArea::evasive;
  Vec2 goal{0.0, 0.0};        ///< the held point (the lee goal point plus hold_buffer_m down the axis)
  double goal_error_m = 0.0;  ///< |p - g|
  /// The current is at least as fast as the vehicle (max_speed_mps): it cannot
  /// hold any point; it heads into the current at full speed and says so.
  bool overpowered = false;
  bool slack = false;  ///< slack water: waiting at the approach point (slack_fraction)
};

/// `others`: the other obstacles the evasive mode keeps clear of (the
/// positioning mode stays in the object's shade and does not look at them).
AlignCommand align_command(const Ellipse& object, const AlignParams& params, AlignMemory& memory, const Vec2& p,
                           double course, const Vec2& current_mps, std::span<const Ellipse> others = {});

}  // namespace deepguide
