#pragma once
// What a current field holds: its grid, times, depth taken, and the range of
// its values (the Python module's CurrentField.summary(); the cost model
// takes its fastest current).

#include <cstddef>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/currents/current_field.hpp"

namespace DEEPGUIDE_API deepguide {

/// What a field holds.
struct CurrentSummary {
  std::string source;
  std::string driver;
  std::string crs;
  std::string crs_source;
  std::string u_name;
  std::string v_name;
  std::size_t width = 0;   ///< nodes along x
  std::size_t height = 0;  ///< nodes along y
  std::size_t steps = 0;
  LonLatExtent extent;
  double time_first_s = std::numeric_limits<double>::quiet_NaN();
  double time_last_s = std::numeric_limits<double>::quiet_NaN();
  double depth_m = 0.0;
  std::string depth_levels;
  std::size_t valid_nodes = 0;  ///< node-steps with u and v known
  std::size_t fill_nodes = 0;
  double min_speed_mps = std::numeric_limits<double>::quiet_NaN();
  double max_speed_mps = std::numeric_limits<double>::quiet_NaN();
  double u_min = std::numeric_limits<double>::quiet_NaN();
  double u_max = std::numeric_limits<double>::quiet_NaN();
  double v_min = std::numeric_limits<double>::quiet_NaN();
  double v_max = std::numeric_limits<double>::quiet_NaN();
};

CurrentSummary summarize_current(const CurrentField& field);

/// The summary's fields under their names; times as ISO 8601 UTC too
/// ("time_first", "time_last"); what is unknown (NaN) as null.
nlohmann::json to_json(const CurrentSummary& summary);

}  // namespace deepguide
