#include "deepguide/world/raster_completeness.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string_view>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

namespace {

// The classic header, big-endian throughout (netCDF Users Guide, "File
// Format Specification"): magic, numrecs, dim_list, gatt_list, var_list;
// each var: name, dimids, vatt_list, nc_type, vsize, begin. CDF-5 widens
// counts and sizes to 8 bytes, CDF-2 and CDF-5 the offsets.
class ClassicHeader {
 public:
  ClassicHeader(std::ifstream& in, std::string path) : in_(in), path_(std::move(path)) {}

  // The byte just past the end of the farthest variable's data.
  std::uint64_t data_end() {
    char magic[4];
    read(magic, 4);
    version_ = magic[3];
    const std::uint64_t numrecs = count();
    const bool streaming = numrecs == (wide() ? std::numeric_limits<std::uint64_t>::max() : 0xFFFFFFFFu);
    std::vector<std::uint64_t> dims;
    if (list(0x0A)) {
      for (std::uint64_t n = count(), i = 0; i < n; ++i) {
        skip_name();
        dims.push_back(count());
      }
    }
    attributes();
    struct Var {
      std::uint64_t begin = 0, bytes = 0;
      bool record = false;
    };
    std::vector<Var> vars;
    std::uint64_t record_bytes = 0;  // one record of every record variable
    std::uint64_t record_vars = 0, last_record_bytes = 0;
    if (list(0x0B)) {
      for (std::uint64_t n = count(), i = 0; i < n; ++i) {
        skip_name();
        Var v;
        std::uint64_t cells = 1;
        for (std::uint64_t k = 0, nd = count(); k < nd; ++k) {
          const std::uint64_t id = count();
          if (id >= dims.size())
            fail("a variable names dimension " + std::to_string(id) + " of " + std::to_string(dims.size()));
          if (k == 0 && dims[id] == 0) {
            v.record = true;
          } else {
            cells = product(cells, dims[id]);
          }
        }
        attributes();
        const std::uint64_t type_size = size_of(u32());
        count();  // vsize: may be clipped to 2^32 - 1 for big variables; the shape says it exactly
        v.begin = wide() || version_ == 2 ? u64() : u32();
        v.bytes = product(cells, type_size);
        if (v.record) {
          record_bytes = sum(record_bytes, (v.bytes + 3) / 4 * 4);
          ++record_vars;
          last_record_bytes = v.bytes;
        }
        vars.push_back(v);
      }
    }
    // One record variable alone is not padded (the format's one exception).
    if (record_vars == 1) record_bytes = last_record_bytes;
    std::uint64_t end = 0;
    for (const Var& v : vars) {
      if (!v.record) {
        end = std::max(end, sum(v.begin, v.bytes));
      } else if (!streaming && numrecs > 0) {
        end = std::max(end, sum(v.begin, sum(product(numrecs - 1, record_bytes), v.bytes)));
      }
    }
    return end;
  }

 private:
  bool wide() const { return version_ == 5; }
  // Saturating, so a hostile header cannot wrap a size round to a small one.
  static std::uint64_t sum(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
  }
  static std::uint64_t product(std::uint64_t a, std::uint64_t b) {
    return b != 0 && a > std::numeric_limits<std::uint64_t>::max() / b ? std::numeric_limits<std::uint64_t>::max()
                                                                       : a * b;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": expected a readable NetCDF classic header, got " + what);
  }
  void read(char* to, std::size_t n) {
    if (!in_.read(to, static_cast<std::streamsize>(n))) fail("one cut short");
  }
  std::uint64_t u32() {
    unsigned char b[4];
    read(reinterpret_cast<char*>(b), 4);
    return (std::uint64_t{b[0]} << 24) | (std::uint64_t{b[1]} << 16) | (std::uint64_t{b[2]} << 8) | b[3];
  }
  std::uint64_t u64() { return (u32() << 32) | u32(); }
  std::uint64_t count() { return wide() ? u64() : u32(); }
  // A list's tag: true when present, false when ABSENT (two zeros).
  bool list(std::uint64_t tag) {
    const std::uint64_t t = u32();
    const std::uint64_t n = count();
    if (t == 0 && n == 0) return false;
    if (t != tag) fail("list tag " + std::to_string(t) + " where " + std::to_string(tag) + " belongs");
    in_.seekg(-static_cast<std::streamoff>(wide() ? 8 : 4), std::ios::cur);  // count() reads nelems again
    return true;
  }
  void skip(std::uint64_t n) {
    const std::uint64_t padded = (n + 3) / 4 * 4;
    if (padded > kMaxHeaderItem) fail("an item of " + std::to_string(n) + " bytes");
    in_.seekg(static_cast<std::streamoff>(padded), std::ios::cur);
    if (!in_) fail("one cut short");
  }
  void skip_name() { skip(count()); }
  void attributes() {
    if (!list(0x0C)) return;
    for (std::uint64_t n = count(), i = 0; i < n; ++i) {
      skip_name();
      const std::uint64_t type_size = size_of(u32());
      const std::uint64_t values = count();
      if (values > kMaxHeaderItem / type_size) fail("an attribute of " + std::to_string(values) + " values");
      skip(values * type_size);
    }
  }
  std::uint64_t size_of(std::uint64_t nc_type) const {
    switch (nc_type) {
      case 1:
      case 2:
      case 7: return 1;  // byte, char, ubyte
      case 3:
      case 8: return 2;  // short, ushort
      case 4:
      case 5:
      case 9: return 4;  // int, float, uint
      case 6:
      case 10:
      case 11: return 8;  // double, int64, uint64
      default: fail("type " + std::to_string(nc_type));
    }
  }

