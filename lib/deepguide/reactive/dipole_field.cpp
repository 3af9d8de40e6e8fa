#include "deepguide/reactive/dipole_field.hpp"

#include <algorithm>
#include <complex>
#include <optional>

#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/reactive/reactive_support.hpp"

namespace deepguide {
namespace {

using namespace reactive_detail;
using Complex = std::complex<double>;

/// Below this speed (U = 1) the field counts as vanished.
constexpr double kStagnation = 1e-6;

double smoothstep(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// The circle enclosing the enclosing circles of two zones.
Ellipse enclosing_circle(const Ellipse& e1, const Ellipse& e2) {
  const Vec2 d = e2.centre - e1.centre;
  const double dist = d.norm();
  Ellipse c;
  if (dist + e2.a <= e1.a) {
    c.centre = e1.centre, c.a = e1.a;
  } else if (dist + e1.a <= e2.a) {
    c.centre = e2.centre, c.a = e2.a;
  } else {
    c.a = 0.5 * (dist + e1.a + e2.a);
    c.centre = e1.centre + (c.a - e1.a) / dist * d;
  }
  c.b = c.a;
  return c;
}

/// The member of zone z whose object is nearest to p (the one reported as steered around).
std::ptrdiff_t nearest_member(const DipoleZone& z, std::span<const Ellipse> objects, const Vec2& p) {
  std::ptrdiff_t best = z.members.front();
  for (std::ptrdiff_t m : z.members) {
    const auto i = static_cast<std::size_t>(m);
    if ((objects[i].centre - p).norm() < (objects[static_cast<std::size_t>(best)].centre - p).norm()) best = m;
  }
  return best;
}

/// Position in the flow's circle plane: zeta (Joukowski inverse) and
/// Z = zeta conj(E), whose real axis is the flow direction through the centre.
struct CirclePlane {
  Complex zeta;
  Complex flow_dir;  ///< E, the flow direction in the zone's frame
  double rho0 = 0.0;
  double k2 = 0.0;
  Complex Z() const { return zeta * std::conj(flow_dir); }
};

CirclePlane circle_plane(const Ellipse& zone, const Vec2& e, const Vec2& x) {
  CirclePlane c;
  const Vec2 l = zone.to_local(x);
  const Complex z(l.x(), l.y());
  c.rho0 = 0.5 * (zone.a + zone.b);
  c.k2 = 0.25 * (zone.a * zone.a - zone.b * zone.b);
  const Complex s = std::sqrt(z * z - 4.0 * c.k2);
  const Complex r1 = 0.5 * (z + s);
  const Complex r2 = 0.5 * (z - s);
  c.zeta = std::abs(r1) >= std::abs(r2) ? r1 : r2;
  c.flow_dir = Complex(e.dot(zone.major_dir()), e.dot(zone.minor_dir()));
  return c;
}

/// Velocity (world frame) of the flow along e past the zone, at the point whose circle-plane position is c.
Vec2 zone_velocity(const Ellipse& zone, const CirclePlane& c) {
  const Complex Z = c.Z();
  const Complex dW = std::conj(c.flow_dir) * (1.0 - c.rho0 * c.rho0 / (Z * Z));
  const Complex dz = 1.0 - c.k2 / (c.zeta * c.zeta);
  const Complex v = std::conj(dW / dz);
  return v.real() * zone.major_dir() + v.imag() * zone.minor_dir();
}

/// The engaged zone's side clamp (see the header): index into zones, side, band.
struct AxisClamp {
  std::ptrdiff_t zone = -1;
  int side = 0;
  double band = 0.0;
};

/// The combined field at p for target g (unnormalised, U = 1).
Vec2 field(const std::vector<DipoleZone>& zones, const Vec2& p, const Vec2& g, double influence, double blend,
           const AxisClamp& clamp) {
  const Vec2 e = unit_or_zero(g - p);
  if (e.squaredNorm() == 0.0) return e;
  const std::size_t n = zones.size();
  std::vector<double> lambda(n, 0.0), shadow(n, 1.0);
  const double reach = std::max(influence, blend);
  for (std::size_t i = 0; i < n; ++i) {
    const Ellipse& z = zones[i].shape;
    if ((p - z.centre).norm() - z.a >= reach) continue;  // cheap: farther than reach from the zone
    const double d = std::max(0.0, signed_distance(z, p));
    lambda[i] = 1.0 - smoothstep(d / influence);
    shadow[i] = smoothstep(d / blend);
  }
  Vec2 v = e;
  for (std::size_t i = 0; i < n; ++i) {
    if (lambda[i] == 0.0) continue;
    double w = lambda[i];
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i) w *= shadow[j];
    }
    if (w == 0.0) continue;
    CirclePlane c = circle_plane(zones[i].shape, e, p);
    if (static_cast<std::ptrdiff_t>(i) == clamp.zone) {
      const Complex Z = c.Z();
      if (Z.real() < 0.0 && std::abs(Z.imag()) < clamp.band) {
        c.zeta = Complex(Z.real(), clamp.side * clamp.band) * c.flow_dir;
      }
    }
    v += w * (zone_velocity(zones[i].shape, c) - e);
  }
  return v;
}

Vec2 direction_of(const Vec2& v) { return v.norm() < kStagnation ? Vec2(0.0, 0.0) : Vec2(v.normalized()); }

/// The zone the vehicle must pass (the latched one while it blocks the line
/// of sight, else the first blocking zone within the influence), with its
/// side; updates the memory. No zone: memory released.
AxisClamp engage(const std::vector<DipoleZone>& zones, const Vec2& p, const Vec2& g, double course,
                 const ReactiveParams& params, const DipoleParams& own, SideLatch& memory) {
  std::vector<Ellipse> near;  // zones within the influence; others cannot be engaged
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < zones.size(); ++i) {
    const Ellipse& z = zones[i].shape;
    // |p - c| - a bounds the distance from below: most zones are skipped
    // without the exact distance (the cost of a step among 100 objects).
    if ((p - z.centre).norm() - z.a >= params.influence_m) continue;
    if (signed_distance(z, p) < params.influence_m) {
      near.push_back(zones[i].shape);
      index.push_back(i);
    }
  }
  std::ptrdiff_t k = -1;
  for (std::size_t i = 0; i < near.size() && k < 0; ++i) {
    if (engaged_with(memory, near[i].centre, 0.5 * near[i].b) && segment_intersects(near[i], p, g)) {
      k = static_cast<std::ptrdiff_t>(i);
    }
  }
  if (k < 0) k = first_zone_hit(near, p, g);
  if (k < 0) {
    release(memory);
    return {};
  }
  const Ellipse& zone = near[static_cast<std::size_t>(k)];
  const Vec2 e = unit_or_zero(g - p);
  const double offset = circle_plane(zone, e, p).Z().imag();
  const double band = own.axis_band_m;
  int side = side_of(offset, e, course, band);
  // Clearly across on the other side (more than the band): that side is taken.
  if (engaged_with(memory, zone.centre, 0.5 * zone.b) && memory.side * offset > -band) side = memory.side;
  const auto zi = index[static_cast<std::size_t>(k)];
  memory.side = side;
  memory.engaged_object = zones[zi].members.front();
  memory.engaged_centre = zone.centre;
  return {static_cast<std::ptrdiff_t>(zi), side, band};
}

}  // namespace

