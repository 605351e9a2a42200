// python/src/hull_bindings.cpp: the convex hull's part of the `drange._drange` extension; the
// scipy-shaped drange.ConvexHull (drange/_hull.py) is built on it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "drange/hull.hpp"
#include "numpy_views.hpp"

namespace drange::python {
namespace {

// A hull and the points it was computed for.
struct Hulled {
  Points points;
  ConvexHull result;

  PointsView view() const { return PointsView(points.data(), result.num_points, result.dim); }
};

}  // namespace

void bind_hull(py::module_& m) {
  py::class_<Hulled>(m, "Hull")
      .def_property_readonly("simplices", [](py::object self) {
        const auto& h = self.cast<const Hulled&>();
        return table_view(h.result.simplices, static_cast<std::size_t>(h.result.dim), self);
      })
      .def_property_readonly("neighbors", [](py::object self) {
        const auto& h = self.cast<const Hulled&>();
        return table_view(h.result.neighbors, static_cast<std::size_t>(h.result.dim), self);
      })
      .def_property_readonly("vertices", [](py::object self) {
        const auto& v = self.cast<const Hulled&>().result.vertices;
        return view(v, {static_cast<py::ssize_t>(v.size())}, self);
      })
      .def_property_readonly("coplanar", [](py::object self) {
        return table_view(self.cast<const Hulled&>().result.coplanar, 3, self);
      })
      .def("geometry", [](const Hulled& h) {
        HullGeometry g;
        {
          py::gil_scoped_release release;
          g = hull_geometry(h.view(), h.result);
        }
        const auto rows = static_cast<py::ssize_t>(h.result.size());
        return py::make_tuple(adopt(std::move(g.equations), {rows, static_cast<py::ssize_t>(h.result.dim + 1)}), g.area, g.volume);
      })
      .def("vertex_groups", [](const Hulled& h, const Points& halfspaces) {
        std::vector<std::int32_t> groups = vertex_groups(points_view(halfspaces, "halfspaces"), h.result);
        const auto rows = static_cast<py::ssize_t>(groups.size());
        return adopt(std::move(groups), {rows});
      }, py::arg("halfspaces"))
      .def("facet_sides", [](const Hulled& h, const Points& x) {
        if (x.ndim() != 1 || x.shape(0) != h.result.dim)
          throw py::value_error("the point must have " + std::to_string(h.result.dim) + " coordinates");
        std::vector<std::int8_t> sides = facet_sides(h.view(), h.result, x.data());
        const auto rows = static_cast<py::ssize_t>(sides.size());
        return adopt(std::move(sides), {rows});
      }, py::arg("x"));

  m.def("convex_hull", [](Points points) {
    const PointsView input = points_view(points, "points");
    auto hulled = std::make_unique<Hulled>();
    {
      py::gil_scoped_release release;
      hulled->result = convex_hull(input);
    }
    hulled->points = std::move(points);
    return hulled;
  }, py::arg("points"));
}

}  // namespace drange::python
