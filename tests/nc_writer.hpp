#pragma once
// Writes small NetCDF current fields for tests (GDAL's multidimensional API):
// lon/lat axes, an optional time axis and depth axis, u/v from functions.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace deepguide::test {

inline void write_attr(GDALMDArray& a, const std::string& name, const std::string& value) {
  auto at = a.CreateAttribute(name, {}, GDALExtendedDataType::CreateString());
  ASSERT_TRUE(at);
  ASSERT_TRUE(at->Write(value.c_str()));
}

inline std::shared_ptr<GDALMDArray> write_axis(GDALGroup& root, const std::string& name, const std::string& type,
                                               const std::vector<double>& values, const std::string& units) {
  auto dim = root.CreateDimension(name, type, "", values.size());
  auto var = root.CreateMDArray(name, {dim}, GDALExtendedDataType::Create(GDT_Float64));
  const GUInt64 start = 0;
  const size_t count = values.size();
  EXPECT_TRUE(var->Write(&start, &count, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), values.data()));
  if (!units.empty()) write_attr(*var, "units", units);
  return var;
}

// A NetCDF field: optional time axis, optional depth axis, lon/lat axes; u/v from functions of
// (lon, lat, time value, depth). NaN from a function is written as _FillValue.
struct NcSpec {
  std::vector<double> lon{10.0, 10.1, 10.3, 10.35, 10.6, 11.0};  // irregular on purpose
  std::vector<double> lat{55.0, 54.8, 54.6, 54.4, 54.2};         // descending on purpose
  std::vector<double> time;                                      // empty = no time axis
  std::vector<double> depth;                                     // empty = no depth axis
  std::string lon_units = "degrees_east";
  std::string lat_units = "degrees_north";
  std::string time_units = "hours since 2020-01-01 00:00:00";
  std::string u_name = "u", v_name = "v";
  std::string u_standard, v_standard;
  bool v_missing_row = false;  // v with one latitude fewer (a shape mismatch)
  std::function<double(double, double, double, double)> u, v;
};

inline void write_nc(const std::string& path, const NcSpec& s) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("netCDF");
  ASSERT_NE(drv, nullptr);
  GDALDatasetUniquePtr ds(drv->CreateMultiDimensional(path.c_str(), nullptr, nullptr));
  ASSERT_TRUE(ds);
  auto root = ds->GetRootGroup();
  std::vector<std::shared_ptr<GDALDimension>> dims;
  if (!s.time.empty()) {
    write_axis(*root, "time", "TEMPORAL", s.time, s.time_units);
  }
  if (!s.depth.empty()) {
    auto z = write_axis(*root, "depth", "VERTICAL", s.depth, "m");
    write_attr(*z, "positive", "down");
  }
  write_axis(*root, "lat", "HORIZONTAL_Y", s.lat, s.lat_units);
  write_axis(*root, "lon", "HORIZONTAL_X", s.lon, s.lon_units);
  auto find_dim = [&](const std::string& n) {
    for (const auto& d : root->GetDimensions())
      if (d->GetName() == n) return d;
    return std::shared_ptr<GDALDimension>();
  };
  if (!s.time.empty()) dims.push_back(find_dim("time"));
  if (!s.depth.empty()) dims.push_back(find_dim("depth"));
  dims.push_back(find_dim("lat"));
  dims.push_back(find_dim("lon"));
  const std::size_t nt = std::max<std::size_t>(1, s.time.size()), nz = std::max<std::size_t>(1, s.depth.size());
  auto write_var = [&](const std::string& name, const std::string& standard,
                       const std::function<double(double, double, double, double)>& fn, bool short_lat) {
    auto d = dims;
    std::size_t ny = s.lat.size();
    if (short_lat) {
      ny -= 1;
      d[d.size() - 2] = root->CreateDimension("lat_short", "", "", ny);
    }
    auto var = root->CreateMDArray(name, d, GDALExtendedDataType::Create(GDT_Float64));
    ASSERT_TRUE(var);
    var->SetNoDataValue(-999.0);
    if (!standard.empty()) write_attr(*var, "standard_name", standard);
    std::vector<double> buf;
    for (std::size_t k = 0; k < nt; ++k)
      for (std::size_t l = 0; l < nz; ++l)
        for (std::size_t j = 0; j < ny; ++j)
          for (std::size_t i = 0; i < s.lon.size(); ++i) {
            const double value =
                fn(s.lon[i], s.lat[j], s.time.empty() ? 0.0 : s.time[k], s.depth.empty() ? 0.0 : s.depth[l]);
            buf.push_back(std::isnan(value) ? -999.0 : value);
          }
    std::vector<GUInt64> start(d.size(), 0);
    std::vector<size_t> count;
    for (const auto& x : d) count.push_back(static_cast<size_t>(x->GetSize()));
    ASSERT_TRUE(var->Write(start.data(), count.data(), nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64),
                           buf.data()));
  };
  write_var(s.u_name, s.u_standard, s.u, false);
  if (!s.v_name.empty()) write_var(s.v_name, s.v_standard, s.v, s.v_missing_row);
}

}  // namespace deepguide::test
