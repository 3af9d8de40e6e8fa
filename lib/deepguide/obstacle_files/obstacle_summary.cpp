#include "deepguide/obstacle_files/obstacle_summary.hpp"

#include <algorithm>
#include <boost/geometry/algorithms/area.hpp>
#include <boost/geometry/algorithms/envelope.hpp>
#include <cmath>

#include "deepguide/core/format.hpp"

namespace deepguide {

void RangeStats::add(double v) {
  min = n == 0 ? v : std::min(min, v);
  max = n == 0 ? v : std::max(max, v);
  mean += (v - mean) / double(++n);
}

ObstacleSummary summarize(const LoadedObstacles& loaded) {
  ObstacleSummary s;
  const ObstacleSet& set = loaded.obstacles;
  s.count = set.size();
  s.ellipses = set.ellipses.size();
  s.polygons = set.polygons.size();
  s.local_crs_id = loaded.frame.id();
  s.local_crs_name = loaded.frame.name();
  s.sources = loaded.sources;

  auto grow = [&](double x0, double y0, double x1, double y1) {
    if (!s.has_extent) {
      s.min_x = x0, s.min_y = y0, s.max_x = x1, s.max_y = y1;
      s.has_extent = true;
      return;
    }
    s.min_x = std::min(s.min_x, x0), s.min_y = std::min(s.min_y, y0);
    s.max_x = std::max(s.max_x, x1), s.max_y = std::max(s.max_y, y1);
  };
  auto vertical = [&](const auto& o) {
    if (o.height_m)
      ++s.with_height;
    else if (o.top_depth_m)
      ++s.with_top_depth;
    else
      ++s.full_column;
  };
  for (const EllipticCylinder& c : set.ellipses) {
    const Ellipse& e = c.footprint;
    // Half-widths of the bounding box are the support function along x and y.
    const double hx = e.support(Vec2::UnitX()) - e.centre.x();
    const double hy = e.support(Vec2::UnitY()) - e.centre.y();
    grow(e.centre.x() - hx, e.centre.y() - hy, e.centre.x() + hx, e.centre.y() + hy);
    s.semi_major_m.add(e.a);
    s.semi_minor_m.add(e.b);
    s.footprint_area_m2.add(e.area());
    vertical(c);
  }
  for (const PolygonObstacle& p : set.polygons) {
    BgBox box;
    boost::geometry::envelope(p.footprint, box);
    grow(box.min_corner().x(), box.min_corner().y(), box.max_corner().x(), box.max_corner().y());
    s.footprint_area_m2.add(std::abs(boost::geometry::area(p.footprint)));
    vertical(p);
  }
  if (s.has_extent) {
    s.west = s.south = std::numeric_limits<double>::infinity();
    s.east = s.north = -std::numeric_limits<double>::infinity();
    for (double x : {s.min_x, s.max_x}) {
      for (double y : {s.min_y, s.max_y}) {
        const Eigen::Vector2d ll = loaded.frame.to_lonlat({x, y});
        s.west = std::min(s.west, ll.x()), s.east = std::max(s.east, ll.x());
        s.south = std::min(s.south, ll.y()), s.north = std::max(s.north, ll.y());
      }
    }
  }
  return s;
}

namespace {
nlohmann::json stats_json(const RangeStats& r) {
  if (r.n == 0) return nullptr;
  return {{"min", r.min}, {"mean", r.mean}, {"max", r.max}};
}
}  // namespace

nlohmann::json to_json(const ObstacleSummary& s) {
  nlohmann::json j;
  j["count"] = s.count;
  j["ellipses"] = s.ellipses;
  j["polygons"] = s.polygons;
  j["local_crs"] = {{"id", s.local_crs_id}, {"name", s.local_crs_name}};
  if (s.has_extent) {
    j["extent_local_m"] = {{"min_x", s.min_x}, {"min_y", s.min_y}, {"max_x", s.max_x}, {"max_y", s.max_y}};
    j["extent_lonlat"] = {{"west", s.west}, {"south", s.south}, {"east", s.east}, {"north", s.north}};
  } else {
    j["extent_local_m"] = nullptr;
    j["extent_lonlat"] = nullptr;
  }
  j["semi_major_m"] = stats_json(s.semi_major_m);
  j["semi_minor_m"] = stats_json(s.semi_minor_m);
  j["footprint_area_m2"] = stats_json(s.footprint_area_m2);
  j["vertical"] = {
      {"height_above_seafloor", s.with_height}, {"top_depth", s.with_top_depth}, {"full_water_column", s.full_column}};
  auto& src = j["sources"] = nlohmann::json::array();
  for (const auto& info : s.sources) {
    src.push_back({{"path", info.path},
                   {"driver", info.driver},
                   {"crs", info.crs},
                   {"ellipses", info.ellipses},
                   {"polygons", info.polygons}});
  }
  return j;
}

namespace {

std::string stats_line(const RangeStats& r, const char* unit) {
  if (r.n == 0) return "-";
  return printf_text("min %.2f %s, mean %.2f %s, max %.2f %s", r.min, unit, r.mean, unit, r.max, unit);
}

}  // namespace

std::string to_text(const ObstacleSummary& s) {
  std::string t;
  for (const auto& src : s.sources) {
    t += src.path + "  [" + src.driver + ", " + src.crs + "]  " + std::to_string(src.ellipses) +
         " elliptical cylinder(s), " + std::to_string(src.polygons) + " polygon(s)\n";
  }
  t += printf_text("count            %zu (%zu elliptical cylinder(s), %zu polygon(s))\n", s.count, s.ellipses,
                   s.polygons);
  t += printf_text("local frame      %s (%s)\n", s.local_crs_id.c_str(), s.local_crs_name.c_str());
  if (s.has_extent) {
    t += printf_text("extent           lon %.6f .. %.6f, lat %.6f .. %.6f\n", s.west, s.east, s.south, s.north);
    t += printf_text("                 %.1f m x %.1f m (east x north)\n", s.max_x - s.min_x, s.max_y - s.min_y);
  }
  t += "semi-major axis  " + stats_line(s.semi_major_m, "m") + "\n";
  t += "semi-minor axis  " + stats_line(s.semi_minor_m, "m") + "\n";
  t += "footprint area   " + stats_line(s.footprint_area_m2, "m2") + "\n";
  t += printf_text("vertical         %zu height above sea floor, %zu top depth, %zu whole water column\n",
                   s.with_height, s.with_top_depth, s.full_column);
  return t;
}

}  // namespace deepguide
