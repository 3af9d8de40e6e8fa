#pragma once
// Quadtree (D = 2) and octree (D = 3) decomposition of a work area into free,
// occupied and mixed cells: one implementation generic over the dimension
// (docs/PLANNING.md, "The quadtree graph").
//
// The root is a box of extent root_size (per axis) at `origin`; a cell of
// level L has extent root_size / 2^L and integer index i (per axis) at that
// level, so it spans origin + [i, i + 1) * side. Octree cells need not be
// cubes: the octree graph flattens them to the vehicle's dive angle.
// classify(cell) says whether a cell is free (no point of it is inside any
// safety zone), occupied (every point is) or mixed; mixed cells split into
// 2^D children down to max_depth, where a mixed leaf counts as occupied. The
// classifier must be conservative: "free" only when the whole closed cell is.
//
// Storage: a linear tree (§4.2). Each leaf is its level and the Morton code
// (bits of the D indices interleaved) of its lowest finest cell, 16 bytes in
// all. The depth-first build visits children in Morton order, so leaves come
// out sorted by code and tile the code range: the leaf holding a finest cell
// is the last leaf whose code is not above the cell's (one binary search, no
// hash map). An octree of ten million leaves is 160 MB.
//
// Neighbours: for each leaf and each of the 3^D - 1 directions (faces, edges,
// corners) the finest cells just outside it are probed and the leaf holding
// each is looked up, so neighbours of every size, across levels, are found.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

enum class CellState : std::uint8_t { free, occupied, mixed };

template <int D>
class CellTree {
  static_assert(D == 2 || D == 3, "quadtrees and octrees only");

 public:
  using Point = Eigen::Matrix<double, D, 1>;
  using Index = std::array<std::int64_t, D>;
  /// Deepest level the 64-bit Morton code holds.
  static constexpr int kMaxLevels = D == 2 ? 31 : 21;

  struct Box {
    Point min, max;
    Point centre() const { return 0.5 * (min + max); }
  };
  struct Leaf {
    std::uint64_t code = 0;  ///< Morton code of the leaf's lowest finest cell
    std::uint8_t level = 0;
    CellState state = CellState::free;  ///< free or occupied (a mixed leaf at max_depth is occupied)
  };
  /// `classify` answers for one cell; it must never call a cell free that is not.
  using Classifier = std::function<CellState(const Box&)>;

  /// A root of the same extent along every axis (a square or a cube).
  CellTree(const Point& origin, double root_size, int max_depth, const Classifier& classify)
      : CellTree(origin, Point::Constant(root_size), max_depth, classify) {}
  CellTree(const Point& origin, const Point& root_size, int max_depth, const Classifier& classify)
      : origin_(origin), root_size_(root_size), max_depth_(std::clamp(max_depth, 0, kMaxLevels)) {
    build(0, Index{}, classify);
  }

  const std::vector<Leaf>& leaves() const { return leaves_; }
  int max_depth() const { return max_depth_; }
  const Point& root_size() const { return root_size_; }
  const Point& origin() const { return origin_; }
  Point side(int level) const { return root_size_ * std::ldexp(1.0, -level); }

  /// The leaf's index per axis at its own level.
  Index index(const Leaf& leaf) const {
    Index at = decode(leaf.code);
    for (auto& v : at) v >>= (max_depth_ - leaf.level);
    return at;
  }
  Box box(const Leaf& leaf) const {
    const Index at = index(leaf);
    const Point s = side(leaf.level);
    Box b;
    for (int k = 0; k < D; ++k) {
      b.min[k] = origin_[k] + s[k] * static_cast<double>(at[k]);
      b.max[k] = b.min[k] + s[k];
    }
    return b;
  }
  Box box(std::size_t i) const { return box(leaves_[i]); }

