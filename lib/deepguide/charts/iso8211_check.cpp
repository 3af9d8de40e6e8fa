#include "deepguide/charts/iso8211_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <string_view>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/core/input_files.hpp"

namespace deepguide {

namespace {

constexpr char kFieldTerminator = 0x1e;
constexpr char kUnitTerminator = 0x1f;

// Subfield labels of the fields GDAL's S57 reader reads by name, as S-57
// Edition 3.1 (Part 3) defines them; checked where a file's data descriptive
// record describes the field. Formats are not compared: writers spell the
// same binary format in more than one way (GDAL writes "(b11,b12,b12)" where
// NOAA writes "(b11,2b12)").
const std::map<std::string_view, std::string_view>& standard_labels() {
  static const std::map<std::string_view, std::string_view> labels = {
      {"VRID", "RCNM!RCID!RVER!RUIN"},
      {"ATTV", "*ATTL!ATVL"},
      {"VRPC", "VPUI!VPIX!NVPT"},
      {"VRPT", "*NAME!ORNT!USAG!TOPI!MASK"},
      {"SGCC", "CCUI!CCIX!CCNC"},
      {"SG2D", "*YCOO!XCOO"},
      {"SG3D", "*YCOO!XCOO!VE3D"},
      {"FRID", "RCNM!RCID!PRIM!GRUP!OBJL!RVER!RUIN"},
      {"FOID", "AGEN!FIDN!FIDS"},
      {"ATTF", "*ATTL!ATVL"},
      {"NATF", "*ATTL!ATVL"},
      {"FFPC", "FFUI!FFIX!NFPT"},
      {"FFPT", "*LNAM!RIND!COMT"},
      {"FSPC", "FSUI!FSIX!NSPT"},
      {"FSPT", "*NAME!ORNT!USAG!MASK"},
      // The exchange set's catalogue (CATALOG.031; S-57 Part 3, 7.4.1).
      {"CATD", "RCNM!RCID!FILE!LFIL!VOLM!IMPL!SLAT!WLON!NLAT!ELON!CRCS!COMT"},
  };
  return labels;
}

bool digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::uint64_t number(std::string_view s) {
  std::uint64_t v = 0;
  for (const char c : s) v = v * 10 + static_cast<std::uint64_t>(c - '0');
  return v;
}

struct Field {
  std::string_view tag, data;  // data ends with its field terminator
};

// One record's fields, or the reason it is not a record. `first`: the data
// descriptive record, whose leader differs from the data records'.
std::string read_record(std::string_view rec, bool first, std::vector<Field>& fields) {
  fields.clear();
  const std::string_view leader = rec.substr(0, 24);
  const char id = leader[6];
  if (first ? id != 'L' : (id != 'D' && id != 'R')) return "a leader identifier '" + std::string(1, id) + "'";
  if (!digits(leader.substr(12, 5)) || !digits(leader.substr(20, 2)) || !digits(leader.substr(23, 1)) ||
      (first && !digits(leader.substr(10, 2)))) {
    return "a leader with a letter where ISO 8211 puts a number";
  }
  const std::uint64_t base = number(leader.substr(12, 5));
  const std::size_t len_size = static_cast<std::size_t>(leader[20] - '0');
  const std::size_t pos_size = static_cast<std::size_t>(leader[21] - '0');
  const std::size_t tag_size = static_cast<std::size_t>(leader[23] - '0');
  const std::size_t entry = tag_size + len_size + pos_size;
  if (len_size == 0 || pos_size == 0 || tag_size == 0 || base < 25 || base > rec.size() ||
      rec[base - 1] != kFieldTerminator || (base - 25) % entry != 0) {
    return "a directory that does not end where the leader says";
  }
  for (std::size_t at = 24; at + entry <= base - 1; at += entry) {
    const std::string_view len = rec.substr(at + tag_size, len_size),
                           pos = rec.substr(at + tag_size + len_size, pos_size);
    if (!digits(len) || !digits(pos)) return "a directory entry with a letter where its length or position goes";
    const std::uint64_t l = number(len), p = number(pos);
    if (l == 0 || base + p + l > rec.size() || rec[base + p + l - 1] != kFieldTerminator) {
      return "a field (" + std::string(rec.substr(at, tag_size)) + ") that does not end with a field terminator";
    }
    fields.push_back({rec.substr(at, tag_size), rec.substr(base + p, l)});
  }
  return "";
}

// The data descriptive record: each field GDAL reads by name must carry the
// standard subfield labels (after its 9 field controls and its name).
std::string check_descriptions(const std::vector<Field>& fields) {
  for (const Field& f : fields) {
    const auto it = standard_labels().find(f.tag);
    if (it == standard_labels().end()) continue;
    const std::string_view body = f.data.substr(std::min<std::size_t>(9, f.data.size()));
    const std::size_t a = body.find(kUnitTerminator);
    const std::size_t b = a == std::string_view::npos ? a : body.find(kUnitTerminator, a + 1);
    if (b == std::string_view::npos) return "a description of field " + std::string(f.tag) + " without its labels";
    const std::string_view labels = body.substr(a + 1, b - a - 1);
    if (labels != it->second) {
      return "field " + std::string(f.tag) + " described with labels '" + printable(std::string(labels), 60) +
             "' where S-57 has '" + std::string(it->second) + "'";
    }
  }
  return "";
}

// The update instruction of a feature (FRID, byte 11) or vector (VRID, byte 7) record.
std::string check_instruction(const std::vector<Field>& fields, bool update) {
  for (const Field& f : fields) {
    std::size_t at = 0;
    if (f.tag == "FRID")
      at = 11;
    else if (f.tag == "VRID")
      at = 7;
    else
      continue;
    if (f.data.size() <= at) return "a " + std::string(f.tag) + " field too short for its update instruction";
    const auto ruin = static_cast<unsigned char>(f.data[at]);
    if (update ? (ruin < 1 || ruin > 3) : ruin != 1) {
      return "a " + std::string(f.tag) + " record with update instruction " + std::to_string(ruin) +
             (update ? " (S-57 has 1 insert, 2 delete, 3 modify)" : " in a base cell (S-57 has 1, insert)");
    }
  }
  return "";
}

// A record longer than 99 999 bytes has "00000" for its length (ISO 8211
// C.1.5.1; GDAL reads such records, a long SG2D edge of a real cell): its
// length is where its last field ends, as the directory says. 0 when the
// leader or directory cannot say.
std::uint64_t long_record_length(std::string_view rest) {
  if (rest.size() < 24) return 0;
  const std::string_view leader = rest.substr(0, 24);
  if (!digits(leader.substr(12, 5)) || !digits(leader.substr(20, 2)) || !digits(leader.substr(23, 1))) return 0;
  const std::uint64_t base = number(leader.substr(12, 5));
  const std::size_t len_size = static_cast<std::size_t>(leader[20] - '0');
  const std::size_t pos_size = static_cast<std::size_t>(leader[21] - '0');
  const std::size_t entry = static_cast<std::size_t>(leader[23] - '0') + len_size + pos_size;
  if (len_size == 0 || pos_size == 0 || entry == 0 || base < 25 || base > rest.size()) return 0;
  std::uint64_t end = base;
  for (std::size_t at = 24; at + entry <= base - 1; at += entry) {
    const std::string_view len = rest.substr(at + entry - len_size - pos_size, len_size);
    const std::string_view field_pos = rest.substr(at + entry - pos_size, pos_size);
    if (!digits(len) || !digits(field_pos)) return 0;
    end = std::max(end, base + number(field_pos) + number(len));
  }
  return end;
}

// The structure check of s57_structure_problem, keeping the data records when `records` is given.
std::string check_file(const std::string& path, bool update, std::vector<Iso8211Record>* records) {
  refuse_special_file(path);  // before opening it: a FIFO would block the open, a device never end
  std::ifstream in(path, std::ios::binary);
  if (!in) return "that could not be opened";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty()) return "that is empty";
  std::vector<Field> fields;
  std::vector<std::string> defined;  // the tags the data descriptive record describes
  std::size_t pos = 0;
  for (bool first = true; pos < bytes.size(); first = false) {
    const std::string at = " at byte " + std::to_string(pos);
    if (bytes.size() - pos < 24) return "cut short" + at;
    const std::string_view length = std::string_view(bytes).substr(pos, 5);
    if (!digits(length)) return "with no ISO 8211 record" + at;
    std::uint64_t n = number(length);
    if (n == 0) n = long_record_length(std::string_view(bytes).substr(pos));
    if (n < 24 || pos + n > bytes.size()) return "cut short in the record" + at;
    const std::string_view rec = std::string_view(bytes).substr(pos, n);
    std::string why = read_record(rec, first, fields);
    if (why.empty()) why = first ? check_descriptions(fields) : check_instruction(fields, update);
    if (why.empty() && first) {
      for (const Field& f : fields) defined.emplace_back(f.tag);
    } else if (why.empty()) {
      // Every field a data record holds must be one the descriptions define
      // (a flipped tag made GDAL stop applying an update half-way).
      for (const Field& f : fields) {
        if (std::find(defined.begin(), defined.end(), f.tag) == defined.end()) {
          why = "a field tag '" + printable(std::string(f.tag), 16) + "' its descriptions do not define";
          break;
        }
      }
    }
    if (!why.empty()) return "with " + why + at;
    if (records != nullptr && !first) {
      Iso8211Record& r = records->emplace_back();
      for (const Field& f : fields) r.push_back({std::string(f.tag), std::string(f.data.substr(0, f.data.size() - 1))});
    }
    pos += n;
  }
  return "";
}

}  // namespace

std::string s57_structure_problem(const std::string& path, bool update) { return check_file(path, update, nullptr); }

std::string read_iso8211_records(const std::string& path, std::vector<Iso8211Record>& records) {
  records.clear();
  return check_file(path, false, &records);
}

}  // namespace deepguide
