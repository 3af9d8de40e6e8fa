#include "deepguide/planning/graphs/navmesh/convex_cells.hpp"

#include <algorithm>

namespace deepguide {
namespace {

constexpr std::int32_t kNone = ConvexCells::kNone;

// Strictly convex at b, coming from a, going on to c: a turn left by more
// than 1e-9 rad, so rounding cannot pass a straight or reflex vertex.
bool turns_left(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, w = c - b;
  return u.x() * w.y() - u.y() * w.x() > 1e-9 * u.norm() * w.norm();
}

// Hertel and Mehlhorn's merge of the triangles `region` (slot[t]: triangle
// t's index in it, or kNone outside it). Each cell's ring is a cycle of the
// triangles' directed edges, 3 i + k for edge k of region[i], linked both
// ways, so a merge relinks four of them.
struct Merged {
  static constexpr std::size_t kOutside = static_cast<std::size_t>(-1);
  std::vector<std::size_t> owner;  // per triangle: the index of the triangle that names its cell
  std::vector<std::size_t> any;    // per naming triangle: one directed edge of its cell's ring
  std::vector<std::size_t> next;   // per directed edge: the next one round its ring
  std::vector<std::size_t> twin;   // per directed edge: the same edge the other way, or kOutside
};

Merged merge_region(const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces,
                    const std::vector<std::int32_t>& region, const std::vector<std::int32_t>& slot) {
  const std::size_t n = region.size();
  const auto from = [&](std::size_t d) { return faces[region[d / 3]].v[d % 3]; };
  const auto to = [&](std::size_t d) { return faces[region[d / 3]].v[(d % 3 + 1) % 3]; };
  Merged m;
  m.owner.resize(n);
  m.any.resize(n);
  m.next.resize(3 * n);
  m.twin.assign(3 * n, Merged::kOutside);
  std::vector<std::size_t> prev(3 * n);
  std::vector<std::size_t> edges;  // each inner edge once, as the directed edge of its lower triangle
  for (std::size_t i = 0; i < n; ++i) {
    m.owner[i] = i;
    m.any[i] = 3 * i;
    const NavMesh::Face& f = faces[region[i]];
    for (std::size_t k = 0; k < 3; ++k) {
      m.next[3 * i + k] = 3 * i + (k + 1) % 3;
      prev[3 * i + k] = 3 * i + (k + 2) % 3;
      const std::int32_t other = f.next[k];
      if (other == NavMesh::kNone || slot[other] == kNone) continue;
      const NavMesh::Face& g = faces[other];
      std::size_t j = 0;
      while (j < 3 && !(g.v[j] == f.v[(k + 1) % 3] && g.v[(j + 1) % 3] == f.v[k])) ++j;
      if (j == 3) continue;  // not the shared edge: cannot happen in a valid mesh
      m.twin[3 * i + k] = 3 * static_cast<std::size_t>(slot[other]) + j;
      if (other > region[i]) edges.push_back(3 * i + k);
    }
  }
  const auto root = [&](std::size_t k) {
    while (m.owner[k] != k) k = m.owner[k] = m.owner[m.owner[k]];
    return k;
  };
  for (const std::size_t d : edges) {
    const std::size_t t = m.twin[d];
    const std::size_t a = root(d / 3), b = root(t / 3);
    if (a == b) continue;  // cannot happen: two convex cells share one edge at most
    // d runs u -> w in one cell, its twin w -> u in the other. Merged, the
    // ring comes from x into u and goes on to q (the twin's cell), and comes
    // from p into w and goes on to y (d's cell).
    const Vec2& x = vertices[from(prev[d])];
    const Vec2& y = vertices[to(m.next[d])];
    const Vec2& p = vertices[from(prev[t])];
    const Vec2& q = vertices[to(m.next[t])];
    if (!turns_left(x, vertices[from(d)], q) || !turns_left(p, vertices[to(d)], y)) continue;
    m.next[prev[d]] = m.next[t];
    prev[m.next[t]] = prev[d];
    m.next[prev[t]] = m.next[d];
    prev[m.next[d]] = prev[t];
    m.owner[b] = a;
    m.any[a] = prev[d];
  }
  for (std::size_t i = 0; i < n; ++i) m.owner[i] = root(i);
  return m;
}

}  // namespace

ConvexCells merge_into_cells(const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces) {
  ConvexCells cells;
  cells.cell_of.assign(faces.size(), kNone);
  merge_again(cells, vertices, faces, {});
  return cells;
}

void merge_again(ConvexCells& cells, const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces,
                 const std::vector<std::int32_t>& dissolved) {
  // The region: the dissolved cells' triangles and the unmerged ones.
  std::vector<char> gone(cells.count.size(), 0);
  for (const std::int32_t c : dissolved) gone[c] = 1;
  std::vector<std::int32_t> region;
  std::vector<std::int32_t> slot(faces.size(), kNone);
  for (std::int32_t t = 0; t < static_cast<std::int32_t>(faces.size()); ++t) {
    const std::int32_t c = cells.cell_of[t];
    if (c == kNone || gone[c]) {
      slot[t] = static_cast<std::int32_t>(region.size());
      region.push_back(t);
    }
  }
  std::vector<std::int32_t> free_numbers;
  for (const std::int32_t c : dissolved) {
    if (cells.count[c] == 0) continue;
    // The cells round it lose their links to it; the new cells link again
    // below (an edge that finds no new cell across stays a wall, never a
    // link to whatever cell takes this number).
    for (std::uint32_t k = cells.begin[c]; k < cells.begin[c] + cells.count[c]; ++k) {
      const std::int32_t d = cells.across[k];
      if (d != kNone && !gone[d]) cells.across[cells.begin[d] + cells.back[k]] = kNone;
    }
    cells.garbage += cells.count[c];
    cells.count[c] = 0;
    --cells.live;
    free_numbers.push_back(c);
  }
  const Merged merged = merge_region(vertices, faces, region, slot);

  // Number the new cells (freed numbers first) and store their corners,
  // noting where each directed edge went.
  std::vector<std::int32_t> number(region.size(), kNone);
  std::vector<std::uint32_t> place(3 * region.size(), 0);  // per directed edge: its corner's offset in its cell
  const std::size_t first_new = cells.corner.size();
  std::vector<std::size_t> edge_of;  // per new corner: its directed edge
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (merged.owner[i] != i) continue;  // another triangle names its cell
    std::int32_t c;
    if (!free_numbers.empty()) {
      c = free_numbers.back();
      free_numbers.pop_back();
    } else {
      c = static_cast<std::int32_t>(cells.count.size());
      cells.begin.push_back(0);
      cells.count.push_back(0);
    }
    number[i] = c;
    cells.begin[c] = static_cast<std::uint32_t>(cells.corner.size());
    std::size_t d = merged.any[i];
    do {
      place[d] = static_cast<std::uint32_t>(cells.corner.size() - cells.begin[c]);
      cells.corner.push_back(faces[region[d / 3]].v[d % 3]);
      edge_of.push_back(d);
      d = merged.next[d];
    } while (d != merged.any[i]);
    cells.count[c] = static_cast<std::uint32_t>(cells.corner.size() - cells.begin[c]);
    ++cells.live;
  }
  cells.across.resize(cells.corner.size(), kNone);
  cells.back.resize(cells.corner.size(), 0);
  for (std::size_t i = 0; i < region.size(); ++i) cells.cell_of[region[i]] = number[merged.owner[i]];
  // Link each new corner's edge to the cell across: a new cell by the
  // twin's place, an old one (across the region's edge) by the corner there
  // that runs the other way.
  for (std::size_t g = first_new; g < cells.corner.size(); ++g) {
    const std::size_t d = edge_of[g - first_new];
    const std::int32_t c = number[merged.owner[d / 3]];
    if (merged.twin[d] != Merged::kOutside) {
      cells.across[g] = number[merged.owner[merged.twin[d] / 3]];
      cells.back[g] = place[merged.twin[d]];
      continue;
    }
    const NavMesh::Face& f = faces[region[d / 3]];
    const std::int32_t t = f.next[d % 3];
    if (t == NavMesh::kNone) continue;
    const std::int32_t old = cells.cell_of[t];
    const std::uint32_t u = f.v[d % 3], w = f.v[(d % 3 + 1) % 3], m = cells.count[old];
    for (std::uint32_t j = 0; j < m; ++j) {
      if (cells.corner[cells.begin[old] + j] == w && cells.corner[cells.begin[old] + (j + 1) % m] == u) {
        cells.across[g] = old;
        cells.back[g] = j;
        cells.across[cells.begin[old] + j] = c;  // the old cell's link to the region turns to the new cell
        cells.back[cells.begin[old] + j] = static_cast<std::uint32_t>(g - cells.begin[c]);
        break;
      }
    }
  }
  if (cells.garbage > cells.corner.size() / 2) {
    // Repairs have left more unused corners than used: pack the rest,
    // keeping every cell's number (links and offsets stay as they are).
    std::vector<std::uint32_t> corner, back;
    std::vector<std::int32_t> across;
    for (std::size_t c = 0; c < cells.count.size(); ++c) {
      const std::uint32_t from = cells.begin[c];
      cells.begin[c] = static_cast<std::uint32_t>(corner.size());
      for (std::uint32_t k = 0; k < cells.count[c]; ++k) {
        corner.push_back(cells.corner[from + k]);
        across.push_back(cells.across[from + k]);
        back.push_back(cells.back[from + k]);
      }
    }
    cells.corner = std::move(corner);
    cells.across = std::move(across);
    cells.back = std::move(back);
    cells.garbage = 0;
  }
}

}  // namespace deepguide
