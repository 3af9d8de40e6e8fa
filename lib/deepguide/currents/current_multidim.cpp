// Current fields in multidimensional files (NetCDF, HDF5, Zarr) through
// GDAL's multidimensional API: the u and v arrays found by name or CF
// standard name, their dimensions' roles, the CRS, the time steps and the
// depth level (or two, interpolated) at the operating depth.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_reading.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide::current_detail {
namespace {

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

// How the array's raw values become m/s: its fill and missing values, scale and offset.
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

// "3 x 4 x 5": the sizes of the dimensions, for messages.
std::string shape(const std::vector<std::shared_ptr<GDALDimension>>& d) {
  std::string s;
  for (const auto& x : d) s += (s.empty() ? "" : " x ") + std::to_string(x->GetSize());
  return s.empty() ? std::string("scalar") : s;
}

// Which of the array's dimensions is x (lon), y (lat), z (depth) and t
// (time), -1 for none; any other must have size 1.
struct Dims {
  int x = -1, y = -1, z = -1, t = -1;
};

Dims dimension_roles(const std::vector<std::shared_ptr<GDALDimension>>& du, const std::string& path,
                     const std::string& u_name) {
  int ix = -1, iy = -1, iz = -1, it = -1;
  for (std::size_t i = 0; i < du.size(); ++i) {
    const Role r = role_of(*du[i]);
    int* slot = r == Role::x ? &ix : r == Role::y ? &iy : r == Role::z ? &iz : r == Role::t ? &it : nullptr;
    if (slot != nullptr && *slot < 0) {
      *slot = static_cast<int>(i);
    } else if (du[i]->GetSize() != 1) {
      throw InputError(path + ": variable '" + printable(u_name) + "': dimension '" + printable(du[i]->GetName()) +
                       "': expected lon/x, lat/y, depth or time, got a dimension of size " +
                       std::to_string(du[i]->GetSize()) + " with no such role");
    }
  }
  if (ix < 0 || iy < 0) {
    throw InputError(path + ": variable '" + printable(u_name) +
                     "': expected horizontal dimensions (lon/x and lat/y), got " + shape(du));
  }
  return {ix, iy, iz, it};
}

// The CRS: CF lon/lat axes, the array's grid mapping, or the assumed one;
// `source` says which.
std::unique_ptr<OGRSpatialReference> field_crs(const GDALMDArray& u, const std::shared_ptr<GDALMDArray>& xvar,
                                               const std::shared_ptr<GDALMDArray>& yvar, const CurrentOptions& options,
                                               const std::string& path, std::string& srs_source) {
  auto is_lon = [](const std::shared_ptr<GDALMDArray>& a) {
    return a && (ascii_lower(a->GetUnit()).rfind("degrees_e", 0) == 0 || ascii_lower(a->GetUnit()) == "degree_east" ||
                 ascii_lower(attr_string(*a, "standard_name")) == "longitude");
  };
  auto is_lat = [](const std::shared_ptr<GDALMDArray>& a) {
    return a && (ascii_lower(a->GetUnit()).rfind("degrees_n", 0) == 0 || ascii_lower(a->GetUnit()) == "degree_north" ||
                 ascii_lower(attr_string(*a, "standard_name")) == "latitude");
  };
  std::unique_ptr<OGRSpatialReference> srs;
  const auto file_srs = u.GetSpatialRef();
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
  return srs;
}

// The time steps into f.times_s (none without a time axis); returns their number.
std::size_t read_times(CurrentField& f, const std::vector<std::shared_ptr<GDALDimension>>& du, int it,
                       const std::string& path) {
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
  return nt;
}

// The level at the operating depth, or the two around it with the weight of the deeper.
struct Levels {
  std::size_t k0 = 0, k1 = 0;
  double wk = 0.0;
};

Levels depth_levels(CurrentField& f, const std::vector<std::shared_ptr<GDALDimension>>& du, int iz,
                    const CurrentOptions& options, const std::string& path) {
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

  return {k0, k1, wk};
}

struct Layout {
  Dims dims;
  Levels levels;
  std::size_t nx, ny, nt;
  bool x_reversed, y_reversed;
};

// All steps of one level of array `a` as [t][y][x], in the file's order of x and y.
std::vector<double> read_level(const GDALMDArray& a, const Layout& l, std::size_t level, const std::string& path) {
  const std::size_t plane = l.nx * l.ny;
  const std::size_t nd = a.GetDimensionCount();
  std::vector<GUInt64> start(nd, 0);
  std::vector<std::size_t> count(nd, 1);
  std::vector<GPtrDiff_t> stride(nd, 0);
  count[static_cast<std::size_t>(l.dims.x)] = l.nx;
  stride[static_cast<std::size_t>(l.dims.x)] = 1;
  count[static_cast<std::size_t>(l.dims.y)] = l.ny;
  stride[static_cast<std::size_t>(l.dims.y)] = static_cast<GPtrDiff_t>(l.nx);
  if (l.dims.t >= 0) {
    count[static_cast<std::size_t>(l.dims.t)] = l.nt;
    stride[static_cast<std::size_t>(l.dims.t)] = static_cast<GPtrDiff_t>(plane);
  }
  if (l.dims.z >= 0) start[static_cast<std::size_t>(l.dims.z)] = level;
  std::vector<double> buf(plane * l.nt);
  if (!a.Read(start.data(), count.data(), nullptr, stride.data(), GDALExtendedDataType::Create(GDT_Float64), buf.data(),
              buf.data(), buf.size() * sizeof(double))) {
    throw InputError(path + ": variable '" + printable(a.GetName()) +
                     "': expected readable values, got: " + printable(gdal::QuietErrors::last_message(), 160));
  }
  const Unpack unpack = unpack_of(a);
  for (double& v : buf) v = unpack(v);
  return buf;
}

// One component at the depth, all steps, as [t][y][x] ascending in x and y.
std::vector<double> read_component(const GDALMDArray& a, const Layout& l, const std::string& path) {
  const auto [k0, k1, wk] = l.levels;
  std::vector<double> out = read_level(a, l, k0, path);
  if (k1 != k0) {
    const std::vector<double> deeper = read_level(a, l, k1, path);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = out[i] + wk * (deeper[i] - out[i]);  // NaN stays NaN
  }
  if (!l.x_reversed && !l.y_reversed) return out;
  const std::size_t nx = l.nx, ny = l.ny;
  std::vector<double> flipped(out.size());
  for (std::size_t k = 0; k < l.nt; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t si = l.x_reversed ? nx - 1 - i : i, sj = l.y_reversed ? ny - 1 - j : j;
        flipped[(k * ny + j) * nx + i] = out[(k * ny + sj) * nx + si];
      }
  return flipped;
}

}  // namespace