  /// The leaf holding p (cells are half-open), or none outside the root.
  std::optional<std::size_t> locate(const Point& p) const {
    Index finest{};
    const Point unit = side(max_depth_);
    const std::int64_t cells = std::int64_t{1} << max_depth_;
    for (int k = 0; k < D; ++k) {
      const double q = std::floor((p[k] - origin_[k]) / unit[k]);
      if (!(q >= 0.0) || q >= static_cast<double>(cells)) return std::nullopt;
      finest[k] = static_cast<std::int64_t>(q);
    }
    return leaf_at_finest(finest);
  }

  /// Every leaf that shares a face, an edge or a corner with leaf `i`, each
  /// once, with whether it shares a face (its centre segment then stays
  /// inside the two cells: the crossing point lies on the shared face).
  std::vector<std::pair<std::size_t, bool>> neighbours(std::size_t i) const {
    std::vector<std::pair<std::size_t, bool>> out;
    neighbours(i, out);
    return out;
  }
  /// The same into `out` (cleared first), for callers that reuse one buffer.
  void neighbours(std::size_t i, std::vector<std::pair<std::size_t, bool>>& out) const {
    out.clear();
    const Leaf& leaf = leaves_[i];
    const std::int64_t span = std::int64_t{1} << (max_depth_ - leaf.level);  // finest cells per side
    const Index lo = decode(leaf.code);
    std::array<int, D> dir{};
    for (int code = 0; code < ipow3(); ++code) {
      int c = code, nonzero = 0, last_free = -1;
      for (int k = 0; k < D; ++k, c /= 3) {
        dir[k] = c % 3 - 1;
        nonzero += dir[k] != 0;
        if (dir[k] == 0) last_free = k;
      }
      if (nonzero == 0) continue;
      // The finest cells just outside the leaf in this direction: along the
      // axes where dir is 0 every position of the leaf's span, except that
      // along the last such axis a neighbour found is skipped to its end (so a
      // big leaf's face costs its neighbours, not its finest cells).
      Index probe{};
      probe_all(dir, lo, span, last_free, 0, probe, [&](const Index& p) -> std::int64_t {
        const std::optional<std::size_t> j = leaf_at_finest(p);
        if (!j) return last_free < 0 ? 0 : p[last_free] + 1;
        const Leaf& other = leaves_[*j];
        const std::int64_t other_span = std::int64_t{1} << (max_depth_ - other.level);
        const std::int64_t end = last_free < 0 ? 0 : (index(other)[last_free] + 1) * other_span;
        for (auto& [k, face] : out) {
          if (k != *j) continue;
          face = face || nonzero == 1;  // met first across an edge or corner, then across a face
          return end;
        }
        out.emplace_back(*j, nonzero == 1);
        return end;
      });
    }
  }

 private:
  static constexpr int ipow3() { return D == 2 ? 9 : 27; }

  // Morton codes by the usual bit spreading: the bits of one index moved to
  // every D-th place, and back.
  static std::uint64_t spread(std::uint64_t x) {
    if constexpr (D == 2) {
      x &= 0xffffffffull;
      x = (x | x << 16) & 0x0000ffff0000ffffull;
      x = (x | x << 8) & 0x00ff00ff00ff00ffull;
      x = (x | x << 4) & 0x0f0f0f0f0f0f0f0full;
      x = (x | x << 2) & 0x3333333333333333ull;
      return (x | x << 1) & 0x5555555555555555ull;
    } else {
      x &= 0x1fffffull;
      x = (x | x << 32) & 0x001f00000000ffffull;
      x = (x | x << 16) & 0x001f0000ff0000ffull;
      x = (x | x << 8) & 0x100f00f00f00f00full;
      x = (x | x << 4) & 0x10c30c30c30c30c3ull;
      return (x | x << 2) & 0x1249249249249249ull;
    }
  }
  static std::uint64_t compact(std::uint64_t x) {
    if constexpr (D == 2) {
      x &= 0x5555555555555555ull;
      x = (x | x >> 1) & 0x3333333333333333ull;
      x = (x | x >> 2) & 0x0f0f0f0f0f0f0f0full;
      x = (x | x >> 4) & 0x00ff00ff00ff00ffull;
      x = (x | x >> 8) & 0x0000ffff0000ffffull;
      return (x | x >> 16) & 0xffffffffull;
    } else {
      x &= 0x1249249249249249ull;
      x = (x | x >> 2) & 0x10c30c30c30c30c3ull;
      x = (x | x >> 4) & 0x100f00f00f00f00full;
      x = (x | x >> 8) & 0x001f0000ff0000ffull;
      x = (x | x >> 16) & 0x001f00000000ffffull;
      return (x | x >> 32) & 0x1fffffull;
    }
  }
  static std::uint64_t encode(const Index& at) {
    std::uint64_t code = 0;
    for (int k = 0; k < D; ++k) code |= spread(static_cast<std::uint64_t>(at[k])) << k;
    return code;
  }
  static Index decode(std::uint64_t code) {
    Index at{};
    for (int k = 0; k < D; ++k) at[k] = static_cast<std::int64_t>(compact(code >> k));
    return at;
  }

