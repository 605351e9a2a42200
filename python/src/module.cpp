// python/src/module.cpp: the `drange._drange` extension. It exposes the engine's results as
// objects that own them, with NumPy views of their arrays; drange/__init__.py builds the
// scipy-shaped Delaunay and Voronoi classes on top.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "drange/check.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/incremental.hpp"
#include "drange/locate.hpp"
#include "drange/voronoi.hpp"
#include "numpy_views.hpp"
#include "run_interruptibly.hpp"

namespace drange::python {
namespace {

Options engine_options(const std::string& variant, const std::string& algorithm, int threads, PythonProgress& progress) {
  Options options;
  options.variant = variant;
  options.algorithm = algorithm;
  options.threads = threads;
  options.progress = progress.hook();
  return options;
}

// The user's figures at the top level; the engine's internal counters (Statistics::Debug)
// in statistics["debug"].
py::dict statistics_dict(const Statistics& s) {
  py::dict debug;
  debug["points_tested"] = s.debug.points_tested;
  debug["candidates"] = s.debug.candidates;
  debug["exact_fallbacks"] = s.debug.exact_fallbacks;
  debug["max_open_facets"] = s.debug.max_open_facets;
  debug["shell_spheres"] = s.debug.shell_spheres;
  debug["wasted_searches"] = s.debug.wasted_searches;
  debug["unfiltered_tests"] = s.debug.unfiltered_tests;
  py::dict d;
  d["points"] = s.points;
  d["distinct_points"] = s.distinct_points;
  d["simplices"] = s.simplices;
  d["hull_facets"] = s.hull_facets;
  d["search_calls"] = s.search_calls;
  d["calls_per_simplex"] = s.calls_per_simplex();
  d["threads"] = s.threads;
  d["algorithm"] = s.algorithm;
  d["seconds_kdtree"] = s.seconds_kdtree;
  d["seconds_first_facet"] = s.seconds_first_facet;
  d["seconds_choice"] = s.seconds_choice;
  d["seconds_search"] = s.seconds_search;
  d["seconds_busy"] = s.seconds_busy;
  d["seconds_critical_path"] = s.seconds_critical_path;
  d["seconds_total"] = s.seconds_total;
  d["peak_rss_bytes"] = s.peak_rss_bytes;
  d["debug"] = debug;
  return d;
}

// A triangulation and the points it was computed for (kept alive: the locator views them).
struct Triangulated {
  Points points;
  Triangulation result;
  std::unique_ptr<SimplexLocator> locator;  // built by the first find_simplex
  std::once_flag locator_built;             // find_simplex may run in several Python threads at once

  py::array_t<std::int32_t> find_simplex(const Points& queries, int threads) {
    const PointsView view = points_view(queries, "xi");
    if (view.dim != result.dim)
      throw py::value_error("wrong dimensionality in xi: " + std::to_string(view.dim) + " coordinates, the points have " +
                            std::to_string(result.dim));
    std::vector<std::int32_t> found(view.n);
    {
      py::gil_scoped_release release;
      std::call_once(locator_built, [&] {
        locator = std::make_unique<SimplexLocator>(PointsView(points.data(), result.num_points, result.dim), result);
      });
      locator->find(view, found.data(), threads);
    }
    return adopt(std::move(found), {static_cast<py::ssize_t>(view.n)});
  }
};

struct Diagram {
  Points points;
  Voronoi result;
  Statistics statistics;
};

// drange::IncrementalDelaunay for Python: each call runs without the GIL, so that other Python
// threads go on, and under the object's lock, so that no two change it at once (the GIL is let
// go before the lock is taken: a thread waiting for the lock never holds the GIL).
struct IncrementalState {
  std::unique_ptr<IncrementalDelaunay> engine;
  std::mutex lock;

