// Exchange sets (enc_catalogue.hpp, enc_cells.hpp): the Kachemak set's
// ENC_ROOT folders are read through their CATALOG.031 files, every file
// checked against the catalogue's CRC-32. The facts the tests compare with
// come from the catalogue's raw bytes (the file names between unit
// terminators) and from zlib, not from the reader; the hostile catalogues are
// written here byte by byte in ISO 8211.

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

#include "deepguide/charts/enc_catalogue.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/core/error.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::run_cli;
using test::ScratchDir;
const auto expect_one_line = test::expect_error;

const char* const kKachemak = "noaa-enc-kachemak";
const char* const kSeldoviaRoot = "noaa-enc-kachemak/US5AK5QG_ENC_ROOT";

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& p, const std::string& b) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << b;
}

// The *.000 names a catalogue's bytes hold (each between unit terminators).
std::set<std::string> cell_names_in(const fs::path& catalogue) {
  std::set<std::string> names;
  const std::string b = bytes_of(catalogue);
  std::size_t at = 0;
  while ((at = b.find(".000", at)) != std::string::npos) {
    std::size_t start = at;
    while (start > 0 && b[start - 1] != '\x1f' && b[start - 1] != '\x1e' && b[start - 1] != '\\') --start;
    names.insert(b.substr(start, at + 4 - start));
    at += 4;
  }
  return names;
}

// A copy of one ENC_ROOT in a scratch folder (writable, unlike shared/).
fs::path copy_root(const std::string& root, const fs::path& into) {
  const fs::path dst = into / fs::path(root).filename();
  fs::copy(root, dst, fs::copy_options::recursive);
  for (const auto& e : fs::recursive_directory_iterator(dst)) {
    fs::permissions(e.path(), fs::perms::owner_write, fs::perm_options::add);
  }
  fs::permissions(dst, fs::perms::owner_write, fs::perm_options::add);
  return dst;
}

// One ISO 8211 data record with the fields given (tag, data without its
// terminator), in the layout NOAA's catalogues use (leader entry map 5504).
std::string data_record(const std::vector<std::pair<std::string, std::string>>& fields) {
  std::string dir, area;
  for (const auto& [tag, data] : fields) {
    char entry[32];
    std::snprintf(entry, sizeof entry, "%s%05zu%05zu", tag.c_str(), data.size() + 1, area.size());
    dir += entry;
    area += data + '\x1e';
  }
  dir += '\x1e';
  const std::size_t base = 24 + dir.size();
  char leader[32];
  std::snprintf(leader, sizeof leader, "%05zu D     %05zu   5504", base + area.size(), base);
  return std::string(leader) + dir + area;
}

// A catalogue listing `entries` (FILE, IMPL, CRCS): the real set's data
// descriptive record, then one CATD record each.
std::string catalogue_bytes(const std::string& real_catalogue,
                            const std::vector<std::tuple<std::string, std::string, std::string>>& entries) {
  const std::string real = bytes_of(real_catalogue);
  const std::string ddr = real.substr(0, static_cast<std::size_t>(std::stoi(real.substr(0, 5))));
  std::string out = ddr;
  int rcid = 1;
  for (const auto& [file, impl, crc] : entries) {
    char head[16];
    std::snprintf(head, sizeof head, "CD%010d", rcid);
    const std::string us(1, '\x1f');
    std::string catd = head + file + us + us + "V01X01" + us + impl + us + us + us + us + crc + us + us;
    char id[16];
    std::snprintf(id, sizeof id, "%05d", rcid);
    out += data_record({{"0001", id}, {"CATD", catd}});
    ++rcid;
  }
  return out;
}

std::string crc_hex(const std::string& bytes) {
  const uLong c =
      crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size()));
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08lX", c);
  return hex;
}