  static constexpr std::uint64_t kMaxHeaderItem = std::uint64_t{1} << 30;
  std::ifstream& in_;
  std::string path_;
  char version_ = 1;
};

bool is_netcdf_classic(std::ifstream& in) {
  char magic[4] = {};
  if (!in.read(magic, 4)) return false;
  in.seekg(0);
  return std::memcmp(magic, "CDF", 3) == 0 && (magic[3] == 1 || magic[3] == 2 || magic[3] == 5);
}

}  // namespace

void require_complete_netcdf(const std::string& path) {
  refuse_special_file(path);  // before opening it: a FIFO would block the open
  std::ifstream in(path, std::ios::binary);
  if (!in || !is_netcdf_classic(in)) return;
  const std::uint64_t need = ClassicHeader(in, path).data_end();
  std::error_code ec;
  const auto have = std::filesystem::file_size(path, ec);
  if (!ec && have < need) {
    throw InputError(path + ": expected a complete NetCDF file (its header places data up to byte " +
                     std::to_string(need) + "), got " + std::to_string(have) + " bytes: the file is cut short");
  }
}

void require_complete_ascii_grid(const std::string& path, std::uint64_t columns, std::uint64_t rows) {
  refuse_special_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) return;  // GDAL opened it; whatever it is, its reads decide
  std::uint64_t numbers = 0, line_no = 0;
  bool in_data = false;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    std::size_t at = 0;
    while (at < line.size()) {
      while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
      if (at == line.size()) break;
      std::size_t end = at;
      while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end]))) ++end;
      const std::string_view token(line.data() + at, end - at);
      at = end;
      if (!in_data && std::isalpha(static_cast<unsigned char>(token[0]))) break;  // a header line: KEY VALUE
      in_data = true;
      double v = 0;
      const char* first = token.data();
      if (*first == '+') ++first;  // from_chars takes no plus sign
      const auto [ptr, err] = std::from_chars(first, token.data() + token.size(), v);
      if (err != std::errc() || ptr != token.data() + token.size()) {
        throw InputError(path + ": line " + std::to_string(line_no) +
                         ": expected a number of the ESRI ASCII grid, got '" + printable(std::string(token), 40) + "'");
      }
      ++numbers;
    }
  }
  if (numbers != columns * rows) {
    throw InputError(path + ": expected " + std::to_string(columns) + " x " + std::to_string(rows) + " = " +
                     std::to_string(columns * rows) + " numbers in the ESRI ASCII grid, got " +
                     std::to_string(numbers) + (numbers < columns * rows ? ": the file is cut short" : ""));
  }
}

void require_complete_raster(GDALDataset& dataset, const std::string& path) {
  const GDALDriver* driver = dataset.GetDriver();
  if (driver == nullptr) return;
  const std::string name = driver->GetDescription();
  if (name == "netCDF") require_complete_netcdf(path);
  // A text grid spends at least one character on each cell. GDAL's XYZ
  // driver infers the grid from the spacing of the coordinates it reads, so
  // 60 damaged bytes stated 51 million x 2 cells (found by the soak of
  // fuzz/fuzz_bathymetry_asc), read as 400 MB of nothing: refused by size.
  // (An ESRI ASCII grid's numbers are counted below, which says more.)
  for (const char* text : {"XYZ", "GRASSASCIIGrid", "GSAG", "ISG"}) {
    if (name != text) continue;
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    const auto cells =
        static_cast<std::uint64_t>(dataset.GetRasterXSize()) * static_cast<std::uint64_t>(dataset.GetRasterYSize());
    if (!ec && cells > bytes) {
      throw InputError(path + ": expected a text grid (" + name + ") with a character at least for each of its " +
                       std::to_string(dataset.GetRasterXSize()) + " x " + std::to_string(dataset.GetRasterYSize()) +
                       " cells, got " + std::to_string(bytes) + " bytes: a damaged header or coordinates");
    }
  }
  if (name == "AAIGrid") {
    // The size GDAL read from the header, not ours: a header with a key twice
    // or a damaged value must not let a short file through to GDAL's reads.
    require_complete_ascii_grid(path, static_cast<std::uint64_t>(dataset.GetRasterXSize()),
                                static_cast<std::uint64_t>(dataset.GetRasterYSize()));
  }
}

}  // namespace deepguide