  // Depth first, children in Morton order (child bit k = axis k), so leaves
  // are appended in increasing code.
  void build(int level, const Index& index, const Classifier& classify) {
    Box b;
    const Point s = side(level);
    for (int k = 0; k < D; ++k) {
      b.min[k] = origin_[k] + s[k] * static_cast<double>(index[k]);
      b.max[k] = b.min[k] + s[k];
    }
    CellState state = classify(b);
    if (state == CellState::mixed && level == max_depth_) state = CellState::occupied;  // conservative
    if (state != CellState::mixed) {
      Index finest = index;
      for (auto& v : finest) v <<= (max_depth_ - level);
      leaves_.push_back(Leaf{encode(finest), static_cast<std::uint8_t>(level), state});
      return;
    }
    for (int child = 0; child < (1 << D); ++child) {
      Index sub{};
      for (int k = 0; k < D; ++k) sub[k] = 2 * index[k] + ((child >> k) & 1);
      build(level + 1, sub, classify);
    }
  }

  std::optional<std::size_t> leaf_at_finest(const Index& finest) const {
    const std::int64_t cells = std::int64_t{1} << max_depth_;
    for (int k = 0; k < D; ++k) {
      if (finest[k] < 0 || finest[k] >= cells) return std::nullopt;
    }
    const std::uint64_t code = encode(finest);
    // The leaves tile the code range in order: the last one starting at or below `code` holds it.
    const auto it = std::upper_bound(leaves_.begin(), leaves_.end(), code,
                                     [](std::uint64_t c, const Leaf& leaf) { return c < leaf.code; });
    if (it == leaves_.begin()) return std::nullopt;
    return static_cast<std::size_t>(it - leaves_.begin() - 1);
  }

  // Visits the probe cells; visit returns where the next probe along the
  // last free axis may start (past the leaf it found).
  template <class F>
  std::int64_t probe_all(const std::array<int, D>& dir, const Index& lo, std::int64_t span, int last_free, int axis,
                         Index& probe, const F& visit) const {
    if (axis == D) return visit(probe);
    if (dir[axis] != 0) {
      probe[axis] = dir[axis] < 0 ? lo[axis] - 1 : lo[axis] + span;
      return probe_all(dir, lo, span, last_free, axis + 1, probe, visit);
    }
    for (std::int64_t t = lo[axis]; t < lo[axis] + span;) {
      probe[axis] = t;
      const std::int64_t next = probe_all(dir, lo, span, last_free, axis + 1, probe, visit);
      t = axis == last_free ? std::max(t + 1, next) : t + 1;
    }
    return 0;
  }

  Point origin_;
  Point root_size_;
  int max_depth_;
  std::vector<Leaf> leaves_;
};

}  // namespace deepguide
