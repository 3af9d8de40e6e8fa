#pragma once
// Gradient lines of a reactive method (the seed's Figs. 8 and 10): the paths
// a point would take that always moves along the method's memoryless gradient
// direction (reactive_gradient), i.e. the integral curves of a unit field.
//
// Integration: the explicit midpoint rule (RK2) with a fixed arc-length step h,
//   k1 = G(p),  k2 = G(p + h/2 k1),  p' = p + h k2.
// The fields are discontinuous (the geometric method's sector borders, the
// side rule across the symmetry axis) and vanish at stagnation points, so a
// higher order buys nothing; h is a fraction of a pixel's worth of metres at
// figure scale. A line ends
//   - at the target: within h of it (the target is appended);
//   - stalled: G = 0, or the direction reverses (k1 . k2 < -0.5, or k1 against
//     the last step's): a unit field flips across the point where the true field
//     vanishes (the dipole's front stagnation point, the potential field's
//     point of balance), so the line would only zigzag on the spot;
//   - leaving the area drawn (the last point is on the boundary);
//   - after max_steps (a closed loop, an orbit).
// Seeds: evenly spaced on the line through the start, perpendicular to
// start -> target, across the area: "upstream" of the objects the way the
// vehicle comes, as the seed's figures draw lines entering from one side.
// The start itself is one of them.
// Dividing lines: where two neighbouring seeds' lines pass an object on
// different sides (the side of the axis centre -> target at the line's point
// nearest the centre), a line in between runs into the point that splits the
// flow: the dipole's front stagnation point, the potential field's saddle
// (the trap). Bisection on the seed finds it (to 1e-6 m, or a line that
// stalls on the way); evenly spaced seeds would almost surely miss it.

#include <cstddef>
#include <span>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/render/canvas.hpp"  // WorldBox

namespace DEEPGUIDE_API deepguide {

enum class LineEnd { target, stalled, left_area, step_limit };

struct GradientLine {
  std::vector<Vec2> points;  ///< from the seed on (local frame, m)
  LineEnd end = LineEnd::step_limit;
};

struct GradientLineOptions {
  double step_m = 1.0;  ///< arc-length step h, > 0
  std::size_t max_steps = 20000;
};

/// The area's seeds: spacing_m (> 0) apart on the line through `start`
/// perpendicular to start -> target, inside `area`. Empty when start is outside
/// the area; just the start when start == target.
std::vector<Vec2> upstream_seeds(const WorldBox& area, const Vec2& start, const Vec2& target, double spacing_m);

/// The gradient line of `method` from `seed` (see the header for the ends).
/// Throws InputError for bad params or objects (reactive_gradient's checks),
/// a non-positive step or a seed outside the area.
GradientLine trace_gradient_line(const ReactiveMethod& method, const ReactiveParams& params, const Vec2& seed,
                                 const Vec2& target, std::span<const Ellipse> objects, const WorldBox& area,
                                 const GradientLineOptions& options);

/// trace_gradient_line for every seed.
std::vector<GradientLine> gradient_lines(const ReactiveMethod& method, const ReactiveParams& params,
                                         std::span<const Vec2> seeds, const Vec2& target,
                                         std::span<const Ellipse> objects, const WorldBox& area,
                                         const GradientLineOptions& options);

/// For each object, the side a line passes it on: +1 if the line's point
/// nearest the object's centre c is left of the axis c -> target, else -1.
std::vector<int> passing_sides(const GradientLine& line, const Vec2& target, std::span<const Ellipse> objects);

/// The dividing lines between neighbouring `seeds` (in order along the seed
/// line, none inside an object) whose `lines` (one per seed) pass some object
/// on different sides; neighbours with an object between them are skipped.
std::vector<GradientLine> dividing_lines(const ReactiveMethod& method, const ReactiveParams& params,
                                         std::span<const Vec2> seeds, std::span<const GradientLine> lines,
                                         const Vec2& target, std::span<const Ellipse> objects, const WorldBox& area,
                                         const GradientLineOptions& options);

}  // namespace deepguide
