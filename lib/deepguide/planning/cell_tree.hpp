#pragma once
// Quadtree (D = 2) and octree (D = 3) decomposition of a work area into free,
// occupied and mixed cells: one implementation generic over the dimension
// (shared/notes/algorithms.md §4).
//
// The root is a cube of side root_size at `origin`; a cell of level L has side
// root_size / 2^L and integer index i (per axis) at that level, so it spans
// origin + [i, i + 1) * side. classify(cell) says whether a cell is free (no
// point of it is inside any safety zone), occupied (every point is) or mixed;
// mixed cells split into 2^D children down to max_depth, where a mixed leaf
// counts as occupied. The classifier must be conservative: "free" only when
// the whole closed cell is free (planning/cell_classifier.hpp gives one from
// any 1-Lipschitz clearance).
//
// Neighbours (§4.2, a linear quadtree): leaves are kept in a hash map keyed
// by (level, index). For each leaf and each of the 3^D - 1 directions (faces,
// edges, corners) the finest cells just outside it are probed and the leaf
// holding each is found by its key at every level, so neighbours of every
// size, across levels, are found.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

namespace deepguide {

enum class CellState : std::uint8_t { free, occupied, mixed };

template <int D>
class CellTree {
  static_assert(D == 2 || D == 3, "quadtrees and octrees only");

 public:
  using Point = Eigen::Matrix<double, D, 1>;
  using Index = std::array<std::int64_t, D>;

  struct Box {
    Point min, max;
    Point centre() const { return 0.5 * (min + max); }
  };
  struct Leaf {
    int level = 0;
    Index index{};
    CellState state = CellState::free;  ///< free or occupied (a mixed leaf at max_depth is occupied)
    Box box;
  };
  /// `classify` answers for one cell; it must never call a cell free that is not.
  using Classifier = std::function<CellState(const Box&)>;

  CellTree(const Point& origin, double root_size, int max_depth, const Classifier& classify)
      : origin_(origin), root_size_(root_size), max_depth_(max_depth) {
    build(0, Index{}, classify);
  }

  const std::vector<Leaf>& leaves() const { return leaves_; }
  int max_depth() const { return max_depth_; }
  double root_size() const { return root_size_; }
  const Point& origin() const { return origin_; }
  double side(int level) const { return std::ldexp(root_size_, -level); }

  /// The leaf holding p (cells are half-open), or none outside the root.
  std::optional<std::size_t> locate(const Point& p) const {
    Index finest{};
    const double unit = side(max_depth_);
    const std::int64_t cells = std::int64_t{1} << max_depth_;
    for (int k = 0; k < D; ++k) {
      const double q = std::floor((p[k] - origin_[k]) / unit);
      if (!(q >= 0.0) || q >= static_cast<double>(cells)) return std::nullopt;
      finest[k] = static_cast<std::int64_t>(q);
    }
    return leaf_at_finest(finest);
  }

  /// Every leaf that shares a face, an edge or a corner with leaf `i`, each
  /// once, with whether it shares a face (its centre segment then stays
  /// inside the two cells: the crossing point lies on the shared face).
  std::vector<std::pair<std::size_t, bool>> neighbours(std::size_t i) const {
    const Leaf& leaf = leaves_[i];
    const std::int64_t span = std::int64_t{1} << (max_depth_ - leaf.level);  // finest cells per side
    Index lo{};
    for (int k = 0; k < D; ++k) lo[k] = leaf.index[k] * span;
    std::vector<std::pair<std::size_t, bool>> out;
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
        const std::int64_t past = last_free < 0 ? 0 : p[last_free] + 1;
        if (!j) return past;
        const Leaf& other = leaves_[*j];
        const std::int64_t other_span = std::int64_t{1} << (max_depth_ - other.level);
        const std::int64_t end = last_free < 0 ? 0 : (other.index[last_free] + 1) * other_span;
        for (auto& [k, face] : out) {
          if (k != *j) continue;
          face = face || nonzero == 1;  // met first across an edge or corner, then across a face
          return end;
        }
        out.emplace_back(*j, nonzero == 1);
        return end;
      });
    }
    return out;
  }

 private:
  static constexpr int ipow3() { return D == 2 ? 9 : 27; }

  struct KeyHash {
    std::size_t operator()(const std::pair<int, Index>& key) const {
      std::uint64_t h = static_cast<std::uint64_t>(key.first) * 0x9E3779B97F4A7C15ull;
      for (std::int64_t v : key.second) h = (h ^ static_cast<std::uint64_t>(v)) * 0x100000001B3ull;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };

  void build(int level, const Index& index, const Classifier& classify) {
    Box box;
    const double s = side(level);
    for (int k = 0; k < D; ++k) {
      box.min[k] = origin_[k] + s * static_cast<double>(index[k]);
      box.max[k] = box.min[k] + s;
    }
    CellState state = classify(box);
    if (state == CellState::mixed && level == max_depth_) state = CellState::occupied;  // conservative
    if (state != CellState::mixed) {
      by_key_.emplace(std::pair{level, index}, leaves_.size());
      leaves_.push_back(Leaf{level, index, state, box});
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
    for (int level = 0; level <= max_depth_; ++level) {
      Index at{};
      for (int k = 0; k < D; ++k) at[k] = finest[k] >> (max_depth_ - level);
      const auto it = by_key_.find(std::pair{level, at});
      if (it != by_key_.end()) return it->second;
    }
    return std::nullopt;
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
  double root_size_;
  int max_depth_;
  std::vector<Leaf> leaves_;
  std::unordered_map<std::pair<int, Index>, std::size_t, KeyHash> by_key_;
};

}  // namespace deepguide