std::vector<DipoleZone> dipole_zones(std::span<const Ellipse> objects, double margin_m, double blend_m) {
  std::vector<DipoleZone> zones;
  zones.reserve(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    zones.push_back({security_ellipse(objects[i], margin_m), {static_cast<std::ptrdiff_t>(i)}});
  }
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < zones.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < zones.size() && !merged; ++j) {
        const Ellipse& a = zones[i].shape;
        const Ellipse& b = zones[j].shape;
        const double reach = a.a + b.a + blend_m;
        if ((a.centre - b.centre).squaredNorm() >= reach * reach) continue;  // cheap: far apart
        if (zone_gap(a, b) >= blend_m) continue;
        zones[i].shape = enclosing_circle(a, b);
        zones[i].members.insert(zones[i].members.end(), zones[j].members.begin(), zones[j].members.end());
        zones.erase(zones.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
    }
  }
  return zones;
}

namespace {

std::vector<Ellipse> shapes(const std::vector<DipoleZone>& zones) {
  std::vector<Ellipse> out;
  out.reserve(zones.size());
  for (const DipoleZone& z : zones) out.push_back(z.shape);
  return out;
}

/// Inside zone k: the flow at the nearest boundary point, blended outward.
Vec2 leave_zone(const std::vector<DipoleZone>& zones, std::size_t k, const Vec2& p, const Vec2& g,
                const ReactiveParams& params, const DipoleParams& own, const AxisClamp& clamp,
                std::optional<double> course) {
  const Ellipse& zone = zones[k].shape;
  const EllipseProjection near = project_to_ellipse(zone, p);
  Vec2 n = outward_normal(zone, near.point);
  const Vec2 outside = near.point + kZoneClearance_m * n;
  Vec2 along = direction_of(field(zones, outside, g, params.influence_m, own.blend_m, clamp));
  const int side = clamp.zone == static_cast<std::ptrdiff_t>(k) ? clamp.side : axis_side(zone.centre, g, p, course);
  // At a stagnation point of the boundary: round it on the passing side.
  if (along.squaredNorm() == 0.0) along = along_boundary(n, side);
  return exit_direction(along, n, depth_fraction(zone, p), params.exit_blend_fraction);
}

}  // namespace

