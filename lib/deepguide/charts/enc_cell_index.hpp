#pragma once
// Library-internal: spatial indexes over one S-57 cell's features that the
// no-go rules (enc_no_go.cpp) query per feature: its zones of confidence
// (which holds a point, which meet an area) and its depth areas (the depth
// around a hazard). Not installed.

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/enc_reader.hpp"
#include "deepguide/geometry/polygon_locator.hpp"
#include "deepguide/geometry/polygon_ops.hpp"

namespace deepguide::enc_detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgLine = bg::model::linestring<BgPoint>;
using BoxItem = std::pair<BgBox, std::size_t>;
using BoxTree = bgi::rtree<BoxItem, bgi::rstar<16>>;

inline BgBox envelope(const BgMultiPolygon& m) { return bg::return_envelope<BgBox>(m); }

// Zones of confidence of one cell.
struct ZocZones {
  std::vector<BgPolygon> polys;
  std::vector<int> catzoc;
  BoxTree tree;
  std::unique_ptr<PolygonLocator> locator;

  void build() {
    std::vector<BoxItem> items;
    std::vector<const BgPolygon*> ptrs;
    for (std::size_t i = 0; i < polys.size(); ++i) {
      items.emplace_back(bg::return_envelope<BgBox>(polys[i]), i);
      ptrs.push_back(&polys[i]);
    }
    tree = BoxTree(items.begin(), items.end());
    locator = std::make_unique<PolygonLocator>(ptrs);
  }
  // Zones meeting `area`.
  std::vector<std::size_t> meeting(const BgMultiPolygon& area) const {
    std::vector<BoxItem> hits;
    tree.query(bgi::intersects(envelope(area)), std::back_inserter(hits));
    std::vector<std::size_t> out;
    for (const auto& h : hits) {
      if (bg::intersects(polys[h.second], area)) out.push_back(h.second);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  // The worst zone holding p (largest uncertainty at depth z), or -1.
  int at(const Vec2& p, double z, const EncNoGoOptions& o) const {
    int best = -1;
    double worst = -1.0;
    for (std::size_t k : locator->covering(p)) {
      const ZocFigures f = zoc_figures(catzoc[k], o);
      const double u = f.depth_fixed_m + f.depth_fraction * std::max(z, 0.0) + 1e-9 * f.position_m;
      if (u > worst) worst = u, best = static_cast<int>(k);
    }
    return best;
  }
};

// Depth areas of one cell, for the depth around a hazard (EXPSOU).
struct DepthAreas {
  std::vector<const EncFeature*> areas;
  BoxTree tree;
  void build() {
    std::vector<BoxItem> items;
    for (std::size_t i = 0; i < areas.size(); ++i) items.emplace_back(envelope(areas[i]->areas), i);
    tree = BoxTree(items.begin(), items.end());
  }
  // Least DRVAL1 of the depth areas meeting the feature's geometry (NaN: none, or unknown).
  double least_drval1(const EncFeature& f) const {
    BgBox box;
    bool any = false;
    auto grow = [&](const Vec2& p) {
      if (!any)
        box = BgBox(to_bg(p), to_bg(p)), any = true;
      else
        bg::expand(box, to_bg(p));
    };
    for (const Vec2& p : f.points) grow(p);
    for (const auto& l : f.lines)
      for (const Vec2& p : l) grow(p);
    if (!f.areas.empty()) {
      const BgBox a = envelope(f.areas);
      grow(to_eigen(a.min_corner()));
      grow(to_eigen(a.max_corner()));
    }
    if (!any) return std::numeric_limits<double>::quiet_NaN();
    std::vector<BoxItem> hits;
    tree.query(bgi::intersects(box), std::back_inserter(hits));
    double least = std::numeric_limits<double>::quiet_NaN();
    for (const auto& h : hits) {
      const EncFeature& d = *areas[h.second];
      bool meets = false;
      for (const Vec2& p : f.points) meets = meets || bg::covered_by(to_bg(p), d.areas);
      if (!f.areas.empty()) meets = meets || bg::intersects(f.areas, d.areas);
      if (!f.lines.empty() && !meets) {
        for (const auto& l : f.lines) {
          BgLine bl;
          for (const Vec2& p : l) bl.push_back(to_bg(p));
          meets = meets || bg::intersects(bl, d.areas);
        }
      }
      if (!meets) continue;
      if (std::isnan(d.drval1)) return std::numeric_limits<double>::quiet_NaN();  // one unknown neighbour: unknown
      least = std::isnan(least) ? d.drval1 : std::min(least, d.drval1);
    }
    return least;
  }
};

}  // namespace deepguide::enc_detail
