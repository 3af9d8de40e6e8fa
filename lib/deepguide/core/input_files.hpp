#pragma once
// What an input path may be. A named pipe, socket or device is not a file a
// reader can take: GDAL and libxml2 wait on a FIFO for ever, and a device may
// never end.

#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Throws InputError "PATH: expected a file, got a named pipe (FIFO)" (or a
/// socket, a device) for such a path; returns for files, folders, paths that
/// do not exist (the reader says what it expected) and GDAL's /vsi... paths.
void refuse_special_file(const std::string& path);

}  // namespace deepguide
