#pragma once
// What the built-in reactive methods share (reactive_method.hpp states the
// behaviour): input checks, the security zones, the substitute target when the
// real one lies in a zone, arrival, the side rule with its latch, the first
// zone on a line of sight, and the blended exit from inside a zone.
//
// Exit blend (geometric_construction.hpp, sector 3). Inside a zone, with n the outward normal
// (gradient of the zone's implicit function) and t the course the method
// would command just outside the nearest boundary point (tangent to the
// boundary, or towards the target once that is free), the course is
//   cos(beta) t + sin(beta) n,   beta = (pi/2) sqrt(min(1, depth / f)),
// depth = 1 - sqrt(implicit value) (0 on the boundary, 1 at the centre; for a
// circle (R - |p - o|)/R) and f = params.exit_blend_fraction. At the boundary
// beta = 0: the course equals the outside course there, so a vehicle riding
// the boundary does not chatter between "in" and "out"; deeper in it heads
// straight out. A linear beta (without the square root) makes the
// outward speed proportional to the depth near the boundary, U pi/(2 f) depth:
// the depth then only decays exponentially and the vehicle rides just inside
// the zone for ever (in continuous time); with the square root it decays like
// sqrt and the vehicle is out within 2 f R / U seconds from depth f (using
// sin(beta) >= 2 beta / pi).
//
// Side rule. For an object with centre o, target g and vehicle p, the side is
// sign(cross(g - o, p - o)): the half-plane of the symmetry axis o -> g the
// vehicle is in. Within `band` of the axis the current course decides
// (sign(cross(g - o, course vector)): the way it is already heading); if it is
// along the axis, the side of the axis however close; exactly on it, -1
// (starboard).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/side_latch.hpp"

namespace deepguide::reactive_detail {

/// Throws InputError for bad params, a non-finite position, course or target, or a bad object.
void validate_input(const ReactiveParams& params, const ReactiveInput& input);
/// The same checks for a memoryless gradient query.
void validate_query(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                    std::span<const Ellipse> objects);

/// Distance between two zones (0 if they overlap).
double zone_gap(const Ellipse& e1, const Ellipse& e2);

std::vector<Ellipse> security_ellipses(std::span<const Ellipse> objects, double margin_m);

/// The target a method steers to: the real one, or, if it lies inside a zone,
/// the nearest point of that zone's boundary (pushed out by kZoneClearance_m);
/// repeated a few times in case that point lies in an overlapping zone.
struct SteeringTarget {
  Vec2 point;
  bool in_zone = false;
};
SteeringTarget steering_target(std::span<const Ellipse> zones, const Vec2& target);
inline constexpr double kZoneClearance_m = 1e-3;

/// The command when the vehicle is within the arrival radius of the steering
/// target (arrived, or target_in_zone and stopped), nullopt otherwise.
std::optional<ReactiveCommand> arrival_command(const ReactiveParams& params, const ReactiveInput& input,
                                               const SteeringTarget& target);
/// A command with speed for `direction` (unit) round `object`, or a stalled
/// stop if the direction is zero. Status target_in_zone replaces ok while the
/// real target is unreachable.
ReactiveCommand course_command(const ReactiveParams& params, const ReactiveInput& input, const Vec2& direction,
                               ReactiveStatus status, std::ptrdiff_t object, const SteeringTarget& target);

/// Side rule above for a vehicle `offset` to the left of an axis along the unit
/// vector `axis` (negative: to the right); `course` empty for memoryless queries.
int side_of(double offset, const Vec2& axis, std::optional<double> course, double band_m);
/// Side rule for the axis centre -> target.
int axis_side(const Vec2& centre, const Vec2& target, const Vec2& p, std::optional<double> course);

/// The latched side for object `index` (zone centre `centre`): the memory's if
/// it is engaged with the same object (matched by centre within `match_m`),
/// else `fresh` side, which is then latched.
int latched_side(SideLatch& memory, std::ptrdiff_t index, const Vec2& centre, double match_m, int fresh);
/// True if the memory is engaged with the object at `centre` (within `match_m`).
bool engaged_with(const SideLatch& memory, const Vec2& centre, double match_m);
void release(SideLatch& memory);

/// The first zone the segment p -> q enters (p outside every zone), -1 none.
std::ptrdiff_t first_zone_hit(std::span<const Ellipse> zones, const Vec2& p, const Vec2& q, std::ptrdiff_t skip = -1);

/// The zone that contains p most deeply (largest depth fraction), -1 none.
std::ptrdiff_t deepest_zone(std::span<const Ellipse> zones, const Vec2& p);
/// 1 - sqrt(implicit value): 0 on the boundary, 1 at the centre (negative outside).
double depth_fraction(const Ellipse& zone, const Vec2& p);
/// Unit outward normal of the zone's level set through p (zero at the centre).
Vec2 outward_normal(const Ellipse& zone, const Vec2& p);
/// Exit blend above: `along` the boundary-following unit direction, `normal` the outward unit normal.
Vec2 exit_direction(const Vec2& along, const Vec2& normal, double depth, double blend_fraction);

/// v rotated by +90 degrees (counter-clockwise).
inline Vec2 left_normal(const Vec2& v) { return {-v.y(), v.x()}; }
/// The direction along a boundary with outward normal n on side `side`
/// (clockwise round the zone for +1, the side convention of reactive_method.hpp).
inline Vec2 along_boundary(const Vec2& n, int side) { return -static_cast<double>(side) * left_normal(n); }
/// Unit vector of v, zero for (near) zero v.
Vec2 unit_or_zero(const Vec2& v);

}  // namespace deepguide::reactive_detail
