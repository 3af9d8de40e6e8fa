#pragma once
// Where a CSV keeps its positions (library-internal): a geometry column
// (WKT), coordinate columns (x/lon, y/lat), or both. The obstacle and route
// readers share the column names and the header's checks, so a CSV that one
// reads the other reads the same way.

#include <string>
#include <vector>

namespace deepguide::gdal {

/// The column names GDAL is told to take coordinates from, lower case.
const std::vector<std::string>& csv_x_names();         ///< x, lon, long, longitude, easting
const std::vector<std::string>& csv_y_names();         ///< y, lat, latitude, northing
const std::vector<std::string>& csv_geometry_names();  ///< wkt, geometry, geom

/// The position columns a CSV's header names (lower case; empty when absent).
struct CsvPositionColumns {
  std::string x, y, geometry;
  bool has_xy() const { return !x.empty() && !y.empty(); }
};

/// Reads the header (GDAL's CSV driver, no coordinate options). InputError
/// naming line 1 for a column named twice, or two columns of one coordinate
/// ("x" and "lon"): GDAL would take one of them without a word (and its CSV
/// driver crashed on such a header: fuzz/fuzz_obstacles_csv). A file the
/// driver cannot read gives no columns; the real open says what is wrong.
CsvPositionColumns csv_position_columns(const std::string& path);

/// GDAL open options that take the positions from `columns`: the geometry
/// column when there is one, else the coordinate columns. `keep_columns`
/// keeps the columns a geometry was made from as fields too.
std::vector<std::string> csv_open_options(const CsvPositionColumns& columns, bool keep_columns);

/// "a/b/c" or "a, b, c": names joined by `separator`.
std::string joined_names(const std::vector<std::string>& names, const char* separator);

}  // namespace deepguide::gdal
