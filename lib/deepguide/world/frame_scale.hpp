#pragma once
// The rule that keeps metres metres. Every length deepguide takes or gives is
// a true metre: obstacle axes, margins, clearances, route lengths, speeds. The
// planner measures in the local frame, so a frame whose scale is not 1 where
// the vehicle goes shrinks or grows everything it is told: in Web Mercator at
// 35 N a 5 m margin is 4.1 true metres and obstacles placed by their centres
// are 18 % too small. The rule (docs/PLANNING.md, "The local frame"):
//
//   over the work area, in every direction, one true metre is between
//   kLeastFrameScale and kGreatestFrameScale metres of the frame.
//
// (Scale: frame metres per true metre.) Above 1 a frame makes every size
// given in metres too small in truth: obstacles, margins, clearances; the
// band lets it be 0.6 % above (3 cm of a 5 m margin), which is what UTM keeps
// within a zone's width (6 degrees) of its central meridian at the equator,
// and what the planner's fixtures and many users' areas need; within 3
// degrees, where the default frame mostly plans, it is under 0.1 %. An
// ellipse's axes are multiplied by the frame's scale at its centre where that
// is above 1, so an obstacle file's obstacles keep their true size; margins
// and a chart's buffers are not (a remaining error of at most 0.6 %). Below 1
// sizes err on the safe side, and the band is tight there (UTM's 0.9996 on
// its central meridian is the least), so lengths stay true.
// A frame that breaks the rule is refused with one line naming it, where, and
// its scale there.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

inline constexpr double kLeastFrameScale = 0.9995;
inline constexpr double kGreatestFrameScale = 1.006;

/// The least and greatest scale of a frame over an extent, and where they are
/// (lon, lat), sampled on a 9 x 9 grid that holds its edges and corners.
struct FrameScaleRange {
  double least = 1.0;
  double greatest = 1.0;
  Eigen::Vector2d least_at{0.0, 0.0};
  Eigen::Vector2d greatest_at{0.0, 0.0};
  bool known = true;  ///< false: PROJ could not tell at some point (outside the projection)
  Eigen::Vector2d unknown_at{0.0, 0.0};
};
FrameScaleRange frame_scale_over(const LocalFrame& frame, const LonLatExtent& area);

/// Throws InputError when the frame breaks the rule over the area: "`what`:
/// the local frame EPSG:3857 stretches distances by 22.08 % at lon .., lat ..
/// (...)", with a frame that keeps it. `what` names what brought the area
/// (e.g. "the route", "--from", "obstacles.csv").
void require_true_scale(const LocalFrame& frame, const LonLatExtent& area, const std::string& what);
void require_true_scale(const LocalFrame& frame, const std::vector<Eigen::Vector2d>& lonlat, const std::string& what);

/// A conformal frame of scale 1 at the area's centre (an oblique or polar
/// stereographic on WGS 84), which keeps the rule within about 1,000 km of it.
std::string stereographic_crs_for(const LonLatExtent& area);

/// The frame deepguide chooses for an area: the UTM zone of its centre where
/// that keeps the rule over the area, else stereographic_crs_for(area).
LocalFrame default_frame_for(const LonLatExtent& area);

}  // namespace deepguide
