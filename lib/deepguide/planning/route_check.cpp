#include "deepguide/planning/route_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {}  // namespace

std::string RouteCheck::describe() const {
  // No verdict word: callers put their own ("UNSAFE: ...", an error message).
  const std::string margin = "(margin " + general(margin_m) + " m)";
  if (std::isinf(min_clearance_m)) return "no obstacles " + margin;
  // Two decimals, more when they would print a clearance just short of the
  // margin as the margin itself.
  int digits = 2;
  while (digits < 9 && min_clearance_m > 0.0 && min_clearance_m != margin_m &&
         fixed(min_clearance_m, digits) == fixed(margin_m, digits)) {
    ++digits;
  }
  std::string s = segments == 0 ? "waypoint 0 " : (of_legs ? "leg " : "segment ") + std::to_string(worst_segment) + " ";
  const std::string obstacle = "obstacle '" + printable(worst_obstacle) + "'";
  if (min_clearance_m > 0.0) {
    s += (segments == 0 ? "lies " : "passes ") + fixed(min_clearance_m, digits) + " m from " + obstacle;
  } else if (min_clearance_m < 0.0) {
    s += (segments == 0 ? "lies inside " : "enters ") + obstacle + " (" + fixed(-min_clearance_m, digits) + " m deep)";
  } else {
    s += "touches " + obstacle;
  }
  return s + " at (" + fixed(worst_point.x(), 2) + ", " + fixed(worst_point.y(), 2) + ") " + margin;
}

RouteCheck check_route(const std::vector<Vec2>& polyline, const ObstacleField& field, double tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw std::invalid_argument("check_route: tolerance must be finite and >= 0, got " + general(tolerance));
  }
  if (polyline.empty()) throw input_error({"route", "", ""}, "at least one waypoint", "none");
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    const Vec2& p = polyline[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
      throw input_error({"route", "waypoint " + std::to_string(i), ""}, "finite coordinates",
                        "(" + general(p.x()) + ", " + general(p.y()) + ")");
    }
  }

  RouteCheck check;
  check.margin_m = field.margin();
  check.segments = polyline.size() - 1;
  check.min_clearance_m = std::numeric_limits<double>::infinity();
  check.worst_point = polyline.front();
  const std::size_t n = std::max<std::size_t>(check.segments, 1);
  for (std::size_t s = 0; s < n; ++s) {
    const Vec2& a = polyline[s];
    const Vec2& b = polyline[std::min(s + 1, polyline.size() - 1)];
    const ObstacleField::Nearest nearest = field.segment_clearance(a, b);
    // Strict: the first segment wins a tie, so the report names where it starts.
    if (nearest.distance < check.min_clearance_m) {
      check.min_clearance_m = nearest.distance;
      check.worst_segment = s;
      check.worst_obstacle = field.obstacle_name(nearest.obstacle);
      check.worst_point = nearest.point_on_segment;
    }
  }
  check.safe = check.min_clearance_m >= field.margin() - tolerance;
  return check;
}

