#include "deepguide/planning/cost_model.hpp"

#include <cmath>
#include <cstdio>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/currents/current_summary.hpp"

namespace deepguide {

CostKind parse_cost_kind(const std::string& text) {
  if (text == "length") return CostKind::length;
  if (text == "time") return CostKind::time;
  if (text == "energy") return CostKind::energy;
  throw InputError("`cost`: expected length, time or energy, got '" + text + "'");
}

std::string to_string(CostKind kind) {
  switch (kind) {
    case CostKind::length: return "length";
    case CostKind::time: return "time";
    case CostKind::energy: return "energy";
  }
  return "?";
}

namespace {

bool positive(double v) { return v > 0.0 && std::isfinite(v); }

// The model's current as the leg integrators want it: zero where the field
// has no value, nothing (infeasible) outside a time-dependent field's axis.
CurrentAtTime usable_current(const CostModel& m) {
  return [&m](const Vec2& p, double t) -> std::optional<Vec2> {
    if (!m.steady && (t < m.time_first_s || t > m.time_last_s)) return std::nullopt;
    if (!m.current) return Vec2(0.0, 0.0);
    return m.current(p, m.steady ? m.depart_s : t).value_or(Vec2(0.0, 0.0));
  };
}

// The smallest distance between neighbouring nodes of a gridded field (m);
// degrees of a lon/lat field at the field's middle latitude (a metre more or
// less does not matter: it only sets the integration step).
double node_spacing_m(const CurrentField& f) {
  const auto smallest_step = [](const std::vector<double>& axis) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < axis.size(); ++i) d = std::min(d, axis[i] - axis[i - 1]);
    return d;
  };
  double dx = smallest_step(f.x), dy = smallest_step(f.y);
  if (f.geographic && !f.y.empty()) {
    const double lat = 0.5 * (f.y.front() + f.y.back()) * M_PI / 180.0;
    dx *= 111320.0 * std::cos(lat);
    dy *= 110540.0;
  }
  return std::min(dx, dy);
}

}  // namespace

void attach_current(CostModel& m, std::shared_ptr<const CurrentField> field, const LocalFrame& frame,
                    const Vec2& area_min, const Vec2& area_max) {
  check_current_coverage(*field, frame, area_min, area_max);
  m.steady = field->steady();
  m.uniform = field->constant;
  if (!m.steady) {
    m.time_first_s = field->times_s.front();
    m.time_last_s = field->times_s.back();
  }
  // Bilinear interpolation in space and linear in time are convex
  // combinations of nodes, and the frame's rotation keeps lengths: no sample
  // is faster than the fastest node.
  m.max_current_mps = field->constant ? field->constant_velocity.norm() : summarize_current(*field).max_speed_mps;
  if (!std::isfinite(m.max_current_mps)) m.max_current_mps = 0.0;  // no node known: still water everywhere
  // Pieces of a quarter of the node spacing: the current is bilinear in each
  // cell, and the midpoint rule over a quarter cell is well inside 0.1 % of
  // a leg's time (the usual rule asks for at most half). Never finer than the
  // model's step (10 m by default); a constant field needs one piece per leg.
  if (field->constant) {
    m.leg.step_m = std::numeric_limits<double>::max();
  } else {
    const double spacing = node_spacing_m(*field);
    if (std::isfinite(spacing)) m.leg.step_m = std::max(m.leg.step_m, 0.25 * spacing);
  }
  const auto sampler = std::make_shared<const CurrentSampler>(std::move(field), frame, area_min, area_max);
  m.current = [sampler](const Vec2& p, double t) { return sampler->sample(p, t); };
}

void validate(const CostModel& m) {
  if (!positive(m.leg.energy.hotel_power_w) || !positive(m.leg.energy.propulsion_k_w_per_mps3)) {
    throw InputError("energy model: hotel_power_w and propulsion_k_w_per_mps3: expected powers > 0, got " +
                     general(m.leg.energy.hotel_power_w) + " W and " + general(m.leg.energy.propulsion_k_w_per_mps3) +
                     " W/(m/s)^3");
  }
  if (!positive(m.min_speed_mps) || !positive(m.max_speed_mps) || m.min_speed_mps > m.max_speed_mps) {
    throw InputError("vehicle speeds: expected 0 < min_speed_mps <= max_speed_mps, got " + general(m.min_speed_mps) +
                     " and " + general(m.max_speed_mps) + " m/s");
  }
  if (!m.economical && (!positive(m.speed_mps) || m.speed_mps > m.max_speed_mps)) {
    throw InputError("`speed`: expected a speed > 0 and <= the vehicle's maximum " + general(m.max_speed_mps) +
                     " m/s, got " + general(m.speed_mps));
  }
  if (!(m.max_current_mps >= 0.0) || !std::isfinite(m.max_current_mps)) {
    throw InputError("current: expected a finite maximum speed >= 0 m/s");
  }
  if (!std::isfinite(m.depart_s)) throw InputError("`depart_s`: expected a finite departure time");
  if (!m.steady && (m.depart_s < m.time_first_s || m.depart_s > m.time_last_s)) {
    throw InputError("`depart_s`: expected a time within the current field's time axis " + format_utc(m.time_first_s) +
                     " .. " + format_utc(m.time_last_s) + ", got " + format_utc(m.depart_s));
  }
  if (m.economical && m.kind == CostKind::time) {
    throw InputError(
        "`speed` optimal: expected `cost` energy or length (the least-energy speed per leg; the "
        "fastest route is flown at the maximum speed: give `speed` " +
        general(m.max_speed_mps) + ")");
  }
  if (m.economical && !m.steady) {
    throw InputError(
        "`speed` optimal: expected a steady current (choosing the speed per leg in a current that changes in time "
        "is not supported; give a fixed `speed`)");
  }
}

