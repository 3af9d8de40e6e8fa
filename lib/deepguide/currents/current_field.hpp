#pragma once
// Sea-current fields read: horizontal water velocity (u east, v north, m/s)
// from a NetCDF file (or any file GDAL opens as a multidimensional raster:
// HDF5, Zarr), from a two-band raster, or a constant current given on the
// command line. Sampling them in the local frame: current_sampling.hpp; what
// a field holds: current_summary.hpp.
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
//   (never a clamped one): the caller decides what to do beyond the forecast
//   (current_sampling.hpp).
// - Two-band rasters (GeoTIFF etc.): band 1 = u, band 2 = v, m/s, steady,
//   each band's NoData, scale and offset applied; north-up geotransform; CRS
//   from the file or the assumed one.
// - The constant current "SPEED_MPS,DIR_DEG" gives the direction the current
//   sets TOWARDS (oceanographic convention; a wind's is where it comes from),
//   degrees clockwise from true north: "1,90" flows east.
// - A classic-format NetCDF file shorter than its variables' bytes is refused:
//   the netCDF library would silently read the missing part as zeros. The
//   check is a lower bound (the header is not counted).

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

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
  std::string source;  ///< the file, or e.g. "--current" for a constant
  std::string driver;  ///< GDAL short name ("netCDF", "GTiff"), or "constant"
  std::string u_name;  ///< variable or band that gave u
  std::string v_name;
  std::string crs;  ///< "EPSG:4326", "EPSG:32632", ...
  std::string crs_wkt;
  std::string crs_source;  ///< "CF lon/lat axes", "file", "assumed (option)"
  bool geographic = true;  ///< x = longitude, y = latitude (degrees)

  bool constant = false;                        ///< the same everywhere, always
  Eigen::Vector2d constant_velocity{0.0, 0.0};  ///< m/s, (east, north), when constant

  std::vector<double> x;  ///< node coordinates, strictly ascending
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

}  // namespace deepguide
