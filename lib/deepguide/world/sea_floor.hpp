#pragma once
// The sea floor in the local frame, for planning in depth (the octree graph
// and the 3-D route checker): depth (m, positive down) on a regular grid of
// nodes, bilinear between them.
//
// - Outside the grid, and where the chart has no data, the depth is 0: water
//   nobody sounded is not water to dive in. Land has negative depth.
// - depth_range(box) bounds the floor over a footprint from a min/max pyramid
//   (a mip-map of the nodes): level k holds the shallowest and deepest node of each block
//   of 2^k x 2^k nodes, and a query reads at most 4 x 4 blocks of the level
//   where the footprint's nodes fit. The blocks cover the footprint, and a
//   bilinear patch lies between its corner nodes, so the range always holds
//   the true one (it may be wider: an octree cell is then split once more).
// - lowest_gap(a, b) is the exact minimum of floor - z along a segment: in
//   each grid cell the patch along a line is a quadratic in the parameter, so
//   each piece's minimum is found in closed form.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

using Vec3 = Eigen::Vector3d;

class SeaFloor {
 public:
  /// Node (i, j) at origin + spacing * (i, j) has depth depths[j * nx + i];
  /// NaN means no data (depth 0). Throws InputError for a spacing that is not
  /// finite and > 0, fewer than 2 x 2 nodes, or a depths size other than nx * ny.
  SeaFloor(const Vec2& origin, double spacing, std::size_t nx, std::size_t ny, std::vector<double> depths);

  /// Depth of the floor at p (bilinear; 0 outside the grid).
  double depth_at(const Vec2& p) const;
  /// {shallowest, deepest} the floor can be over the box [lo, hi] (see the header).
  std::pair<double, double> depth_range(const Vec2& lo, const Vec2& hi) const;

  /// The smallest floor depth minus z along the segment [a, b] (x, y, depth
  /// z), and where: negative when the segment runs into the floor.
  struct Gap {
    double gap_m;
    Vec3 where;
  };
  Gap lowest_gap(const Vec3& a, const Vec3& b) const;
  /// The first parameter t in [0, 1] where floor - z along [a, b] drops below
  /// `clearance` (where the danger begins), or none.
  std::optional<double> first_below(const Vec3& a, const Vec3& b, double clearance) const;

  /// Node (i, j)'s depth (0 for no data and outside the grid).
  double node_depth(std::size_t i, std::size_t j) const {
    return node(static_cast<std::ptrdiff_t>(i), static_cast<std::ptrdiff_t>(j));
  }
  const Vec2& origin() const { return origin_; }
  double spacing() const { return spacing_; }
  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  /// The deepest and shallowest node.
  double max_depth() const { return max_[levels_ - 1][0]; }
  double min_depth() const { return min_[levels_ - 1][0]; }

 private:
  double node(std::ptrdiff_t i, std::ptrdiff_t j) const;
  /// The segment's parameters where it crosses grid lines, with 0 and 1, sorted.
  std::vector<double> cuts(const Vec3& a, const Vec3& b) const;
  Vec2 origin_;
  double spacing_;
  std::size_t nx_, ny_;
  std::vector<double> depth_;
  // min_[k] / max_[k]: blocks of 2^k nodes a side, row-major, (nx >> k) + 1 wide.
  std::vector<std::vector<double>> min_, max_;
  std::vector<std::size_t> width_;
  std::size_t levels_ = 0;
};

}  // namespace deepguide
