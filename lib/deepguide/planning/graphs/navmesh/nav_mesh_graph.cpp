#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <stdexcept>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graph_zones.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_file.hpp"
#include "deepguide/planning/graphs/navmesh/polyanya.hpp"
#include "deepguide/planning/turn_rounding.hpp"
#include "deepguide/planning/zone_polygons.hpp"

namespace deepguide {
namespace bg = boost::geometry;

namespace {

// The area round `lo`..`hi`: a tenth wider on every side, at least 100 m.
std::pair<Vec2, Vec2> widened(const Vec2& lo, const Vec2& hi) {
  const double pad = std::max(0.1 * (hi - lo).maxCoeff(), 100.0);
  return {lo - Vec2::Constant(pad), hi + Vec2::Constant(pad)};
}

}  // namespace

NavMeshGraph::NavMeshGraph(const GraphBuild& in)
    : margin_(in.margin), tolerance_(in.options.tolerance), turn_radius_(in.options.turn_radius_m) {
  KeptNavMesh kept;
  if (in.prepared != nullptr) {
    kept = read_nav_mesh(*in.prepared);
    zones_ = std::move(kept.zones);
  } else {
    zones_ = graph_zone_polygons(in);
  }
  // The visibility graph's frame and band test (centred_polygons), so a
  // start in the band steps to the same point for both.
  local_ = centred_polygons(zones_);
  origin_ = local_.origin;
  if (kept.mesh) {
    if (kept.origin != origin_) throw InputError("navigation mesh: expected the origin its zones give");
    mesh_ = std::move(kept.mesh);
    edge_count_ = mesh_->edge_count();
    return;
  }
  BgBox box;
  bg::assign_inverse(box);
  if (!zones_.empty()) bg::envelope(zones_, box);
  if (in.focus.active()) {
    bg::expand(box, to_bg(in.focus.start));
    bg::expand(box, to_bg(in.focus.goal));
  }
  Vec2 lo(0.0, 0.0), hi(0.0, 0.0);
  if (box.min_corner().x() <= box.max_corner().x()) lo = to_eigen(box.min_corner()), hi = to_eigen(box.max_corner());
  const auto [area_lo, area_hi] = widened(lo - origin_, hi - origin_);
  triangulate(area_lo, area_hi);
}

NavMeshGraph::~NavMeshGraph() = default;

void NavMeshGraph::triangulate(const Vec2& lo, const Vec2& hi) {
  {
    const std::lock_guard<std::mutex> hold(band_lock_);
    add_zone_polygons(local_.polygons, inserted_);
    inserted_.clear();
  }
  mesh_ = std::make_unique<NavMesh>(local_.polygons, lo, hi);
  edge_count_ = mesh_->edge_count();
}

const PolygonVisibility& NavMeshGraph::band() const {
  const std::lock_guard<std::mutex> hold(band_lock_);
  if (!band_) {
    add_zone_polygons(local_.polygons, inserted_);
    inserted_.clear();
    band_ = std::make_unique<PolygonVisibility>(local_.polygons, local_.eps);
  }
  return *band_;
}

NavMesh::Repair NavMeshGraph::insert(const ObstacleSet& found) {
  BgMultiPolygon zones = merged_zone_polygons(found, {margin_, tolerance_});
  if (turn_radius_ > 0.0) zones = rounded_zone_polygons(zones, found, margin_, turn_radius_, tolerance_);
  BgMultiPolygon local;
  for (const BgPolygon& zone : zones) {
    BgPolygon moved;
    bg::transform(zone, moved,
                  bg::strategy::transform::translate_transformer<double, 2, 2>(-origin_.x(), -origin_.y()));
    local.push_back(std::move(moved));
  }
  {
    // The zone polygons matter again only for a start or goal in no water
    // face (the band test): they are joined there, or when the area widens,
    // once per batch of inserts (joining them to a chart's coast costs more
    // than the insert). Noted before the mesh changes, so an insert that
    // fails part way still keeps the mesh from being saved as the one built.
    const std::lock_guard<std::mutex> hold(band_lock_);
    inserted_.insert(inserted_.end(), local.begin(), local.end());
    band_.reset();
    ever_inserted_ = true;
  }
  // A zone reaching the area's edge can send the shortest route round it
  // outside the area: the area widens, and the mesh is made again.
  BgBox box;
  bg::assign_inverse(box);
  if (!local.empty()) bg::envelope(local, box);
  const Vec2 lo = to_eigen(box.min_corner()), hi = to_eigen(box.max_corner());
  if (!local.empty() &&
      ((lo.array() <= mesh_->area_min().array()).any() || (hi.array() >= mesh_->area_max().array()).any())) {
    const std::size_t before = mesh_->faces().size();
    const auto [area_lo, area_hi] = widened(lo.cwiseMin(mesh_->area_min()), hi.cwiseMax(mesh_->area_max()));
    triangulate(area_lo, area_hi);
    return {before, mesh_->faces().size()};
  }
  const NavMesh::Repair repair = mesh_->insert(local);
  edge_count_ = mesh_->edge_count();
  return repair;
}

PlanResult NavMeshGraph::solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel*,
                               const SearchBudget& budget) {
  const Vec2 s = problem.start - origin_, g = problem.goal - origin_;
  const Vec2 lo = s.cwiseMin(g), hi = s.cwiseMax(g);
  if ((lo.array() <= mesh_->area_min().array()).any() || (hi.array() >= mesh_->area_max().array()).any()) {
    const auto [area_lo, area_hi] = widened(lo.cwiseMin(mesh_->area_min()), hi.cwiseMax(mesh_->area_max()));
    triangulate(area_lo, area_hi);
  }
  PolyanyaResult found;
  PlanResult result = solve_from_zone_boundary(
      problem,
      // In a water face (to a nanometre) is never strictly inside a zone.
      [&](const Vec2& p) { return mesh_->faces_at(p - origin_).empty() && band().strictly_inside(p - origin_); },
      [&](const Vec2& p) -> Vec2 { return band().closest_boundary_point(p - origin_) + origin_; },
      [&](const PlanningProblem& banded) {
        found =
            polyanya(*mesh_, banded.start - origin_, banded.goal - origin_, budget, search == SearchAlgorithm::astar);
        PlanResult r;
        r.found = found.found;
        r.cost = found.length;
        r.stats.stopped = found.stopped;
        r.stats.expanded = found.expanded;
        if (found.found) {
          for (const Vec2& p : found.path) r.route.points.push_back(p + origin_);
          r.route.points.front() = banded.start;
          r.route.points.back() = banded.goal;
        } else {
          r.message = found.stopped != SearchStop::none
                          ? search_stop_message(found.stopped, found.expanded)
                          : "the goal cannot be reached from the start without entering a safety zone";
        }
        return r;
      });
  result.stats.graph_vertices = mesh_->vertices().size();
  result.stats.graph_edges = edge_count_;
  return result;
}

std::vector<std::uint8_t> NavMeshGraph::save() const {
  if (ever_inserted_) throw std::logic_error("navigation mesh: a mesh obstacles were inserted into is not kept");
  return write_nav_mesh(zones_, origin_, *mesh_);
}

std::vector<std::pair<Vec2, Vec2>> NavMeshGraph::edges() const {
  std::vector<std::pair<Vec2, Vec2>> out = mesh_->edges();
  for (auto& [a, b] : out) a += origin_, b += origin_;
  return out;
}

GraphEntry nav_mesh_graph_entry() {
  GraphEntry e;
  e.name = "navmesh";
  e.help = "Polyanya on a navigation mesh, exact among the zone polygons";
  e.can = {.turn_radius = true, .finished_by_planner = true, .repairs = true, .covers_area = true};
  e.build = [](const GraphBuild& in) -> std::unique_ptr<RouteGraph> { return std::make_unique<NavMeshGraph>(in); };
  e.save = [](const RouteGraph& g) { return g.as<NavMeshGraph>()->save(); };
  e.insert = [](RouteGraph& g, const ObstacleSet& found) { g.as<NavMeshGraph>()->insert(found); };
  return e;
}

}  // namespace deepguide