LegCost price_leg(const CostModel& m, const Vec2& a, const Vec2& b, double depart_s) {
  const CurrentAtTime current = usable_current(m);
  if (!m.steady) return leg_cost_in_time(a, b, m.speed_mps, depart_s, current, m.leg);
  const CurrentAt steady = [&](const Vec2& p) { return *current(p, depart_s); };
  if (m.economical) return leg_cost_economical(a, b, m.min_speed_mps, m.max_speed_mps, steady, m.leg);
  return leg_cost(a, b, m.speed_mps, steady, m.leg);
}

double edge_weight(const CostModel& m, const LegCost& leg) {
  if (!leg.feasible) return std::numeric_limits<double>::infinity();
  switch (m.kind) {
    case CostKind::length: return leg.length_m;
    case CostKind::time: return leg.time_s;
    case CostKind::energy: return leg.energy_j;
  }
  return leg.length_m;
}

double departure_after(const CostModel& m, double cost_so_far) {
  if (m.steady) return m.depart_s;
  switch (m.kind) {
    case CostKind::time: return m.depart_s + cost_so_far;
    case CostKind::energy: return m.depart_s + cost_so_far / m.leg.energy.power_w(m.speed_mps);
    case CostKind::length: break;
  }
  // A length search does not price edges by the model (the graph's weights are lengths).
  return m.depart_s;
}

double cost_per_metre_lower_bound(const CostModel& m) {
  switch (m.kind) {
    case CostKind::length: return 1.0;
    case CostKind::time:
      return m.economical ? 1.0 / (m.max_speed_mps + m.max_current_mps) : 1.0 / (m.speed_mps + m.max_current_mps);
    case CostKind::energy:
      return m.economical
                 ? energy_per_metre_lower_bound(m.leg.energy, m.min_speed_mps, m.max_speed_mps, m.max_current_mps)
                 : m.leg.energy.power_w(m.speed_mps) / (m.speed_mps + m.max_current_mps);
  }
  return 1.0;
}

RoutePricing price_route(const CostModel& m, const std::vector<Vec2>& points) {
  RoutePricing out;
  double t = m.depart_s;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    PricedLeg leg;
    leg.depart_s = t;
    if (out.feasible) {
      leg.cost = price_leg(m, points[i], points[i + 1], t);
    } else {
      // After a leg the vehicle cannot sail there is no time to leave at:
      // the rest is infeasible too, unpriced.
      leg.cost.length_m = (points[i + 1] - points[i]).norm();
      leg.cost.time_s = leg.cost.energy_j = std::numeric_limits<double>::infinity();
    }
    out.feasible = out.feasible && leg.cost.feasible;
    if (leg.cost.feasible) t += leg.cost.time_s;
    leg.arrive_s = leg.cost.feasible ? t : std::numeric_limits<double>::infinity();
    out.length_m += leg.cost.length_m;
    out.time_s += leg.cost.time_s;
    out.energy_j += leg.cost.energy_j;
    out.cost += edge_weight(m, leg.cost);
    out.legs.push_back(leg);
    // Where the field had no value: the same pieces the integration used, at the leg's departure.
    if (m.current && leg.cost.length_m > 0.0) {
      const auto n = static_cast<std::size_t>(std::ceil(leg.cost.length_m / m.leg.step_m));
      const double piece = leg.cost.length_m / static_cast<double>(n);
      const Vec2 d = (points[i + 1] - points[i]) / leg.cost.length_m;
      for (std::size_t k = 0; k < n; ++k) {
        const Vec2 x = points[i] + (static_cast<double>(k) + 0.5) * piece * d;
        if (!m.current(x, m.steady ? m.depart_s : leg.depart_s)) out.unknown_current_m += piece;
      }
    }
  }
  return out;
}

}  // namespace deepguide
