// delaunay/incremental/bowyer_watson.cpp: the one-shot kernel: the first simplex, the insertions, the export.
#include "delaunay/incremental/bowyer_watson.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "delaunay/incremental/cell_complex.hpp"
#include "delaunay/incremental/cell_predicates.hpp"
#include "drange/errors.hpp"

namespace drange::engine {
namespace {

// d points of the hull facet and the first point off its hyperplane, positively oriented.
std::vector<std::int32_t> first_simplex(const PointStore& points, const FirstFacet& first,
                                        const std::vector<std::int32_t>& order) {
  const int d = points.dim;
  std::vector<std::int32_t> ids(first.ids);
  ids.push_back(-1);
  std::vector<const double*> rows(static_cast<std::size_t>(d + 1));
  for (int i = 0; i < d; ++i) rows[static_cast<std::size_t>(i)] = points.point(ids[static_cast<std::size_t>(i)]);
  for (const std::int32_t x : order) {
    rows[static_cast<std::size_t>(d)] = points.point(x);
    const int s = geometry::simplex_orientation(d, rows.data());
    if (s == 0) continue;
    ids[static_cast<std::size_t>(d)] = x;
    if (s < 0) std::swap(ids[0], ids[1]);
    return ids;
  }
  throw InternalError("incremental: the first facet's hyperplane holds every point");
}

}  // namespace

IncrementalCounters triangulate_incrementally(const PointStore& points, const FirstFacet& first,
                                              const std::vector<std::int32_t>& order, Triangulation& result,
                                              bool record_neighbors, const std::function<void(std::size_t)>& progress) {
  IncrementalCounters counters;
  const std::vector<std::int32_t> start = first_simplex(points, first, order);
  const KernelPoints view = kernel_points(points);
  Insertion insertion(view, static_cast<std::size_t>(points.size), counters);
  insertion.start(start.data());
  // Options::progress's contract: multiples of kProgressInterval, increasing (the finite cells
  // can decrease by an insertion; a report waits until their count passes the next multiple).
  std::size_t next_report = kProgressInterval;
  for (const std::int32_t q : order) {
    if (std::find(start.begin(), start.end(), q) != start.end()) continue;
    insertion.insert(q);
    if (insertion.finite_cells() >= next_report) {
      if (progress) progress(next_report);
      next_report += kProgressInterval;
    }
  }
  counters.unfiltered_tests = insertion.unfiltered_tests();
  export_cells(insertion.cells(), result, record_neighbors);
  return counters;
}


void export_cells(const CellComplex& cells, Triangulation& result, bool record_neighbors) {
  const int width = cells.width();
  std::vector<std::int32_t> number(cells.capacity(), -1);
  std::int32_t finite = 0, hull = 0;
  for (std::size_t c = 0; c < cells.capacity(); ++c) {
    const auto cell = static_cast<std::int32_t>(c);
    if (cells.removed(cell)) continue;
    if (cells.infinite_position(cell) >= 0) ++hull;
    else number[c] = finite++;
  }
  result.simplices.resize(static_cast<std::size_t>(finite) * static_cast<std::size_t>(width));
  result.neighbors.clear();
  if (record_neighbors) result.neighbors.resize(result.simplices.size());
  for (std::size_t c = 0; c < cells.capacity(); ++c) {
    if (number[c] < 0) continue;
    const auto cell = static_cast<std::int32_t>(c);
    const std::size_t row = static_cast<std::size_t>(number[c]) * static_cast<std::size_t>(width);
    std::copy(cells.vertices(cell), cells.vertices(cell) + width, result.simplices.begin() + static_cast<std::ptrdiff_t>(row));
    if (record_neighbors)
      for (int k = 0; k < width; ++k) result.neighbors[row + static_cast<std::size_t>(k)] = number[static_cast<std::size_t>(cells.neighbors(cell)[k])];
  }
  result.stats.hull_facets = static_cast<std::size_t>(hull);
}

}  // namespace drange::engine
