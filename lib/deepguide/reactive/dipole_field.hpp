#pragma once
// (a) Uniform flow towards the target + a dipole per object (the seed's
// synthetic harmonic potentials; Kim & Khosla, IEEE T-RA 8(3), 1992; Feder & Slotine, ICRA 1997).
//
// One zone. Complex notation, U = 1 (only the direction is used). For a circle
// of radius R at the origin in a uniform flow along e = e^{i alpha}:
//   w(z) = conj(E) z + R^2 E / z,   E = e^{i alpha},   velocity V = conj(w'(z));
// the circle is a streamline, the field vanishes only at the stagnation points
// z = -R E (front) and z = +R E (rear). Zones are security ellipses, not their
// enclosing circles (a better choice than the circle a + d, which would double
// the detour round an elongated object): the Joukowski map
//   z = zeta + k^2 / zeta,   k^2 = (A^2 - B^2) / 4,
// takes the circle |zeta| = rho0 = (A + B)/2 onto the ellipse with semi-axes
// A, B (in the ellipse's own frame); its inverse on the outside is the root
// zeta = (z +- sqrt(z^2 - 4 k^2)) / 2 of larger modulus. The flow past the
// ellipse is the circle flow in the zeta plane:
//   W(zeta) = conj(E) zeta + rho0^2 E / zeta,  dw/dz = (dW/dzeta) / (1 - k^2 / zeta^2),
// so the ellipse is exactly a streamline; a circle (k = 0) gives the formula above.
//
// Point target. The flow direction is taken at each point as e(p) = unit(g - p)
// (the obstacle frame whose x-axis points at the target, evaluated per point). Every
// member of that family has the zone as a streamline, so V(p) is tangent to the
// zone wherever p is on it; far away V -> e(p), so the lines end at the target
// instead of passing it at their initial offset as a fixed uniform flow would.
// Stagnation points are where the target, the zone's centre and p line up.
//
// Several zones: superposition with a partition that keeps every zone a
// streamline. With D_i = V_i - e the perturbation of zone i alone,
//   V = e + sum_i w_i D_i,   w_i = lambda_i prod_{j != i} s_j,
//   lambda_i = 1 - smoothstep(d_i / influence_m)   (influence taper),
//   s_j      = smoothstep(d_j / dipole_blend_m)     (zone j's shadow),
// d the distance to the zone. On zone i's boundary w_i = 1 and every other
// w_j = 0 (s_i = 0), provided no other zone is within dipole_blend_m: zones
// closer than that (overlapping objects included) are merged first into the
// circle enclosing their enclosing circles, repeatedly. Why not plain
// superposition: it lets zones leak (the other dipoles' flow makes the circles stop being
// streamlines). Why not the nearest zone only: the field jumps where the
// nearest one changes (r_ref spikes). The price: two close objects become one
// big circle (a passage narrower than dipole_blend_m is given up), and
// saddles of the combined field (between zones) can stall the vehicle.
//
// Axis tie-break (command only). The line through the front stagnation point
// (the dividing streamline: Im(Z) = 0 upstream, Z = zeta conj(E)) splits the
// flow; on it the vehicle runs into the stagnation point. The zone engaged
// (the first one blocking the line of sight, kept while it blocks it) gets a
// side: the side of the dividing streamline the vehicle is on, or within
// dipole_axis_band_m of it the side its course points to (with the course
// along the flow, the side it is on; exactly on the line, starboard);
// latched until the zone no longer blocks. Upstream (Re Z < 0) and within the
// band on either side of the dividing streamline, the zone's flow is evaluated
// at Im(Z) = side * band instead: as if the vehicle were that far on its side.
// The clamp is continuous on the latched side; a vehicle pushed (current, lag)
// more than the band across to the other side takes that side (a hysteresis
// of two bands), since steering it back across the stagnation line would aim
// it at the zone. The price of the clamp is that a vehicle within the band
// follows a flow line up to a band's width too close: clearance can drop by
// up to the band (in the circle plane). Exactly where the field vanishes
// otherwise (saddles): status stalled.
//
// Inside a zone: the flow direction at the nearest boundary point blended
// outward (reactive_support.hpp), status leaving_zone.

#include <cstddef>
#include <span>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/reactive_registry.hpp"

namespace DEEPGUIDE_API deepguide {

/// A zone of the dipole method: one object's security ellipse, or the circle
/// that merged several close ones (members: their indices).
struct DipoleZone {
  Ellipse shape;
  std::vector<std::ptrdiff_t> members;
};

/// The zones for `objects`, merged as described above.
std::vector<DipoleZone> dipole_zones(std::span<const Ellipse> objects, double margin_m, double blend_m);

/// The method's own parameters, read from ReactiveParams::tuning (defaults
/// and ranges in its registry entry).
struct DipoleParams {
  /// Axis tie-break: a vehicle upstream of the object it is passing and
  /// closer than this to the dividing streamline (in the circle plane of the
  /// flow, metres near the object) steers as if this far on its latched side
  /// ("dipole_axis_band_m", 0.5 m, >= 0).
  double axis_band_m;
  /// Near one zone the other zones' dipoles fade out over this distance;
  /// zones closer than this to each other are merged into one circle
  /// ("dipole_blend_m", 5 m, > 0).
  double blend_m;
};
DipoleParams dipole_params(const ReactiveParams& params);

/// One step; the memory is a SideLatch (side_latch.hpp).
ReactiveCommand dipole_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& input);

Vec2 dipole_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                     std::span<const Ellipse> objects);

/// The method's registry entry (reactive_registry.hpp).
ReactiveMethodEntry dipole_method_entry();

}  // namespace deepguide
