#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <deque>
#include <unordered_map>

#include "deepguide/core/error.hpp"
#include "deepguide/core/parallel_blocks.hpp"
#include "deepguide/planning/graphs/navmesh/convex_cells.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int depth = -1;        // constraint edges crossed from outside the area (insert: its region); -1: not reached yet
  std::int32_t id = -1;  // insert: the new face's number; -1: no water
};
struct VertexInfo {
  std::int64_t id = -1;  // the mesh's vertex; -1: none yet
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Each ring as closed constraint edges, its repeated closing point left out.
// All rings go to CGAL at once: insert_constraints sorts the points along a
// space-filling curve before inserting them, which locates each from the
// last instead of walking from afar (a third of the tight band's build).
struct Constraints {
  std::vector<K::Point_2> points;
  std::vector<std::pair<std::size_t, std::size_t>> edges;

  template <class Ring>
  void add_ring(const Ring& ring) {
    const std::size_t first = points.size();
    for (const BgPoint& p : ring) {
      const K::Point_2 q(p.x(), p.y());
      if (points.size() == first || points.back() != q) points.push_back(q);
    }
    while (points.size() > first + 1 && points[first] == points.back()) points.pop_back();
    const std::size_t n = points.size() - first;
    if (n < 3) {
      points.resize(first);
      return;
    }
    for (std::size_t i = 0; i < n; ++i) edges.emplace_back(first + i, first + (i + 1) % n);
  }
};

// The flood: faces reached without crossing a constraint share a depth; each
// constraint crossed adds one (CGAL's polygon-with-holes example, in breadth).
void mark_depths(Cdt& cdt) {
  std::deque<std::pair<Cdt::Face_handle, int>> border{{cdt.infinite_face(), 0}};
  while (!border.empty()) {
    const auto [start, depth] = border.front();
    border.pop_front();
    if (start->info().depth != -1) continue;
    std::deque<Cdt::Face_handle> flood{start};
    start->info().depth = depth;
    while (!flood.empty()) {
      const Cdt::Face_handle f = flood.front();
      flood.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (n->info().depth != -1) continue;
        if (cdt.is_constrained({f, i})) {
          border.emplace_back(n, depth + 1);
        } else {
          n->info().depth = depth;
          flood.push_back(n);
        }
      }
    }
  }
}

bool water(const Cdt& cdt, Cdt::Face_handle f) { return !cdt.is_infinite(f) && f->info().depth % 2 == 1; }

}  // namespace

struct NavMesh::Index {
  using Item = std::pair<BgBox, std::int32_t>;
  bgi::rtree<Item, bgi::rstar<16>> faces;
};

NavMesh::NavMesh(const BgMultiPolygon& no_go, const Vec2& area_min, const Vec2& area_max)
    : area_min_(area_min), area_max_(area_max), index_(std::make_unique<Index>()) {
  if (!area_min.allFinite() || !area_max.allFinite() || !((area_max - area_min).minCoeff() > 0.0)) {
    throw InputError("navigation mesh: expected a work area with a positive, finite extent");
  }
  Cdt cdt;
  const std::vector<BgPoint> box{{area_min.x(), area_min.y()},
                                 {area_max.x(), area_min.y()},
                                 {area_max.x(), area_max.y()},
                                 {area_min.x(), area_max.y()}};
  Constraints constraints;
  constraints.add_ring(box);
  for (const BgPolygon& poly : no_go) {
    constraints.add_ring(poly.outer());
    for (const auto& inner : poly.inners()) constraints.add_ring(inner);
  }
  cdt.insert_constraints(constraints.points.begin(), constraints.points.end(), constraints.edges.begin(),
                         constraints.edges.end());
  mark_depths(cdt);

  // Number the water's faces and the vertices they use.
  std::int32_t faces = 0;
  std::int64_t next_vertex = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!water(cdt, f)) continue;
    f->info().id = faces++;
    for (int i = 0; i < 3; ++i) {
      if (f->vertex(i)->info().id == -1) {
        f->vertex(i)->info().id = next_vertex++;
        vertices_.emplace_back(f->vertex(i)->point().x(), f->vertex(i)->point().y());
      }
    }
  }
  faces_.resize(static_cast<std::size_t>(faces));
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!water(cdt, f)) continue;
    const std::int32_t id = f->info().id;
    Face& out = faces_[id];
    for (int k = 0; k < 3; ++k) out.v[k] = static_cast<std::uint32_t>(f->vertex(k)->info().id);
    for (int k = 0; k < 3; ++k) {
      // Edge (v[k], v[k+1]) lies opposite CGAL's vertex k + 2.
      const int opposite = (k + 2) % 3;
      const Cdt::Face_handle n = f->neighbor(opposite);
      const bool open = !cdt.is_constrained({f, opposite}) && water(cdt, n);
      out.next[k] = open ? n->info().id : kNone;
    }
  }
  finish();
}

