#include "deepguide/reactive/geometric_construction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/geometry/ellipse_tangents.hpp"
#include "deepguide/reactive/reactive_support.hpp"

namespace deepguide {
namespace {

using namespace reactive_detail;

struct Construction {
  Vec2 direction{0.0, 0.0};  ///< unit, zero when stalled
  int sector = 2;
  std::ptrdiff_t object = -1;
};

/// Objects move a little between scans (estimation noise); half the minor
/// semi-axis of the zone recognises the same one without confusing neighbours.
double match_radius(const Ellipse& zone) { return 0.5 * zone.b; }

/// latched_side for zone k, and a fresh latch starts its count of turn switches anew.
int latch(GeometricMemory& memory, std::ptrdiff_t k, const Ellipse& zone, int fresh) {
  if (!engaged_with(memory, zone.centre, match_radius(zone))) memory.turn_switches = 0;
  return latched_side(memory, k, zone.centre, match_radius(zone), fresh);
}

/// The whole memory released: the latch and the count of turn switches.
void release(GeometricMemory& memory) { memory = GeometricMemory{}; }

/// The side for zone k: latched in `memory`, or fresh from the axis rule.
/// `keep_any` keeps a latched side even if it was latched for another zone.
int side_for(const std::vector<Ellipse>& zones, std::ptrdiff_t k, const Vec2& p, const Vec2& g,
             std::optional<double> course, GeometricMemory* memory, bool keep_any) {
  const Ellipse& zone = zones[static_cast<std::size_t>(k)];
  const int fresh = (keep_any && memory && memory->side != 0) ? memory->side : axis_side(zone.centre, g, p, course);
  if (!memory) return fresh;
  return latch(*memory, k, zone, fresh);
}

struct Tuning {
  double blend;            ///< exit_blend_fraction
  double passage;          ///< geometric_passage_m
  double turn_rate = 0.0;  ///< turn_rate_limit; 0: the course line alone
  double speed = 0.0;      ///< through the water, for the turn
  double margin = 0.0;
  double turn_lag = 0.0;  ///< turn_lag_s
  double rate_now = 0.0;  ///< the vehicle's present turning rate
};

/// The hysteresis band of a vehicle that sails the construction (a turning
/// rate known): a fifth of the margin, at least 1 m; 0 for the construction
/// itself (the figures' gradient lines, a vehicle that turns at once).
double sailing_band(const Tuning& tuning) { return tuning.turn_rate > 0.0 ? std::max(1.0, 0.2 * tuning.margin) : 0.0; }

/// How deep a sailed turn may cut into a zone (the security ellipse, which
/// lies outside the margin's offset curve) before another course is sought.
double sailed_cut(const Tuning& tuning) { return 0.2 * tuning.margin; }

Ellipse widened(const Ellipse& zone, double band) { return {zone.centre, zone.a + band, zone.b + band, zone.theta}; }

constexpr double kSmallTurn = 20.0 * std::numbers::pi / 180.0;
constexpr int kMaxTurnSwitches = 3;
constexpr int kFan = 24;

/// The least signed distance to the zones that do not hold p along the way
/// a vehicle at `speed` sails a new course from its present one: its turning
/// rate goes from the present one towards the full rate (the way the new
/// course lies, easing off the last 2 s of the turn) as a first-order lag,
/// then straight on for two turning radii. The lag matters: DeepC's closed
/// loop takes about 7 s to reach a turning rate, 15 m of straight travel a
/// turn that starts at once does not have, and a turn the other way first
/// undoes the present one. (The current's drift is left out: the autopilot
/// makes good the course over ground, and the comparison below is between
/// two such turns.)
double sailed_clearance(const std::vector<Ellipse>& zones, const Vec2& p, double course, const Vec2& direction,
                        const Tuning& tuning) {
  constexpr double kEase_s = 2.0;
  const double to = math_angle(direction), rate = tuning.turn_rate, speed = tuning.speed;
  const double radius = speed / rate;
  const double horizon = std::abs(wrap_pi(to - course)) / rate + tuning.turn_lag + kEase_s + 2.0 * radius / speed;
  std::vector<std::size_t> near;
  for (std::size_t k = 0; k < zones.size(); ++k) {
    const double reach = zones[k].a + speed * horizon;
    if ((zones[k].centre - p).squaredNorm() < reach * reach && !zones[k].contains(p)) near.push_back(k);
  }
  double least = std::numeric_limits<double>::infinity();
  if (near.empty()) return least;
  constexpr double dt = 0.2;
  Vec2 x = p;
  double psi = course, r = std::clamp(tuning.rate_now, -rate, rate);
  for (double t = 0.0; t < horizon; t += dt) {
    const double wanted = std::clamp(wrap_pi(to - psi) / kEase_s, -rate, rate);
    r += tuning.turn_lag > 0.0 ? (wanted - r) * std::min(1.0, dt / tuning.turn_lag) : wanted - r;
    x += speed * dt * unit_vector(psi + 0.5 * r * dt);
    psi += r * dt;
    for (const std::size_t k : near) {
      // An ellipse lies within a of its centre: a zone that far off cannot
      // lower the least distance, and its exact distance (a Newton solve)
      // is skipped. The result is the same, bit for bit.
      if ((x - zones[k].centre).norm() - zones[k].a >= least) continue;
      least = std::min(least, signed_distance(zones[k], x));
    }
  }
  return least;
}

Construction construct(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g, std::optional<double> course,
                       GeometricMemory* memory, const Tuning& tuning, bool outside_only = false);

/// Whether the zones labelled `id` surround p: every direction from p meets
/// one of them (or p is on or in one).
bool surrounded(const std::vector<Ellipse>& zones, const std::vector<std::size_t>& group, std::size_t id,
                const Vec2& p) {
  std::vector<std::pair<double, double>> arcs;  // [from, to] anticlockwise, from in [0, 2 pi)
  for (std::size_t m = 0; m < zones.size(); ++m) {
    if (group[m] != id) continue;
    const std::optional<PointTangents> t = tangent_points(zones[m], p);
    if (!t) return true;  // on or in a member
    const double from = wrap_two_pi(math_angle(t->right - p));
    double to = wrap_two_pi(math_angle(t->left - p));
    if (to < from) to += 2.0 * std::numbers::pi;
    arcs.emplace_back(from, to);
  }
  if (arcs.size() < 2) return false;
  std::sort(arcs.begin(), arcs.end());
  // Largest uncovered gap going round once (the first arc again after a full turn closes it).
  double reach = arcs.front().second, gap = 0.0;
  for (std::size_t i = 1; i <= arcs.size(); ++i) {
    const double from = i < arcs.size() ? arcs[i].first : arcs.front().first + 2.0 * std::numbers::pi;
    gap = std::max(gap, from - reach);
    if (i < arcs.size()) reach = std::max(reach, arcs[i].second);
  }
  return gap <= 0.0;
}

/// Group label per zone: zones less than `passage` apart (overlapping ones
/// included) share one, transitively.
std::vector<std::size_t> zone_groups(const std::vector<Ellipse>& zones, double passage) {
  std::vector<std::size_t> label(zones.size());
  for (std::size_t i = 0; i < zones.size(); ++i) label[i] = i;
  auto root = [&](std::size_t i) {
    while (label[i] != i) i = label[i] = label[label[i]];
    return i;
  };
  for (std::size_t i = 0; i < zones.size(); ++i) {
    for (std::size_t j = i + 1; j < zones.size(); ++j) {
      const double reach = zones[i].a + zones[j].a + passage;
      if ((zones[i].centre - zones[j].centre).squaredNorm() >= reach * reach) continue;  // cheap: far apart
      if (root(i) == root(j) || zone_gap(zones[i], zones[j]) >= passage) continue;
      label[root(j)] = root(i);
    }
  }
  for (std::size_t i = 0; i < zones.size(); ++i) label[i] = root(i);
  return label;
}

/// Sector 3: the outside course at the nearest boundary point, blended outward.
Construction leave_zone(const std::vector<Ellipse>& zones, std::ptrdiff_t k, const Vec2& p, const Vec2& g,
                        std::optional<double> course, GeometricMemory* memory, const Tuning& tuning) {
  const Ellipse& zone = zones[static_cast<std::size_t>(k)];
  const int side = side_for(zones, k, p, g, course, memory, true);
  Vec2 x = project_to_ellipse(zone, p).point;
  Vec2 n = outward_normal(zone, x);
  if (zone.a == zone.b && (p - zone.centre).norm() < 1e-9 * zone.a) {
    // At the very centre of a circle every boundary point is nearest: out on the passing side.
    n = static_cast<double>(side) * left_normal(unit_or_zero(g - zone.centre));
    if (n.squaredNorm() == 0.0) n = zone.minor_dir();
    x = zone.centre + zone.a * n;
  }
  // The outside course from the boundary point itself (its tangent is the boundary's), with the same
  // side (a copy of the latch: only this call's counts).
  GeometricMemory probe;
  probe.side = side;
  probe.engaged_object = k;
  probe.engaged_centre = zone.centre;
  Vec2 along = construct(zones, x, g, course, &probe, tuning, true).direction;
  if (along.squaredNorm() == 0.0 || along.dot(n) < -1e-9) along = along_boundary(n, side);
  return {exit_direction(along, n, depth_fraction(zone, p), tuning.blend), 3, k};
}

/// The zone the construction steers round (p outside every zone): the
/// engaged one while the line of sight still meets it, else the first the
/// line of sight enters, else, under way, the engaged one while a turn to the
/// target would cut a zone; -1 when the way to the target is free.
std::ptrdiff_t engaged_zone(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g,
                            std::optional<double> course, const GeometricMemory* memory, const Tuning& tuning) {
  std::ptrdiff_t active = -1;
  if (memory) {
    // The engaged zone stays engaged until the line of sight clears it by a
    // band (hysteresis): a line that grazes a zone flips between blocked and
    // free from scan to scan with the sonar's noise, and each release put
    // the turn off until it came too late to sail.
    const double band = sailing_band(tuning);
    for (std::size_t i = 0; i < zones.size() && active < 0; ++i) {
      const Ellipse& z = zones[i];
      if (engaged_with(*memory, z.centre, match_radius(z)) && segment_intersects(widened(z, band), p, g)) {
        active = static_cast<std::ptrdiff_t>(i);
      }
    }
  }
  if (active < 0) active = first_zone_hit(zones, p, g);
  if (active < 0 && memory && memory->side != 0 && course && tuning.turn_rate > 0.0 && tuning.speed > 0.0) {
    // The way to the target is free, but a turn to it sailed from here would
    // cut a zone (a large turn beside the zone just passed): the engaged zone
    // stays engaged, its tangent held, until the turn to the target keeps clear.
    const Vec2 direct = unit_or_zero(g - p);
    if (std::abs(wrap_pi(math_angle(direct) - *course)) >= kSmallTurn &&
        sailed_clearance(zones, p, *course, direct, tuning) < -sailed_cut(tuning)) {
      for (std::size_t i = 0; i < zones.size() && active < 0; ++i) {
        if (engaged_with(*memory, zones[i].centre, match_radius(zones[i]))) active = static_cast<std::ptrdiff_t>(i);
      }
    }
  }
  return active;
}

/// `outside_only`: p is taken as outside every zone (the probe just outside a
/// boundary, which may lie in an overlapping zone): no sector 3 recursion.
Construction construct(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g, std::optional<double> course,
                       GeometricMemory* memory, const Tuning& tuning, bool outside_only) {
  if (!outside_only) {
    if (const std::ptrdiff_t inside = deepest_zone(zones, p); inside >= 0) {
      return leave_zone(zones, inside, p, g, course, memory, tuning);
    }
  }
  const std::ptrdiff_t active = engaged_zone(zones, p, g, course, memory, tuning);
  if (active < 0) {
    if (memory) release(*memory);
    return {unit_or_zero(g - p), 2, -1};
  }
  const std::vector<std::size_t> group = zone_groups(zones, tuning.passage);
  // The tangent from p on `side` to the group of zone k: the most extreme of
  // its members' tangents (the tangent to their convex hull). Returns the
  // member touched, the tangent point and whether the group surrounds p. (From a pocket of the group, inside
  // its hull, this is the way out round the group.) A group that surrounds p
  // has no tangent at all: zone k alone then, as without groups, and the
  // cascade ends stalled if it finds no free tangent.
  auto group_tangent = [&](std::ptrdiff_t k, int side) {
    const Vec2 ref = unit_or_zero(zones[static_cast<std::size_t>(k)].centre - p);
    const bool alone = surrounded(zones, group, group[static_cast<std::size_t>(k)], p);
    std::ptrdiff_t best = k;
    Vec2 best_touch = p;
    double best_turn = -std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < zones.size(); ++m) {
      if (group[m] != group[static_cast<std::size_t>(k)] || (alone && m != static_cast<std::size_t>(k))) continue;
      const std::optional<PointTangents> tangents = tangent_points(zones[m], p);
      const Vec2 touch = tangents ? (side > 0 ? tangents->left : tangents->right) : p;  // none: on the boundary
      const Vec2 dir = touch - p;
      const double turn = dir.squaredNorm() == 0.0 ? 0.0 : side * std::atan2(cross(ref, dir), ref.dot(dir));
      if (turn > best_turn || (m == static_cast<std::size_t>(k) && turn >= best_turn)) {
        best_turn = turn, best = static_cast<std::ptrdiff_t>(m), best_touch = touch;
      }
    }
    return std::tuple{best, best_touch, alone};
  };
  // Cascade: the tangent segment p -> T must itself be free. Under way it
  // must clear the other zones by the band: a tangent that grazes another
  // zone is blocked in one scan and free in the next with the sonar's noise,
  // and the course flips between the two ways round.
  std::vector<Ellipse> banded;
  if (memory && sailing_band(tuning) > 0.0) {
    for (const Ellipse& z : zones) banded.push_back(widened(z, sailing_band(tuning)));
  }
  const std::vector<Ellipse>& blocking = banded.empty() ? zones : banded;
  auto cascade = [&](int side) -> Construction {
    std::ptrdiff_t k = active;
    for (std::size_t step = 0; step < zones.size(); ++step) {
      const auto [member, touch, alone] = group_tangent(k, side);
      const Ellipse& zone = zones[static_cast<std::size_t>(member)];
      const std::ptrdiff_t blocker = first_zone_hit(blocking, p, touch, member);
      const bool own_group =
          blocker >= 0 && group[static_cast<std::size_t>(blocker)] == group[static_cast<std::size_t>(member)] && !alone;
      if (blocker < 0 || own_group) {
        return {along_boundary(outward_normal(zone, touch), side), 1, member};
      }
      k = blocker;
    }
    return {Vec2(0.0, 0.0), 1, active};
  };
  const Ellipse& engaged = zones[static_cast<std::size_t>(active)];
  // The turn: a course whose turn, sailed at the vehicle's rate, cuts deep
  // into a zone gives way to the other side's when that turn keeps clearer.
  // The line alone cannot tell: a far zone's tangent that slips behind a near
  // one asks for a turn across the near one, and the cascade's same-side rule
  // sends the vehicle round the far side of a zone it could pass on the near.
  const auto sailed = [&](Construction chosen, int side) -> Construction {
    if (!memory || !course || !(tuning.turn_rate > 0.0) || !(tuning.speed > 0.0) ||
        chosen.direction.squaredNorm() == 0.0) {
      return chosen;
    }
    // A small turn sweeps little: the line is what the vehicle sails (and the check costs nothing then).
    if (std::abs(wrap_pi(math_angle(chosen.direction) - *course)) < kSmallTurn) return chosen;
    const double cut = sailed_cut(tuning);
    const double mine = sailed_clearance(zones, p, *course, chosen.direction, tuning);
    if (mine >= -cut) return chosen;
    double best = mine;
    if (memory->turn_switches < kMaxTurnSwitches) {
      const Construction other = cascade(-side);
      if (other.direction.squaredNorm() > 0.0) {
        const double theirs = sailed_clearance(zones, p, *course, other.direction, tuning);
        // A turn that keeps clear, or one that cuts much less deep (the
        // sailed turn counts the reversal a change of side may need).
        if (theirs >= -cut || theirs > mine + cut) {
          memory->side = -side;
          memory->engaged_object = active;
          memory->engaged_centre = engaged.centre;
          ++memory->turn_switches;
          return other;
        }
        best = std::max(best, theirs);
      }
    }
    // Neither way round can be sailed clear from here: for this step, the
    // course of a fan round the vehicle nearest the construction's whose
    // turn keeps clear, else the one that cuts least. The construction is
    // asked again at the next step, and taken as soon as its turn is clear.
    Vec2 safest = chosen.direction;
    double nearest = std::numeric_limits<double>::infinity();
    const double want = math_angle(chosen.direction);
    for (int i = 0; i < kFan; ++i) {
      const double heading = *course + 2.0 * std::numbers::pi * i / kFan;
      const Vec2 d = unit_vector(heading);
      const double c = sailed_clearance(zones, p, *course, d, tuning);
      const double off = std::abs(wrap_pi(heading - want));
      if (c >= -cut ? off < nearest : nearest == std::numeric_limits<double>::infinity() && c > best + cut) {
        if (c >= -cut) nearest = off;
        best = std::max(best, c);
        safest = d;
      }
    }
    return {safest, chosen.sector, chosen.object};
  };
  if (memory && course && !engaged_with(*memory, engaged.centre, match_radius(engaged))) {
    // A zone engaged afresh while under way: the side whose course is the
    // smaller turn from the present one. The axis rule alone can ask for a
    // 60 degree turn when a second zone blocks the first's tangent close by,
    // and a vehicle turning at most 5 deg/s sweeps ~20 m while it turns: into
    // the zone (the Monte Carlo's collisions). Far from the zones both rules
    // agree; an even split keeps the axis rule.
    const Construction left = cascade(+1), right = cascade(-1);
    auto turn = [&](const Construction& c) {
      return c.direction.squaredNorm() == 0.0 ? 4.0 : std::abs(wrap_pi(math_angle(c.direction) - *course));
    };
    const double tl = turn(left), tr = turn(right);
    const int side = std::abs(tl - tr) < 1e-9 ? axis_side(engaged.centre, g, p, course) : tl < tr ? +1 : -1;
    latch(*memory, active, engaged, side);
    return sailed(side > 0 ? left : right, side);
  }
  const int side = side_for(zones, active, p, g, course, memory, false);
  return sailed(cascade(side), side);
}

}  // namespace

