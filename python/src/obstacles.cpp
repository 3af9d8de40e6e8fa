// deepguide.read_obstacles: obstacle files as NumPy arrays in one planning
// frame, read by the library's reader (load_obstacles) as `plan` reads them,
// so `plan(..., ellipses=obstacles.ellipses, crs=obstacles.crs)` plans among
// the same ellipses.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

struct Obstacles {
  LoadedObstacles loaded;

  // Rows x, y (the frame), semi_major_m, semi_minor_m, orientation_deg: plan's `ellipses`.
  py::array_t<double> ellipses() const {
    const auto& es = loaded.obstacles.ellipses;
    py::array_t<double> out({static_cast<py::ssize_t>(es.size()), py::ssize_t{5}});
    auto o = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < es.size(); ++i) {
      const EllipseFields f = ellipse_fields(loaded.frame, es[i].footprint);
      o(i, 0) = es[i].footprint.centre.x(), o(i, 1) = es[i].footprint.centre.y();
      o(i, 2) = f.semi_major_m, o(i, 3) = f.semi_minor_m, o(i, 4) = f.orientation_deg;
    }
    return out;
  }
  // Per polygon its rings in the frame, the outline first.
  py::list polygons() const {
    py::list out;
    for (const PolygonObstacle& p : loaded.obstacles.polygons) {
      py::list rings;
      const auto add = [&](const auto& ring) {
        py::array_t<double> a({static_cast<py::ssize_t>(ring.size()), py::ssize_t{2}});
        auto o = a.template mutable_unchecked<2>();
        for (std::size_t i = 0; i < ring.size(); ++i) o(i, 0) = ring[i].x(), o(i, 1) = ring[i].y();
        rings.append(a);
      };
      add(p.footprint.outer());
      for (const auto& inner : p.footprint.inners()) add(inner);
      out.append(rings);
    }
    return out;
  }
};

}  // namespace

void bind_obstacles(py::module_& m) {
  py::class_<Obstacles>(m, "Obstacles", "Obstacle files read into one planning frame.")
      .def_property_readonly(
          "crs", [](const Obstacles& o) { return o.loaded.frame.id(); }, "The planning frame, e.g. 'EPSG:32632'.")
      .def_property_readonly("ellipses", &Obstacles::ellipses,
                             "An (n, 5) array: x, y in the frame, semi_major_m, semi_minor_m (true metres), "
                             "orientation_deg (clockwise from true north): plan's `ellipses`.")
      .def_property_readonly("ellipse_ids",
                             [](const Obstacles& o) {
                               std::vector<std::string> ids;
                               for (const auto& e : o.loaded.obstacles.ellipses) ids.push_back(e.id);
                               return ids;
                             })
      .def_property_readonly("polygons", &Obstacles::polygons,
                             "Per polygon obstacle its rings in the frame, (k, 2) arrays, the outline first.")
      .def_property_readonly("polygon_ids",
                             [](const Obstacles& o) {
                               std::vector<std::string> ids;
                               for (const auto& p : o.loaded.obstacles.polygons) ids.push_back(p.id);
                               return ids;
                             })
      .def("__len__", [](const Obstacles& o) { return o.loaded.obstacles.size(); })
      .def("__repr__", [](const Obstacles& o) {
        return "Obstacles(" + std::to_string(o.loaded.obstacles.ellipses.size()) + " ellipses, " +
               std::to_string(o.loaded.obstacles.polygons.size()) + " polygons, crs='" + o.loaded.frame.id() + "')";
      });

  m.def(
      "read_obstacles",
      [](const std::vector<std::filesystem::path>& paths, const std::string& crs, const std::string& src_crs) {
        const std::vector<std::string> files = path_texts(paths);
        py::gil_scoped_release free;
        return Obstacles{load_obstacles(files, {crs, src_crs})};
      },
      py::arg("paths"), py::kw_only(), py::arg("crs") = "", py::arg("src_crs") = "",
      "Reads obstacle files (GeoJSON, GeoPackage, CSV, an obstacle store, ...) into one frame: `crs`, else the "
      "UTM zone of the obstacles, as `plan` chooses it.");
}

}  // namespace deepguide::python