NavMesh::NavMesh(std::vector<Vec2> vertices, std::vector<Face> faces, const Vec2& area_min, const Vec2& area_max)
    : vertices_(std::move(vertices)),
      faces_(std::move(faces)),
      area_min_(area_min),
      area_max_(area_max),
      index_(std::make_unique<Index>()) {
  finish();
}

void NavMesh::finish() {
  // Three independent passes over the faces; on a large mesh (the 5000
  // ellipses' band: 90,000 faces) the index goes to another core.
  constexpr std::size_t kParallelFaces = 20000;
  cells_ = std::make_unique<ConvexCells>();
  parallel_blocks(2, 1, faces_.size() >= kParallelFaces ? hardware_workers() : 1,
                  [&](std::size_t begin, std::size_t end, std::size_t) {
                    for (std::size_t task = begin; task < end; ++task) {
                      if (task == 0) {
                        index_faces();
                      } else {
                        find_corners();
                        *cells_ = merge_into_cells(vertices_, faces_);
                      }
                    }
                  });
}

void NavMesh::find_corners() {
  angle_.assign(vertices_.size(), 0.0);
  boundary_.assign(vertices_.size(), 0);
  corner_.assign(vertices_.size(), 0);
  for (std::size_t id = 0; id < faces_.size(); ++id) count_face(id, 1);
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) mark_corner(v);
}

void NavMesh::count_face(std::size_t id, int sign) {
  const Face& f = faces_[id];
  for (int k = 0; k < 3; ++k) {
    const Vec2& p = vertices_[f.v[k]];
    const Vec2 a = vertices_[f.v[(k + 1) % 3]] - p, b = vertices_[f.v[(k + 2) % 3]] - p;
    angle_[f.v[k]] += sign * std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (f.next[k] == kNone) boundary_[f.v[k]] += sign, boundary_[f.v[(k + 1) % 3]] += sign;
  }
}

void NavMesh::mark_corner(std::uint32_t v) {
  // Two boundary edges where one wedge of water ends, more where the water
  // touches itself. Sums kept face by face drift by rounding, far below the
  // 1e-9 rad that separates a straight vertex (a corner too) from a convex one.
  constexpr double kStraight = 3.14159265358979323846 - 1e-9;
  corner_[v] = boundary_[v] > 2 || (boundary_[v] == 2 && angle_[v] > kStraight) ? 1 : 0;
}

void NavMesh::index_faces() {
  std::vector<Index::Item> boxes;
  boxes.reserve(faces_.size());
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    boxes.emplace_back(face_box(static_cast<std::int32_t>(id)), static_cast<std::int32_t>(id));
  }
  index_->faces = bgi::rtree<Index::Item, bgi::rstar<16>>(boxes.begin(), boxes.end());
}

NavMesh::~NavMesh() = default;
NavMesh::NavMesh(NavMesh&&) noexcept = default;
NavMesh& NavMesh::operator=(NavMesh&&) noexcept = default;

std::vector<std::int32_t> NavMesh::faces_at(const Vec2& p) const {
  // A point on an edge counts as in the face up to a nanometre: a start
  // stepped onto a zone polygon's boundary (the band round a zone) comes out
  // within rounding of the edge, on either side of it.
  constexpr double kOn = 1e-9;
  std::vector<Index::Item> near;
  const BgBox around(to_bg(p - Vec2::Constant(kOn)), to_bg(p + Vec2::Constant(kOn)));
  index_->faces.query(bgi::intersects(around), std::back_inserter(near));
  std::vector<std::int32_t> out;
  for (const auto& [box, id] : near) {
    const Face& f = faces_[id];
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Vec2& a = vertices_[f.v[k]];
      const Vec2& b = vertices_[f.v[(k + 1) % 3]];
      const Vec2 ab = b - a, ap = p - a;
      inside = ab.x() * ap.y() - ab.y() * ap.x() >= -kOn * ab.norm();  // signed distance times |ab|
    }
    if (inside) out.push_back(id);
  }
  return out;
}