TEST(EncCatalogue, KachemakCellsAreTheCataloguesCells) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(set, kKachemak);
  std::set<std::string> listed;
  std::size_t catalogues = 0;
  for (const auto& e : fs::recursive_directory_iterator(set)) {
    if (e.path().filename() != "CATALOG.031") continue;
    ++catalogues;
    for (const std::string& n : cell_names_in(e.path())) listed.insert(n);
  }
  EXPECT_EQ(catalogues, 11u);
  EXPECT_EQ(listed.size(), 11u);
  const std::vector<EncCellFiles> cells = find_enc_cells({set});
  std::set<std::string> read;
  for (const EncCellFiles& c : cells) {
    read.insert(fs::path(c.base).filename().string());
    EXPECT_TRUE(is_enc_catalogue_name(c.catalogue)) << c.base << " not read through a catalogue";
    EXPECT_TRUE(c.updates.empty());
  }
  EXPECT_EQ(read, listed);
  EXPECT_EQ(cells.size(), 11u);
}

TEST(EncCatalogue, EntriesCarryTheFilesCrcsAsZlibComputesThem) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  const EncCatalogue cat = read_enc_catalogue((fs::path(root) / "CATALOG.031").string());
  ASSERT_EQ(cat.entries.size(), 4u);  // itself, two notes, the cell
  EXPECT_EQ(cat.entries[0].file, "CATALOG.031");
  EXPECT_FALSE(cat.entries[0].crc.has_value());
  const EncCatalogueEntry& cell = cat.entries[3];
  EXPECT_EQ(cell.file, "US5AK5QG/US5AK5QG.000");
  EXPECT_EQ(cell.impl, "BIN");
  ASSERT_TRUE(cell.crc.has_value());
  EXPECT_EQ(*cell.crc, 0x8FE7298Cu);  // SOURCES.md
  EXPECT_EQ(crc_hex(bytes_of(cell.path)), "8FE7298C");
  EXPECT_EQ(file_crc32(cell.path), 0x8FE7298Cu);
  EXPECT_EQ(cat.entries[1].impl, "TXT");
  // NOAA drops a CRC's leading zeros: US5AK5QF's cell is 00C70EA4, listed as C70EA4.
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(qf, "noaa-enc-kachemak/US5AK5QF_ENC_ROOT");
  const EncCatalogue short_crc = read_enc_catalogue((fs::path(qf) / "CATALOG.031").string());
  const auto cell_qf = std::find_if(short_crc.entries.begin(), short_crc.entries.end(),
                                    [](const EncCatalogueEntry& e) { return e.impl == "BIN"; });
  ASSERT_NE(cell_qf, short_crc.entries.end());
  EXPECT_EQ(cell_qf->crc, 0x00C70EA4u);
  EXPECT_EQ(crc_hex(bytes_of(cell_qf->path)), "00C70EA4");
}

TEST(EncCatalogue, OneByteChangedInACellIsRefusedNamingIt) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  ScratchDir tmp;
  const fs::path copy = copy_root(root, tmp.path());
  EXPECT_EQ(find_enc_cells({copy.string()}).size(), 1u);
  const fs::path cell = copy / "US5AK5QG" / "US5AK5QG.000";
  std::string b = bytes_of(cell);
  b[b.size() / 2] ^= 0x01;  // inside a value: the ISO 8211 structure stays sound
  write_bytes(cell, b);
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }),
                  {"US5AK5QG.000", "expected CRC-32 8FE7298C", "CATALOG.031"});
  // Named by the catalogue itself, or by the folder above, the same.
  expect_one_line(error_of([&] { find_enc_cells({(copy / "CATALOG.031").string()}); }), {"US5AK5QG.000", "CRC"});
  expect_one_line(error_of([&] { find_enc_cells({tmp.path().string()}); }), {"US5AK5QG.000", "CRC"});
}

TEST(EncCatalogue, AListedFileTheFolderLacksIsRefused) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  ScratchDir tmp;
  const fs::path copy = copy_root(root, tmp.path());
  fs::remove(copy / "US5AK5QG" / "US5AK5QG.000");
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }),
                  {"US5AK5QG.000", "expected the file", "CATALOG.031", "found none"});
}

