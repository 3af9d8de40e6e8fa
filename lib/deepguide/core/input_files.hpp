#pragma once
// What an input path may be. A named pipe, socket or device is not a file a
// reader can take: GDAL and libxml2 wait on a FIFO for ever, and a device may
// never end. A text file in UTF-16 or UTF-32 (as some Windows editors save
// CSV and GPX) is one GDAL's text drivers do not read, and say nothing of why.

#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Throws InputError "PATH: expected a file, got a named pipe (FIFO)" (or a
/// socket, a device) for such a path, and "PATH: expected UTF-8 text, got
/// UTF-16 ..." for a text format's file (.csv, .gpx, .kml, .geojson, .json,
/// .rtz, .xml, .txt, .asc) that starts with a UTF-16 or UTF-32 byte-order
/// mark; returns for other files, folders, paths that do not exist (the reader
/// says what it expected) and GDAL's /vsi... paths.
void refuse_special_file(const std::string& path);

}  // namespace deepguide
