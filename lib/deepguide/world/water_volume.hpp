#pragma once
// The water a vehicle may use in depth: the obstacle field in 3-D (the
// octree graph's validity checker and the 3-D route checker's ground truth).
//
// A point (x, y, z), z depth positive down, is free when
//   - it lies in the operating depth band: min_depth <= z <= max_depth (the
//     band's top keeps the vehicle off the surface);
//   - it keeps the vertical clearance over the sea floor: z <= floor(x, y) - c;
//   - for every obstacle whose safety zone (the 2-D footprint grown by the
//     margin) holds (x, y), it keeps the clearance over the obstacle's top:
//     z <= top - c. An obstacle's top is its top_depth_m, or the shallowest
//     floor under its footprint minus its height_m; an obstacle with neither
//     (or a height without a sea floor) fills the water column.
// Boundaries count as free, as in 2-D (within a nanometre in depth).
//
// A segment is free when every point of it is. Along a segment z is linear,
// so for one obstacle only the deepest point within its zone matters: at the
// first or the last parameter where the segment is inside the zone (an
// interval for an ellipse, whose distance along a line is convex; for a
// polygon the zone is the union of its edges' capsules and its inside, so the
// ends are the capsules' first entry and last exit). The floor is checked
// exactly by SeaFloor::lowest_gap.
// The octree's cell test builds on the same pieces (planning/octree_graph).

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

struct VolumeOptions {
  double vertical_clearance_m = 2.0;                             ///< kept over the sea floor and over obstacle tops
  double min_depth_m = 2.0;                                      ///< the band's top (m, positive down), >= 0
  double max_depth_m = std::numeric_limits<double>::infinity();  ///< the band's bottom
};

class WaterVolume {
 public:
  /// The field and the floor must outlive the volume; the floor may be null
  /// (no chart: only the band bounds the depth). Throws InputError for a band
  /// above the surface (a bottom <= 0 m or a top < 0 m), a top below the
  /// bottom, or a clearance that is not finite and >= 0.
  WaterVolume(const ObstacleField& field, const SeaFloor* floor, const VolumeOptions& options);

  const ObstacleField& field() const { return *field_; }
  const SeaFloor* floor() const { return floor_; }
  const VolumeOptions& options() const { return options_; }
  /// The depth below which obstacle i's zone lies (its top minus the
  /// clearance); -inf for an obstacle that fills the water column.
  double zone_top(std::size_t obstacle) const { return zone_top_[obstacle]; }

  /// Why a point or a segment is not free (blocked == false: it is free).
  struct Verdict {
    bool blocked = false;
    std::string reason;  ///< one line, e.g. "runs into the sea floor's clearance (0.42 m short)"
    Vec3 where{0.0, 0.0, 0.0};
  };
  Verdict check_point(const Vec3& p) const;
  Verdict check_segment(const Vec3& a, const Vec3& b) const;
  bool is_free(const Vec3& p) const { return !check_point(p).blocked; }
  bool segment_free(const Vec3& a, const Vec3& b) const { return !check_segment(a, b).blocked; }

  /// The first parameter t in [0, 1] where the leg a -> b is inside obstacle
  /// i's zone below its top (collision observation: where the danger
  /// begins), or none.
  std::optional<double> first_in_zone(std::size_t obstacle, const Vec3& a, const Vec3& b) const;

 private:
  // The first and last parameters of the leg's horizontal track within
  // obstacle i's zone (the header), or none when it stays out.
  std::optional<std::pair<double, double>> zone_span(std::size_t i, const Vec2& a2, const Vec2& b2) const;
  // For polygon obstacle i: the parameters where the leg is within the margin
  // of each edge (its capsule), clipped to those that meet [0, 1].
  std::vector<std::pair<double, double>> capsule_intervals(std::size_t i, const Vec2& a2, const Vec2& b2) const;

  const ObstacleField* field_;
  const SeaFloor* floor_;
  VolumeOptions options_;
  std::vector<double> zone_top_;
};

}  // namespace deepguide
