#include "deepguide/planning/graphs/navmesh/polyanya.hpp"

#include "deepguide/planning/graphs/navmesh/convex_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>

namespace deepguide {
namespace {

constexpr std::int32_t kNone = ConvexCells::kNone;
constexpr std::int32_t kNoVertex = -1;
constexpr std::int32_t kStartRoot = -2;
constexpr std::int32_t kFinal = -1;  // Node::face of a node that ends at the goal
// Ray parameters this close to an edge's end are its end: the ray passes
// through the vertex, which then bounds the interval as a vertex (a corner
// the route may turn round), not as a point a rounding error away from it.
constexpr double kSnap = 1e-10;
constexpr double kInf = std::numeric_limits<double>::infinity();

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
// A vector's size for the scales of what counts as zero: within a factor
// sqrt(2) of its length, and no square root (the search's innermost loop).
double extent(const Vec2& v) { return std::abs(v.x()) + std::abs(v.y()); }

struct Node {
  Vec2 root;
  std::int32_t root_id;                    // mesh vertex, or kStartRoot
  Vec2 left, right;                        // the interval's ends as seen from the root
  std::int32_t left_vertex, right_vertex;  // the mesh vertex at that end, else kNoVertex
  std::int32_t face;                       // the cell beyond the interval, or kFinal
  std::uint32_t edge;  // that cell's edge from its corner `edge` to the next, holding the interval, left at `edge`
  bool fan = false;    // the root is an end of that edge: it sees the whole cell beyond
  double g, f;
  std::int32_t parent;  // the node this one was made from; -1 for the start's
};

// min over p in [left, right] of |r p| + |p t|, t mirrored onto the far side.
double heuristic(const Vec2& r, const Vec2& left, const Vec2& right, const Vec2& t) {
  const Vec2 d = left - right;
  const double len2 = d.squaredNorm();
  const double sr = cross(d, r - right);
  if (len2 == 0.0 || sr == 0.0) return (t - r).norm();  // admissible; such nodes are not made
  const double st = cross(d, t - right);
  const Vec2 goal = (sr > 0.0) == (st > 0.0) && st != 0.0 ? Vec2(t - 2.0 * st / len2 * Vec2(-d.y(), d.x())) : t;
  const Vec2 w = goal - r;
  const double den = cross(d, w);
  const double u = den != 0.0 ? cross(r - right, w) / den : -1.0;
  if (u >= 0.0 && u <= 1.0) return w.norm();
  return std::min((left - r).norm() + (goal - left).norm(), (right - r).norm() + (goal - right).norm());
}

struct Range {
  double lo = 1.0, hi = 0.0;
  bool empty() const { return !(hi - lo > kSnap); }
};

double snapped(double t) {
  if (std::abs(t) < kSnap) return 0.0;
  if (std::abs(t - 1.0) < kSnap) return 1.0;
  return t;
}

// The t in [0, 1] where a + b t >= 0; eps: what counts as zero for a and b.
Range where_not_negative(double a, double b, double eps) {
  if (std::abs(b) <= eps) return a >= -eps ? Range{0.0, 1.0} : Range{};
  // Both ends on one side: what the division below would give, without it.
  if (a >= 0.0 && a + b >= 0.0) return Range{0.0, 1.0};
  if (a < 0.0 && a + b < 0.0) return Range{};
  const double t0 = snapped(-a / b);
  return b > 0.0 ? Range{std::max(t0, 0.0), 1.0} : Range{0.0, std::min(t0, 1.0)};
}

Range both(const Range& x, const Range& y) { return {std::max(x.lo, y.lo), std::min(x.hi, y.hi)}; }

class Search {
 public:
  Search(const NavMesh& mesh, const Vec2& goal, const SearchBudget& budget, bool heuristic)
      : mesh_(mesh),
        cells_(mesh.cells()),
        goal_(goal),
        budget_(budget),
        heuristic_(heuristic),
        best_(mesh.vertices().size(), kInf),
        goal_faces_(cells_at(goal)) {}

  PolyanyaResult run(const Vec2& start) {
    PolyanyaResult out;
    const std::vector<std::int32_t> start_faces = cells_at(start);
    if (start_faces.empty() || goal_faces_.empty()) return out;
    for (const std::int32_t f : start_faces) {
      if (holds_goal(f)) {  // a cell is convex: the straight line
        out.found = true;
        out.path = {start, goal_};
        out.length = (goal_ - start).norm();
        return out;
      }
    }
    for (const std::int32_t f : start_faces) start_successors(start, f);
    while (!open_.empty()) {
      const std::int32_t id = open_.top().second;
      open_.pop();
      const Node n = nodes_[id];
      if (n.face == kFinal) return finish(id, out);
      if (n.root_id >= 0 && n.g > best_[n.root_id] + tie(n.g)) continue;  // its root has a shorter way since
      if (budget_.max_expansions > 0 && out.expanded >= budget_.max_expansions) {
        out.stopped = SearchStop::budget;
        break;
      }
      if (budget_.cancelled && out.expanded % 256 == 0 && budget_.cancelled()) {
        out.stopped = SearchStop::cancelled;
        break;
      }
      expand(id, n, out.expanded);
    }
    out.generated = nodes_.size();
    return out;
  }

