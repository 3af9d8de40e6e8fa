#pragma once
// Library-internal: what the tangent graph's files share (tangent_graph.cpp
// builds the environment's graph, tangent_arcs.cpp walks and checks arcs on
// the zone pieces, tangent_query.cpp answers a query). Not installed.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/graphs/tangent/tangent_graph.hpp"
#include "deepguide/planning/graphs/tangent/zone_pieces.hpp"
#include "deepguide/planning/polygon_visibility.hpp"
#include "deepguide/planning/turn_rounding.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace deepguide {
namespace tangent_detail {

inline constexpr std::size_t kNoPiece = static_cast<std::size_t>(-1);
// Tangent segments touch zones exactly; the field judging them allows this
// much (m) so rounding does not reject them. The route checker allows 1e-6.
inline constexpr double kTouchEps = 1e-7;

inline Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

inline double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

struct Node {
  std::size_t piece;  // kNoPiece for start and goal
  double phi;         // outward normal angle on the piece, in [0, 2 pi)
  Vec2 p;
  int orient = 0;  // the way round the piece a route passes here: +1 anticlockwise, -1 clockwise, 0 either (one_way)
};

// The way round a piece of a route moving along `d` where the piece's outward
// normal is `u`: anticlockwise when d is u turned left.
inline int orientation(const Vec2& u, const Vec2& d) { return u.x() * d.y() - u.y() * d.x() > 0.0 ? +1 : -1; }

struct Segment {
  Node a, b;
};

}  // namespace tangent_detail

using tangent_detail::kNoPiece;
using tangent_detail::Node;
using tangent_detail::Segment;

// Hidden: the public TangentGraph would otherwise export its Impl's members.
struct [[gnu::visibility("hidden")]] TangentGraph::Impl {
  Vec2 origin;
  double margin;
  double tolerance;
  QueryFocus focus;  // in the shifted frame
  std::vector<ZonePiece> pieces;
  std::vector<std::string> piece_names;
  std::vector<bool> needs_arc_check;  // another zone reaches into the piece's box
  double turn_radius = 0.0;           // routes turn on no boundary tighter than this (m)
  // Dubins ends: a query with a start (goal) heading leaves (reaches) that
  // end only along one of the two circles of this radius through it, the
  // way round that has the heading there. The circles are appended to
  // `pieces` while the query runs; end_way is +1 (anticlockwise) or -1 on
  // them, 0 on the environment's pieces, which may be passed either way.
  double heading_radius = 0.0;
  std::vector<int> end_way;
  std::vector<bool> end_is_start;
  // Whether a route may turn at the piece's point with normal phi, and along
  // its arc from phi0 to phi1 (phi0 < phi1): only where the radius is >= turn_radius.
  bool turns_at(std::size_t piece, double phi) const { return turns_along(piece, phi, phi); }
  bool turns_along(std::size_t piece, double phi0, double phi1) const {
    const ZonePiece& z = pieces[piece];
    if (turn_radius <= 0.0) return true;
    const double least =
        z.kind == ZonePiece::Kind::ellipse ? least_offset_ellipse_radius(z.ellipse, z.margin, phi0, phi1) : z.margin;
    return least >= turn_radius * (1.0 - 1e-12);
  }
  std::unique_ptr<ObstacleField> field;  // shifted frame, accepts margin - kTouchEps
  std::vector<Segment> tangents;         // collision-free common tangents
  double build_ms = 0.0;

  // The environment's graph, built once: vertex 0 and 1 are reserved for
  // start and goal, then one vertex per tangent point and way round its piece
  // (anticlockwise, clockwise). A tangent leaves its first point and reaches
  // its second going one way round each; it is an edge between those
  // vertices and, backwards, between the other two. Arcs join vertices of one
  // way round: a route never reverses along a piece (with pieces that are not
  // obstacles, the turning circles, a reversal could otherwise look short).
  // Without a turning radius there are no such pieces, and a shortest route
  // never reverses (a cusp is never shortest): one vertex per tangent point
  // (orient 0), tangents and arcs both ways, half the vertices to build,
  // join and search (`one_way`).
  // Arcs are stored in the direction of travel (from u to v), with the way
  // round they run (+1 anticlockwise).
  struct Arc {
    std::size_t u, v;
    double w;
    int turn;
  };
  bool one_way = false;
  std::vector<Node> nodes;  // the environment's, then a query's own while it runs
  std::size_t env_nodes = 0;
  std::vector<std::vector<std::size_t>> on_piece;  // vertex ids per piece, by phi
  PlanningGraph base;
  std::vector<Arc> arcs;
  std::unordered_map<std::uint64_t, std::size_t> arc_of;  // (u, v) -> cheapest arc
  std::size_t base_edges = 0;

