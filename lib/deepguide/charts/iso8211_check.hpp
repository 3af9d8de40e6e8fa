#pragma once
// The structure of an S-57 file (ISO/IEC 8211), checked before GDAL reads it.
//
// GDAL's S57 reader takes a damaged cell or update as data where it can: a
// file cut short fails half-way and (for an update) is dropped with every
// later one; a flipped digit in a record's directory drops that feature; a
// flipped letter in a subfield label of the data descriptive record (the
// file's first record) drops every attribute of that field (measured on
// US5FL4DQ: "ATTL" damaged, and every depth area lost its depths and every
// zone of confidence its CATZOC); an update instruction other than insert,
// delete or modify is skipped (one wreck fewer in US4MD81M). Each is a
// one-line reason here. What stays out of reach is a flipped byte inside a
// value (a coordinate, an attribute): S-57 files carry no checksum of their
// own (the exchange set's CATALOG.031 holds CRCs; a lone cell has none).
//
// Checked: every record's leader (digits where ISO 8211 puts numbers, the
// leader identifier), its directory (digits, a field terminator at the end,
// each field inside the record and ending with a field terminator), the data
// descriptive record's subfield labels of the fields GDAL reads by name, and
// each feature and vector record's update instruction (RUIN: insert only in
// a base cell; insert, delete or modify in an update).

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Why the S-57 file at `path` cannot be read as one, or "" when its
/// structure is sound. `update`: the file is an update (*.001 ..), not a base cell.
std::string s57_structure_problem(const std::string& path, bool update);

/// One field of a data record: its tag and its bytes, without the field terminator.
struct Iso8211Field {
  std::string tag;
  std::string data;
};
using Iso8211Record = std::vector<Iso8211Field>;

/// Checks the file as s57_structure_problem does (as a base file) and hands
/// back its data records (every record after the data descriptive record).
/// Returns "" or why the file is not sound; `records` is then incomplete.
std::string read_iso8211_records(const std::string& path, std::vector<Iso8211Record>& records);

}  // namespace deepguide