 private:
  static double tie(double g) { return 1e-12 * std::max(g, 1.0); }

  // The cells whose closure holds p.
  std::vector<std::int32_t> cells_at(const Vec2& p) const {
    std::vector<std::int32_t> out;
    for (const std::int32_t f : mesh_.faces_at(p)) out.push_back(cells_.cell_of[f]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  int open_edges(std::int32_t cell) const {
    int open = 0;
    for (std::uint32_t i = cells_.begin[cell]; i < cells_.begin[cell] + cells_.count[cell]; ++i)
      open += cells_.across[i] != kNone;
    return open;
  }

  // The mesh vertex at corner k (k < 2 * count) of a cell.
  std::uint32_t vertex(std::uint32_t base, std::uint32_t count, std::uint32_t k) const {
    return cells_.corner[base + (k < count ? k : k - count)];
  }

  bool holds_goal(std::int32_t face) const {
    return std::find(goal_faces_.begin(), goal_faces_.end(), face) != goal_faces_.end();
  }

  std::int32_t store(const Node& n) {
    nodes_.push_back(n);
    return static_cast<std::int32_t>(nodes_.size() - 1);
  }
  // f is worked out only here: most nodes made are expanded at once
  // (intermediate pruning) and never need it. A final node has its own.
  void push(Node& n) {
    if (n.face != kFinal) n.f = n.g + (heuristic_ ? heuristic(n.root, n.left, n.right, goal_) : 0.0);
    open_.push({{n.f, -n.g}, store(n)});
  }

  // The node for the part [lo, hi] of edge (P, Q) (P on the right), seen
  // from `root`, into the cell across it; nothing when the part is a point
  // or lies on a line through the root.
  void make(std::int32_t parent, const Vec2& root, std::int32_t root_id, double g, std::int32_t face, std::uint32_t e,
            const Range& part) {
    const std::uint32_t base = cells_.begin[face];
    const std::int32_t across = cells_.across[base + e];
    if (across == kNone || part.empty()) return;
    const std::uint32_t p = cells_.corner[base + e], q = vertex(base, cells_.count[face], e + 1);
    const Vec2& P = mesh_.vertices()[p];
    const Vec2& Q = mesh_.vertices()[q];
    const double len = extent(Q - P);
    Node n;
    if (std::abs(cross(Q - P, root - P)) <= 1e-10 * len * std::max(len, extent(root - P))) {
      // On the edge's line the root sees through the edge only when it is one
      // of its ends, and then sees all of the face beyond (it is a corner of
      // it): the fan round a corner a route turns at. Elsewhere on the line
      // the interval leads nowhere.
      if (root_id < 0 || (root_id != static_cast<std::int32_t>(p) && root_id != static_cast<std::int32_t>(q))) return;
      n.fan = true;
    }
    n.root = root;
    n.root_id = root_id;
    n.right = part.lo == 0.0 ? P : Vec2(P + part.lo * (Q - P));
    n.left = part.hi == 1.0 ? Q : Vec2(P + part.hi * (Q - P));
    n.right_vertex = part.lo == 0.0 ? static_cast<std::int32_t>(p) : kNoVertex;
    n.left_vertex = part.hi == 1.0 ? static_cast<std::int32_t>(q) : kNoVertex;
    // Dead-end pruning (the paper's): a cell whose only open edge is the one
    // crossed leads back only, so nothing shorter passes through it; unless
    // the goal lies in it.
    if (open_edges(across) == 1 && !holds_goal(across)) return;
    n.face = across;
    n.edge = cells_.back[base + e];
    n.g = g;
    n.parent = parent;
    fresh_.push_back(n);
  }

  void start_successors(const Vec2& start, std::int32_t face) {
    // From inside a face its edges, anticlockwise, run from right to left.
    fresh_.clear();
    for (std::uint32_t e = 0; e < cells_.count[face]; ++e) make(-1, start, kStartRoot, 0.0, face, e, Range{0.0, 1.0});
    for (Node& n : fresh_) push(n);
  }

  // A turn round the interval's end `v` (a mesh vertex or none): its g, or
  // +inf when v is no corner or a shorter way to it is known.
  double turn(const Node& n, std::int32_t v, const Vec2& at) {
    if (v == kNoVertex || !mesh_.corner(static_cast<std::uint32_t>(v))) return kInf;
    const double g = n.g + (at - n.root).norm();
    if (g > best_[v] + tie(g)) return kInf;
    best_[v] = std::min(best_[v], g);
    return g;
  }

  // Intermediate pruning (the paper's): a node with one successor, not at
  // the goal's face, leads nowhere else, so that successor is expanded at
  // once instead of passing through the open list (its f is no lower). It
  // is kept (for the route back) only when it turns round a new root: the
  // route is the chain of roots, and a node with its parent's root adds
  // nothing to it, so its successors can name that parent instead.
  void expand(std::int32_t id, Node n, std::size_t& expanded) {
    for (;;) {
      ++expanded;
      fresh_.clear();
      successors(id, n);
      if (fresh_.size() != 1 || fresh_[0].face == kFinal || holds_goal(fresh_[0].face) ||
          (budget_.max_expansions > 0 && expanded >= budget_.max_expansions)) {
        break;
      }
      const bool same_root = fresh_[0].root_id == n.root_id && fresh_[0].root == n.root;
      n = fresh_[0];
      if (!same_root) id = store(n);
    }
    for (Node& s : fresh_) push(s);
  }

  void successors(std::int32_t id, const Node& n) {
    const std::uint32_t base = cells_.begin[n.face], count = cells_.count[n.face];
    if (n.fan) {
      // The root is a corner of this face: every far edge is seen whole (the
      // next edge round the root fans on; the way back is not taken again).
      for (std::uint32_t e = 0; e < count; ++e) {
        if (e != n.edge) make(id, n.root, n.root_id, n.g, n.face, e, Range{0.0, 1.0});
      }
      if (holds_goal(n.face)) finals(id, n, kInf, kInf);
      return;
    }
    const Vec2& r = n.root;
    const Vec2 to_right = n.right - r, to_left = n.left - r;
    const double g_right = turn(n, n.right_vertex, n.right);
    const double g_left = turn(n, n.left_vertex, n.left);
    // The far edges, from the interval's right end round to its left.
    for (std::uint32_t step = 1; step < count; ++step) {
      const std::uint32_t e = n.edge + step < count ? n.edge + step : n.edge + step - count;
      const Vec2& P = mesh_.vertices()[cells_.corner[base + e]];
      const Vec2& Q = mesh_.vertices()[vertex(base, count, e + 1)];
      const double reach = extent(Q - P) + extent(P - r);
      const double eps_r = 1e-12 * extent(to_right) * reach;
      const double eps_l = 1e-12 * extent(to_left) * reach;
      // Left of (or on) the ray r -> right, and right of (or on) r -> left.
      const double ar = cross(to_right, P - r), br = cross(to_right, Q - P);
      const double al = cross(to_left, P - r), bl = cross(to_left, Q - P);
      const Range right_of_left = where_not_negative(-al, -bl, eps_l);
      const Range left_of_right = where_not_negative(ar, br, eps_r);
      make(id, r, n.root_id, n.g, n.face, e, both(left_of_right, right_of_left));
      if (g_right < kInf) make(id, n.right, n.right_vertex, g_right, n.face, e, where_not_negative(-ar, -br, eps_r));
      if (g_left < kInf) make(id, n.left, n.left_vertex, g_left, n.face, e, where_not_negative(al, bl, eps_l));
    }
    if (holds_goal(n.face)) finals(id, n, g_right, g_left);
  }

  // The goal lies in the face beyond n's interval: seen from the root, or
  // round an end of the interval that is a corner.
  void finals(std::int32_t id, const Node& n, double g_right, double g_left) {
    const Vec2& r = n.root;
    const double sr = cross(n.right - r, goal_ - r), sl = cross(n.left - r, goal_ - r);
    const double eps = 1e-12 * (goal_ - r).norm() * ((n.right - r).norm() + (n.left - r).norm());
    Node last = n;
    last.face = kFinal;
    last.parent = id;
    if (n.fan || (sr >= -eps && sl <= eps)) {
      last.f = n.g + (goal_ - r).norm();
    } else if (sr < 0.0 && g_right < kInf) {
      last.root = n.right, last.root_id = n.right_vertex, last.g = g_right;
      last.f = g_right + (goal_ - n.right).norm();
    } else if (sl > 0.0 && g_left < kInf) {
      last.root = n.left, last.root_id = n.left_vertex, last.g = g_left;
      last.f = g_left + (goal_ - n.left).norm();
    } else {
      return;
    }
    fresh_.push_back(last);
  }

  PolyanyaResult& finish(std::int32_t id, PolyanyaResult& out) {
    out.found = true;
    out.generated = nodes_.size();
    out.length = nodes_[id].f;
    std::vector<Vec2> path{goal_};
    std::int32_t last_root = std::numeric_limits<std::int32_t>::min();
    for (std::int32_t k = id; k != -1; k = nodes_[k].parent) {
      if (nodes_[k].root_id == last_root) continue;
      last_root = nodes_[k].root_id;
      path.push_back(nodes_[k].root);
    }
    out.path.assign(path.rbegin(), path.rend());
    return out;
  }

  const NavMesh& mesh_;
  const ConvexCells& cells_;
  Vec2 goal_;
  const SearchBudget& budget_;
  bool heuristic_;
  std::vector<double> best_;              // the shortest way found to each corner used as a root
  std::vector<std::int32_t> goal_faces_;  // cells
  std::vector<Node> nodes_;
  std::vector<Node> fresh_;                                          // the successors of the node being expanded
  using Entry = std::pair<std::pair<double, double>, std::int32_t>;  // (f, -g), node: least f, then most g
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open_;
};

}  // namespace

PolyanyaResult polyanya(const NavMesh& mesh, const Vec2& start, const Vec2& goal, const SearchBudget& budget,
                        bool heuristic) {
  return Search(mesh, goal, budget, heuristic).run(start);
}

}  // namespace deepguide
