#pragma once
// Checks that a raster file holds everything its own header promises, where
// GDAL's drivers read a damaged file as data:
//
// - netCDF classic (CDF-1, CDF-2, CDF-5): the netCDF library reads the part
//   of a file cut short as zeros, silently (a bathymetry grid cut in half read
//   as "100 % valid" with half its depths 0; a HYCOM file cut to 20 kB gave
//   v = 0 everywhere). The header gives each variable's offset and shape, so
//   the file must reach the end of every variable.
// - ESRI ASCII grid: GDAL 3.6's reader, asked for a row past the end of a file
//   cut short, rescans and reports for ever (a cut small_crm.asc ran for more
//   than 600 s). The file must hold ncols x nrows numbers (as GDAL read them), each a whole number
//   token; a flipped byte that turns a digit into a letter is refused here.
//
// What no reader can see is listed in docs/RELIABILITY.md: a flipped byte in
// the data section of a format without checksums is a different, valid value.

#include <cstdint>
#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// InputError naming the file when a netCDF classic file is shorter than its
/// header says; other formats (netCDF-4 among them) pass.
void require_complete_netcdf(const std::string& path);

/// InputError naming the file and the line when an ESRI ASCII grid holds
/// other than `columns` x `rows` numbers (the size GDAL read from its
/// header), or a token that is not a number.
void require_complete_ascii_grid(const std::string& path, std::uint64_t columns, std::uint64_t rows);

}  // namespace deepguide
