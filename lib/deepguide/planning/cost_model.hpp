#pragma once
// What a route planner minimises (in the spirit of OMPL's
// OptimizationObjective): the length of a route, the time it takes, or the
// propulsion energy it spends, in a sea current that may change in space and
// time. Graph searches ask it for the cost of one directed edge leaving at a
// given time, and for an admissible, consistent A* heuristic.
//
// Edge costs (edge_cost.hpp; docs/PLANNING.md, "Costs in a current"):
//   length  L
//   time    t = sum dl / s_k at the speed through the water v
//   energy  E = P(v) t,  P(v) = P_hotel + k v^3; with `economical`, v is chosen
//           per edge in [v_min, v_max] to spend least energy (steady currents only)
// An edge on which the current beats the vehicle costs +inf (no route uses it).
//
// Heuristic: h(x) = c * |x - goal| with c a lower bound of the cost per metre
// of straight-line progress anywhere: 1 for length, 1 / (v + c_max) for time,
// min over v of P(v) / (v + c_max) for energy (c_max the fastest current over
// the area and time span). Admissible because the ground speed never exceeds
// v + c_max and every route to the goal is at least |x - goal| long;
// consistent because every edge x -> y costs at least c |x - y| >= h(x) - h(y)
// (the triangle inequality), also when the edge is priced at a later departure.
//
// Where the field has no value (land cells, gaps) the current is taken as
// zero and the route's summary says over how many metres; routes through land
// are the charts' business, not the current's. A time-dependent field gives
// no value outside its time axis: an edge that would still be under way after
// the field's last time is infeasible, so a route never relies on a current
// nobody forecast.

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/planning/edge_cost.hpp"

namespace DEEPGUIDE_API deepguide {

enum class CostKind { length, time, energy };

/// "length", "time", "energy"; InputError otherwise.
CostKind parse_cost_kind(const std::string& text);
std::string to_string(CostKind kind);

struct CostModel {
  CostKind kind = CostKind::length;
  /// The current at (point, time); empty = still water.
  CurrentAtTime current;
  /// The current does not change in time (it is sampled at the departure time).
  bool steady = true;
  /// The current is the same everywhere and at every time (--current-const):
  /// straight legs between corners are then optimal for every cost.
  bool uniform = false;
  /// The fastest current over the area and time span (m/s): the heuristics' c_max.
  double max_current_mps = 0.0;
  /// Speed through the water (m/s) unless `economical`.
  double speed_mps = 4.0 * 1852.0 / 3600.0;
  /// Choose the speed per edge in [min_speed_mps, max_speed_mps] that spends
  /// least energy on it (--speed optimal; steady currents only).
  bool economical = false;
  double min_speed_mps = 0.5;
  double max_speed_mps = 6.0 * 1852.0 / 3600.0;
  /// Departure time, seconds since the Unix epoch (what a time-dependent field's axis uses).
  double depart_s = 0.0;
  /// The field's time axis; an edge under way outside it is infeasible (time-dependent fields).
  double time_first_s = -std::numeric_limits<double>::infinity();
  double time_last_s = std::numeric_limits<double>::infinity();
  LegOptions leg;  ///< integration step and the energy model
};

/// Binds a loaded current field to the model: its sampler in `frame`, its
/// fastest current (over all nodes and steps), whether it is steady, its time
/// axis, and the integration step (a quarter of the node spacing, at least
/// the model's; one piece per leg for a constant current). Checks that the field covers the box [area_min, area_max]
/// (InputError naming the file otherwise, current_field.hpp).
void attach_current(CostModel& model, std::shared_ptr<const CurrentField> field, const LocalFrame& frame,
                    const Vec2& area_min, const Vec2& area_max);

/// Checks the model (speeds, energy coefficients, departure within the time
/// axis, economical only in steady currents); throws InputError naming the
/// parameter (e.g. "`speed`", "hotel_power_w", "`depart_s`").
void validate(const CostModel& model);

/// The edge a -> b leaving at `depart_s`.
LegCost price_leg(const CostModel& model, const Vec2& a, const Vec2& b, double depart_s);

/// The number the search adds up for a priced leg: its length, time or energy (+inf when infeasible).
double edge_weight(const CostModel& model, const LegCost& leg);

/// When a search whose cost so far is `cost_so_far` leaves its vertex: the
/// departure plus the time that cost stands for (time: itself; energy at a
/// fixed speed: cost / P(v)). Only time-dependent fields need it, and validate()
/// refuses the one model where the cost does not tell the time (economical speeds).
double departure_after(const CostModel& model, double cost_so_far);

/// c in h(x) = c |x - goal| (see the header comment).
double cost_per_metre_lower_bound(const CostModel& model);

struct PricedLeg {
  LegCost cost;
  double depart_s = 0.0;
  double arrive_s = 0.0;
};

/// A route's legs priced one after another from the model's departure time.
struct RoutePricing {
  bool feasible = true;
  std::vector<PricedLeg> legs;
  double length_m = 0.0;
  double time_s = 0.0;
  double energy_j = 0.0;
  double cost = 0.0;               ///< in the model's kind
  double unknown_current_m = 0.0;  ///< metres of route where the field had no value (taken as still water)
};

RoutePricing price_route(const CostModel& model, const std::vector<Vec2>& points);

}  // namespace deepguide
