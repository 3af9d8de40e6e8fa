#pragma once
// Which S-57 cells a chart argument names, and whether each cell's update
// files form an unbroken sequence.
//
// Decisions (docs/CHARTS.md, "Cells and updates"):
// - A chart argument is a cell file (*.000, any case) or a folder; a folder
//   is searched recursively for *.000 files. A folder without one is an
//   error, as is a file named *.000 that the S57 driver does not open (the
//   reader reports that).
// - Updates are the files BASE.001, BASE.002, ... beside the base cell (same
//   stem, any case). They must run 1, 2, ..., N without a gap: a missing
//   number is an error naming the first file past the gap. Each must be a
//   whole ISO 8211 file (its records' lengths add up to its size): one cut
//   short is an error naming it, before GDAL sees it. GDAL applies the
//   sequence when the cell is opened; the reader then checks that the cell's
//   DSID_UPDN reached N (a damaged update stops GDAL's sequence silently).
// - Cells are returned sorted by path, each once (a cell named twice, or
//   found in a folder and named too, is read once).
// - Exchange sets: a folder holding a CATALOG.031 (an ENC_ROOT) gives the
//   cells and updates its catalogue lists, each checked against the
//   catalogue's CRC (enc_catalogue.hpp), instead of those a search finds
//   there. A catalogue may also be named itself.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct EncCellFiles {
  std::string base;                  ///< the base cell, *.000
  std::vector<std::string> updates;  ///< BASE.001 .. BASE.N in order
  std::string catalogue;             ///< the CATALOG.031 that listed them, "" when found by a search
};

/// True for a folder or a file whose extension is .000 (any case) or an
/// update's (.001 .. .999): an argument that must be read as S-57 whatever
/// GDAL thinks of it (an update alone is then refused naming its base).
bool names_enc(const std::string& path);

/// Expands files and folders into base cells with their updates. Throws
/// InputError (one line naming the path) for a missing path, a folder
/// without cells, a file that is not named *.000, or a gap in the updates;
/// in an exchange set, for a damaged catalogue, a catalogue without cells, a
/// listed file that is missing or whose CRC differs, or an update beside a
/// listed cell that the catalogue does not list.
std::vector<EncCellFiles> find_enc_cells(const std::vector<std::string>& paths);

}  // namespace deepguide