  static std::uint64_t key(std::size_t u, std::size_t v) { return (static_cast<std::uint64_t>(u) << 32) | v; }
  // Adds the arcs between cyclically consecutive vertices of `ids` (sorted by
  // phi) of one way round for which `want(a, b)` holds.
  template <class Want>
  void add_arcs(std::size_t piece, const std::vector<std::size_t>& ids, const std::vector<Node>& all, Want want,
                PlanningGraph& graph, std::vector<Arc>& out, std::unordered_map<std::uint64_t, std::size_t>& index)
      const;

  // The obstacle polygons: a segment crossing one is blocked for certain,
  // found far faster than the exact polygon test, which then only judges the
  // rest. (Ellipses have their own quick verdicts in ObstacleField.)
  std::unique_ptr<PolygonVisibility> inner;
  // A convex zone (an ellipse's) does not meet a line tangent to it beyond
  // the touch, nor a point on its boundary: the tests skip the ellipse a
  // segment or point was built on (`skip_*` are piece indices or kNoPiece).
  std::size_t own_ellipse(std::size_t piece) const {
    return piece != kNoPiece && pieces[piece].kind == ZonePiece::Kind::ellipse ? pieces[piece].obstacle
                                                                               : ObstacleField::kNone;
  }
  bool segment_free(const Vec2& a, const Vec2& b, std::size_t piece_a = kNoPiece, std::size_t piece_b = kNoPiece)
      const {
    return !inner->properly_crosses(a, b) && field->segment_free(a, b, own_ellipse(piece_a), own_ellipse(piece_b));
  }
  bool point_free(const Vec2& p, std::size_t piece) const { return field->is_free(p, own_ellipse(piece)); }
  bool arc_free(std::size_t piece, double phi0, double phi1) const;
  // Tangents from p to the pieces whose lower bound of |x - s| + |x - g| is
  // within `bound` (all pieces for an infinite bound).
  void add_point_tangents(const Vec2& p, std::vector<Segment>& out, const std::vector<double>& low, double bound) const;
  // The collision-free common tangents of pieces i and j, from i to j.
  void common_tangents(std::size_t i, std::size_t j, std::vector<Segment> & out) const;
  std::vector<Vec2> arc_polyline(std::size_t piece, double phi0, double phi1, int turn) const;
  // The route's legs along a piece from normal angle phi0 to phi1 (turn: the
  // sign of phi1 - phi0), in the unshifted frame: one arc on an ellipse's
  // zone; on a capsule, arcs round its ends and lines along its flat sides.
  // from_p and to_p are the route's points there (at a flat side's normal
  // they tell which end the route is at).
  std::vector<RouteLeg> arc_legs(std::size_t piece, double phi0, double phi1, int turn, const Vec2& from_p,
                                 const Vec2& to_p) const;
  // One query's additions to the graph, taken out when it ends (tangent_query.cpp).
  struct Query;
};

template <class Want>
void TangentGraph::Impl::add_arcs(std::size_t piece, const std::vector<std::size_t>& ids, const std::vector<Node>& all,
                                  Want want, PlanningGraph& graph, std::vector<Arc>& out,
                                  std::unordered_map<std::uint64_t, std::size_t>& index) const {
  for (int orient : one_way ? std::vector<int>{0} : std::vector<int>{+1, -1}) {
    std::vector<std::size_t> way;
    for (std::size_t v : ids) {
      if (all[v].orient == orient) way.push_back(v);
    }
    if (way.size() < 2) continue;
    for (std::size_t k = 0; k < way.size(); ++k) {
      const std::size_t a = way[k], b = way[(k + 1) % way.size()];
      if (!want(a, b)) continue;
      const double phi0 = all[a].phi;
      const double phi1 = k + 1 < way.size() ? all[b].phi : all[b].phi + kTwoPi;
      if (!turns_along(piece, phi0, phi1)) continue;
      if (needs_arc_check[piece] && !arc_free(piece, phi0, phi1)) continue;
      const double w = pieces[piece].arc_length(phi0, phi1);
      // Anticlockwise is from a (smaller phi) to b; clockwise the other way.
      // Two vertices at one point (the sort's order between them is
      // arbitrary) are joined both ways.
      const bool same_point = k + 1 < way.size() && phi1 == phi0;
      const bool both_ways = same_point || orient == 0;
      for (const int dir : {+1, -1}) {
        if (!both_ways && dir != orient) continue;
        const std::size_t from = dir > 0 ? a : b, to = dir > 0 ? b : a;
        boost::add_edge(from, to, w, graph);
        out.push_back({from, to, w, orient != 0 ? orient : dir});
        auto it = index.find(key(from, to));
        if (it == index.end() || out[it->second].w > w) index[key(from, to)] = out.size() - 1;
      }
    }
  }
}

}  // namespace deepguide
