#pragma once
// Sea-current fields: horizontal water velocity (u east, v north, m/s) from a
// NetCDF file (or any file GDAL opens as a multidimensional raster: HDF5,
// Zarr), from a two-band raster, or a constant current given on the command
// line; sampled in the local frame, fast, for route costs that integrate the
// ground speed along edges.
//
// Decisions (to be mirrored in docs/FORMATS.md):
// - Reading goes through GDAL only, once: the grid needed (every time step,
//   the one or two depth levels used) is loaded into memory as doubles and
//   sampling never calls GDAL. A field of more than
//   CurrentOptions::max_cells_per_step nodes (default 2^26) per time step, or
//   more than max_total_cells (default 2^28) over all steps, is refused: it
//   would need 16 bytes per node and step.
// - Multidimensional files: u and v are the root group's arrays named by the
//   options, else by CF standard_name (eastward_/northward_sea_water_velocity,
//   their surface_ variants, sea_water_x/y_velocity), else by a common name
//   (water_u/water_v, u/v, uo/vo, U/V, ucur/vcur). Raw values are read as
//   doubles; a value equal to _FillValue (or missing_value) or NaN is unknown;
//   the others become raw * scale_factor + add_offset.
// - Axes are told by the dimension's GDAL type, else by the axis variable's
//   attributes (axis, units, standard_name), else by name. Longitudes and
//   latitudes (units degrees_east / degrees_north, or standard_name
//   longitude / latitude) give EPSG:4326; otherwise the array's CRS
//   (grid_mapping) or CurrentOptions::assumed_crs; with none the read fails.
//   Axes may be descending (stored ascending here) or irregular (binary
//   search), but must be strictly monotonic. Other dimensions of size 1 are
//   taken at index 0.
// - Components are along the field CRS's axes: true east/north for lon/lat
//   fields (CF eastward/northward), grid easting/northing for projected
//   fields. CurrentSampler turns them into the local frame by the difference
//   of the directions of true north (meridian convergence), so a field in
//   the local frame's own CRS is not rotated at all.
// - Depth: CurrentOptions::depth_m (default 0, the surface), positive down
//   (a depth axis with positive=up or negative values is negated). Between
//   two levels u and v are interpolated linearly in depth; above the first
//   level the first level is used (HYCOM's first level is 0 m); deeper than
//   the last level is an error. A node unknown at either level used is
//   unknown (below the sea floor).
// - Time: a CF time axis ("UNITS since DATE [TIME][ZONE]", units seconds,
//   minutes, hours or days; gregorian/standard/proleptic_gregorian calendar)
//   becomes seconds since 1970-01-01T00:00:00Z (double). Between two steps u
//   and v are linear in time. A field with one step (or none) is steady: it
//   holds at any time, and that step's time is only reported. For a field
//   with two or more steps, a time outside [first, last] gives no value
//   (never a clamped one): the caller decides what to do beyond the forecast.
// - Space: bilinear between the four nodes around the point; a node is an
//   axis value (for a two-band raster: a pixel centre), so the field is
//   defined from the first to the last node, not to the outer cell edges.
//   At a node the stored value comes back exactly. If any of the nodes used
//   is unknown (land in HYCOM), the sample is std::nullopt, never a zero.
//   Longitudes wrap by 360 degrees into the field's range; a global field's
//   cell between its last and first longitude is not bridged.
// - Two-band rasters (GeoTIFF etc.): band 1 = u, band 2 = v, m/s, steady,
//   each band's NoData, scale and offset applied; north-up geotransform; CRS
//   from the file or the assumed one.
// - The constant current "SPEED_MPS,DIR_DEG" gives the direction the current
//   sets TOWARDS (oceanographic convention; a wind's is where it comes from),
//   degrees clockwise from true north: "1,90" flows east.
// - CurrentSampler maps local (x, y) to field coordinates through a lattice
//   of up to 256 x 256 exact OSR transforms over the field's extent (4 lattice
//   cells per field cell), interpolated bilinearly; the rotation (cos, sin of
//   the convergence) rides on the same lattice. Against the exact per-point
//   transform the HYCOM test field in UTM 18N differs by at most 3.5e-6 m/s.
//   A field in the local frame's CRS needs no lattice and is exact. About
//   0.1 us per sample (measured on the shared 2-core machine, 1e6 samples).
// - A classic-format NetCDF file shorter than its variables' bytes is refused:
//   the netCDF library would silently read the missing part as zeros. The
//   check is a lower bound (the header is not counted).

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/s57_chart.hpp"  // LonLatExtent

