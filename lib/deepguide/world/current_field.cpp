#include "deepguide/world/current_field.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/raster_completeness.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// ------------------------------------------------------------------ time

// "UNITS since YYYY-MM-DD[( |T)hh:mm[:ss[.f]]][Z| UTC|+hh[:mm]]" -> (seconds per unit, epoch of the origin).
std::optional<std::pair<double, double>> parse_time_units(const std::string& text) {
  const std::string t = ascii_lower(trim(text));
  const auto since = t.find(" since ");
  if (since == std::string::npos) return std::nullopt;
  const std::string unit = trim(t.substr(0, since));
  double per = 0;
  if (unit == "seconds" || unit == "second" || unit == "secs" || unit == "sec" || unit == "s")
    per = 1;
  else if (unit == "minutes" || unit == "minute" || unit == "mins" || unit == "min")
    per = 60;
  else if (unit == "hours" || unit == "hour" || unit == "hrs" || unit == "hr" || unit == "h")
    per = 3600;
  else if (unit == "days" || unit == "day" || unit == "d")
    per = 86400;
  else
    return std::nullopt;

  const std::optional<double> origin = parse_iso8601(t.substr(since + 7), false);
  if (!origin) return std::nullopt;
  return std::make_pair(per, *origin);
}

// ------------------------------------------------------------------ axes

// An axis stored ascending; `reversed` when the file had it descending.
struct Axis {
  std::vector<double> values;
  bool reversed = false;
};

Axis ascending_axis(std::vector<double> values, const std::string& path, const std::string& name) {
  Axis a;
  for (double v : values) {
    if (!std::isfinite(v))
      throw InputError(path + ": axis '" + printable(name) + "': expected finite coordinates, got NaN or infinity");
  }
  if (values.size() >= 2 && values[1] < values[0]) {
    std::reverse(values.begin(), values.end());
    a.reversed = true;
  }
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (!(values[i] > values[i - 1])) {
      throw InputError(path + ": axis '" + printable(name) + "': expected strictly monotonic coordinates, got " +
                       fixed(values[i - 1], 6) + " then " + fixed(values[i], 6));
    }
  }
  a.values = std::move(values);
  return a;
}

// ------------------------------------------------------------------ multidimensional reading

enum class Role { x, y, z, t, other };

std::string attr_string(const GDALMDArray& a, const char* name) {
  const auto at = a.GetAttribute(name);
  if (!at) return {};
  const char* s = at->ReadAsString();
  return s != nullptr ? s : "";
}

Role role_of(const GDALDimension& dim) {
  const std::string type = dim.GetType();
  if (type == "HORIZONTAL_X") return Role::x;
  if (type == "HORIZONTAL_Y") return Role::y;
  if (type == "VERTICAL") return Role::z;
  if (type == "TEMPORAL") return Role::t;
  if (const auto var = dim.GetIndexingVariable()) {
    const std::string axis = ascii_lower(attr_string(*var, "axis"));
    const std::string units = ascii_lower(var->GetUnit());
    const std::string sn = ascii_lower(attr_string(*var, "standard_name"));
    if (axis == "x" || units == "degrees_east" || sn == "longitude" || sn == "projection_x_coordinate") return Role::x;
    if (axis == "y" || units == "degrees_north" || sn == "latitude" || sn == "projection_y_coordinate") return Role::y;
    if (axis == "z" || sn == "depth" || attr_string(*var, "positive").size() > 0) return Role::z;
    if (axis == "t" || sn == "time" || units.find(" since ") != std::string::npos) return Role::t;
  }
  const std::string n = ascii_lower(dim.GetName());
  if (n == "lon" || n == "longitude" || n == "x") return Role::x;
  if (n == "lat" || n == "latitude" || n == "y") return Role::y;
  if (n == "depth" || n == "z" || n == "lev" || n == "level" || n == "deptht" || n == "depthu") return Role::z;
  if (n == "time" || n == "t") return Role::t;
  return Role::other;
}

