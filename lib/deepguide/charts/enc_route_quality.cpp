#include "deepguide/charts/enc_route_quality.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace bg = boost::geometry;

namespace {

using BgLine = bg::model::linestring<BgPoint>;
using BgMultiLine = bg::model::multi_linestring<BgLine>;

// Distance along the route to the point of it nearest p.
double along(const std::vector<Vec2>& route, const Vec2& p) {
  double best = INFINITY, best_along = 0.0, run = 0.0;
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {
    const Vec2 a = route[i], d = route[i + 1] - route[i];
    const double len2 = d.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - p).norm();
    if (dist < best) best = dist, best_along = run + t * std::sqrt(len2);
    run += std::sqrt(len2);
  }
  return best_along;
}

Vec2 point_at(const std::vector<Vec2>& route, double s) {
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {
    const double len = (route[i + 1] - route[i]).norm();
    if (s <= len || i + 2 == route.size())
      return route[i] + (len > 0.0 ? std::min(s / len, 1.0) : 0.0) * (route[i + 1] - route[i]);
    s -= len;
  }
  return route.back();
}

// The route's length inside `area`, and where it first enters (along the route), or nothing.
struct Inside {
  double length_m = 0.0;
  double first_along_m = INFINITY;
  Vec2 inner{0.0, 0.0};  ///< a point inside, on the first piece (its first segment's middle), not on an edge
};
Inside inside(const std::vector<Vec2>& route, const BgLine& line, const BgMultiPolygon& area) {
  Inside in;
  if (area.empty() || !bg::intersects(line, area)) return in;
  BgMultiLine pieces;
  bg::intersection(line, area, pieces);
  for (const BgLine& piece : pieces) {
    in.length_m += bg::length(piece);
    for (const BgPoint& q : piece) {
      const double s = along(route, to_eigen(q));
      if (s < in.first_along_m && piece.size() >= 2) in.inner = 0.5 * (to_eigen(piece[0]) + to_eigen(piece[1]));
      in.first_along_m = std::min(in.first_along_m, s);
    }
  }
  if (pieces.empty()) in.first_along_m = INFINITY;
  return in;
}

// The route's point nearest the feature and its distance to the feature's edge (0 inside).
std::pair<double, Vec2> nearest_to(const std::vector<Vec2>& route, const BgLine& line, const EncNoGoFeature& f) {
  if (f.point) {
    const double d = bg::distance(to_bg(*f.point), line) - f.radius_m;
    return {std::max(d, 0.0), point_at(route, along(route, *f.point))};
  }
  // Between two sets of segments that do not cross, the least distance is at an end of one of them.
  double best = INFINITY;
  Vec2 at = route.front();
  for (const Vec2& v : route) {
    const double d = bg::distance(to_bg(v), f.area);
    if (d < best) best = d, at = v;
  }
  for (const BgPolygon& p : f.area) {
    auto ring = [&](const auto& r) {
      for (const BgPoint& q : r) {
        const double d = bg::distance(q, line);
        if (d < best) best = d, at = point_at(route, along(route, to_eigen(q)));
      }
    };
    ring(p.outer());
    for (const auto& h : p.inners()) ring(h);
  }
  if (bg::intersects(line, f.area)) best = 0.0;
  return {best, at};
}

// "ID of CELL", the cell left out where the id names it already ("CELL:DEPARE/12").
std::string named(const std::string& id, const std::string& cell) {
  if (cell.empty() || id.rfind(cell + ":", 0) == 0) return printable(id);
  return printable(id) + " of " + printable(cell);
}

std::string lonlat(const LocalFrame& frame, const Vec2& p) {
  const Vec2 ll = frame.to_lonlat(p);
  return fixed(ll.x(), 6) + ", " + fixed(ll.y(), 6);
}

}  // namespace