CurrentField load_multidim(GDALDataset& ds, const std::string& path, const CurrentOptions& options) {
  const auto root = ds.GetRootGroup();
  if (!root) throw InputError(path + ": expected a NetCDF file with a root group, got none");
  const Variables vars = find_uv(*root, path, options);
  const auto& du = vars.u->GetDimensions();
  const auto& dv = vars.v->GetDimensions();
  bool same = du.size() == dv.size();
  for (std::size_t i = 0; same && i < du.size(); ++i) same = du[i]->GetSize() == dv[i]->GetSize();
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

  const Dims dims = dimension_roles(du, path, f.u_name);
  const auto xvar = du[static_cast<std::size_t>(dims.x)]->GetIndexingVariable();
  const auto yvar = du[static_cast<std::size_t>(dims.y)]->GetIndexingVariable();

  std::string srs_source;
  const std::unique_ptr<OGRSpatialReference> srs = field_crs(*vars.u, xvar, yvar, options, path, srs_source);
  if (!xvar || !yvar) {
    throw InputError(path + ": variable '" + printable(f.u_name) +
                     "': expected coordinate variables for its horizontal dimensions, got none");
  }
  set_crs(f, *srs, srs_source);
  const Axis ax = ascending_axis(read_vector(*xvar, path), path, xvar->GetName());
  const Axis ay = ascending_axis(read_vector(*yvar, path), path, yvar->GetName());
  f.x = ax.values;
  f.y = ay.values;

  const std::size_t nt = read_times(f, du, dims.t, path);
  check_size(path, f.nx(), f.ny(), nt, options);

  const Levels levels = depth_levels(f, du, dims.z, options, path);
  const Layout layout{dims, levels, f.nx(), f.ny(), nt, ax.reversed, ay.reversed};
  f.u = read_component(*vars.u, layout, path);
  f.v = read_component(*vars.v, layout, path);
  set_extent(f, *srs);
  return f;
}

}  // namespace deepguide::current_detail
