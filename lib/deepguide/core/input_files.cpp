#include "deepguide/core/input_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>

#include "deepguide/core/error.hpp"

namespace deepguide {

void refuse_special_file(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.rfind("/vsi", 0) == 0) return;
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  const char* got = type == fs::file_type::fifo                                        ? "a named pipe (FIFO)"
                    : type == fs::file_type::socket                                    ? "a socket"
                    : type == fs::file_type::character || type == fs::file_type::block ? "a device"
                                                                                       : nullptr;
  if (got != nullptr) throw InputError(printable(path) + ": expected a file, got " + got);
  if (type != fs::file_type::regular) return;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  static const std::set<std::string> text = {".csv", ".gpx", ".kml", ".geojson", ".json",
                                             ".rtz", ".xml", ".txt", ".asc"};
  if (!text.count(ext)) return;
  unsigned char bom[4] = {1, 1, 1, 1};
  std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(bom), 4);
  const char* encoding = bom[0] == 0xFF && bom[1] == 0xFE && bom[2] == 0 && bom[3] == 0   ? "UTF-32 (little-endian)"
                         : bom[0] == 0 && bom[1] == 0 && bom[2] == 0xFE && bom[3] == 0xFF ? "UTF-32 (big-endian)"
                         : bom[0] == 0xFF && bom[1] == 0xFE                               ? "UTF-16 (little-endian)"
                         : bom[0] == 0xFE && bom[1] == 0xFF                               ? "UTF-16 (big-endian)"
                                                                                          : nullptr;
  if (encoding != nullptr) {
    throw InputError(printable(path) + ": expected UTF-8 text, got " + encoding +
                     " (its byte-order mark): save it as UTF-8");
  }
}

}  // namespace deepguide