std::vector<double> read_vector(const GDALMDArray& a, const std::string& path) {
  if (a.GetDimensionCount() != 1) {
    throw InputError(path + ": variable '" + printable(a.GetName()) +
                     "': expected a one-dimensional coordinate variable");
  }
  // A header can state any length; the values are read only for a length a
  // real axis can have (GEBCO's 15" longitudes are 86 400; the soak found
  // 2^32 - 1, 32 GiB, in 4.5 KB).
  constexpr GUInt64 kMaxAxis = 10'000'000;
  const GUInt64 stated = a.GetDimensions()[0]->GetSize();
  if (stated > kMaxAxis) {
    throw InputError(path + ": variable '" + printable(a.GetName()) + "': expected a coordinate axis of at most " +
                     std::to_string(kMaxAxis) + " values, got " + std::to_string(stated));
  }
  const std::size_t n = static_cast<std::size_t>(stated);
  std::vector<double> out(n);
  const GUInt64 start = 0;
  const std::size_t count = n;
  if (n > 0 && !a.Read(&start, &count, nullptr, nullptr, GDALExtendedDataType::Create(GDT_Float64), out.data())) {
    throw InputError(path + ": variable '" + printable(a.GetName()) +
                     "': expected readable values, got: " + printable(gdal::QuietErrors::last_message(), 160));
  }
  return out;
}

std::shared_ptr<GDALMDArray> find_by(const GDALGroup& root, const std::vector<std::string>& names,
                                     const std::vector<std::string>& standard_names, const std::string& explicit_name) {
  if (!explicit_name.empty()) return root.OpenMDArray(explicit_name);
  for (const auto& sn : standard_names) {
    for (const auto& name : root.GetMDArrayNames()) {
      auto a = root.OpenMDArray(name);
      if (a && ascii_lower(attr_string(*a, "standard_name")) == sn) return a;
    }
  }
  for (const auto& n : names) {
    if (auto a = root.OpenMDArray(n)) return a;
  }
  return nullptr;
}

struct Variables {
  std::shared_ptr<GDALMDArray> u, v;
};

Variables find_uv(const GDALGroup& root, const std::string& path, const CurrentOptions& options) {
  gdal::QuietErrors quiet;  // OpenMDArray on an absent name complains
  Variables out;
  out.u = find_by(root, {"water_u", "u", "uo", "U", "ucur", "UCUR", "eastward_velocity"},
                  {"eastward_sea_water_velocity", "surface_eastward_sea_water_velocity", "sea_water_x_velocity"},
                  options.u_variable);
  out.v = find_by(root, {"water_v", "v", "vo", "V", "vcur", "VCUR", "northward_velocity"},
                  {"northward_sea_water_velocity", "surface_northward_sea_water_velocity", "sea_water_y_velocity"},
                  options.v_variable);
  if (!out.u || !out.v) {
    std::string names;
    for (const auto& n : root.GetMDArrayNames()) names += (names.empty() ? "" : ", ") + n;
    const std::string which = !out.u && !out.v ? "u and v" : (!out.u ? "u" : "v");
    const std::string asked =
        !options.u_variable.empty() || !options.v_variable.empty()
            ? " (asked for '" + printable(options.u_variable) + "'/'" + printable(options.v_variable) + "')"
            : "";
    throw InputError(path + ": expected current variables " + which + asked +
                     " (standard_name eastward/northward_sea_water_velocity or a name such as water_u/water_v, u/v, "
                     "uo/vo), got variables: " +
                     (names.empty() ? std::string("none") : printable(names, 120)));
  }
  return out;
}

// The value of a raw read: unknown (NaN) when fill or NaN, else scaled.
struct Unpack {
  bool has_fill = false;
  double fill = 0;
  bool has_missing = false;
  double missing = 0;
  bool float32 = false;
  double scale = 1;
  double offset = 0;

  bool same(double v, double f) const { return v == f || (float32 && static_cast<float>(v) == static_cast<float>(f)); }
  double operator()(double raw) const {
    if (std::isnan(raw) || (has_fill && same(raw, fill)) || (has_missing && same(raw, missing))) return kNaN;
    return raw * scale + offset;
  }
};

Unpack unpack_of(const GDALMDArray& a) {
  Unpack u;
  bool has = false;
  const double fill = a.GetNoDataValueAsDouble(&has);
  u.has_fill = has;
  u.fill = fill;
  if (const auto m = a.GetAttribute("missing_value")) {
    u.has_missing = true;
    u.missing = m->ReadAsDouble();
  }
  u.float32 = a.GetDataType().GetClass() == GEDTC_NUMERIC && a.GetDataType().GetNumericDataType() == GDT_Float32;
  bool has_scale = false, has_offset = false;
  const double s = a.GetScale(&has_scale);
  const double o = a.GetOffset(&has_offset);
  if (has_scale) u.scale = s;
  if (has_offset) u.offset = o;
  return u;
}

