#pragma once
// Library-internal: what the current field's readers share
// (current_field.cpp reads two-band rasters and chooses the reader,
// current_multidim.cpp reads NetCDF, HDF5 and Zarr arrays). Not installed:
// it names GDAL's types.

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/currents/current_field.hpp"

namespace deepguide::current_detail {

// An axis stored ascending; `reversed` when the file had it descending.
struct Axis {
  std::vector<double> values;
  bool reversed = false;
};

/// The values ascending (reversed when the file has them descending); an
/// InputError naming `path` and the axis `name` when they are not monotonic.
Axis ascending_axis(std::vector<double> values, const std::string& path, const std::string& name);

/// Raw values to m/s: fill and missing values (compared as float32 where the
/// data are) become NaN, then scale and offset.
struct Unpack {
  bool has_fill = false;
  double fill = 0;
  bool has_missing = false;
  double missing = 0;
  bool float32 = false;
  double scale = 1;
  double offset = 0;

  bool same(double v, double f) const { return v == f || (float32 && static_cast<float>(v) == static_cast<float>(f)); }
  double operator()(double raw) const {
    if (std::isnan(raw) || (has_fill && same(raw, fill)) || (has_missing && same(raw, missing)))
      return std::numeric_limits<double>::quiet_NaN();
    return raw * scale + offset;
  }
};

/// `s` without leading and trailing white space.
std::string trim(const std::string& s);

void set_extent(CurrentField& f, const OGRSpatialReference& srs);
void set_crs(CurrentField& f, const OGRSpatialReference& srs, const std::string& source);
/// Refuses a field larger than the options allow (per step and in all).
void check_size(const std::string& path, std::size_t nx, std::size_t ny, std::size_t steps, const CurrentOptions& o);

/// A field of u/v arrays in a multidimensional file (NetCDF, HDF5, Zarr).
CurrentField load_multidim(GDALDataset& ds, const std::string& path, const CurrentOptions& options);

}  // namespace deepguide::current_detail
