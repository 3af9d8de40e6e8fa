#include "deepguide/world/enc_cells.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/iso8211_check.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

bool is_base_cell_name(const fs::path& p) { return ascii_lower(p.extension().string()) == ".000"; }

// BASE.001 .. BASE.999: an update, which is read only with its base cell.
bool is_update_name(const fs::path& p) {
  const std::string ext = p.extension().string();
  return ext.size() == 4 && ext != ".000" &&
         std::all_of(ext.begin() + 1, ext.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The update number of BASE.NNN (1..999), or 0 when `p` is not an update of `stem`.
int update_number(const fs::path& p, const std::string& stem) {
  if (ascii_lower(p.stem().string()) != ascii_lower(stem)) return 0;
  const std::string ext = p.extension().string();
  if (ext.size() != 4 || !std::all_of(ext.begin() + 1, ext.end(), [](unsigned char c) { return std::isdigit(c); })) {
    return 0;
  }
  return std::stoi(ext.substr(1));
}

EncCellFiles with_updates(const fs::path& base) {
  EncCellFiles cell{base.string(), {}};
  if (const std::string why = s57_structure_problem(base.string(), false); !why.empty()) {
    throw InputError(printable(base.string(), 240) + ": expected an S-57 ENC cell (ISO 8211), got a file " + why);
  }
  std::map<int, fs::path> found;
  std::error_code ec;
  const fs::path dir = base.has_parent_path() ? base.parent_path() : fs::path(".");
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    if (const int n = update_number(entry.path(), base.stem().string()); n > 0) found.emplace(n, entry.path());
  }
  int expected = 1;
  for (const auto& [n, path] : found) {
    if (n != expected) {
      throw InputError(printable(path.string(), 240) + ": expected update " + std::to_string(expected) + " of " +
                       printable(base.string(), 240) + " before it, found none (the update sequence is broken)");
    }
    if (const std::string why = s57_structure_problem(path.string(), true); !why.empty()) {
      throw InputError(printable(path.string(), 240) + ": expected an intact S-57 update (ISO 8211) to apply to " +
                       printable(base.string(), 240) + ", got a file " + why);
    }
    cell.updates.push_back(path.string());
    ++expected;
  }
  return cell;
}

}  // namespace

bool names_enc(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) || is_base_cell_name(fs::path(path)) || is_update_name(fs::path(path));
}

std::vector<EncCellFiles> find_enc_cells(const std::vector<std::string>& paths) {
  // Keyed by the canonical path (each cell once), holding the path as the user spelled it.
  std::map<fs::path, fs::path> bases;
  for (const std::string& arg : paths) {
    std::error_code ec;
    if (!fs::exists(arg, ec)) {
      throw InputError(printable(arg, 240) + ": expected an S-57 cell (*.000) or a folder of cells, found nothing");
    }
    if (fs::is_directory(arg, ec)) {
      std::size_t here = 0;
      for (auto it = fs::recursive_directory_iterator(arg, fs::directory_options::skip_permission_denied, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_regular_file(ec) && is_base_cell_name(it->path())) {
          bases.emplace(fs::weakly_canonical(it->path(), ec), it->path());
          ++here;
        }
      }
      if (here == 0)
        throw InputError(printable(arg, 240) + ": expected a folder holding S-57 cells (*.000), found none");
      continue;
    }
    if (is_update_name(arg)) {
      fs::path base(arg);
      base.replace_extension(".000");
      throw InputError(printable(arg, 240) + ": expected an S-57 base cell (*.000), got an update; give " +
                       printable(base.filename().string(), 80) + " (its updates beside it are applied in order)");
    }
    if (!is_base_cell_name(arg)) {
      throw InputError(printable(arg, 240) +
                       ": expected an S-57 base cell named *.000 (updates *.001.. are found beside it)");
    }
    bases.emplace(fs::weakly_canonical(arg, ec), fs::path(arg));
  }
  std::vector<EncCellFiles> cells;
  for (const auto& [canonical, spelled] : bases) cells.push_back(with_updates(spelled));
  return cells;
}

}  // namespace deepguide
