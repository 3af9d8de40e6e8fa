#include "deepguide/planning/graphs/navmesh/convex_cells.hpp"

#include <algorithm>

namespace deepguide {
namespace {

constexpr std::int32_t kNone = ConvexCells::kNone;

// One corner of a cell being merged: the vertex, and the triangle across the
// edge that leaves it (anticlockwise), or kNone.
struct Corner {
  std::uint32_t vertex;
  std::int32_t across;
};

// Strictly convex at b, coming from a, going on to c: a turn left by more
// than 1e-9 rad, so rounding cannot pass a straight or reflex vertex.
bool turns_left(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, w = c - b;
  return u.x() * w.y() - u.y() * w.x() > 1e-9 * u.norm() * w.norm();
}

// Hertel and Mehlhorn's merge of the triangles `region`; slot[t] is
// triangle t's index in it, or kNone outside it.
struct Merged {
  std::vector<std::vector<Corner>> ring;  // a cell's ring at one of its triangles' index, else empty
  std::vector<std::size_t> owner;         // the index whose ring holds each triangle
};

Merged merge_region(const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces,
                    const std::vector<std::int32_t>& region, const std::vector<std::int32_t>& slot) {
  Merged out;
  out.ring.resize(region.size());
  out.owner.resize(region.size());
  struct Edge {
    double length2;
    std::size_t from;
    int k;
  };
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const NavMesh::Face& f = faces[region[i]];
    out.owner[i] = i;
    for (int k = 0; k < 3; ++k) {
      out.ring[i].push_back({f.v[k], f.next[k]});
      if (f.next[k] > region[i] && slot[f.next[k]] != kNone) {
        edges.push_back({(vertices[f.v[(k + 1) % 3]] - vertices[f.v[k]]).squaredNorm(), i, k});
      }
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.length2 > b.length2; });
  const auto root = [&](std::size_t k) {
    while (out.owner[k] != k) k = out.owner[k] = out.owner[out.owner[k]];
    return k;
  };
  for (const Edge& e : edges) {
    const std::int32_t t = region[e.from], other = faces[t].next[e.k];
    const std::size_t a = root(e.from), b = root(static_cast<std::size_t>(slot[other]));
    if (a == b) continue;  // cannot happen: two convex cells share one edge at most
    std::vector<Corner>& A = out.ring[a];
    std::vector<Corner>& B = out.ring[b];
    // The edge u -> w leaves a corner of A towards `other`, and w -> u one
    // of B towards t.
    const std::uint32_t u = faces[t].v[e.k], w = faces[t].v[(e.k + 1) % 3];
    const auto i = std::find_if(A.begin(), A.end(), [&](const Corner& c) { return c.vertex == u && c.across == other; });
    const auto j = std::find_if(B.begin(), B.end(), [&](const Corner& c) { return c.vertex == w && c.across == t; });
    if (i == A.end() || j == B.end()) continue;
    // Both rings from just after the shared edge: A from w round to u, B
    // from u round to w. Merged: A's without u, then B's without w.
    std::rotate(A.begin(), std::next(i) == A.end() ? A.begin() : std::next(i), A.end());
    std::rotate(B.begin(), std::next(j) == B.end() ? B.begin() : std::next(j), B.end());
    const Vec2& x = vertices[A[A.size() - 2].vertex];  // before u in A
    const Vec2& y = vertices[A[1].vertex];             // after w in A
    const Vec2& p = vertices[B[B.size() - 2].vertex];  // before w in B
    const Vec2& q = vertices[B[1].vertex];             // after u in B
    if (!turns_left(x, vertices[u], q) || !turns_left(p, vertices[w], y)) continue;
    A.pop_back();
    A.insert(A.end(), B.begin(), std::prev(B.end()));
    std::vector<Corner>().swap(B);
    out.owner[b] = a;
  }
  for (std::size_t i = 0; i < region.size(); ++i) out.owner[i] = root(i);
  return out;
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
  const auto& ring = merged.ring;

  // Number the new cells (freed numbers first) and store their corners.
  std::vector<std::int32_t> number(region.size(), kNone);
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (merged.owner[i] != i) continue;  // merged into another's ring
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
    cells.count[c] = static_cast<std::uint32_t>(ring[i].size());
    ++cells.live;
    for (const Corner& k : ring[i]) {
      cells.corner.push_back(k.vertex);
      cells.across.push_back(kNone);
      cells.back.push_back(0);
    }
  }
  for (std::size_t i = 0; i < region.size(); ++i) cells.cell_of[region[i]] = number[merged.owner[i]];
  // Link each new cell to the cells across its edges: the corner there
  // that starts at this edge's far end and ends at its near one.
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (number[i] == kNone) continue;
    const std::int32_t c = number[i];
    const std::uint32_t m = cells.count[c];
    for (std::uint32_t k = 0; k < m; ++k) {
      const std::int32_t t = ring[i][k].across;
      if (t == kNone) continue;
      const std::int32_t d = cells.cell_of[t];
      const std::uint32_t u = ring[i][k].vertex, w = ring[i][(k + 1) % m].vertex;
      const std::uint32_t md = cells.count[d];
      for (std::uint32_t j = 0; j < md; ++j) {
        if (cells.corner[cells.begin[d] + j] == w && cells.corner[cells.begin[d] + (j + 1) % md] == u) {
          cells.across[cells.begin[c] + k] = d;
          cells.back[cells.begin[c] + k] = j;
          cells.across[cells.begin[d] + j] = c;  // an old cell's link to the region turns to the new cell
          cells.back[cells.begin[d] + j] = k;
          break;
        }
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
