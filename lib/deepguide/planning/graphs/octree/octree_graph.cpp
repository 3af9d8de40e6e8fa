#include "deepguide/planning/graphs/octree/octree_graph.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_set>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/string_pulling.hpp"

namespace deepguide {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
constexpr int kAttachRings = 4;

std::string where(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.1f, %.1f, depth %.1f m)", p.x(), p.y(), p.z());
  return buf;
}

// The cell test of the header; `bottom` is the volume's deepest allowed depth.
CellState classify(const WaterVolume& volume, const Vec3& lo, const Vec3& hi, const Vec2& area_max, double bottom) {
  if (lo.x() >= area_max.x() || lo.y() >= area_max.y() || lo.z() >= bottom) return CellState::occupied;
  // Straddling the area's far side with the centre outside: split, so every vertex lies in the area.
  if (0.5 * (lo.x() + hi.x()) > area_max.x() || 0.5 * (lo.y() + hi.y()) > area_max.y()) return CellState::mixed;
  const VolumeOptions& band = volume.options();
  if (hi.z() < band.min_depth_m) return CellState::occupied;
  bool mixed = lo.z() < band.min_depth_m || hi.z() > bottom;
  const Vec2 lo2 = lo.head<2>(), hi2 = hi.head<2>();
  if (const SeaFloor* floor = volume.floor()) {
    const auto [shallowest, deepest] = floor->depth_range(lo2, hi2);
    const double c = band.vertical_clearance_m;
    if (lo.z() > deepest - c) return CellState::occupied;
    if (hi.z() > shallowest - c) return CellState::mixed;  // split either way: obstacles need not be asked
  }
  const ObstacleField& field = volume.field();
  const double margin = field.margin();
  const Vec2 centre = 0.5 * (lo2 + hi2);
  const double r = 0.5 * (hi2 - lo2).norm();
  for (std::size_t i : field.near(lo2, hi2, margin)) {
    const double top = volume.zone_top(i);
    if (hi.z() <= top) continue;  // the cell lies above this obstacle's zone
    const double d = field.distance_to(i, centre);
    if (d - r >= margin) continue;
    if (d + r < margin && lo.z() > top) return CellState::occupied;
    mixed = true;
  }
  return mixed ? CellState::mixed : CellState::free;
}

}  // namespace

void validate(const OctreeOptions& options) {
  if (!(options.min_cell_m > 0.0) || !std::isfinite(options.min_cell_m)) {
    throw InputError("`min_cell_m`: expected a cell size > 0 m, got " + general(options.min_cell_m));
  }
  if (!(options.max_dive_deg > 0.0 && options.max_dive_deg < 90.0)) {
    throw InputError("`max_dive_deg`: expected an angle between 0 and 90 degrees, got " +
                     general(options.max_dive_deg));
  }
}