ReactiveCommand dipole_command(const ReactiveParams& params, ReactiveMemory& state, const ReactiveInput& input) {
  validate_input(params, input);
  const DipoleParams own = dipole_params(params);
  SideLatch& memory = method_state<SideLatch>(state);
  const std::vector<DipoleZone> zones = dipole_zones(input.objects, params.margin_m, own.blend_m);
  const std::vector<Ellipse> zone_shapes = shapes(zones);
  const SteeringTarget target = steering_target(zone_shapes, input.target);
  if (auto stop = arrival_command(params, input, target)) {
    release(memory);
    return *stop;
  }
  const Vec2& p = input.position;
  const AxisClamp clamp = engage(zones, p, target.point, input.course, params, own, memory);
  const std::ptrdiff_t inside = deepest_zone(zone_shapes, p);
  const std::ptrdiff_t steered = inside >= 0 ? inside : clamp.zone;
  const std::ptrdiff_t object =
      steered >= 0 ? nearest_member(zones[static_cast<std::size_t>(steered)], input.objects, p) : -1;
  if (inside >= 0) {
    const Vec2 dir =
        leave_zone(zones, static_cast<std::size_t>(inside), p, target.point, params, own, clamp, input.course);
    return course_command(params, input, dir, ReactiveStatus::leaving_zone, object, target);
  }
  const Vec2 v = field(zones, p, target.point, params.influence_m, own.blend_m, clamp);
  return course_command(params, input, direction_of(v), ReactiveStatus::ok, object, target);
}

Vec2 dipole_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                     std::span<const Ellipse> objects) {
  validate_query(params, point, target, objects);
  const DipoleParams own = dipole_params(params);
  const std::vector<DipoleZone> zones = dipole_zones(objects, params.margin_m, own.blend_m);
  const std::vector<Ellipse> zone_shapes = shapes(zones);
  const Vec2 g = steering_target(zone_shapes, target).point;
  if (const std::ptrdiff_t k = deepest_zone(zone_shapes, point); k >= 0) {
    return leave_zone(zones, static_cast<std::size_t>(k), point, g, params, own, AxisClamp{}, std::nullopt);
  }
  return direction_of(field(zones, point, g, params.influence_m, own.blend_m, AxisClamp{}));
}

namespace {

const ReactiveTuning kAxisBand{"dipole_axis_band_m", 0.5, 0.0, 1e4, true, true, "a distance in metres"};
const ReactiveTuning kBlend{"dipole_blend_m", 5.0, 0.0, 1e4, false, true, "a distance in metres"};

}  // namespace

DipoleParams dipole_params(const ReactiveParams& params) {
  return {tuning_value(params, kAxisBand), tuning_value(params, kBlend)};
}

ReactiveMethodEntry dipole_method_entry() {
  return {"dipole",
          "a harmonic dipole potential per object in a uniform flow to the target",
          0x0072b2,  // blue
          {kAxisBand, kBlend},
          dipole_command,
          dipole_gradient};
}

}  // namespace deepguide