RouteQuality route_quality(const std::vector<Vec2>& route, const EncNoGo& no_go) {
  if (route.size() < 2) throw InputError("route: expected at least two waypoints for its quality on the charts");
  RouteQuality q;
  BgLine line;
  for (const Vec2& p : route) line.push_back(to_bg(p));
  q.length_m = bg::length(line);

  // Cells, where each is the best scale.
  std::vector<std::pair<double, RouteQuality::CellPart>> entered;
  double charted = 0.0;
  for (const EncChartArea& c : no_go.cell_areas) {
    const Inside in = inside(route, line, c.area);
    if (in.length_m <= 0.0) continue;
    const auto s =
        std::find_if(no_go.cells.begin(), no_go.cells.end(), [&](const EncCellSummary& x) { return x.name == c.cell; });
    entered.push_back({in.first_along_m,
                       {c.cell, s == no_go.cells.end() ? 0 : s->usage_band,
                        s == no_go.cells.end() ? 0 : s->compilation_scale, in.length_m}});
    charted += in.length_m;
  }
  std::stable_sort(entered.begin(), entered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [s, part] : entered) q.cells.push_back(std::move(part));

  // Zones of confidence; charted water outside every zone is "none", water outside every cell "uncharted".
  double zoned = 0.0;
  for (const EncChartArea& z : no_go.zones) {
    const Inside in = inside(route, line, z.area);
    if (in.length_m <= 0.0) continue;
    q.length_by_zoc[zoc_name(z.catzoc) == "unknown" ? "U" : zoc_name(z.catzoc)] += in.length_m;
    zoned += in.length_m;
  }
  if (!no_go.cell_areas.empty()) {
    if (charted - zoned > 1e-6) q.length_by_zoc["none"] += charted - zoned;
    if (q.length_m - charted > 1e-6) q.length_by_zoc["uncharted"] += q.length_m - charted;
  }

  // The least charted depth under the route.
  for (const EncChartArea& d : no_go.depth_areas) {
    if (std::isnan(d.depth_m)) continue;
    if (q.least_depth && d.depth_m >= q.least_depth->depth_m) continue;
    const Inside in = inside(route, line, d.area);
    if (in.length_m <= 0.0) continue;  // areas the route runs through, not ones it only touches
    RouteQuality::Depth depth;
    depth.feature_id = d.id;
    depth.cell = d.cell;
    depth.depth_m = d.depth_m;
    depth.along_m = in.first_along_m;
    depth.at = point_at(route, in.first_along_m);
    depth.zoc = "none";
    for (const EncChartArea& z : no_go.zones) {
      if (z.cell == d.cell && bg::covered_by(to_bg(in.inner), z.area)) depth.zoc = zoc_name(z.catzoc);
    }
    q.least_depth = depth;
  }

  // The nearest no-go feature: candidates by their box, nearest box first.
  std::vector<std::pair<double, const EncNoGoFeature*>> by_box;
  for (const EncNoGoFeature& f : no_go.features) {
    BgBox box;
    if (f.point) {
      box = BgBox(to_bg(*f.point - Vec2(f.radius_m, f.radius_m)), to_bg(*f.point + Vec2(f.radius_m, f.radius_m)));
    } else if (!f.area.empty()) {
      box = bg::return_envelope<BgBox>(f.area);
    } else {
      continue;
    }
    BgPolygon b;
    bg::convert(box, b);
    by_box.push_back({bg::distance(line, b), &f});
  }
  std::sort(by_box.begin(), by_box.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [box_distance, f] : by_box) {
    if (q.nearest_no_go && box_distance > q.nearest_no_go->distance_m) break;
    const auto [d, at] = nearest_to(route, line, *f);
    if (q.nearest_no_go && d >= q.nearest_no_go->distance_m) continue;
    q.nearest_no_go = RouteQuality::Nearest{f->id, f->cell, f->reason, d, at, along(route, at)};
  }
  return q;
}

nlohmann::json RouteQuality::to_json(const LocalFrame& frame) const {
  nlohmann::json j;
  nlohmann::json cs = nlohmann::json::array();
  for (const CellPart& c : cells) {
    cs.push_back({{"cell", c.cell},
                  {"usage_band", c.usage_band},
                  {"compilation_scale", c.compilation_scale},
                  {"length_m", c.length_m}});
  }
  j["cells"] = cs;
  j["length_by_zoc_m"] = length_by_zoc;
  if (least_depth) {
    const Vec2 ll = frame.to_lonlat(least_depth->at);
    j["least_depth"] = {{"depth_m", least_depth->depth_m},
                        {"feature", least_depth->feature_id},
                        {"cell", least_depth->cell},
                        {"zoc", least_depth->zoc},
                        {"lon", ll.x()},
                        {"lat", ll.y()},
                        {"along_m", least_depth->along_m}};
  } else {
    j["least_depth"] = nullptr;
  }
  if (nearest_no_go) {
    const Vec2 ll = frame.to_lonlat(nearest_no_go->at);
    j["nearest_no_go"] = {{"feature", nearest_no_go->feature_id},
                          {"cell", nearest_no_go->cell},
                          {"reason", nearest_no_go->reason},
                          {"distance_m", nearest_no_go->distance_m},
                          {"lon", ll.x()},
                          {"lat", ll.y()},
                          {"along_m", nearest_no_go->along_m}};
  } else {
    j["nearest_no_go"] = nullptr;
  }
  return j;
}

std::string RouteQuality::to_text(const LocalFrame& frame) const {
  std::string t;
  std::string cs;
  for (const CellPart& c : cells) {
    cs += (cs.empty() ? "" : ", ") + c.cell + " (band " + std::to_string(c.usage_band) + ", " +
          fixed(c.length_m / 1000.0, 2) + " km)";
  }
  if (!cs.empty()) t += report_line("cells", cs);
  if (least_depth) {
    t += report_line("least depth", general(least_depth->depth_m, 4) + " m charted (DRVAL1 of " +
                                        named(least_depth->feature_id, least_depth->cell) + ", CATZOC " +
                                        least_depth->zoc + ") at " + lonlat(frame, least_depth->at) + ", " +
                                        fixed(least_depth->along_m, 1) + " m along");
  }
  std::string zs;
  for (const auto& [zoc, len] : length_by_zoc) {
    zs += (zs.empty() ? "" : ", ") + zoc + " " + fixed(len / 1000.0, 2) + " km";
  }
  if (!zs.empty()) t += report_line("zones", zs);
  if (nearest_no_go) {
    t += report_line("nearest no-go", fixed(nearest_no_go->distance_m, 2) + " m from " +
                                          named(nearest_no_go->feature_id, nearest_no_go->cell) + " (" +
                                          nearest_no_go->reason + ") at " + lonlat(frame, nearest_no_go->at) + ", " +
                                          fixed(nearest_no_go->along_m, 1) + " m along");
  }
  return t;
}

}  // namespace deepguide