void set_extent(CurrentField& f, const OGRSpatialReference& srs) {
  if (f.geographic) {
    f.extent = {f.x.front(), f.x.back(), f.y.front(), f.y.back()};
    return;
  }
  auto geo = gdal::wgs84();
  auto ct = gdal::make_transform(srs, *geo);
  double w, s, e, n;
  if (!ct || !ct->TransformBounds(f.x.front(), f.y.front(), f.x.back(), f.y.back(), &w, &s, &e, &n, 21)) {
    throw InputError(f.source + ": expected a field extent that converts to lon/lat from " + f.crs +
                     ", got one PROJ cannot transform");
  }
  f.extent = {w, e, s, n};
}

void set_crs(CurrentField& f, const OGRSpatialReference& srs, const std::string& source) {
  f.crs = gdal::srs_id(srs);
  f.crs_source = source;
  f.geographic = srs.IsGeographic();
  char* wkt = nullptr;
  if (srs.exportToWkt(&wkt) == OGRERR_NONE && wkt != nullptr) f.crs_wkt = wkt;
  CPLFree(wkt);
}

void check_size(const std::string& path, std::size_t nx, std::size_t ny, std::size_t steps, const CurrentOptions& o) {
  const double cells = static_cast<double>(nx) * static_cast<double>(ny);
  if (cells > static_cast<double>(o.max_cells_per_step) ||
      cells * static_cast<double>(std::max<std::size_t>(steps, 1)) > static_cast<double>(o.max_total_cells)) {
    throw InputError(path + ": expected a current field of at most " + std::to_string(o.max_cells_per_step) +
                     " nodes per time step and " + std::to_string(o.max_total_cells) + " in all, got " +
                     std::to_string(nx) + " x " + std::to_string(ny) + " nodes x " + std::to_string(steps) +
                     " step(s); cut the work area out first (e.g. gdal_translate -projwin or ncks)");
  }
}

