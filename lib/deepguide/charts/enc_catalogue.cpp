#include "deepguide/charts/enc_catalogue.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "deepguide/charts/iso8211_check.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/input_files.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

constexpr char kUnitTerminator = 0x1f;
// CATD's subfields in order; FILE, IMPL and CRCS are the ones read.
constexpr std::size_t kFile = 2, kImpl = 5, kCrcs = 10, kSubfields = 12;

std::string shown(const std::string& path) { return printable(path, 240); }

// CATD's data in the format S-57 gives it, (A(2),I(10),3A,A(3),4R,2A):
// RCNM and RCID fixed width, FILE, LFIL and VOLM each ended by a unit
// terminator, IMPL three characters with none, then SLAT, WLON, NLAT, ELON,
// CRCS and COMT each ended by one.
std::vector<std::string> subfields(const std::string& data) {
  std::vector<std::string> out;
  if (data.size() < 12) return out;
  out.push_back(data.substr(0, 2));
  out.push_back(data.substr(2, 10));
  std::size_t at = 12;
  while (at < data.size() && out.size() < kSubfields) {
    if (out.size() == kImpl) {
      out.push_back(data.substr(at, 3));
      at += 3;
      continue;
    }
    const std::size_t end = data.find(kUnitTerminator, at);
    out.push_back(data.substr(at, end == std::string::npos ? std::string::npos : end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return out;
}

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
  return s.substr(i);
}

}  // namespace

bool is_enc_catalogue_name(const std::string& path) {
  return ascii_lower(fs::path(path).filename().string()) == "catalog.031";
}

EncCatalogue read_enc_catalogue(const std::string& path) {
  refuse_special_file(path);
  std::vector<Iso8211Record> records;
  if (const std::string why = read_iso8211_records(path, records); !why.empty()) {
    throw InputError(shown(path) + ": expected an exchange set catalogue (ISO 8211), got a file " + why);
  }
  EncCatalogue cat;
  cat.path = path;
  const fs::path root = fs::path(path).parent_path();
  for (std::size_t r = 0; r < records.size(); ++r) {
    const auto field =
        std::find_if(records[r].begin(), records[r].end(), [](const Iso8211Field& f) { return f.tag == "CATD"; });
    if (field == records[r].end()) continue;
    const std::string where = shown(path) + ": record " + std::to_string(r + 2) + " (CATD)";
    const std::vector<std::string> sub = subfields(field->data);
    if (sub.size() <= kFile || trimmed(sub[kFile]).empty()) {
      throw InputError(where + ": expected a FILE subfield naming a file of the set, got none");
    }
    EncCatalogueEntry e;
    e.file = trimmed(sub[kFile]);
    std::replace(e.file.begin(), e.file.end(), '\\', '/');
    const fs::path rel = fs::path(e.file).lexically_normal();
    if (rel.is_absolute() || rel.empty() || *rel.begin() == "..") {
      throw InputError(where + ": expected a FILE inside the catalogue's folder, got '" + printable(e.file, 120) + "'");
    }
    e.path = (root / rel).string();
    if (sub.size() > kImpl) e.impl = trimmed(sub[kImpl]);
    const std::string crc = sub.size() > kCrcs ? trimmed(sub[kCrcs]) : std::string();
    if (!crc.empty()) {
      // NOAA writes the CRC without its leading zeros (US5AK5QF: C70EA4 for 00C70EA4).
      const bool hex =
          crc.size() <= 8 && std::all_of(crc.begin(), crc.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
      if (!hex) {
        throw InputError(where + ": expected CRCS, the CRC-32 of " + printable(e.file, 120) +
                         ", as up to 8 hexadecimal digits, got '" + printable(crc, 20) + "'");
      }
      e.crc = static_cast<std::uint32_t>(std::stoul(crc, nullptr, 16));
    }
    cat.entries.push_back(std::move(e));
  }
  if (cat.entries.empty()) {
    throw InputError(shown(path) + ": expected an exchange set catalogue listing its files (CATD records), got none");
  }
  return cat;
}

std::uint32_t file_crc32(const std::string& path) {
  refuse_special_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(shown(path) + ": expected a readable file, could not open it");
  uLong crc = crc32(0L, Z_NULL, 0);
  std::vector<char> buf(1 << 16);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const std::streamsize n = in.gcount();
    if (n > 0) crc = crc32(crc, reinterpret_cast<const Bytef*>(buf.data()), static_cast<uInt>(n));
  }
  if (in.bad()) throw InputError(shown(path) + ": expected a readable file, reading it failed");
  return static_cast<std::uint32_t>(crc);
}

void check_catalogue_entry(const EncCatalogue& catalogue, const EncCatalogueEntry& entry) {
  std::error_code ec;
  if (!fs::is_regular_file(entry.path, ec)) {
    throw InputError(shown(entry.path) + ": expected the file " + shown(catalogue.path) + " lists, found " +
                     (fs::exists(entry.path, ec) ? "something else" : "none"));
  }
  if (!entry.crc) return;
  const std::uint32_t got = file_crc32(entry.path);
  if (got != *entry.crc) {
    throw InputError(shown(entry.path) + ": expected CRC-32 " + printf_text("%08X", *entry.crc) + " as " +
                     shown(catalogue.path) + " lists, got " + printf_text("%08X", got) +
                     " (the file differs from the one the exchange set shipped)");
  }
}

}  // namespace deepguide
