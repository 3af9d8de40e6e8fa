#include "deepguide/planning/zone_polygons.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "deepguide/core/parallel_blocks.hpp"
#include "deepguide/geometry/safety_zone.hpp"
#include "deepguide/world/no_go_union.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

// Beyond this ratio of the margin to the polygon's size, GEOS grows it (below).
constexpr double kLargestBoostRatio = 10.0;

}  // namespace

BgMultiPolygon polygon_zone(const BgPolygon& footprint, const ZoneOptions& options) {
  if (options.margin <= 0.0) return {footprint};
  // Smallest n with d (1/cos(pi/n) - 1) <= tol; the joins' vertices at d / cos(pi/n).
  const double d = options.margin;
  const int n = std::max(8, static_cast<int>(std::ceil(std::numbers::pi / std::acos(d / (d + options.tolerance)))));
  const double distance = d / std::cos(std::numbers::pi / n);
  // Boost.Geometry's buffer of a polygon far smaller than the distance is
  // wrong: a 65 m square grown by 50 km came out round one corner, short by
  // the square's diagonal (92 m inside the margin; the route check caught it
  // as an internal error), and growing it in steps did not help. GEOS's
  // buffer (through OGR) is robust there; Boost's stays where it has been
  // checked on every chart and scenario, margins up to ten times the size.
  const BgBox box = bg::return_envelope<BgBox>(footprint);
  BgMultiPolygon out;
  if (d > kLargestBoostRatio * bg::distance(box.min_corner(), box.max_corner())) {
    for (BgPolygon& part : geos_buffer(footprint, distance, n)) out.push_back(std::move(part));
    return out;
  }
  bg::strategy::buffer::distance_symmetric<double> dist(distance);
  bg::strategy::buffer::side_straight side;
  bg::strategy::buffer::join_round join(static_cast<std::size_t>(n));
  bg::strategy::buffer::end_round end(static_cast<std::size_t>(n));
  bg::strategy::buffer::point_circle circle(static_cast<std::size_t>(n));
  bg::buffer(footprint, out, dist, side, join, end, circle);
  return out;
}

