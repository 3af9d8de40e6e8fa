#include "deepguide/mission/basic_manoeuvres.hpp"

#include <boost/geometry.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/identification/offset_path.hpp"

namespace deepguide {
namespace {

namespace bg = boost::geometry;

// "FILE: line N: TYPE 'NAME'", the name made printable (one line).
std::string place(const Mission& mission, const ComplexManoeuvre& c) {
  return mission.source + ": " + c.line + ": " + c.type + " '" + printable(c.name) + "'";
}

// Appends basic manoeuvres, keeping the position, depth and distance along.
class Builder {
 public:
  Builder(const Vec2& start, double depth) : at_(start), depth_(depth) {}

  void begin(std::size_t source, double depth, double speed) {
    source_ = source;
    target_depth_ = depth;
    speed_ = speed;
    first_ = true;
  }
  void line(const Vec2& to) {
    if ((to - at_).norm() < 1e-9) return;
    BasicManoeuvre b = base(BasicManoeuvre::Kind::line);
    b.to = to;
    b.length_m = (to - at_).norm();
    push(b);
  }
  void arc(const Vec2& centre, const Vec2& to, int turn) {
    BasicManoeuvre b = base(BasicManoeuvre::Kind::arc);
    b.to = to;
    b.centre = centre;
    b.radius_m = (at_ - centre).norm();
    b.turn = turn;
    double sweep = std::atan2(cross(at_ - centre, to - centre), (at_ - centre).dot(to - centre));
    if (turn > 0 && sweep < 0.0) sweep += 2.0 * M_PI;
    if (turn < 0 && sweep > 0.0) sweep -= 2.0 * M_PI;
    b.length_m = std::abs(sweep) * b.radius_m;
    push(b);
  }
  void point(double depth, double hold) {
    BasicManoeuvre b = base(BasicManoeuvre::Kind::point);
    b.to = at_;
    b.depth_m = depth;
    b.hold_s = hold;
    push(b);
  }
  const Vec2& at() const { return at_; }
  MissionPlan plan;