CurrentField load_multidim(GDALDataset& ds, const std::string& path, const CurrentOptions& options) {
  const auto root = ds.GetRootGroup();
  if (!root) throw InputError(path + ": expected a NetCDF file with a root group, got none");
  const Variables vars = find_uv(*root, path, options);
  const auto& du = vars.u->GetDimensions();
  const auto& dv = vars.v->GetDimensions();
  bool same = du.size() == dv.size();
  for (std::size_t i = 0; same && i < du.size(); ++i) same = du[i]->GetSize() == dv[i]->GetSize();
  auto shape = [](const std::vector<std::shared_ptr<GDALDimension>>& d) {
    std::string s;
    for (const auto& x : d) s += (s.empty() ? "" : " x ") + std::to_string(x->GetSize());
    return s.empty() ? std::string("scalar") : s;
  };
  if (!same) {
    throw InputError(path + ": variables '" + printable(vars.u->GetName()) + "' and '" + printable(vars.v->GetName()) +
                     "': expected the same shape, got " + shape(du) + " and " + shape(dv));
  }

  CurrentField f;
  f.source = path;
  f.driver = ds.GetDriver() != nullptr ? ds.GetDriver()->GetDescription() : "";
  f.u_name = vars.u->GetName();
  f.v_name = vars.v->GetName();
  f.depth_m = options.depth_m;

  int ix = -1, iy = -1, iz = -1, it = -1;
  for (std::size_t i = 0; i < du.size(); ++i) {
    const Role r = role_of(*du[i]);
    int* slot = r == Role::x ? &ix : r == Role::y ? &iy : r == Role::z ? &iz : r == Role::t ? &it : nullptr;
    if (slot != nullptr && *slot < 0) {
      *slot = static_cast<int>(i);
    } else if (du[i]->GetSize() != 1) {
      throw InputError(path + ": variable '" + printable(f.u_name) + "': dimension '" + printable(du[i]->GetName()) +
                       "': expected lon/x, lat/y, depth or time, got a dimension of size " +
                       std::to_string(du[i]->GetSize()) + " with no such role");
    }
  }
  if (ix < 0 || iy < 0) {
    throw InputError(path + ": variable '" + printable(f.u_name) +
                     "': expected horizontal dimensions (lon/x and lat/y), got " + shape(du));
  }
  const auto xvar = du[static_cast<std::size_t>(ix)]->GetIndexingVariable();
  const auto yvar = du[static_cast<std::size_t>(iy)]->GetIndexingVariable();

  // CRS: CF lon/lat axes, the array's grid mapping, or the assumed one.
  auto is_lon = [](const std::shared_ptr<GDALMDArray>& a) {
    return a && (ascii_lower(a->GetUnit()).rfind("degrees_e", 0) == 0 || ascii_lower(a->GetUnit()) == "degree_east" ||
                 ascii_lower(attr_string(*a, "standard_name")) == "longitude");
  };
  auto is_lat = [](const std::shared_ptr<GDALMDArray>& a) {
    return a && (ascii_lower(a->GetUnit()).rfind("degrees_n", 0) == 0 || ascii_lower(a->GetUnit()) == "degree_north" ||
                 ascii_lower(attr_string(*a, "standard_name")) == "latitude");
  };
  std::unique_ptr<OGRSpatialReference> srs;
  std::string srs_source;
  const auto file_srs = vars.u->GetSpatialRef();
  if (is_lon(xvar) && is_lat(yvar)) {
    srs = gdal::wgs84();
    srs_source = "CF lon/lat axes (degrees_east/degrees_north)";
  } else if (file_srs && !file_srs->IsEmpty()) {
    srs.reset(file_srs->Clone());
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    srs_source = "file";
  } else if (!options.assumed_crs.empty()) {
    srs = gdal::srs_from_user_input(options.assumed_crs);
    if (!srs)
      throw InputError(path + ": assumed CRS: expected a CRS OSR knows, got '" + printable(options.assumed_crs) + "'");
    srs_source = "assumed (option)";
  } else {
    throw InputError(path + ": expected lon/lat axes (units degrees_east/degrees_north) or a CRS (grid_mapping), got " +
                     "neither; give the CRS it uses (`src_crs`, e.g. EPSG:32632)");
  }
  if (!xvar || !yvar) {
    throw InputError(path + ": variable '" + printable(f.u_name) +
                     "': expected coordinate variables for its horizontal dimensions, got none");
  }
  set_crs(f, *srs, srs_source);
  const Axis ax = ascending_axis(read_vector(*xvar, path), path, xvar->GetName());
  const Axis ay = ascending_axis(read_vector(*yvar, path), path, yvar->GetName());
  f.x = ax.values;
  f.y = ay.values;

  // Time.
  std::size_t nt = 1;
  if (it >= 0) {
    nt = static_cast<std::size_t>(du[static_cast<std::size_t>(it)]->GetSize());
    const auto tvar = du[static_cast<std::size_t>(it)]->GetIndexingVariable();
    if (tvar) {
      const std::string units = tvar->GetUnit();
      const auto parsed = parse_time_units(units);
      if (!parsed) {
        throw input_error({path, "variable '" + printable(tvar->GetName()) + "'", "units"},
                          "'UNITS since YYYY-MM-DD hh:mm:ss' with UNITS seconds, minutes, hours or days",
                          "'" + printable(units) + "'");
      }
      const std::string cal = ascii_lower(attr_string(*tvar, "calendar"));
      if (!cal.empty() && cal != "gregorian" && cal != "standard" && cal != "proleptic_gregorian") {
        throw input_error({path, "variable '" + printable(tvar->GetName()) + "'", "calendar"},
                          "gregorian, standard or proleptic_gregorian", "'" + printable(cal) + "'");
      }
      for (double v : read_vector(*tvar, path)) f.times_s.push_back(parsed->second + v * parsed->first);
      for (std::size_t i = 1; i < f.times_s.size(); ++i) {
        if (!(f.times_s[i] > f.times_s[i - 1])) {
          throw input_error({path, "variable '" + printable(tvar->GetName()) + "'", ""}, "strictly increasing times",
                            format_utc(f.times_s[i - 1]) + " then " + format_utc(f.times_s[i]));
        }
      }
    } else if (nt > 1) {
      throw InputError(path + ": dimension '" + printable(du[static_cast<std::size_t>(it)]->GetName()) +
                       "': expected a time coordinate variable for " + std::to_string(nt) + " steps, got none");
    }
  }
  check_size(path, f.nx(), f.ny(), nt, options);

  // Depth: one level, or two with a weight.
  std::size_t k0 = 0, k1 = 0;
  double wk = 0;
  if (!(std::isfinite(options.depth_m) && options.depth_m >= 0)) {
    throw InputError(path + ": depth: expected a depth >= 0 m, got " + fixed(options.depth_m, 3));
  }
  if (iz >= 0) {
    const auto zdim = du[static_cast<std::size_t>(iz)];
    const std::size_t nz = static_cast<std::size_t>(zdim->GetSize());
    std::vector<double> z(nz, 0.0);
    if (const auto zvar = zdim->GetIndexingVariable()) {
      z = read_vector(*zvar, path);
      bool up = ascii_lower(attr_string(*zvar, "positive")) == "up";
      if (!up && ascii_lower(attr_string(*zvar, "positive")).empty()) {
        up = std::all_of(z.begin(), z.end(), [](double d) { return d <= 0; }) &&
             std::any_of(z.begin(), z.end(), [](double d) { return d < 0; });
      }
      if (up)
        for (double& d : z) d = -d;
    } else if (nz > 1) {
      throw InputError(path + ": dimension '" + printable(zdim->GetName()) +
                       "': expected a depth coordinate variable for " + std::to_string(nz) + " levels, got none");
    }
    std::vector<std::size_t> order(nz);
    for (std::size_t i = 0; i < nz; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return z[a] < z[b]; });
    const double d = options.depth_m;
    if (d <= z[order.front()]) {
      k0 = k1 = order.front();
      f.depth_levels = "level " + std::to_string(k0 + 1) + " of " + std::to_string(nz) + " (" + fixed(z[k0], 1) + " m)";
    } else if (d > z[order.back()]) {
      throw InputError(path + ": depth: expected a depth within the field's levels (" + fixed(z[order.front()], 1) +
                       " .. " + fixed(z[order.back()], 1) + " m), got " + fixed(d, 1) + " m");
    } else {
      std::size_t i = 0;
      while (z[order[i + 1]] < d) ++i;
      k0 = order[i];
      k1 = order[i + 1];
      wk = (d - z[k0]) / (z[k1] - z[k0]);
      if (wk == 1.0) {
        k0 = k1;
        wk = 0;
      }
      f.depth_levels =
          k0 == k1 || wk == 0.0
              ? "level " + std::to_string(k0 + 1) + " of " + std::to_string(nz) + " (" + fixed(z[k0], 1) + " m)"
              : "between levels " + std::to_string(k0 + 1) + " and " + std::to_string(k1 + 1) + " of " +
                    std::to_string(nz) + " (" + fixed(z[k0], 1) + " and " + fixed(z[k1], 1) + " m)";
      if (wk == 0.0) k1 = k0;
    }
  } else {
    f.depth_levels = "no depth axis";
  }

  // Read all steps of one level into [t][y][x] (file order of x and y kept; flipped below).
  const std::size_t nx = f.nx(), ny = f.ny(), plane = nx * ny;
  auto read_level = [&](const GDALMDArray& a, std::size_t level) {
    const std::size_t nd = a.GetDimensionCount();
    std::vector<GUInt64> start(nd, 0);
    std::vector<std::size_t> count(nd, 1);
    std::vector<GPtrDiff_t> stride(nd, 0);
    count[static_cast<std::size_t>(ix)] = nx;
    stride[static_cast<std::size_t>(ix)] = 1;
    count[static_cast<std::size_t>(iy)] = ny;
    stride[static_cast<std::size_t>(iy)] = static_cast<GPtrDiff_t>(nx);
    if (it >= 0) {
      count[static_cast<std::size_t>(it)] = nt;
      stride[static_cast<std::size_t>(it)] = static_cast<GPtrDiff_t>(plane);
    }
    if (iz >= 0) start[static_cast<std::size_t>(iz)] = level;
    std::vector<double> buf(plane * nt);
    if (!a.Read(start.data(), count.data(), nullptr, stride.data(), GDALExtendedDataType::Create(GDT_Float64),
                buf.data(), buf.data(), buf.size() * sizeof(double))) {
      throw InputError(path + ": variable '" + printable(a.GetName()) +
                       "': expected readable values, got: " + printable(gdal::QuietErrors::last_message(), 160));
    }
    const Unpack unpack = unpack_of(a);
    for (double& v : buf) v = unpack(v);
    return buf;
  };
  auto read_component = [&](const GDALMDArray& a) {
    std::vector<double> out = read_level(a, k0);
    if (k1 != k0) {
      const std::vector<double> deeper = read_level(a, k1);
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = out[i] + wk * (deeper[i] - out[i]);  // NaN stays NaN
    }
    // Stored ascending in x and y.
    if (ax.reversed || ay.reversed) {
      std::vector<double> flipped(out.size());
      for (std::size_t k = 0; k < nt; ++k)
        for (std::size_t j = 0; j < ny; ++j)
          for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t si = ax.reversed ? nx - 1 - i : i, sj = ay.reversed ? ny - 1 - j : j;
            flipped[(k * ny + j) * nx + i] = out[(k * ny + sj) * nx + si];
          }
      out.swap(flipped);
    }
    return out;
  };
  f.u = read_component(*vars.u);
  f.v = read_component(*vars.v);
  set_extent(f, *srs);
  return f;
}

