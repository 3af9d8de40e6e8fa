#include "deepguide/world/gdal_support.hpp"

#include <mutex>

namespace deepguide::gdal {

void ensure_registered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

namespace {
thread_local std::string g_last_message;

void CPL_STDCALL remember_error(CPLErr level, CPLErrorNum, const char* msg) {
  if (level >= CE_Failure && msg != nullptr) g_last_message = msg;
}
}  // namespace

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

}  // namespace deepguide::gdal