namespace deepguide {

struct CurrentOptions {
  /// Depth at which to take the current (m, positive down); 0 = surface.
  double depth_m = 0.0;
  /// Names of the u (east) and v (north) variables; empty = found by standard_name or common name.
  std::string u_variable;
  std::string v_variable;
  /// CRS for fields that carry none and have no lon/lat axes, e.g. "EPSG:32632"; empty = error.
  std::string assumed_crs;
  std::size_t max_cells_per_step = std::size_t{1} << 26;
  std::size_t max_total_cells = std::size_t{1} << 28;
};

/// A current field in its own CRS. Plain data; node (i, j) of step k sits at
/// u[(k * ny() + j) * nx() + i], x ascending with i, y ascending with j; NaN = unknown.
struct CurrentField {
  std::string source;      ///< the file, or e.g. "--current" for a constant
  std::string driver;      ///< GDAL short name ("netCDF", "GTiff"), or "constant"
  std::string u_name;      ///< variable or band that gave u
  std::string v_name;
  std::string crs;         ///< "EPSG:4326", "EPSG:32632", ...
  std::string crs_wkt;
  std::string crs_source;  ///< "CF lon/lat axes", "file", "assumed (option)"
  bool geographic = true;  ///< x = longitude, y = latitude (degrees)

  bool constant = false;                           ///< the same everywhere, always
  Eigen::Vector2d constant_velocity{0.0, 0.0};     ///< m/s, (east, north), when constant

  std::vector<double> x;        ///< node coordinates, strictly ascending
  std::vector<double> y;
  std::vector<double> times_s;  ///< seconds since the Unix epoch, ascending; 0 or 1 entries = steady
  std::vector<double> u;        ///< m/s, along the CRS's x axis
  std::vector<double> v;        ///< m/s, along the CRS's y axis

  double depth_m = 0.0;      ///< depth asked for
  std::string depth_levels;  ///< how it was taken, e.g. "level 1 of 40 (0 m)"
  LonLatExtent extent;       ///< of the nodes, WGS 84 (NaN for a constant)

  std::size_t nx() const { return x.size(); }
  std::size_t ny() const { return y.size(); }
  std::size_t steps() const { return constant ? 0 : (times_s.empty() ? 1 : times_s.size()); }
  bool steady() const { return times_s.size() < 2; }
};

/// Loads the field at `path`: a multidimensional file (NetCDF) with u/v
/// variables, else a two-band raster. Throws InputError (one line naming the
/// file) for a missing file, a file GDAL cannot open, no u/v variables (the
/// variables it has are listed), u/v of different shapes, no CRS and no
/// lon/lat axes, time units it cannot read, a depth below the deepest level,
/// and a field too large.
CurrentField load_current_field(const std::string& path, const CurrentOptions& options = {});

/// Parses "SPEED_MPS,DIR_DEG" given as `what` (e.g. "--current"): speed >= 0,
/// direction the current sets towards, clockwise from true north.
CurrentField parse_constant_current(const std::string& text, const std::string& what);

/// The velocity (m/s, along the field CRS's axes) at field coordinates
/// (x, y) and time; std::nullopt outside the nodes, outside a time-dependent
/// field's time axis, or where a node used is unknown. Exact at nodes and steps.
std::optional<Eigen::Vector2d> sample_native(const CurrentField& field, const Eigen::Vector2d& field_xy,
                                             double time_s);

/// A field bound to a local frame; sample() does no GDAL/OSR call (see the
/// header comment). Thread-safe for concurrent sample() calls.
class CurrentSampler {
 public:
  /// `area_min`/`area_max` (local metres) tell a constant field where its
  /// convergence lattice goes; outside it, and without it, a constant field's
  /// samples take the exact (slower, OSR) path. Gridded fields ignore them.
  CurrentSampler(std::shared_ptr<const CurrentField> field, const LocalFrame& frame,
                 const std::optional<Eigen::Vector2d>& area_min = std::nullopt,
                 const std::optional<Eigen::Vector2d>& area_max = std::nullopt);

  /// Velocity in the local frame (x east, y north of the frame's grid, m/s) at
  /// local xy and time (seconds since the Unix epoch; ignored when steady).
  std::optional<Eigen::Vector2d> sample(const Eigen::Vector2d& xy, double time_s) const;

  const CurrentField& field() const { return *field_; }

 private:
  struct Lattice;
  std::shared_ptr<const CurrentField> field_;
  LocalFrame frame_;
  std::shared_ptr<const Lattice> lattice_;  ///< null: the field is in the frame's CRS
};

/// What a work area holds of the field.
struct CurrentCoverage {
  std::size_t nodes = 0;       ///< nodes inside the area's bounding box in field coordinates
  std::size_t fill_nodes = 0;  ///< of those, unknown (at any step)
};

/// Checks that the field covers the local box [area_min, area_max] and, for a
/// time-dependent field, the interval [time_first_s, time_last_s] (NaN = no
/// check). Throws InputError "FILE: the current field covers lon A..B, lat
/// C..D (times ...); the work area lon .., lat .. is outside" when not. A
/// constant field covers everything.
CurrentCoverage check_current_coverage(const CurrentField& field, const LocalFrame& frame,
                                       const Eigen::Vector2d& area_min, const Eigen::Vector2d& area_max,
                                       double time_first_s = std::numeric_limits<double>::quiet_NaN(),
                                       double time_last_s = std::numeric_limits<double>::quiet_NaN());

/// For `deepguide chart info`: what a field holds.
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

}  // namespace deepguide
