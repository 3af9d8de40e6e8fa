#include "deepguide/obstacle_files/csv_positions.hpp"

#include <algorithm>
#include <cctype>

#include "deepguide/core/error.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide::gdal {

const std::vector<std::string>& csv_x_names() {
  static const std::vector<std::string> names = {"x", "lon", "long", "longitude", "easting"};
  return names;
}

const std::vector<std::string>& csv_y_names() {
  static const std::vector<std::string> names = {"y", "lat", "latitude", "northing"};
  return names;
}

const std::vector<std::string>& csv_geometry_names() {
  static const std::vector<std::string> names = {"wkt", "geometry", "geom"};
  return names;
}

std::string joined_names(const std::vector<std::string>& names, const char* separator) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

CsvPositionColumns csv_position_columns(const std::string& path) {
  const char* const drivers[] = {"CSV", nullptr};
  const GDALDatasetUniquePtr plain = open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers);
  if (!plain || plain->GetLayerCount() < 1) return {};
  const OGRFeatureDefn* defn = plain->GetLayer(0)->GetLayerDefn();
  std::vector<std::string> seen;
  for (int i = 0; i < defn->GetFieldCount(); ++i) {
    std::string name = defn->GetFieldDefn(i)->GetNameRef();
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    const auto first = std::find(seen.begin(), seen.end(), name);
    if (first != seen.end()) {
      throw InputError(path + ": line 1: expected each column once, got '" + printable(name) + "' as columns " +
                       std::to_string(first - seen.begin() + 1) + " and " + std::to_string(i + 1));
    }
    seen.push_back(name);
  }
  CsvPositionColumns columns;
  const auto pick = [&](const std::vector<std::string>& names, std::string& chosen) {
    std::vector<std::string> present;
    for (const std::string& n : seen) {
      if (std::find(names.begin(), names.end(), n) != names.end()) present.push_back(n);
    }
    if (present.size() > 1) {
      throw InputError(path + ": line 1: expected one column of " + joined_names(names, "/") + ", got " +
                       joined_names(present, " and ") + ": which one holds the coordinate is not known");
    }
    if (!present.empty()) chosen = present.front();
  };
  pick(csv_x_names(), columns.x);
  pick(csv_y_names(), columns.y);
  pick(csv_geometry_names(), columns.geometry);
  return columns;
}

std::vector<std::string> csv_open_options(const CsvPositionColumns& columns, bool keep_columns) {
  std::vector<std::string> options;
  if (!columns.geometry.empty()) {
    options.push_back("GEOM_POSSIBLE_NAMES=" + columns.geometry);
  } else if (columns.has_xy()) {
    options.push_back("X_POSSIBLE_NAMES=" + columns.x);
    options.push_back("Y_POSSIBLE_NAMES=" + columns.y);
  }
  options.push_back(std::string("KEEP_GEOM_COLUMNS=") + (keep_columns ? "YES" : "NO"));
  return options;
}

}  // namespace deepguide::gdal