TEST(EncCatalogue, AnUpdateTheCatalogueDoesNotListIsRefused) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  ScratchDir tmp;
  const fs::path copy = copy_root(root, tmp.path());
  // An update of Chesapeake's renamed would be applied by GDAL unchecked: refused before that.
  DEEPGUIDE_REAL_FILE_OR_SKIP(update, "noaa-enc-US4MD81M/US4MD81M.001");
  fs::copy_file(update, copy / "US5AK5QG" / "US5AK5QG.001");
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"US5AK5QG.001", "does not list"});
}

// The updates a catalogue lists are checked as its cells are: one listed
// but absent is missing, one present with another CRC is refused naming it.
TEST(EncCatalogue, ListedUpdatesAreCheckedToo) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  DEEPGUIDE_REAL_FILE_OR_SKIP(update, "noaa-enc-US4MD81M/US4MD81M.001");
  const std::string real = (fs::path(root) / "CATALOG.031").string();
  ScratchDir tmp;
  const fs::path copy = copy_root(root, tmp.path());
  const std::string cell_crc = crc_hex(bytes_of(copy / "US5AK5QG" / "US5AK5QG.000"));
  const std::string update_crc = crc_hex(bytes_of(update));
  write_bytes(copy / "CATALOG.031", catalogue_bytes(real, {{"US5AK5QG\\US5AK5QG.000", "BIN", cell_crc},
                                                           {"US5AK5QG\\US5AK5QG.001", "BIN", update_crc}}));
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }),
                  {"US5AK5QG.001", "expected the file", "CATALOG.031", "found none"});
  // Present and intact, but the catalogue says another file shipped (the cell's CRC given for it).
  fs::copy_file(update, copy / "US5AK5QG" / "US5AK5QG.001");
  write_bytes(copy / "CATALOG.031", catalogue_bytes(real, {{"US5AK5QG\\US5AK5QG.000", "BIN", cell_crc},
                                                           {"US5AK5QG\\US5AK5QG.001", "BIN", cell_crc}}));
  EXPECT_NE(cell_crc, update_crc);
  const std::string expected_crc = "expected CRC-32 " + cell_crc;
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }),
                  {"US5AK5QG.001", expected_crc.c_str(), "CATALOG.031"});
}

TEST(EncCatalogue, HostileCataloguesAreOneLineEach) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(root, kSeldoviaRoot);
  const std::string real = (fs::path(root) / "CATALOG.031").string();
  ScratchDir tmp;
  const fs::path copy = copy_root(root, tmp.path());
  const fs::path cat = copy / "CATALOG.031";
  const std::string cell_crc = crc_hex(bytes_of(copy / "US5AK5QG" / "US5AK5QG.000"));

  // A catalogue written here that lists the cell as the real one does: read, and the cell found.
  write_bytes(cat, catalogue_bytes(real, {{"CATALOG.031", "ASC", ""}, {"US5AK5QG\\US5AK5QG.000", "BIN", cell_crc}}));
  ASSERT_EQ(find_enc_cells({copy.string()}).size(), 1u) << "the test's own catalogue writer is wrong";

  // An ENC_ROOT without cells.
  write_bytes(cat, catalogue_bytes(real, {{"CATALOG.031", "ASC", ""}, {"US5AK5QG\\US209QGA.TXT", "TXT", ""}}));
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "listing S-57 cells", "none"});
  // A CRC that is not hexadecimal.
  write_bytes(cat, catalogue_bytes(real, {{"US5AK5QG\\US5AK5QG.000", "BIN", "8FE7298G"}}));  // not hexadecimal
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "record 2", "CRCS", "8FE7298G"});
  // A FILE that climbs out of the exchange set.
  write_bytes(cat, catalogue_bytes(real, {{"..\\..\\etc\\US5AK5QG.000", "BIN", cell_crc}}));
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "inside the catalogue's folder"});
  // Cut short, and empty.
  const std::string good = bytes_of(real);
  write_bytes(cat, good.substr(0, good.size() - 40));
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "cut short"});
  write_bytes(cat, "");
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "empty"});
  // Only the data descriptive record.
  write_bytes(cat, good.substr(0, static_cast<std::size_t>(std::stoi(good.substr(0, 5)))));
  expect_one_line(error_of([&] { find_enc_cells({copy.string()}); }), {"CATALOG.031", "CATD records"});
}