CurrentField load_two_band(GDALDataset& ds, const std::string& path, const CurrentOptions& options) {
  if (ds.GetRasterCount() != 2) {
    throw InputError(path +
                     ": expected a two-band raster (band 1 u east, band 2 v north, m/s) or a NetCDF file with u/v " +
                     "variables, got a raster with " + std::to_string(ds.GetRasterCount()) + " band(s)");
  }
  CurrentField f;
  f.source = path;
  f.driver = ds.GetDriver() != nullptr ? ds.GetDriver()->GetDescription() : "";
  f.u_name = "band 1";
  f.v_name = "band 2";
  f.depth_m = options.depth_m;
  f.depth_levels = "no depth axis";
  std::unique_ptr<OGRSpatialReference> srs;
  if (const OGRSpatialReference* file_srs = ds.GetSpatialRef(); file_srs != nullptr && !file_srs->IsEmpty()) {
    srs.reset(file_srs->Clone());
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    set_crs(f, *srs, "file");
  } else if (!options.assumed_crs.empty()) {
    srs = gdal::srs_from_user_input(options.assumed_crs);
    if (!srs)
      throw InputError(path + ": assumed CRS: expected a CRS OSR knows, got '" + printable(options.assumed_crs) + "'");
    set_crs(f, *srs, "assumed (option)");
  } else {
    throw InputError(path +
                     ": expected a raster with a CRS, got none; give the CRS it uses (`src_crs`, e.g. EPSG:4326)");
  }
  double gt[6];
  if (ds.GetGeoTransform(gt) != CE_None)
    throw InputError(path + ": expected a georeferenced raster (a geotransform), got none");
  if (gt[2] != 0.0 || gt[4] != 0.0) throw InputError(path + ": expected a north-up raster, got a rotated geotransform");
  const std::size_t nx = static_cast<std::size_t>(ds.GetRasterXSize()),
                    ny = static_cast<std::size_t>(ds.GetRasterYSize());
  check_size(path, nx, ny, 1, options);
  std::vector<double> xs(nx), ys(ny);
  for (std::size_t i = 0; i < nx; ++i) xs[i] = gt[0] + (static_cast<double>(i) + 0.5) * gt[1];
  for (std::size_t j = 0; j < ny; ++j) ys[j] = gt[3] + (static_cast<double>(j) + 0.5) * gt[5];
  const Axis ax = ascending_axis(xs, path, "x (columns)");
  const Axis ay = ascending_axis(ys, path, "y (rows)");
  f.x = ax.values;
  f.y = ay.values;
  for (int b = 1; b <= 2; ++b) {
    GDALRasterBand& band = *ds.GetRasterBand(b);
    std::vector<double> buf(nx * ny);
    if (band.RasterIO(GF_Read, 0, 0, static_cast<int>(nx), static_cast<int>(ny), buf.data(), static_cast<int>(nx),
                      static_cast<int>(ny), GDT_Float64, 0, 0, nullptr) != CE_None) {
      throw InputError(path + ": band " + std::to_string(b) +
                       ": expected readable cells, got: " + printable(gdal::QuietErrors::last_message(), 160));
    }
    Unpack unpack;
    int has = 0;
    unpack.fill = band.GetNoDataValue(&has);
    unpack.has_fill = has != 0;
    unpack.float32 = band.GetRasterDataType() == GDT_Float32;
    int ok = 0;
    const double s = band.GetScale(&ok);
    if (ok) unpack.scale = s;
    const double o = band.GetOffset(&ok);
    if (ok) unpack.offset = o;
    std::vector<double>& out = b == 1 ? f.u : f.v;
    out.resize(nx * ny);
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t si = ax.reversed ? nx - 1 - i : i, sj = ay.reversed ? ny - 1 - j : j;
        out[j * nx + i] = unpack(buf[sj * nx + si]);
      }
  }
  set_extent(f, *srs);
  return f;
}

}  // namespace

