#pragma once
// Library-internal helpers around GDAL/OGR/OSR (not installed): driver
// registration, quiet error handling that keeps GDAL's message for ours, and
// spatial references with lon/lat axis order.

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <memory>
#include <string>

namespace deepguide::gdal {

/// Registers all GDAL drivers once; cheap to call again.
void ensure_registered();

/// GDALDataset::Open, after refuse_special_file (core/input_files.hpp): GDAL
/// would wait on a named pipe for ever.
GDALDatasetUniquePtr open_dataset(const std::string& path, unsigned flags, const char* const* drivers = nullptr,
                                  const char* const* open_options = nullptr);

/// While alive, GDAL errors and warnings are not printed; last_message() keeps the latest.
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;
  static std::string last_message();
};

/// A spatial reference from user input ("EPSG:4326", WKT, PROJ string) with
/// traditional GIS axis order (x = lon/easting). Null when OSR does not know it.
std::unique_ptr<OGRSpatialReference> srs_from_user_input(const std::string& text);
/// WGS 84 geographic, lon/lat order.
std::unique_ptr<OGRSpatialReference> wgs84();
/// "EPSG:n" when the authority is EPSG, else the CRS's name.
std::string srs_id(const OGRSpatialReference& srs);

using TransformPtr = std::unique_ptr<OGRCoordinateTransformation, void (*)(OGRCoordinateTransformation*)>;
/// Transformation between two references; null when PROJ cannot make one.
TransformPtr make_transform(const OGRSpatialReference& from, const OGRSpatialReference& to);

/// A dataset GDAL writes in memory (/vsimem/) and we then write to disk with
/// every write, the fsync and the close checked. GDAL's text drivers
/// (GeoJSON, GPX, KML, CSV) ignore a failed write, so on a full disk they
/// left a short file that looked whole; this cannot.
class MemoryOutput {
 public:
  /// `file_name` gives the in-memory file its name and extension (drivers look at it).
  explicit MemoryOutput(const std::string& file_name);
  ~MemoryOutput();  ///< frees the memory
  MemoryOutput(const MemoryOutput&) = delete;
  MemoryOutput& operator=(const MemoryOutput&) = delete;

  /// Where GDAL creates the dataset (close it before save()).
  const std::string& path() const { return path_; }
  /// Writes the bytes to `disk_path`; InputError naming `destination` on any failure.
  void save(const std::string& disk_path, const std::string& destination) const;

 private:
  std::string dir_, path_;
};

}  // namespace deepguide::gdal

namespace deepguide {

/// The completeness check (raster_completeness.hpp) for the dataset's
/// driver (netCDF, AAIGrid); other drivers pass.
void require_complete_raster(GDALDataset& dataset, const std::string& path);

}  // namespace deepguide
