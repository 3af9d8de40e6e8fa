#include "deepguide/planning/edge_cost.hpp"

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/vehicle/autopilot.hpp"

namespace deepguide {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The leg cut into pieces: the direction, each piece's length and the current at its middle.
struct Pieces {
  Vec2 d{1.0, 0.0};
  double length = 0.0, piece = 0.0;
  std::vector<Vec2> currents;
};

Pieces cut(const Vec2& a, const Vec2& b, const CurrentAt& current, const LegOptions& options) {
  if (!a.allFinite() || !b.allFinite()) throw InputError("leg cost: expected finite end points");
  if (!(options.step_m > 0.0) || !std::isfinite(options.step_m)) {
    throw InputError("leg cost: step_m: expected a length > 0 m");
  }
  Pieces p;
  p.length = (b - a).norm();
  if (p.length == 0.0) return p;
  p.d = (b - a) / p.length;
  const auto n = static_cast<std::size_t>(std::ceil(p.length / options.step_m));
  p.piece = p.length / static_cast<double>(n);
  p.currents.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 c = current(a + (static_cast<double>(k) + 0.5) * p.piece * p.d);
    if (!c.allFinite()) throw InputError("leg cost: the current: expected finite values along the leg");
    p.currents.push_back(c);
  }
  return p;
}

// Time over the pieces at speed v; +inf when a piece is infeasible.
double time_at(const Pieces& p, double v) {
  double t = 0.0;
  for (const Vec2& c : p.currents) {
    const auto s = ground_speed_along(p.d, c, v);
    if (!s) return kInf;
    t += p.piece / *s;
  }
  return t;
}

LegCost cost_at(const Pieces& p, double v, const EnergyModel& energy) {
  LegCost out;
  out.length_m = p.length;
  out.speed_mps = v;
  out.time_s = time_at(p, v);
  out.feasible = std::isfinite(out.time_s);
  out.energy_j = out.feasible ? energy.power_w(v) * out.time_s : kInf;
  return out;
}

void check_speed(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(std::string("leg cost: ") + what + ": expected a speed > 0 m/s");
  }
}

}  // namespace

LegCost leg_cost(const Vec2& a, const Vec2& b, double speed_mps, const CurrentAt& current, const LegOptions& options) {
  check_speed(speed_mps, "speed");
  return cost_at(cut(a, b, current, options), speed_mps, options.energy);
}

LegCost leg_cost_economical(const Vec2& a, const Vec2& b, double min_speed_mps, double max_speed_mps,
                            const CurrentAt& current, const LegOptions& options) {
  check_speed(min_speed_mps, "minimum speed");
  check_speed(max_speed_mps, "maximum speed");
  if (min_speed_mps > max_speed_mps) throw InputError("leg cost: expected a minimum speed <= the maximum speed");
  const Pieces p = cut(a, b, current, options);
  // Below |d x c| of the strongest cross-current no heading holds the line.
  double lo = min_speed_mps;
  for (const Vec2& c : p.currents) lo = std::max(lo, std::abs(p.d.x() * c.y() - p.d.y() * c.x()));
  if (lo > max_speed_mps || !std::isfinite(time_at(p, max_speed_mps))) return cost_at(p, max_speed_mps, options.energy);
  // Just above lo a head current may still win; E is +inf there, which Brent treats as large.
  const auto energy = [&](double v) {
    const double t = time_at(p, v);
    return std::isfinite(t) ? options.energy.power_w(v) * t : std::numeric_limits<double>::max();
  };
  const auto best = boost::math::tools::brent_find_minima(energy, lo, max_speed_mps, 52);
  LegCost out = cost_at(p, best.first, options.energy);
  // The ends of the range are candidates too (a minimum at an end is where Brent stops short).
  for (double v : {lo, max_speed_mps}) {
    const LegCost end = cost_at(p, v, options.energy);
    if (end.energy_j < out.energy_j) out = end;
  }
  return out;
}

LegCost leg_cost_in_time(const Vec2& a, const Vec2& b, double speed_mps, double depart_s, const CurrentAtTime& current,
                         const LegOptions& options) {
  check_speed(speed_mps, "speed");
  if (!std::isfinite(depart_s)) throw InputError("leg cost: expected a finite departure time");
  // The pieces' geometry, without currents (they depend on when the vehicle gets there).
  const Pieces p = cut(
      a, b, [](const Vec2&) { return Vec2(0.0, 0.0); }, options);
  LegCost out;
  out.length_m = p.length;
  out.speed_mps = speed_mps;
  out.time_s = kInf;
  out.energy_j = kInf;
  const auto ground_speed = [&](const Vec2& x, double t) -> std::optional<double> {
    const std::optional<Vec2> c = current(x, t);
    if (!c) return std::nullopt;
    if (!c->allFinite()) throw InputError("leg cost: the current: expected finite values along the leg");
    return ground_speed_along(p.d, *c, speed_mps);
  };
  double t = depart_s;
  for (std::size_t k = 0; k < p.currents.size(); ++k) {
    const Vec2 x = a + (static_cast<double>(k) + 0.5) * p.piece * p.d;
    const std::optional<double> s0 = ground_speed(x, t);
    if (!s0) return out;
    const std::optional<double> s = ground_speed(x, t + 0.5 * p.piece / *s0);
    if (!s) return out;
    t += p.piece / *s;
  }
  // The arrival too must lie where the field has a value (within its time axis).
  if (!current(b, t)) return out;
  out.feasible = true;
  out.time_s = t - depart_s;
  out.energy_j = options.energy.power_w(speed_mps) * out.time_s;
  return out;
}

double time_lower_bound(double distance_m, double speed_mps, double max_current_mps) {
  return distance_m / (speed_mps + max_current_mps);
}

double energy_per_metre_lower_bound(const EnergyModel& energy, double min_speed_mps, double max_speed_mps,
                                    double max_current_mps) {
  check_speed(min_speed_mps, "minimum speed");
  if (!(max_speed_mps >= min_speed_mps) || !(max_current_mps >= 0.0)) {
    throw InputError("leg cost: expected min speed <= max speed and a current >= 0");
  }
  const auto per_metre = [&](double v) { return energy.power_w(v) / (v + max_current_mps); };
  const auto best = boost::math::tools::brent_find_minima(per_metre, min_speed_mps, max_speed_mps, 52);
  return std::min({best.second, per_metre(min_speed_mps), per_metre(max_speed_mps)});
}

}  // namespace deepguide