  template <class Work>
  void run(Work&& work) {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> guard(lock);
    work(*engine);
  }
};

// A property getter: the diagram's vector `member` as a 1-D view.
template <class T>
auto diagram_array(std::vector<T> Voronoi::*member) {
  return [member](py::object self) {
    const std::vector<T>& data = self.cast<const Diagram&>().result.*member;
    return view(data, {static_cast<py::ssize_t>(data.size())}, self);
  };
}

// A property getter: one part (offsets or values) of the diagram's ragged lists `lists`.
template <class T>
auto diagram_lists(IndexLists Voronoi::*lists, std::vector<T> IndexLists::*part) {
  return [lists, part](py::object self) {
    const std::vector<T>& data = self.cast<const Diagram&>().result.*lists.*part;
    return view(data, {static_cast<py::ssize_t>(data.size())}, self);
  };
}

py::dict clipped_dict(const ClippedCells& cells) {
  py::dict d;
  const auto dim = static_cast<py::ssize_t>(cells.dim);
  d["lower"] = py::array_t<double>(dim, cells.box.lower.data());
  d["upper"] = py::array_t<double>(dim, cells.box.upper.data());
  d["points"] = py::array_t<double>({static_cast<py::ssize_t>(cells.points.size()) / dim, dim}, cells.points.data());
  d["face_offsets"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(cells.faces.offsets.size()), cells.faces.offsets.data());
  d["face_indices"] = py::array_t<std::int32_t>(static_cast<py::ssize_t>(cells.faces.values.size()), cells.faces.values.data());
  d["cell_faces"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(cells.cell_faces.size()), cells.cell_faces.data());
  d["volumes"] = py::array_t<double>(static_cast<py::ssize_t>(cells.volumes.size()), cells.volumes.data());
  return d;
}

// scipy.spatial.QhullError (a RuntimeError) where scipy is importable, so that code written for
// scipy catches drange's errors as it catches Qhull's; RuntimeError otherwise.
PyObject* error_base() {
  try {
    py::object base = py::module_::import("scipy.spatial").attr("QhullError");
    return base.release().ptr();  // a new reference, kept for the module's life
  } catch (py::error_already_set&) {  // no scipy: its error is cleared with the exception object
    return PyExc_RuntimeError;
  }
}

void register_errors(py::module_& m) {
  static PyObject* const error = PyErr_NewExceptionWithDoc(
      "drange.Error", "Base of the errors drange raises for reasons of its own (a scipy.spatial.QhullError "
      "when scipy is installed, else a RuntimeError).", error_base(), nullptr);
  static PyObject* const degenerate = PyErr_NewExceptionWithDoc(
      "drange.DegenerateInputError",
      "The points have no full-dimensional triangulation: fewer than ndim+1 distinct points, or all in one hyperplane.",
      error, nullptr);
  m.attr("Error") = py::handle(error);
  m.attr("DegenerateInputError") = py::handle(degenerate);
  // Bad input and bad arguments are ValueErrors, as in scipy; the engine's message is kept.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const DegenerateInputError& e) {
      PyErr_SetString(degenerate, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Error& e) {
      PyErr_SetString(error, e.what());
    }
  });
}

}  // namespace

void bind_hull(py::module_& m);  // hull_bindings.cpp