namespace {

// Groups of overlapping zones up to this size are merged by Boost.Geometry
// one zone at a time (every scenario and mission so far); larger ones by GEOS.
constexpr std::size_t kLargestBoostGroup = 64;
// Below this many ellipses, threads cost more than they save.
constexpr std::size_t kParallelEllipses = 256;

// Union-find over zone indices, to merge only zones that overlap.
struct Components {
  std::vector<std::size_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

}  // namespace

BgMultiPolygon merged_zone_polygons(const ObstacleSet& obstacles, const ZoneOptions& options) {
  if (!(options.tolerance > 0.0)) throw std::invalid_argument("zone tolerance must be positive");
  if (!(options.margin >= 0.0)) throw std::invalid_argument("safety margin must be >= 0");
  const ZonePolygonOptions poly_options{options.tolerance, 4096};
  // Each ellipse's polygon is refined alone (the point-to-ellipse distances
  // are most of the zones' time): thousands of them go to every core.
  std::vector<BgPolygon> zones(obstacles.ellipses.size());
  const std::size_t workers = zones.size() >= kParallelEllipses ? hardware_workers() : 1;
  parallel_blocks(zones.size(), 64, workers, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t i = begin; i < end; ++i) {
      zones[i] = enclosing_bg_polygon(SafetyZone{obstacles.ellipses[i].footprint, options.margin}, poly_options);
    }
  });
  for (const PolygonObstacle& p : obstacles.polygons) {
    for (BgPolygon& part : polygon_zone(p.footprint, options)) zones.push_back(std::move(part));
  }

  using Item = std::pair<BgBox, std::size_t>;
  std::vector<Item> boxes;
  boxes.reserve(zones.size());
  for (std::size_t i = 0; i < zones.size(); ++i) boxes.emplace_back(bg::return_envelope<BgBox>(zones[i]), i);
  const bgi::rtree<Item, bgi::rstar<16>> tree(boxes);
  Components comp(zones.size());
  std::vector<Item> hits;
  for (const Item& item : boxes) {
    hits.clear();
    tree.query(bgi::intersects(item.first), std::back_inserter(hits));
    for (const Item& h : hits) {
      if (h.second > item.second && comp.find(h.second) != comp.find(item.second) &&
          bg::intersects(zones[item.second], zones[h.second])) {
        comp.join(h.second, item.second);
      }
    }
  }

  std::vector<std::vector<std::size_t>> groups;
  {
    std::vector<std::vector<std::size_t>> by_root(zones.size());
    for (std::size_t i = 0; i < zones.size(); ++i) by_root[comp.find(i)].push_back(i);
    for (auto& group : by_root) {
      if (!group.empty()) groups.push_back(std::move(group));
    }
  }
  // Each group is merged alone, so groups go to every core (Boost's union
  // keeps no state); GEOS's groups stay on this thread. The output keeps
  // the groups' order, whatever thread merged them.
  std::vector<BgMultiPolygon> parts(groups.size());
  std::vector<char> to_geos(groups.size(), 0);
  const std::size_t union_workers = zones.size() >= kParallelEllipses ? hardware_workers() : 1;
  parallel_blocks(groups.size(), 16, union_workers, [&](std::size_t begin, std::size_t end, std::size_t) {
    for (std::size_t g = begin; g < end; ++g) {
      const std::vector<std::size_t>& group = groups[g];
      // Boost's buffer of a long coast can cross itself (a 15,000-vertex Kachemak zone did): such a
      // zone, and any group holding one, is repaired and joined by GEOS (world/no_go_union.hpp).
      const bool any_invalid =
          std::any_of(group.begin(), group.end(), [&](std::size_t k) { return !bg::is_valid(zones[k]); });
      if (group.size() > kLargestBoostGroup || any_invalid) {
        to_geos[g] = 1;
        continue;
      }
      if (group.size() == 1) {
        parts[g].push_back(std::move(zones[group[0]]));
        continue;
      }
      BgMultiPolygon acc;
      acc.push_back(zones[group[0]]);
      for (std::size_t k = 1; k < group.size(); ++k) {
        BgMultiPolygon next;
        bg::union_(acc, zones[group[k]], next);
        acc = std::move(next);
      }
      parts[g] = std::move(acc);
    }
  });
  BgMultiPolygon merged;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (to_geos[g]) {
      // A chart's coast with its hazards: thousands of zones in one group.
      // Adding them one by one costs O(group x vertices), and Boost 1.74's
      // union is not robust at that scale (world/no_go_union.hpp).
      std::vector<const BgPolygon*> group;
      for (std::size_t k : groups[g]) group.push_back(&zones[k]);
      for (BgPolygon& part : union_no_go({}, group)) merged.push_back(std::move(part));
      continue;
    }
    for (BgPolygon& part : parts[g]) merged.push_back(std::move(part));
  }
  return merged;
}

void add_zone_polygons(BgMultiPolygon& merged, const BgMultiPolygon& added) {
  for (const BgPolygon& zone : added) {
    const BgBox box = bg::return_envelope<BgBox>(zone);
    std::vector<const BgPolygon*> parts{&zone};
    std::vector<std::size_t> met;
    for (std::size_t i = 0; i < merged.size(); ++i) {
      if (bg::intersects(box, bg::return_envelope<BgBox>(merged[i])) && bg::intersects(zone, merged[i])) {
        met.push_back(i);
        parts.push_back(&merged[i]);
      }
    }
    if (met.empty()) {
      merged.push_back(zone);
      continue;
    }
    std::vector<BgPolygon> united = union_no_go({}, parts);
    for (std::size_t k = met.size(); k-- > 0;) merged.erase(merged.begin() + static_cast<std::ptrdiff_t>(met[k]));
    for (BgPolygon& part : united) merged.push_back(std::move(part));
  }
}

}  // namespace deepguide