std::vector<std::pair<Vec2, Vec2>> NavMesh::edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    const Face& f = faces_[id];
    for (int k = 0; k < 3; ++k) {
      if (f.next[k] != kNone && static_cast<std::size_t>(f.next[k]) < id) continue;  // the other face has it
      out.emplace_back(vertices_[f.v[k]], vertices_[f.v[(k + 1) % 3]]);
    }
  }
  return out;
}

std::size_t NavMesh::edge_count() const {
  // An edge shared by two faces is counted by one of them; a boundary edge by its only face.
  std::size_t count = 0;
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    for (const std::int32_t n : faces_[id].next) count += n == kNone || static_cast<std::size_t>(n) > id ? 1 : 0;
  }
  return count;
}

}  // namespace deepguide

namespace deepguide {

namespace {

// A face left in place across the cut region's boundary, and its edge there.
struct Across {
  std::int32_t face;
  int edge;
};

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

// The region the taken faces cover, triangulated anew: its boundary (their
// edges with no taken face across) and the polygon's rings as constraints.
// The rings may cross the region's boundary only where no water lies beyond
// it (a face left in place has its box clear of the polygon's), so every
// edge shared with a face left in place comes out whole; where the rings
// cross each other or the boundary, CGAL splits them at the crossing.
struct Cut {
  Cdt cdt;
  // The faces left in place across the boundary, keyed by the taken face's
  // edge a -> b, which the new face on the same side has in the same direction.
  std::unordered_map<std::uint64_t, Across> across;
  std::vector<std::int32_t> neighbours;  // those faces, once each
  std::vector<std::uint32_t> touched;    // vertices whose corners may change
};

void triangulate_region(Cut& cut, const NavMesh& mesh, const std::vector<std::int32_t>& taken, const BgPolygon& no_go) {
  const auto is_taken = [&](std::int32_t id) { return std::binary_search(taken.begin(), taken.end(), id); };
  std::unordered_map<std::uint32_t, Cdt::Vertex_handle> local;
  const auto mesh_vertex = [&](std::uint32_t v) {
    auto [at, fresh] = local.try_emplace(v);
    if (fresh) {
      at->second = cut.cdt.insert(K::Point_2(mesh.vertices()[v].x(), mesh.vertices()[v].y()));
      at->second->info().id = v;
    }
    return at->second;
  };
  for (const std::int32_t id : taken) {
    const NavMesh::Face& f = mesh.faces()[id];
    for (int k = 0; k < 3; ++k) {
      cut.touched.push_back(f.v[k]);
      const std::int32_t n = f.next[k];
      if (n != NavMesh::kNone && is_taken(n)) continue;
      const std::uint32_t a = f.v[k], b = f.v[(k + 1) % 3];
      cut.cdt.insert_constraint(mesh_vertex(a), mesh_vertex(b));
      if (n == NavMesh::kNone) continue;
      const NavMesh::Face& m = mesh.faces()[n];
      const int back = m.next[0] == id ? 0 : m.next[1] == id ? 1 : 2;
      cut.across.emplace(edge_key(a, b), Across{n, back});
      cut.neighbours.push_back(n);
    }
  }
  std::sort(cut.neighbours.begin(), cut.neighbours.end());
  cut.neighbours.erase(std::unique(cut.neighbours.begin(), cut.neighbours.end()), cut.neighbours.end());
  const auto add_ring = [&](const auto& ring) {
    std::vector<Cdt::Vertex_handle> hs;
    for (const BgPoint& p : ring) {
      const Cdt::Vertex_handle h = cut.cdt.insert(K::Point_2(p.x(), p.y()));
      if (hs.empty() || hs.back() != h) hs.push_back(h);
    }
    while (hs.size() > 1 && hs.front() == hs.back()) hs.pop_back();
    if (hs.size() < 3) return;
    for (std::size_t i = 0; i < hs.size(); ++i) cut.cdt.insert_constraint(hs[i], hs[(i + 1) % hs.size()]);
  };
  add_ring(no_go.outer());
  for (const auto& inner : no_go.inners()) add_ring(inner);
}

// Which of the new faces are water, by piece (FaceInfo::depth numbers the
// pieces). Faces joined across edges that are no constraint lie all in the
// region or all out of it, all in the polygon or all out: one point inside
// the largest of them answers for every one. In the region: in a taken face
// (exact orientation tests); water: strictly outside the polygon (its holes
// are water).
std::vector<char> water_pieces(Cdt& cdt, const NavMesh& mesh, const std::vector<std::int32_t>& taken,
                               const BgPolygon& no_go) {
  // The taken faces by box: a long zone at an angle takes thousands of
  // faces, and the pieces outside the region would each test all of them.
  using Item = std::pair<BgBox, std::int32_t>;
  std::vector<Item> boxes;
  boxes.reserve(taken.size());
  for (const std::int32_t id : taken) boxes.emplace_back(mesh.face_box(id), id);
  const bgi::rtree<Item, bgi::rstar<16>> by_box(boxes.begin(), boxes.end());
  std::vector<Item> near;
  const auto in_region = [&](const K::Point_2& c) {
    near.clear();
    by_box.query(bgi::intersects(BgPoint(c.x(), c.y())), std::back_inserter(near));
    for (const auto& [box, id] : near) {
      const NavMesh::Face& f = mesh.faces()[id];
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        const Vec2& a = mesh.vertices()[f.v[k]];
        const Vec2& b = mesh.vertices()[f.v[(k + 1) % 3]];
        inside = CGAL::orientation(K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y()), c) != CGAL::RIGHT_TURN;
      }
      if (inside) return true;
    }
    return false;
  };
  std::vector<char> water;
  for (auto start = cdt.finite_faces_begin(); start != cdt.finite_faces_end(); ++start) {
    if (start->info().depth != -1) continue;
    const int piece = static_cast<int>(water.size());
    Cdt::Face_handle largest = start;
    double largest_area = -1.0;
    std::deque<Cdt::Face_handle> flood{start};
    start->info().depth = piece;
    while (!flood.empty()) {
      const Cdt::Face_handle f = flood.front();
      flood.pop_front();
      const double area = std::abs(cdt.triangle(f).area());
      if (area > largest_area) largest_area = area, largest = f;
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (cdt.is_infinite(n) || n->info().depth != -1 || cdt.is_constrained({f, i})) continue;
        n->info().depth = piece;
        flood.push_back(n);
      }
    }
    const K::Point_2 c = CGAL::centroid(cdt.triangle(largest));
    water.push_back(in_region(c) && !bg::within(BgPoint(c.x(), c.y()), no_go) ? 1 : 0);
  }
  return water;
}

}  // namespace