PYBIND11_MODULE(_drange, m) {
  m.doc() = "drange's engine; use the classes of the drange package.";
  register_errors(m);

  py::class_<Triangulated>(m, "Triangulated")
      .def_property_readonly("ndim", [](const Triangulated& t) { return t.result.dim; })
      .def_property_readonly("simplices", [](py::object self) {
        const auto& t = self.cast<const Triangulated&>();
        return table_view(t.result.simplices, static_cast<std::size_t>(t.result.dim + 1), self);
      })
      .def_property_readonly("neighbors", [](py::object self) {
        const auto& t = self.cast<const Triangulated&>();
        return table_view(t.result.neighbors, static_cast<std::size_t>(t.result.dim + 1), self);
      })
      .def_property_readonly("duplicates", [](const Triangulated& t) {
        std::vector<std::int64_t> pairs;
        for (const Duplicate& dup : t.result.duplicates) {
          pairs.push_back(dup.index);
          pairs.push_back(dup.original);
        }
        return adopt(std::move(pairs), {static_cast<py::ssize_t>(t.result.duplicates.size()), 2});
      })
      .def_property_readonly("statistics", [](const Triangulated& t) { return statistics_dict(t.result.stats); })
      .def("find_simplex", &Triangulated::find_simplex, py::arg("xi"), py::arg("threads"));

  py::class_<Diagram>(m, "Diagram")
      .def_property_readonly("vertices", [](py::object self) {
        const auto& v = self.cast<const Diagram&>().result;
        return table_view(v.vertices, static_cast<std::size_t>(v.dim), self);
      })
      .def_property_readonly("ridge_points", [](py::object self) {
        return table_view(self.cast<const Diagram&>().result.ridge_points, 2, self);
      })
      .def_property_readonly("simplex_vertex", diagram_array(&Voronoi::simplex_vertex))
      .def_property_readonly("point_region", diagram_array(&Voronoi::point_region))
      .def_property_readonly("region_point", diagram_array(&Voronoi::region_point))
      .def_property_readonly("volumes", diagram_array(&Voronoi::volumes))
      .def_property_readonly("ridge_offsets", diagram_lists(&Voronoi::ridge_vertices, &IndexLists::offsets))
      .def_property_readonly("ridge_indices", diagram_lists(&Voronoi::ridge_vertices, &IndexLists::values))
      .def_property_readonly("region_offsets", diagram_lists(&Voronoi::regions, &IndexLists::offsets))
      .def_property_readonly("region_indices", diagram_lists(&Voronoi::regions, &IndexLists::values))
      .def_property_readonly("statistics", [](const Diagram& d) { return statistics_dict(d.statistics); })
      .def("clip", [](const Diagram& d, std::vector<double> lower, std::vector<double> upper) {
        ClippedCells cells;
        {
          py::gil_scoped_release release;
          cells = clip_cells(PointsView(d.points.data(), d.result.num_points, d.result.dim), d.result,
                             Box{std::move(lower), std::move(upper)});
        }
        return clipped_dict(cells);
      }, py::arg("lower"), py::arg("upper"));

  m.def("triangulate", [](Points points, const std::string& variant, const std::string& algorithm, int threads,
                          py::object progress) {
    const PointsView input = points_view(points, "points");
    PythonProgress reporter(std::move(progress));
    const Options options = engine_options(variant, algorithm, threads, reporter);
    auto triangulated = std::make_unique<Triangulated>();
    triangulated->result = reporter.run([&] { return delaunay(input, options); });
    triangulated->points = std::move(points);
    return triangulated;
  }, py::arg("points"), py::arg("variant"), py::arg("algorithm"), py::arg("threads"), py::arg("progress"));

  m.def("stars", [](Points points, std::vector<std::int64_t> ids, const std::string& variant, int threads) {
    const PointsView input = points_view(points, "points");
    PythonProgress reporter{py::none()};
    const Options options = engine_options(variant, "auto", threads, reporter);
    auto triangulated = std::make_unique<Triangulated>();
    triangulated->result = reporter.run([&] { return delaunay_stars(input, ids, options); });
    triangulated->points = std::move(points);
    return triangulated;
  }, py::arg("points"), py::arg("ids"), py::arg("variant"), py::arg("threads"));

  m.def("voronoi", [](Points points, const std::string& variant, const std::string& algorithm, int threads,
                      bool cell_volumes, py::object progress) {
    const PointsView input = points_view(points, "points");
    PythonProgress reporter(std::move(progress));
    VoronoiOptions options;
    options.delaunay = engine_options(variant, algorithm, threads, reporter);
    options.cell_volumes = cell_volumes;
    auto diagram = std::make_unique<Diagram>();
    diagram->result = reporter.run([&] {
      const Triangulation triangulation = delaunay(input, options.delaunay);
      diagram->statistics = triangulation.stats;
      return voronoi(input, triangulation, options);
    });
    diagram->points = std::move(points);
    return diagram;
  }, py::arg("points"), py::arg("variant"), py::arg("algorithm"), py::arg("threads"), py::arg("cell_volumes"),
     py::arg("progress"));

  m.def("voronoi_cells", [](Points points, std::vector<std::int64_t> ids, const std::string& variant, int threads,
                            bool cell_volumes) {
    const PointsView input = points_view(points, "points");
    PythonProgress reporter{py::none()};
    VoronoiOptions options;
    options.delaunay = engine_options(variant, "auto", threads, reporter);
    options.cell_volumes = cell_volumes;
    auto diagram = std::make_unique<Diagram>();
    diagram->result = reporter.run([&] { return voronoi_cells(input, ids, options); });
    diagram->points = std::move(points);
    return diagram;
  }, py::arg("points"), py::arg("ids"), py::arg("variant"), py::arg("threads"), py::arg("cell_volumes"));

  // The incremental triangulation: the caller (drange.Delaunay, drange.Voronoi) keeps the
  // array of every point added and passes it to each result, which views it.
  py::class_<IncrementalState>(m, "IncrementalDelaunay")
      .def(py::init([](const Points& points, bool furthest_site) {
        const PointsView input = points_view(points, "points");
        auto state = std::make_unique<IncrementalState>();
        py::gil_scoped_release release;
        state->engine = std::make_unique<IncrementalDelaunay>(input, furthest_site);
        return state;
      }), py::arg("points"), py::arg("furthest_site") = false)
      .def("add_points", [](IncrementalState& t, const Points& points) {
        const PointsView input = points_view(points, "points");
        t.run([&](IncrementalDelaunay& engine) { engine.add_points(input); });
      }, py::arg("points"))
      .def("natural_neighbours", [](IncrementalState& t, const Points& queries) {
        const PointsView input = points_view(queries, "xi");
        IncrementalDelaunay::NaturalNeighbours found;
        t.run([&](IncrementalDelaunay& engine) { found = engine.natural_neighbours(input); });
        std::vector<std::int64_t> offsets(found.offsets.begin(), found.offsets.end());
        const auto count = static_cast<py::ssize_t>(found.ids.size());
        return py::make_tuple(adopt(std::move(offsets), {static_cast<py::ssize_t>(found.offsets.size())}),
                              adopt(std::move(found.ids), {count}), adopt(std::move(found.weights), {count}));
      }, py::arg("queries"))
      .def("triangulated", [](IncrementalState& t, Points all_points) {
        auto triangulated = std::make_unique<Triangulated>();
        t.run([&](IncrementalDelaunay& engine) { triangulated->result = engine.triangulation(); });
        triangulated->points = std::move(all_points);
        return triangulated;
      }, py::arg("all_points"))
      .def("diagram", [](IncrementalState& t, Points all_points, bool cell_volumes) {
        const PointsView input = points_view(all_points, "points");
        VoronoiOptions options;
        options.cell_volumes = cell_volumes;
        auto diagram = std::make_unique<Diagram>();
        t.run([&](IncrementalDelaunay& engine) {
          const Triangulation triangulation = engine.triangulation();
          diagram->statistics = triangulation.stats;
          diagram->result = voronoi(input, triangulation, options);
        });
        diagram->points = std::move(all_points);
        return diagram;
      }, py::arg("all_points"), py::arg("cell_volumes"));

  m.def("default_clip_box", [](Points points, double margin) {
    const Box box = default_clip_box(points_view(points, "points"), margin);
    return py::make_tuple(py::array_t<double>(static_cast<py::ssize_t>(box.lower.size()), box.lower.data()),
                          py::array_t<double>(static_cast<py::ssize_t>(box.upper.size()), box.upper.data()));
  }, py::arg("points"), py::arg("margin"));

  m.def("check_triangulation", [](Points points, py::array_t<std::int32_t, py::array::c_style | py::array::forcecast> simplices,
                                  std::size_t max_problems) {
    const PointsView input = points_view(points, "points");
    if (simplices.ndim() != 2 || simplices.shape(1) != input.dim + 1)
      throw py::value_error("simplices must be a 2-D array with ndim+1 = " + std::to_string(input.dim + 1) + " columns");
    const std::vector<std::int32_t> rows(simplices.data(), simplices.data() + simplices.size());
    CheckReport report;
    {
      py::gil_scoped_release release;
      report = check_triangulation(input, rows, max_problems);
    }
    py::dict d;
    d["valid"] = report.valid;
    d["problems"] = report.problems;
    d["problem_count"] = report.problem_count;
    d["simplices"] = report.simplices;
    d["interior_facets"] = report.interior_facets;
    d["boundary_facets"] = report.boundary_facets;
    return d;
  }, py::arg("points"), py::arg("simplices"), py::arg("max_problems"));

  bind_hull(m);
  m.attr("variant_names") = variant_names();
  m.attr("algorithm_names") = algorithm_names();
}

}  // namespace drange::python
