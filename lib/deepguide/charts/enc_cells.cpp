#include "deepguide/charts/enc_cells.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>

#include "deepguide/charts/enc_catalogue.hpp"
#include "deepguide/charts/iso8211_check.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

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
  EncCellFiles cell{base.string(), {}, {}};
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

// The cells an exchange set's catalogue lists, each with its updates; every
// file checked against the catalogue's CRC.
std::vector<EncCellFiles> catalogued_cells(const std::string& catalogue_path) {
  const EncCatalogue cat = read_enc_catalogue(catalogue_path);
  std::vector<EncCellFiles> cells;
  for (const EncCatalogueEntry& e : cat.entries) {
    if (!is_base_cell_name(e.file)) continue;
    check_catalogue_entry(cat, e);
    EncCellFiles cell = with_updates(fs::path(e.path));
    cell.catalogue = catalogue_path;
    // Every update GDAL will apply (the files beside the cell) must be listed, and match.
    for (const std::string& u : cell.updates) {
      const auto listed = std::find_if(cat.entries.begin(), cat.entries.end(), [&](const EncCatalogueEntry& x) {
        std::error_code ec;
        return fs::equivalent(x.path, u, ec);
      });
      if (listed == cat.entries.end()) {
        throw InputError(printable(u, 240) + ": expected only the updates " + printable(catalogue_path, 240) +
                         " lists beside " + printable(e.path, 240) + ", got one it does not list");
      }
      check_catalogue_entry(cat, *listed);
    }
    // An update listed but not beside its cell is missing.
    for (const EncCatalogueEntry& x : cat.entries) {
      if (!is_update_name(x.file) || update_number(x.file, fs::path(e.file).stem().string()) == 0) continue;
      if (fs::path(x.file).parent_path() != fs::path(e.file).parent_path()) continue;
      check_catalogue_entry(cat, x);
    }
    cells.push_back(std::move(cell));
  }
  if (cells.empty()) {
    throw InputError(printable(catalogue_path, 240) +
                     ": expected an exchange set catalogue listing S-57 cells (*.000), got none");
  }
  return cells;
}

}  // namespace

bool names_enc(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) || is_base_cell_name(fs::path(path)) || is_update_name(fs::path(path)) ||
         is_enc_catalogue_name(path);
}

std::vector<EncCellFiles> find_enc_cells(const std::vector<std::string>& paths) {
  // Keyed by the canonical path (each cell once), holding the cell as the user spelled it.
  std::map<fs::path, EncCellFiles> cells;
  std::map<fs::path, fs::path> bases;
  auto add_catalogue = [&](const fs::path& catalogue) {
    std::error_code ec;
    for (EncCellFiles& c : catalogued_cells(catalogue.string())) {
      cells.emplace(fs::weakly_canonical(c.base, ec), std::move(c));
    }
  };
  for (const std::string& arg : paths) {
    std::error_code ec;
    if (!fs::exists(arg, ec)) {
      throw InputError(printable(arg, 240) + ": expected an S-57 cell (*.000) or a folder of cells, found nothing");
    }
    if (fs::is_directory(arg, ec)) {
      // Exchange sets (folders with a catalogue) give their listed cells; a search the rest.
      std::vector<fs::path> catalogues, found;
      for (auto it = fs::recursive_directory_iterator(arg, fs::directory_options::skip_permission_denied, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file(ec)) continue;
        if (is_enc_catalogue_name(it->path().string())) catalogues.push_back(it->path());
        if (is_base_cell_name(it->path())) found.push_back(it->path());
      }
      const auto under_catalogue = [&](const fs::path& cell) {
        return std::any_of(catalogues.begin(), catalogues.end(), [&](const fs::path& c) {
          const fs::path rel = cell.lexically_relative(c.parent_path());
          return !rel.empty() && *rel.begin() != "..";
        });
      };
      for (const fs::path& c : catalogues) add_catalogue(c);
      std::size_t searched = 0;
      for (const fs::path& b : found) {
        if (under_catalogue(b)) continue;
        bases.emplace(fs::weakly_canonical(b, ec), b);
        ++searched;
      }
      if (catalogues.empty() && searched == 0)
        throw InputError(printable(arg, 240) + ": expected a folder holding S-57 cells (*.000), found none");
      continue;
    }
    if (is_enc_catalogue_name(arg)) {
      add_catalogue(arg);
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
  for (const auto& [canonical, spelled] : bases) {
    if (!cells.count(canonical)) cells.emplace(canonical, with_updates(spelled));
  }
  std::vector<EncCellFiles> out;
  for (auto& [canonical, cell] : cells) out.push_back(std::move(cell));
  return out;
}

}  // namespace deepguide