// ------------------------------------------------------------------ public

CurrentField load_current_field(const std::string& path, const CurrentOptions& options) {
  gdal::ensure_registered();
  gdal::QuietErrors quiet;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": expected an existing current field file, found none");
  if (fs::is_directory(path, ec)) throw InputError(path + ": expected a current field file, got a folder");
  if (!(std::isfinite(options.depth_m) && options.depth_m >= 0)) {
    throw InputError(path + ": depth: expected a depth >= 0 m, got " + fixed(options.depth_m, 3));
  }
  // Before GDAL sees it: the netCDF library, given a classic header whose
  // counts were damaged, allocated 12.8 GB and took 56 s to give up (found by
  // fuzz/fuzz_current_nc); the header walk refuses such a file at once.
  require_complete_netcdf(path);
  // Only the drivers of the formats docs/FORMATS.md lists: GDAL probes a file
  // with every driver it has, and each is a parser a damaged file can reach.
  static const char* const multidim[] = {"netCDF", "HDF5", "Zarr", nullptr};
  static const char* const two_band[] = {"GTiff", "netCDF", "HDF5Image", "Zarr", "GRIB", "ENVI", "EHdr", nullptr};
  {
    GDALDatasetUniquePtr md = gdal::open_dataset(path, GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY, multidim);
    if (md) return load_multidim(*md, path, options);
  }
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_RASTER | GDAL_OF_READONLY, two_band);
  if (!ds || ds->GetRasterCount() == 0) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(
        path + ": expected a current field GDAL can open (NetCDF with u/v or a two-band raster)" +
        (why.empty() ? std::string(", got a file no driver recognises") : ", got: " + printable(why, 160)));
  }
  require_complete_raster(*ds, path);
  return load_two_band(*ds, path, options);
}