NavMesh::Repair NavMesh::insert(const BgMultiPolygon& no_go) {
  Repair total;
  for (const BgPolygon& polygon : no_go) {
    const Repair r = insert(polygon);
    total.removed += r.removed;
    total.added += r.added;
  }
  return total;
}

BgBox NavMesh::face_box(std::int32_t id) const {
  BgBox b;
  bg::assign_inverse(b);
  for (const std::uint32_t v : faces_[id].v) bg::expand(b, to_bg(vertices_[v]));
  return b;
}

NavMesh::Repair NavMesh::insert(const BgPolygon& no_go) {
  if (no_go.outer().size() < 4) return {};
  BgBox box;
  bg::envelope(no_go, box);
  std::vector<Index::Item> hit;
  index_->faces.query(bgi::intersects(box), std::back_inserter(hit));
  if (hit.empty()) return {};  // it lies in no water: nothing changes
  std::vector<std::int32_t> taken;
  for (const auto& item : hit) taken.push_back(item.second);
  std::sort(taken.begin(), taken.end());
  std::vector<std::int32_t> dissolved;  // the cells of the taken faces, merged again at the end
  for (const std::int32_t id : taken) dissolved.push_back(cells_->cell_of[id]);
  std::sort(dissolved.begin(), dissolved.end());
  dissolved.erase(std::unique(dissolved.begin(), dissolved.end()), dissolved.end());
  Cut cut;
  triangulate_region(cut, *this, taken, no_go);
  const std::vector<char> water = water_pieces(cut.cdt, *this, taken, no_go);

  // Out with the taken faces: their part of the corners' sums, their boxes,
  // and the links to them from across the boundary.
  for (const std::int32_t id : taken) {
    count_face(id, -1);
    index_->faces.remove(Index::Item(face_box(id), id));
  }
  for (const std::int32_t n : cut.neighbours) count_face(n, -1);
  for (const auto& [edge, a] : cut.across) faces_[a.face].next[a.edge] = kNone;

  // In with the water's new faces: the taken faces' numbers first, then new ones.
  std::vector<Cdt::Face_handle> made;
  for (auto f = cut.cdt.finite_faces_begin(); f != cut.cdt.finite_faces_end(); ++f) {
    if (!water[f->info().depth]) continue;
    f->info().id = made.size() < taken.size() ? taken[made.size()]
                                              : static_cast<std::int32_t>(faces_.size() + made.size() - taken.size());
    made.push_back(f);
  }
  if (made.size() > taken.size()) faces_.resize(faces_.size() + made.size() - taken.size());
  cells_->cell_of.resize(faces_.size());
  for (const Cdt::Face_handle& f : made) cells_->cell_of[f->info().id] = ConvexCells::kNone;
  for (const Cdt::Face_handle& f : made) {
    for (int i = 0; i < 3; ++i) {
      VertexInfo& v = f->vertex(i)->info();
      if (v.id != -1) continue;
      v.id = static_cast<std::int64_t>(vertices_.size());
      vertices_.emplace_back(f->vertex(i)->point().x(), f->vertex(i)->point().y());
      corner_.push_back(0);
      angle_.push_back(0.0);
      boundary_.push_back(0);
    }
  }
  for (const Cdt::Face_handle& f : made) {
    const std::int32_t id = f->info().id;
    Face& face = faces_[id];
    for (int k = 0; k < 3; ++k) face.v[k] = static_cast<std::uint32_t>(f->vertex(k)->info().id);
    for (int k = 0; k < 3; ++k) {
      const int opposite = (k + 2) % 3;  // edge (v[k], v[k+1]) lies opposite CGAL's vertex k + 2
      const Cdt::Face_handle n = f->neighbor(opposite);
      face.next[k] = kNone;
      if (!cut.cdt.is_constrained({f, opposite})) {
        if (!cut.cdt.is_infinite(n)) face.next[k] = n->info().id;
        continue;
      }
      const auto found = cut.across.find(edge_key(face.v[k], face.v[(k + 1) % 3]));
      if (found == cut.across.end()) continue;
      face.next[k] = found->second.face;
      faces_[found->second.face].next[found->second.edge] = id;
    }
    count_face(static_cast<std::size_t>(id), 1);
    for (const std::uint32_t v : face.v) cut.touched.push_back(v);
    index_->faces.insert(Index::Item(face_box(id), id));
  }
  for (const std::int32_t n : cut.neighbours) {
    count_face(n, 1);
    for (const std::uint32_t v : faces_[n].v) cut.touched.push_back(v);
  }
  for (const std::uint32_t v : cut.touched) mark_corner(v);
  fill_freed(taken, made.size());
  merge_again(*cells_, vertices_, faces_, dissolved);
  return {taken.size(), made.size()};
}

void NavMesh::fill_freed(const std::vector<std::int32_t>& taken, std::size_t reused) {
  // Taken numbers no new face took: the last face moves into each, largest
  // first, so the last is never one of them.
  for (std::size_t i = taken.size(); i-- > reused;) {
    const std::int32_t hole = taken[i];
    const std::int32_t last = static_cast<std::int32_t>(faces_.size()) - 1;
    if (hole != last) {
      index_->faces.remove(Index::Item(face_box(last), last));
      faces_[hole] = faces_[last];
      cells_->cell_of[hole] = cells_->cell_of[last];
      for (const std::int32_t n : faces_[hole].next) {
        if (n == kNone) continue;
        for (std::int32_t& back : faces_[n].next) back = back == last ? hole : back;
      }
      index_->faces.insert(Index::Item(face_box(hole), hole));
    }
    faces_.pop_back();
    cells_->cell_of.pop_back();
  }
}

}  // namespace deepguide
