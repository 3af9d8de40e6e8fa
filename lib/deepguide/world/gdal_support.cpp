#include "deepguide/world/gdal_support.hpp"

#include <mutex>

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "deepguide/core/error.hpp"
#include "deepguide/core/input_files.hpp"

namespace deepguide::gdal {

namespace {

// HDF5 (under GDAL's BAG, HDF5 and netCDF-4 readers) prints its own error
// stack to stderr, 10 to 20 lines before our one-line error, while GDAL
// reports the failure to us anyway. Its printing is switched off through the
// HDF5 library GDAL already loaded (H5Eset_auto2(H5E_DEFAULT, NULL, NULL)),
// found at run time so that deepguide needs no HDF5 headers; without HDF5
// there is nothing to silence.
void silence_hdf5_diagnostics() {
  using SetAuto = int (*)(std::int64_t, void*, void*);
  void* symbol = dlsym(RTLD_DEFAULT, "H5Eset_auto2");
  if (symbol == nullptr) return;
  SetAuto set_auto = nullptr;
  std::memcpy(&set_auto, &symbol, sizeof set_auto);
  set_auto(0, nullptr, nullptr);
}

}  // namespace

namespace {
thread_local std::string g_last_message;

void CPL_STDCALL remember_error(CPLErr level, CPLErrorNum, const char* msg) {
  if (level >= CE_Failure && msg != nullptr) g_last_message = msg;
}
}  // namespace

void ensure_registered() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    // GDAL 3.6's NLAPS (NDF) driver dereferences a null list while probing a
    // damaged header (found by fuzz/fuzz_current_nc: `chart info` and every
    // raster open crashed on 1835 bytes). A 1990s Landsat format nobody
    // plans from: it is not offered.
    for (const char* unsafe : {"NDF"}) {
      if (GDALDriver* d = GetGDALDriverManager()->GetDriverByName(unsafe)) {
        GetGDALDriverManager()->DeregisterDriver(d);
        GDALDestroyDriver(d);
      }
    }
    silence_hdf5_diagnostics();
    // GDAL prints "ERROR 1: ..." to stderr where no QuietErrors is active
    // (a layer read after the open, say); ours is the one line the user
    // sees, so GDAL's messages are only ever kept, never printed.
    CPLSetErrorHandler(remember_error);
  });
}

GDALDatasetUniquePtr open_dataset(const std::string& path, unsigned flags, const char* const* drivers,
                                  const char* const* open_options) {
  refuse_special_file(path);
  ensure_registered();
  return GDALDatasetUniquePtr(GDALDataset::Open(path.c_str(), flags, drivers, open_options, nullptr));
}

QuietErrors::QuietErrors() {
  g_last_message.clear();
  CPLPushErrorHandler(remember_error);
}

QuietErrors::~QuietErrors() { CPLPopErrorHandler(); }

std::string QuietErrors::last_message() { return g_last_message; }

std::unique_ptr<OGRSpatialReference> srs_from_user_input(const std::string& text) {
  auto srs = std::make_unique<OGRSpatialReference>();
  QuietErrors quiet;
  if (text.empty() || srs->SetFromUserInput(text.c_str()) != OGRERR_NONE) return nullptr;
  srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

std::unique_ptr<OGRSpatialReference> wgs84() {
  auto srs = std::make_unique<OGRSpatialReference>();
  srs->SetWellKnownGeogCS("WGS84");
  srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

std::string srs_id(const OGRSpatialReference& srs) {
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (auth != nullptr && code != nullptr) return std::string(auth) + ":" + code;
  const char* name = srs.GetName();
  return name != nullptr ? name : "unnamed CRS";
}

TransformPtr make_transform(const OGRSpatialReference& from, const OGRSpatialReference& to) {
  QuietErrors quiet;
  return TransformPtr(OGRCreateCoordinateTransformation(&from, &to),
                      [](OGRCoordinateTransformation* t) { OGRCoordinateTransformation::DestroyCT(t); });
}

MemoryOutput::MemoryOutput(const std::string& file_name) {
  static std::atomic<unsigned> counter{0};
  dir_ = "/vsimem/deepguide-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  path_ = dir_ + "/" + std::filesystem::path(file_name).filename().string();
  VSIMkdir(dir_.c_str(), 0755);  // drivers such as CSV look at the folder they write into
}

MemoryOutput::~MemoryOutput() { VSIRmdirRecursive(dir_.c_str()); }

void MemoryOutput::save(const std::string& disk_path, const std::string& destination) const {
  vsi_l_offset size = 0;
  const GByte* bytes = VSIGetMemFileBuffer(path_.c_str(), &size, FALSE);
  if (bytes == nullptr) throw InputError(destination + ": could not write the file: GDAL wrote nothing");
  const int fd = ::open(disk_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(destination + ": could not write the file: " + std::strerror(errno));
  std::size_t done = 0;
  int err = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, bytes + done, static_cast<std::size_t>(size - done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) {
    throw InputError(destination + ": could not write the file (" + std::to_string(done) + " of " +
                     std::to_string(size) + " bytes): " + std::strerror(err));
  }
}

}  // namespace deepguide::gdal