CurrentField parse_constant_current(const std::string& text, const std::string& what) {
  const std::string expected =
      "SPEED_MPS,DIR_DEG (speed >= 0 m/s, direction it sets towards, clockwise from true north)";
  const auto comma = text.find(',');
  double v[2] = {0.0, 0.0};
  bool ok = comma != std::string::npos && text.find(',', comma + 1) == std::string::npos;
  for (int i = 0; ok && i < 2; ++i) {
    const std::string part = trim(i == 0 ? text.substr(0, comma) : text.substr(comma + 1));
    const char* first = part.data();
    const char* last = part.data() + part.size();
    if (first < last && *first == '+') ++first;
    auto [ptr, e] = std::from_chars(first, last, v[i]);
    ok = e == std::errc() && ptr == last && std::isfinite(v[i]);
  }
  if (!ok) throw InputError(what + ": expected " + expected + ", got '" + printable(text) + "'");
  if (v[0] < 0) throw InputError(what + ": expected a speed >= 0 m/s, got " + printable(text));
  CurrentField f;
  f.source = what;
  f.driver = "constant";
  f.constant = true;
  f.crs = "EPSG:4326";
  f.crs_source = "constant (true north)";
  f.geographic = true;
  f.depth_levels = "constant";
  f.constant_velocity = v[0] * vector_of_course_deg(v[1]);
  // sin(180 deg) is not 0 in doubles: keep the exact axis directions exact.
  for (int i = 0; i < 2; ++i)
    if (std::abs(f.constant_velocity[i]) < 1e-15 * v[0]) f.constant_velocity[i] = 0.0;
  return f;
}

}  // namespace deepguide
