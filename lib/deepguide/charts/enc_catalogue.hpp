#pragma once
// An exchange set's catalogue, CATALOG.031 (IHO S-57 Edition 3.1, Part 3,
// 7.4.1 and Appendix B.1 5.3): the ISO 8211 file at the root of an ENC_ROOT
// that lists every file of the set, with a CATD field each:
// RCNM!RCID!FILE!LFIL!VOLM!IMPL!SLAT!WLON!NLAT!ELON!CRCS!COMT. FILE is the
// file's path from the catalogue's folder, with '\' between folders (S-57's
// separator); IMPL is "BIN" for cells and updates, "ASC" or "TXT" for text;
// CRCS is the file's CRC-32 (the one zlib computes) in hexadecimal, empty for
// the catalogue itself (NOAA drops leading zeros: C70EA4 for 00C70EA4).
//
// Decisions (docs/CHARTS.md, "Exchange sets"):
// - The cells and updates a catalogue lists are the ones read: a file the
//   catalogue lists but its folder lacks, and one whose CRC differs from the
//   catalogue's, is an error naming the file. Text files (NOAA's notes) are
//   not read, so they are not checked.
// - A file not listed is not read; an update beside a listed cell that the
//   catalogue does not list is an error (GDAL would apply it unchecked).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct EncCatalogueEntry {
  std::string file;                  ///< as listed, with '/' between folders (relative to the catalogue's folder)
  std::string path;                  ///< where it is: the catalogue's folder joined with `file`
  std::string impl;                  ///< "BIN", "ASC", "TXT", ...
  std::optional<std::uint32_t> crc;  ///< CRCS; none where the catalogue gives none
};

struct EncCatalogue {
  std::string path;  ///< the CATALOG.031 read
  std::vector<EncCatalogueEntry> entries;
};

/// True for a file named CATALOG.031 (any case).
bool is_enc_catalogue_name(const std::string& path);

/// Reads a catalogue. Throws InputError naming the file (and the record) for
/// a file that is not a sound ISO 8211 catalogue: no CATD records, a CATD
/// without FILE, a CRCS that is not up to 8 hexadecimal digits, a FILE that climbs
/// out of the catalogue's folder.
EncCatalogue read_enc_catalogue(const std::string& path);

/// The CRC-32 of a file's bytes (zlib's). Throws InputError naming the file when it cannot be read.
std::uint32_t file_crc32(const std::string& path);

/// Checks a listed file against its entry: it exists, and its CRC is the
/// catalogue's. Throws InputError naming the file and the catalogue.
void check_catalogue_entry(const EncCatalogue& catalogue, const EncCatalogueEntry& entry);

}  // namespace deepguide