TEST(EncCatalogue, AFolderWithoutCatalogueIsSearchedAsBefore) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, "noaa-enc-US4MD81M/US4MD81M.000");
  const std::vector<EncCellFiles> cells = find_enc_cells({fs::path(cell).parent_path().string()});
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_TRUE(cells.front().catalogue.empty());
  EXPECT_EQ(cells.front().updates.size(), 3u);
}

// The issue's 116 km transit at 5 m, which stopped with "internal error: GEOS
// could not join the no-go areas" (a safety zone Boost's buffer made cross
// itself), and the prepared chart of the set, whose polygons plan refused
// ("rings that cross themselves"): both plan, and check route passes the route
// against the cells.
TEST(EncExchangeSet, TheLongTransitPlansFromTheCellsAndFromItsPreparedChart) {
  DEEPGUIDE_REAL_FOLDER_OR_SKIP(set, kKachemak);
  ScratchDir tmp;
  const std::string q = "'" + set + "'";
  const std::string ends = " --depth 5 --from -152.775099,59.423333 --to -150.795995,59.162818";
  const test::RunResult cold = run_cli("plan --chart " + q + ends + " -o '" + tmp.file("cold.geojson") + "' --json");
  ASSERT_EQ(cold.exit_code, 0) << cold.err;
  const double length = nlohmann::json::parse(cold.out).at("length_m").get<double>();
  EXPECT_GT(length, 116000.0);  // the straight line is 116 km
  EXPECT_LT(length, 130000.0);
  const test::RunResult check = run_cli("check route '" + tmp.file("cold.geojson") + "' --chart " + q + " --depth 5");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;

#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "the prepared chart's half runs in the Release build (a minute more under the sanitizers)";
#endif
  const test::RunResult prep = run_cli("chart prepare " + q + " --depth 5 -o '" + tmp.file("ak5.gpkg") + "'");
  ASSERT_EQ(prep.exit_code, 0) << prep.err;
  const test::RunResult warm =
      run_cli("plan --chart '" + tmp.file("ak5.gpkg") + "'" + ends + " -o '" + tmp.file("warm.geojson") + "' --json");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_NEAR(nlohmann::json::parse(warm.out).at("length_m").get<double>(), length, 1.0);
  const test::RunResult recheck = run_cli("check route '" + tmp.file("warm.geojson") + "' --chart " + q + " --depth 5");
  EXPECT_EQ(recheck.exit_code, 0) << recheck.out << recheck.err;
  // At 7 m the set's prepared polygons, valid where they were made, came back from their lon/lat
  // round trip with two holes touching (enc/25): read back, they are repaired, not refused.
  const std::string gpkg7 = tmp.file("ak7.gpkg");
  ASSERT_EQ(run_cli("chart prepare " + q + " --depth 7 -o '" + gpkg7 + "'").exit_code, 0);
  const test::RunResult at7 = run_cli("plan --chart '" + gpkg7 + "' --depth 7" +
                                      std::string(" --from -152.775099,59.423333 --to -150.795995,59.162818 -o '") +
                                      tmp.file("at7.geojson") + "'");
  EXPECT_EQ(at7.exit_code, 0) << at7.err;
  const test::RunResult check7 = run_cli("check route '" + tmp.file("at7.geojson") + "' --chart " + q + " --depth 7");
  EXPECT_EQ(check7.exit_code, 0) << check7.out << check7.err;
}

}  // namespace
}  // namespace deepguide
