// delaunay/algorithm_choice.hpp: Options::algorithm "auto": which construction to run.
//
// The direct search's work per simplex is constant on points spread through space, and grows
// where its Delaunay balls run along a band of points: on samples of surfaces, each simplex
// costs about the square root of n kd-tree nodes. The incremental kernel's work does not depend
// on the shape, but it runs on one thread, and on spread points the direct search, with its
// threads, is faster. So "auto" measures: it runs the direct search, on one thread, on a
// random sample of the points (the first rounds of the incremental insertion order), and
// takes the incremental kernel when the kd-tree nodes entered plus the points tested per
// simplex exceed twice what uniform points take, unless (in 3D) the kernel, run on the sample
// too, is slower still by a model of both constructions' costs from their counts, the search's
// extrapolated to n from the sample and a quarter of it (on points near one sphere, whose
// signs the kernel leaves to the exact stages). The measures are
// counts, not times: the choice, and so the output, is the same on every machine and every
// thread count.
// From 4D on the direct search stays: there its exact stages outrun the incremental kernel's
// generic predicates on the inputs full of ties where the search is also slow.
#pragma once

#include <cstdint>
#include <vector>

#include "delaunay/point_store.hpp"

namespace drange::engine {

// Whether "auto" probes these points at all (2D and 3D, enough of them); if not, it runs the
// direct search.
bool worth_probing(const PointStore& points);
// True when Options::algorithm "auto" should run the incremental kernel on these points, for
// which worth_probing holds. `order`: their insertion order (insertion_order.hpp), whose
// first points are the sample.
bool prefer_incremental(const PointStore& points, const std::vector<std::int32_t>& order);

}  // namespace drange::engine