ReactiveCommand geometric_command(const ReactiveParams& params, ReactiveMemory& state, const ReactiveInput& input) {
  validate_input(params, input);
  GeometricMemory& memory = method_state<GeometricMemory>(state);
  const std::vector<Ellipse> zones = security_ellipses(input.objects, params.margin_m);
  const SteeringTarget target = steering_target(zones, input.target);
  if (auto stop = arrival_command(params, input, target)) {
    release(memory);
    return *stop;
  }
  const Construction c =
      construct(zones, input.position, target.point, input.course, &memory,
                {params.exit_blend_fraction, geometric_params(params).passage_m, params.turn_rate_limit.value_or(0.0),
                 std::max(input.speed_mps, params.speed_mps), params.margin_m, params.turn_lag_s, input.turn_rate});
  const ReactiveStatus status = c.sector == 3 ? ReactiveStatus::leaving_zone : ReactiveStatus::ok;
  ReactiveCommand cmd = course_command(params, input, c.direction, status, c.object, target);
  cmd.sector = c.sector;
  return cmd;
}

Vec2 geometric_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                        std::span<const Ellipse> objects) {
  validate_query(params, point, target, objects);
  const std::vector<Ellipse> zones = security_ellipses(objects, params.margin_m);
  const Vec2 g = steering_target(zones, target).point;
  return construct(zones, point, g, std::nullopt, nullptr,
                   {params.exit_blend_fraction, geometric_params(params).passage_m})
      .direction;
}

namespace {

const ReactiveTuning kPassage{"geometric_passage_m", 20.0, 0.0, 1e4, true, true, "a distance in metres"};

}  // namespace

GeometricParams geometric_params(const ReactiveParams& params) { return {tuning_value(params, kPassage)}; }

ReactiveMethodEntry geometric_method_entry() {
  return {"geometric",       "the seed's construction of tangents in three sectors",
          0xd55e00,  // vermillion
          {kPassage},        geometric_command,
          geometric_gradient};
}

}  // namespace deepguide