OctreeGraph::OctreeGraph(const WaterVolume& volume, const OctreeOptions& options)
    : volume_(&volume), options_(options) {
  const auto t0 = std::chrono::steady_clock::now();
  validate(options);
  const Vec2 extent = options.area_max - options.area_min;
  if (!options.area_min.allFinite() || !options.area_max.allFinite() || !(extent.minCoeff() > 0.0)) {
    throw InputError("octree: expected a work area with a positive, finite extent");
  }
  const VolumeOptions& band = volume.options();
  double bottom = band.max_depth_m;
  if (volume.floor() != nullptr) bottom = std::min(bottom, volume.floor()->max_depth() - band.vertical_clearance_m);
  if (!std::isfinite(bottom)) {
    throw InputError("octree: expected a depth band with a bottom or a sea floor (a chart), got neither");
  }
  if (!(bottom > band.min_depth_m)) {
    throw InputError("octree: no free cell: the sea floor less the clearance (" + general(bottom) +
                     " m at its deepest) is not below the depth band's top (" + general(band.min_depth_m) + " m)");
  }
  slope_ = std::tan(options.max_dive_deg * M_PI / 180.0);
  const double height = options.min_cell_m, width = height / std::min(1.0, slope_);
  const double need = std::max(extent.maxCoeff() / width, (bottom - band.min_depth_m) / height);
  if (!(need < std::ldexp(1.0, CellTree<3>::kMaxLevels))) {
    throw InputError("`min_cell_m`: " + general(options.min_cell_m) + " m cells over this volume need more than " +
                     std::to_string(CellTree<3>::kMaxLevels) + " levels; give a larger cell");
  }
  // Strictly more than the extent: cells are half-open, and a point on the
  // area's far side must still lie in a cell.
  const int depth = std::max(0, static_cast<int>(std::floor(std::log2(need))) + 1);
  const Vec3 root(std::ldexp(width, depth), std::ldexp(width, depth), std::ldexp(height, depth));
  const Vec3 origin(options.area_min.x(), options.area_min.y(), band.min_depth_m);
  std::size_t cells = 0;
  tree_ = std::make_unique<CellTree<3>>(origin, root, depth, [&](const CellTree<3>::Box& box) {
    if (++cells > options.max_cells) {
      throw InputError("`min_cell_m`: " + general(options.min_cell_m) + " m cells over this volume make more than " +
                       std::to_string(options.max_cells) + " cells; give a larger cell or a smaller volume");
    }
    return classify(volume, box.min, box.max, options.area_max, bottom);
  });

  const auto& leaves = tree_->leaves();
  if (leaves.size() >= kNone) throw InputError("octree: more than 4e9 leaves; give a larger cell");
  vertex_of_.assign(leaves.size(), kNone);
  for (std::size_t i = 0; i < leaves.size(); ++i) {
    if (leaves[i].state != CellState::free) continue;
    vertex_of_[i] = static_cast<std::uint32_t>(free_.size());
    free_.push_back(static_cast<std::uint32_t>(i));
  }
  if (free_.empty()) {
    throw InputError(
        "octree: no free cell in the volume (every cell is outside the band, in the sea floor's "
        "clearance or within " +
        general(volume.field().margin()) + " m of an obstacle)");
  }
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::size_t OctreeGraph::memory_bytes() const {
  return tree_->leaves().capacity() * sizeof(CellTree<3>::Leaf) + vertex_of_.capacity() * sizeof(std::uint32_t) +
         free_.capacity() * sizeof(std::uint32_t);
}

Vec3 OctreeGraph::centre(std::uint32_t vertex) const { return tree_->box(free_[vertex]).centre(); }

bool OctreeGraph::flyable(const Vec3& a, const Vec3& b) const {
  // A relative allowance of 1e-9: a stacked diagonal is exactly the dive angle.
  return std::abs(b.z() - a.z()) <= slope_ * (b - a).head<2>().norm() * (1.0 + 1e-9);
}

// The free cells p joins: its own cell and then ring after ring of
// neighbours, until a ring has cells p sees within the dive angle.
std::vector<std::pair<std::uint32_t, double>> OctreeGraph::joins(const Vec3& p) const {
  std::vector<std::pair<std::uint32_t, double>> out;
  const std::optional<std::size_t> own = tree_->locate(p);
  if (!own) return out;
  std::vector<std::size_t> ring{*own};
  std::unordered_set<std::size_t> seen{*own};
  std::vector<std::pair<std::size_t, bool>> around;
  const auto consider = [&](std::size_t leaf) {
    const std::uint32_t w = vertex_of_[leaf];
    if (w == kNone) return;
    const Vec3 c = centre(w);
    if (flyable(p, c) && volume_->segment_free(p, c)) out.emplace_back(w, (c - p).norm());
  };
  consider(*own);
  for (int r = 0; r < kAttachRings && out.empty() && !ring.empty(); ++r) {
    std::vector<std::size_t> next;
    for (std::size_t cell : ring) {
      tree_->neighbours(cell, around);
      for (const auto& [other, face] : around) {
        if (!seen.insert(other).second) continue;
        next.push_back(other);
        consider(other);
      }
    }
    ring = std::move(next);
  }
  return out;
}

PlanResult OctreeGraph::solve(const Vec3& start, const Vec3& goal, SearchAlgorithm algorithm) const {
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& [p, name] : {std::pair{start, "the start"}, std::pair{goal, "the goal"}}) {
    if (!p.allFinite()) throw InputError(std::string(name) + ": expected finite coordinates and depth");
    if ((p.head<2>().array() < options_.area_min.array()).any() ||
        (p.head<2>().array() > options_.area_max.array()).any()) {
      throw InputError(std::string(name) + " " + where(p) + " lies outside the octree's work area");
    }
    if (const WaterVolume::Verdict v = volume_->check_point(p); v.blocked) {
      const std::string message = std::string(name) + " " + where(p) + " " + v.reason;
      if (v.reason.find("obstacle") != std::string::npos) throw NoRouteError(message);
      throw InputError(message);
    }
    if (!tree_->locate(p)) {
      throw InputError(std::string(name) + " " + where(p) + " lies outside the octree's volume");
    }
  }
  const std::size_t n = free_.size();
  const std::size_t sv = n, gv = n + 1;
  const auto start_joins = joins(start);
  std::unordered_set<std::uint32_t> goal_side;
  std::vector<std::pair<std::uint32_t, double>> goal_joins = joins(goal);
  for (const auto& [w, len] : goal_joins) goal_side.insert(w);
  const bool direct = flyable(start, goal) && volume_->segment_free(start, goal);

  const auto position = [&](std::size_t v) {
    return v == sv ? start : v == gv ? goal : centre(static_cast<std::uint32_t>(v));
  };
  ImplicitGraph graph;
  graph.vertex_count = n + 2;
  graph.successors = [&, buffer = std::vector<std::pair<std::size_t, bool>>()](std::size_t v,
                                                                               ImplicitGraph::Successors& out) mutable {
    if (v == gv) return;
    if (v == sv) {
      for (const auto& [w, len] : start_joins) out.emplace_back(w, len);
      if (direct) out.emplace_back(gv, (goal - start).norm());
      return;
    }
    const Vec3 a = centre(static_cast<std::uint32_t>(v));
    tree_->neighbours(free_[v], buffer);
    for (const auto& [other, face] : buffer) {
      const std::uint32_t w = vertex_of_[other];
      if (w == kNone) continue;
      const Vec3 b = centre(w);
      if (!flyable(a, b) || (!face && !volume_->segment_free(a, b))) continue;
      out.emplace_back(w, (b - a).norm());
    }
    if (goal_side.count(static_cast<std::uint32_t>(v)) != 0) out.emplace_back(gv, (goal - a).norm());
  };
  const SearchResult found =
      shortest_path(graph, sv, gv, algorithm, [&](GraphVertex v) { return (position(v) - goal).norm(); });

  PlanResult result;
  result.stats.graph_vertices = n + 2;
  result.stats.expanded = found.expanded;
  result.stats.build_ms = build_ms_;
  result.found = found.found;
  result.cost = found.cost;
  if (!found.found) {
    result.message = start_joins.empty() || goal_joins.empty()
                         ? "the start or the goal sees no free cell near it within the dive angle"
                         : "the goal cannot be reached from the start through the octree's free cells";
    result.stats.query_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
  }
  std::vector<Vec3> points;
  for (GraphVertex v : found.path) points.push_back(position(v));
  if (options_.smooth && points.size() > 2) {
    // Keeping every leg flyable.
    points = pull_string(points,
                         [this](const Vec3& a, const Vec3& b) { return flyable(a, b) && volume_->segment_free(a, b); });
  }
  for (const Vec3& p : points) {
    result.route.points.push_back(p.head<2>());
    result.route.depth_m.push_back(p.z());
  }
  result.cost = result.route.length();
  result.stats.query_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

GraphEntry octree_graph_entry() {
  GraphEntry e;
  e.name = GraphKind::octree.name;
  e.help = "a route in depth over the sea floor";
  e.can = {.in_depth = true};
  return e;
}

}  // namespace deepguide