RouteCheck check_route_legs(const std::vector<RouteLeg>& legs, const ObstacleField& field, double tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw std::invalid_argument("check_route_legs: tolerance must be finite and >= 0, got " + general(tolerance));
  }
  if (legs.empty()) throw input_error({"route", "", ""}, "at least one leg", "none");
  RouteCheck check;
  check.of_legs = true;
  check.margin_m = field.margin();
  check.segments = legs.size();
  check.min_clearance_m = std::numeric_limits<double>::infinity();
  check.worst_point = legs.front().from;
  auto note = [&](std::size_t k, const ObstacleField::Nearest& n) {
    if (n.distance < check.min_clearance_m) {
      check.min_clearance_m = n.distance;
      check.worst_segment = k;
      check.worst_obstacle = field.obstacle_name(n.obstacle);
      check.worst_point = n.point_on_segment;
    }
  };
  const double need = field.margin() - tolerance;
  for (std::size_t k = 0; k < legs.size(); ++k) {
    const RouteLeg& leg = legs[k];
    for (const Vec2& p : {leg.from, leg.to}) {
      if (!p.allFinite()) {
        throw input_error({"route", "leg " + std::to_string(k), ""}, "finite coordinates",
                          "(" + general(p.x()) + ", " + general(p.y()) + ")");
      }
    }
    if (k > 0 && (legs[k - 1].to - leg.from).norm() > 1e-6) {
      throw input_error({"route", "leg " + std::to_string(k), "from"}, "the end of leg " + std::to_string(k - 1),
                        point_text(leg.from, 6) + " vs " + point_text(legs[k - 1].to, 6));
    }
    if (leg.kind == RouteLeg::Kind::line) {
      note(k, field.segment_clearance(leg.from, leg.to));
      continue;
    }
    // A stretch of a convex arc turning by dphi < pi lies between its chord
    // and the tangents at its ends, at most chord * tan(dphi / 2) / 2 off the
    // chord: its clearance is at least the chord's (exact) less that. A
    // stretch is split until this bound decides it, or until it is within
    // a quarter of `tolerance`, when the bound itself is its clearance (never
    // above the truth, and within half the tolerance of it).
    //
    // An arc on an ellipse obstacle's own zone (its core that ellipse, bit for
    // bit) is the boundary of the ellipse grown by offset_m, every point of
    // which lies offset_m from it (a convex set's Minkowski sum with a disc):
    // that obstacle's clearance along the arc is offset_m exactly, and the
    // chords judge the others only. Split against it, the chords ran down to
    // the tolerance: thousands of exact distances per arc (bench_compare:
    // the tangent graph's solve 10 times slower than before this checker).
    //
    // The core may be its ellipse moved by rounding (the tangent graph works
    // in a frame centred on its zones and adds the origin back; bit for bit,
    // most arcs of bench_planning's fields went unrecognised and split down
    // to the tolerance, 4,000 to 9,000 chords each): the arc then lies
    // offset_m from the moved ellipse, so at least offset_m less the shift
    // from the obstacle.
    const double within = 1e-9 * (1.0 + leg.core.centre.cwiseAbs().maxCoeff());
    const std::size_t own = leg.core.a > 0.0 ? field.ellipse_index(leg.core, within) : ObstacleField::kNone;
    if (own != ObstacleField::kNone) {
      const double shift = (field.obstacles().ellipses[own].footprint.centre - leg.core.centre).norm();
      note(k, {leg.offset_m - shift, own, arc_point(leg, 0.5 * (leg.phi_from + leg.phi_to))});
    }
    std::vector<std::pair<double, double>> todo{{leg.phi_from, leg.phi_to}};
    note(k, field.segment_clearance(leg.to, leg.to));
    std::size_t chords = 0;
    while (!todo.empty() && chords < 1000000) {
      const auto [phi0, phi1] = todo.back();
      todo.pop_back();
      const double dphi = std::abs(phi1 - phi0);
      const Vec2 p0 = arc_point(leg, phi0), p1 = arc_point(leg, phi1);
      note(k, field.segment_clearance(p0, p0));  // points of the arc: what the report names
      bool split = dphi > 0.5 * std::numbers::pi;
      if (!split) {
        const double off = 0.5 * (p1 - p0).norm() * std::tan(0.5 * dphi);
        ObstacleField::Nearest n = field.segment_clearance(p0, p1, own);
        ++chords;
        n.distance -= off;
        if (n.distance < std::min(need, check.min_clearance_m)) {
          if (off > 0.25 * tolerance) {  // the chord of an arc on a zone lies inside it by up to `off` too
            split = true;
          } else {
            note(k, n);
          }
        }
      }
      if (split) {
        const double mid = 0.5 * (phi0 + phi1);
        todo.push_back({phi0, mid});
        todo.push_back({mid, phi1});
      }
    }
    if (!todo.empty()) note(k, {-std::numeric_limits<double>::infinity(), 0, arc_point(leg, todo.back().first)});
  }
  check.safe = check.min_clearance_m >= need;
  return check;
}

std::string DepthRouteCheck::describe() const {
  if (!safe) return "leg " + std::to_string(first_bad_segment) + " " + problem;
  std::string s = std::to_string(segments) + " legs in the band, steepest " + fixed(steepest_deg, 1) + " deg";
  if (std::isfinite(min_floor_gap_m)) s += ", at least " + fixed(min_floor_gap_m, 2) + " m above the sea floor";
  return s;
}

DepthRouteCheck check_route_in_depth(const Route& route, const WaterVolume& volume, double max_dive_deg) {
  if (route.points.empty() || route.depth_m.size() != route.points.size()) {
    throw InputError("route check in depth: expected a route with one depth per waypoint, got " +
                     std::to_string(route.points.size()) + " waypoints and " + std::to_string(route.depth_m.size()) +
                     " depths");
  }
  std::vector<Vec3> p;
  for (std::size_t i = 0; i < route.points.size(); ++i) {
    p.emplace_back(route.points[i].x(), route.points[i].y(), route.depth_m[i]);
    if (!p.back().allFinite())
      throw InputError("route check in depth: waypoint " + std::to_string(i) + " is not finite");
  }
  if (!(max_dive_deg > 0.0 && max_dive_deg < 90.0)) {
    throw InputError("route check in depth: expected a dive angle between 0 and 90 degrees");
  }
  DepthRouteCheck check;
  check.segments = p.size() - 1;
  const double slope = std::tan(max_dive_deg * M_PI / 180.0);
  for (std::size_t i = 0; i < std::max<std::size_t>(check.segments, 1); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[std::min(i + 1, p.size() - 1)];
    const double run = (b - a).head<2>().norm(), rise = std::abs(b.z() - a.z());
    check.steepest_deg = std::max(check.steepest_deg, std::atan2(rise, run) * 180.0 / M_PI);
    if (volume.floor() != nullptr) {
      check.min_floor_gap_m = std::min(check.min_floor_gap_m, volume.floor()->lowest_gap(a, b).gap_m);
    }
    if (!check.safe) continue;
    std::string problem;
    if (rise > slope * run * (1.0 + 1e-9)) {
      problem = "is " + fixed(std::atan2(rise, run) * 180.0 / M_PI, 2) + " deg steep (the dive angle is " +
                general(max_dive_deg) + " deg)";
    } else if (const WaterVolume::Verdict v = volume.check_segment(a, b); v.blocked) {
      problem = v.reason + " at (" + fixed(v.where.x(), 2) + ", " + fixed(v.where.y(), 2) + ", depth " +
                fixed(v.where.z(), 2) + ")";
    }
    if (!problem.empty()) {
      check.safe = false;
      check.first_bad_segment = i;
      check.problem = problem;
    }
  }
  return check;
}

}  // namespace deepguide
