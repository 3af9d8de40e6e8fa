#pragma once
// Aligning to an object in a current (the seed's Figs. 13-14; docs/IDENTIFICATION.md,
// "Aligning"): where the vehicle must go and which area it is in.
//
// The safety ellipse is the object's security ellipse for the standoff
// (reactive_method.hpp: it contains the true offset zone), so the evasive
// mode's geometric method, whose zones are the same ellipses, can take the
// goal point as its target without finding it inside a zone.
//
// c the centre, e the unit direction the water goes (the current's set).
//   Goal point: where the ray from c along +e (downstream, the lee side)
//   meets the safety ellipse. In the ellipse's frame, with u = R^T e,
//     t* = 1 / sqrt((u_x / A)^2 + (u_y / B)^2),   goal = c + t* e.
//   Borderline: the line through c perpendicular to e. Downstream of it and
//   within the shade's half-width w of the axis c + s e, the vehicle is in
//   the positioning area (the flow shade); everywhere else in the evasive
//   area. w is the ellipse's half-width across e: its support function along
//   n = e rotated by 90 degrees, w = sqrt(n^T M n) with M = R diag(A^2, B^2) R^T.
// Without a current there is no lee: the direction is then the one from the
// object's centre towards the vehicle (the near side), see align_direction.

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

/// The direction the goal lies in from the object: the current's (unit) when
/// it is faster than `still_mps`, else from the centre towards `vehicle`
/// (east if the vehicle sits on the centre).
Vec2 align_direction(const Vec2& current_mps, double still_mps, const Vec2& centre, const Vec2& vehicle);

/// The goal point on `safety` along the unit direction `e` from its centre.
Vec2 lee_goal_point(const Ellipse& safety, const Vec2& e);

/// Half-width of `safety` across the unit direction `e` (the shade's half-width).
double shade_half_width(const Ellipse& safety, const Vec2& e);

enum class AlignArea { evasive, positioning };

/// The area point `p` lies in for the unit direction `e` (header).
AlignArea align_area(const Ellipse& safety, const Vec2& e, const Vec2& p);

}  // namespace deepguide
