#include "deepguide/mission/plan_splice.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {
namespace {

constexpr double kEps = 1e-9;  // m: a cut this close to a manoeuvre's end is at its end

double depth_along(const BasicManoeuvre& b, double s) {
  if (b.kind != BasicManoeuvre::Kind::line || b.length_m <= 0.0) return b.depth_m;
  return b.from_depth_m + std::clamp(s / b.length_m, 0.0, 1.0) * (b.depth_m - b.from_depth_m);
}

// The part of b from s0 to s1 metres along it.
BasicManoeuvre piece(const BasicManoeuvre& b, double s0, double s1) {
  BasicManoeuvre p = b;
  p.from = b.point_at(s0);
  p.to = b.point_at(s1);
  p.from_depth_m = depth_along(b, s0);
  p.depth_m = depth_along(b, s1);
  p.length_m = s1 - s0;
  return p;
}

}  // namespace

PlanPosition position_at(const MissionPlan& plan, double along_m) {
  PlanPosition out;
  if (plan.basics.empty()) return out;
  std::size_t i = 0;
  double time = 0.0;  // at the start of basic i
  for (std::size_t k = 0; k < plan.basics.size(); ++k) {
    const BasicManoeuvre& b = plan.basics[k];
    if (b.start_m > along_m + kEps) break;
    i = k;
    if (b.kind != BasicManoeuvre::Kind::point && along_m < b.start_m + b.length_m - kEps) break;
    if (k + 1 < plan.basics.size() && plan.basics[k + 1].start_m <= along_m + kEps) {
      time += b.duration_s();
    }
  }
  const BasicManoeuvre& b = plan.basics[i];
  const double s = std::clamp(along_m - b.start_m, 0.0, b.length_m);
  out.time_s = time + (b.speed_mps > 0.0 ? s / b.speed_mps : 0.0);
  out.basic = i;
  out.xy = b.point_at(s);
  out.depth_m = depth_along(b, s);
  out.speed_mps = b.speed_mps;
  return out;
}

bool holds_within(const MissionPlan& plan, double from_m, double to_m) {
  return std::any_of(plan.basics.begin(), plan.basics.end(), [&](const BasicManoeuvre& b) {
    return b.kind == BasicManoeuvre::Kind::point && b.start_m > from_m + kEps && b.start_m < to_m - kEps;
  });
}

MissionPlan splice_plan(const MissionPlan& plan, double from_m, double to_m, std::vector<BasicManoeuvre> replacement) {
  MissionPlan out;
  out.warnings = plan.warnings;
  const auto push = [&](BasicManoeuvre b) {
    b.start_m = out.length_m;
    out.length_m += b.length_m;
    out.basics.push_back(std::move(b));
  };
  bool inserted = false;
  for (const BasicManoeuvre& b : plan.basics) {
    const double b0 = b.start_m, b1 = b.start_m + b.length_m;
    if (b.kind == BasicManoeuvre::Kind::point) {
      if (b0 <= from_m + kEps) {
        push(b);
        continue;
      }
      if (!inserted) {
        for (BasicManoeuvre& r : replacement) push(r);
        inserted = true;
      }
      if (b0 >= to_m - kEps) push(b);
      continue;
    }
    if (b0 < from_m - kEps) push(piece(b, 0.0, std::min(b.length_m, from_m - b0)));
    if (!inserted && b1 > from_m + kEps) {
      for (BasicManoeuvre& r : replacement) push(r);
      inserted = true;
    }
    if (b1 > to_m + kEps) push(piece(b, std::max(0.0, to_m - b0), b.length_m));
  }
  if (!inserted) {
    for (BasicManoeuvre& r : replacement) push(r);
  }
  return out;
}

}  // namespace deepguide