 private:
  BasicManoeuvre base(BasicManoeuvre::Kind kind) const {
    BasicManoeuvre b;
    b.kind = kind;
    b.from = at_;
    b.from_depth_m = depth_;
    b.depth_m = kind == BasicManoeuvre::Kind::line ? target_depth_ : depth_;
    b.speed_mps = speed_;
    b.source = source_;
    b.start_m = plan.length_m;
    return b;
  }
  void push(const BasicManoeuvre& b) {
    plan.basics.push_back(b);
    plan.length_m += b.length_m;
    at_ = b.to;
    depth_ = b.depth_m;
    first_ = false;
  }
  Vec2 at_;
  double depth_;
  double target_depth_ = 0.0, speed_ = 0.0;
  std::size_t source_ = 0;
  bool first_ = true;
};

// Lines through the waypoints, corners rounded where the legs leave room.
void track(Builder& b, const std::vector<Vec2>& waypoints, double radius, const std::string& name) {
  std::vector<Vec2> pts{b.at()};
  for (const Vec2& w : waypoints) {
    if ((w - pts.back()).norm() > 1e-9) pts.push_back(w);
  }
  double used_in = 0.0;  // tangent length already taken from the start of the current leg
  for (std::size_t i = 1; i < pts.size(); ++i) {
    if (i + 1 == pts.size()) {
      b.line(pts[i]);
      break;
    }
    const Vec2 d0 = (pts[i] - pts[i - 1]).normalized(), d1 = (pts[i + 1] - pts[i]).normalized();
    const double turn_angle = std::atan2(std::abs(cross(d0, d1)), d0.dot(d1));
    const double tangent = radius * std::tan(0.5 * turn_angle);
    const double in_room = (pts[i] - pts[i - 1]).norm() - used_in, out_room = 0.5 * (pts[i + 1] - pts[i]).norm();
    if (turn_angle < 1e-6 || tangent > in_room || tangent > out_room) {
      if (turn_angle >= 1e-6) {
        b.plan.warnings.push_back(name + ": the turn at waypoint " + std::to_string(i) + " (" +
                                  fixed(turn_angle * 180.0 / M_PI, 1) + " deg) leaves no room for a " +
                                  fixed(radius, 1) + " m turn: it stays a corner");
      }
      b.line(pts[i]);
      used_in = 0.0;
      continue;
    }
    const int side = cross(d0, d1) > 0.0 ? 1 : -1;
    const Vec2 normal = side > 0 ? Vec2(-d0.y(), d0.x()) : Vec2(d0.y(), -d0.x());
    const Vec2 in = pts[i] - tangent * d0, out = pts[i] + tangent * d1;
    b.line(in);
    b.arc(in + radius * normal, out, side);
    used_in = tangent;
  }
}

void survey(Builder& b, const Mission& mission, const ComplexManoeuvre& c, const SurveySpec& s, double radius) {
  bg::model::point<double, 2, bg::cs::cartesian> centroid;
  bg::centroid(s.area, centroid);
  const Vec2 centre(centroid.get<0>(), centroid.get<1>());
  const double a = mission.frame.heading_to_local(s.heading_deg, centre);
  if (!std::isfinite(a)) {
    throw InputError(place(mission, c) + ": area: expected an area inside the frame " + mission.frame.id() +
                     ", got one where it has no north");
  }
  const Vec2 u(std::cos(a), std::sin(a)), n(-u.y(), u.x());
  double n_lo = 1e300, n_hi = -1e300, u_lo = 1e300, u_hi = -1e300;
  for (const BgPoint& p : s.area.outer()) {
    const Vec2 q = to_eigen(p);
    n_lo = std::min(n_lo, q.dot(n));
    n_hi = std::max(n_hi, q.dot(n));
    u_lo = std::min(u_lo, q.dot(u));
    u_hi = std::max(u_hi, q.dot(u));
  }
  // Checked before the lines are made: a tiny spacing would make no end of them.
  const double width = n_hi - n_lo;
  if (width > s.line_spacing_m && s.line_spacing_m < 2.0 * radius - 1e-9) {
    throw InputError(place(mission, c) + ": line_spacing_m " + general(s.line_spacing_m) +
                     " is under twice the turn radius (2 x " + fixed(radius, 1) + " m): widen the spacing");
  }
  if (width / s.line_spacing_m > 1e5) {
    throw InputError(place(mission, c) + ": line_spacing_m " + general(s.line_spacing_m) +
                     " makes more than 100000 "
                     "lines across the area: widen the spacing");
  }
  // Each line's span inside the area.
  struct Span {
    double offset, from, to;
  };
  std::vector<Span> lines;
  for (double o = n_lo + 0.5 * s.line_spacing_m; o < n_hi; o += s.line_spacing_m) {
    bg::model::linestring<BgPoint> cut{to_bg(o * n + (u_lo - 1.0) * u), to_bg(o * n + (u_hi + 1.0) * u)};
    bg::model::multi_linestring<bg::model::linestring<BgPoint>> inside;
    bg::intersection(cut, s.area, inside);
    double lo = 1e300, hi = -1e300;
    for (const auto& piece : inside) {
      for (const BgPoint& p : piece) {
        lo = std::min(lo, to_eigen(p).dot(u));
        hi = std::max(hi, to_eigen(p).dot(u));
      }
    }
    if (hi > lo) lines.push_back({o, lo, hi});
  }
  if (lines.empty()) {
    throw InputError(place(mission, c) +
                     ": expected an area wider than its line spacing across the heading, got "
                     "none of its lines inside it");
  }
  if (lines.size() > 1 && s.line_spacing_m < 2.0 * radius - 1e-9) {
    throw InputError(place(mission, c) + ": line_spacing_m " + general(s.line_spacing_m) +
                     " is under twice the turn radius (2 x " + fixed(radius, 1) + " m): widen the spacing");
  }
  // Start from the line and the end nearest the vehicle.
  const auto at = [&](const Span& l, double along) { return Vec2(l.offset * n + along * u); };
  const auto near_end = [&](const Span& l) {
    return std::min((at(l, l.from) - b.at()).norm(), (at(l, l.to) - b.at()).norm());
  };
  if (near_end(lines.back()) < near_end(lines.front())) std::reverse(lines.begin(), lines.end());
  const bool first_forward =
      (at(lines.front(), lines.front().from) - b.at()).norm() <= (at(lines.front(), lines.front().to) - b.at()).norm();
  // Boustrophedon: lines alternate along u and against it; ends extended to
  // a common turning line, joined by quarter arc, straight, quarter arc.
  for (std::size_t k = 0; k < lines.size(); ++k) {
    Span& l = lines[k];
    const bool forward = (k % 2 == 0) == first_forward;
    if (k + 1 < lines.size()) {
      Span& next = lines[k + 1];
      if (forward)
        l.to = next.to = std::max(l.to, next.to);
      else
        l.from = next.from = std::min(l.from, next.from);
    }
    const Vec2 start = at(l, forward ? l.from : l.to), end = at(l, forward ? l.to : l.from);
    b.line(start);  // the transit to the first line; a no-op after a turn
    b.line(end);
    if (k + 1 == lines.size()) break;
    const Vec2 d = forward ? u : Vec2(-u);
    const double step = lines[k + 1].offset - l.offset;
    const Vec2 across = step > 0.0 ? n : Vec2(-n);  // towards the next line
    const double gap = std::abs(step);
    const int side = cross(d, across) > 0.0 ? 1 : -1;
    b.arc(end + radius * across, end + radius * d + radius * across, side);
    b.line(end + radius * d + (gap - radius) * across);
    b.arc(end + (gap - radius) * across, end + gap * across, side);
  }
}

const Ellipse* find_object(const ObstacleSet& obstacles, const std::string& id) {
  for (const EllipticCylinder& e : obstacles.ellipses) {
    if (e.id == id) return &e.footprint;
  }
  return nullptr;
}

}  // namespace

Vec2 BasicManoeuvre::point_at(double s) const {
  if (kind == Kind::point || length_m <= 0.0) return from;
  const double f = std::clamp(s / length_m, 0.0, 1.0);
  if (kind == Kind::line) return from + f * (to - from);
  const double sweep = turn * length_m / radius_m;
  const double a = std::atan2((from - centre).y(), (from - centre).x()) + f * sweep;
  return centre + radius_m * Vec2(std::cos(a), std::sin(a));
}

Vec2 BasicManoeuvre::direction_at(double s) const {
  if (kind == Kind::point || length_m <= 0.0) return Vec2::Zero();
  if (kind == Kind::line) return (to - from) / length_m;
  const Vec2 r = (point_at(s) - centre) / radius_m;
  return turn * Vec2(-r.y(), r.x());
}

bool joins_smoothly(const BasicManoeuvre& before, const BasicManoeuvre& next) {
  constexpr double kSameDirection = 1e-6;  // rad
  const Vec2 a = before.direction_at(before.length_m), b = next.direction_at(0.0);
  return a.squaredNorm() > 0.0 && b.squaredNorm() > 0.0 && (a - b).norm() < kSameDirection;
}

double plan_duration(const MissionPlan& plan) {
  double t = 0.0;
  for (const BasicManoeuvre& b : plan.basics) t += b.duration_s();
  return t;
}

MissionPlan expand_mission(const Mission& mission, const ObstacleSet& obstacles) {
  Builder b(mission.start, mission.start_depth_m);
  for (std::size_t i = 0; i < mission.manoeuvres.size(); ++i) {
    const ComplexManoeuvre& c = mission.manoeuvres[i];
    b.begin(i, c.depth_m, c.speed_mps);
    const double radius = turn_radius(mission.vehicle, c.speed_mps);
    const std::string name = c.type + " '" + printable(c.name) + "'";
    if (const auto* t = std::get_if<TrackSpec>(&c.spec)) {
      track(b, t->waypoints, radius, name);
    } else if (const auto* g = std::get_if<GotoSpec>(&c.spec)) {
      b.line(g->position);
    } else if (const auto* s = std::get_if<SurveySpec>(&c.spec)) {
      if (s->turn_radius_m > 0.0 && s->turn_radius_m < radius - 1e-9) {
        throw InputError(place(mission, c) + ": turn_radius_m " + general(s->turn_radius_m) +
                         " is below the vehicle's " + fixed(radius, 1) + " m at " + fixed(c.speed_mps, 2) + " m/s");
      }
      survey(b, mission, c, *s, std::max(radius, s->turn_radius_m));
    } else if (const auto* gps = std::get_if<GpsUpdateSpec>(&c.spec)) {
      b.point(0.0, gps->hold_s);
      b.point(c.depth_m, 0.0);
    } else if (const auto* id = std::get_if<IdentifyTask>(&c.spec)) {
      const Ellipse* object = find_object(obstacles, id->object);
      if (object == nullptr) {
        throw InputError(place(mission, c) +
                         ": object: expected the id of one of the mission's elliptic-cylinder "
                         "obstacles, got '" +
                         printable(id->object) + "'");
      }
      if (id->mode == IdentifyTask::Mode::align) {
        b.line(project_to_offset(*object, id->distance_m, b.at()).point);
        b.point(c.depth_m, 60.0);
      } else {
        check_offset_path_fits(*object, id->distance_m, radius, name);
        const IdentificationLap lap = identification_lap(*object, id->distance_m, b.at());
        b.line(lap.start);
        for (const CircleArc& a : lap.arcs) b.arc(a.centre, a.to, a.turn);
      }
    }
  }
  return std::move(b.plan);
}

IdentificationLap identification_lap(const Ellipse& object, double distance_m, const Vec2& from) {
  const OffsetProjection nearest = project_to_offset(object, distance_m, from);
  double t0 = nearest.t;
  if (nearest.signed_m > kLapTolerance_m) {
    // The tangent from `from` that runs on anticlockwise: where p lies on the
    // path's tangent line behind the point, g(t) = cross(tangent, p - o) = 0
    // with (o - p) . tangent > 0. g changes sign at both tangent points.
    const auto g = [&](double t) {
      return cross(offset_tangent(object, t), from - offset_point(object, distance_m, t));
    };
    constexpr int kSteps = 720;
    for (int k = 0; k < kSteps; ++k) {
      double lo = nearest.t + 2.0 * std::numbers::pi * k / kSteps, hi = lo + 2.0 * std::numbers::pi / kSteps;
      double glo = g(lo);
      if ((glo > 0.0) == (g(hi) > 0.0)) continue;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        if ((g(mid) > 0.0) == (glo > 0.0)) {
          lo = mid;
          glo = g(mid);
        } else {
          hi = mid;
        }
      }
      const double t = 0.5 * (lo + hi);
      if ((offset_point(object, distance_m, t) - from).dot(offset_tangent(object, t)) > 0.0) {
        t0 = t;
        break;
      }
    }
  }
  return {offset_point(object, distance_m, t0), offset_lap_arcs(object, distance_m, t0, kLapTolerance_m)};
}

std::vector<TrackPoint> plan_polyline(const MissionPlan& plan, double tolerance_m) {
  std::vector<TrackPoint> out;
  for (std::size_t i = 0; i < plan.basics.size(); ++i) {
    const BasicManoeuvre& m = plan.basics[i];
    if (out.empty()) out.push_back({m.from, m.from_depth_m, i, m.start_m});
    if (m.kind == BasicManoeuvre::Kind::arc) {
      // Chords of a circle of radius R stay within R (1 - cos(dphi / 2)) of it.
      const double dphi = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance_m / m.radius_m));
      const int steps = std::max(1, static_cast<int>(std::ceil(m.length_m / m.radius_m / dphi)));
      for (int k = 1; k < steps; ++k) {
        out.push_back({m.point_at(m.length_m * k / steps), m.depth_m, i, m.start_m + m.length_m * k / steps});
      }
    }
    out.push_back({m.to, m.depth_m, i, m.start_m + m.length_m});
  }
  return out;
}

}  // namespace deepguide
