// bench/micro_predicates.cpp: Google Benchmark microbenchmarks of the exact predicates
// (src/geometry/predicates.hpp), of one facet search (src/delaunay/facet_search.hpp), of the
// point preparation and the kd-tree build (src/delaunay/prepare_points.hpp,
// src/spatial/kdtree.hpp) and of a whole triangulation of 10 000 uniform 2D points.
//
// Predicates in d = 2, 3, 5 on three kinds of input:
//   random   uniform points in [0,1)^d: the floating-point filter decides;
//   cube     vertices of the integer cube {0,1}^d, all cospherical: exact ties (zero), decided
//            by the static "no rounding happened" check on dyadic coordinates or by GMP;
//   decimal  vertices of the cube {0.1,0.3}^d: cospherical before rounding to doubles, so the
//            determinants are tiny and must be decided exactly (GMP).
// Each iteration evaluates one predicate on the next of 1024 pre-generated tuples.
//
// Facet search: FacetSearch::find_apex on interior facets of a finished triangulation (the
// facet of a simplex opposite one vertex, searched on the other side), cycling over 4096 facets.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "delaunay/facet_search.hpp"
#include "delaunay/prepare_points.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "geometry/predicates.hpp"
#include "spatial/kdtree.hpp"

namespace {

using drange::geometry::Frame;

enum Kind { kRandom = 0, kCube = 1, kDecimal = 2 };
const char* const kKindNames[] = {"random", "cube", "decimal"};

// 1024 tuples of d+2 points: a simplex s_0..s_d and a query point q (last).
struct Tuples {
  int d = 0;
  std::vector<double> coords;  // tuple t, point i, coordinate k at ((t*(d+2))+i)*d + k
  const double* point(std::size_t t, int i) const { return &coords[(t * static_cast<std::size_t>(d + 2) + static_cast<std::size_t>(i)) * static_cast<std::size_t>(d)]; }
};
constexpr std::size_t kTuples = 1024;

Tuples make_tuples(int d, Kind kind) {
  Tuples t;
  t.d = d;
  std::mt19937_64 rng(12345 + static_cast<unsigned>(d * 10 + kind));
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (std::size_t n = 0; n < kTuples; ++n) {
    if (kind == kRandom) {
      for (int i = 0; i < (d + 2) * d; ++i) t.coords.push_back(uniform(rng));
      continue;
    }
    // A corner simplex of the cube at a random vertex v: v, v^e_1, ..., v^e_d, and the query
    // q = v^(e_a + e_b), another vertex: all on the cube's circumsphere.
    std::vector<int> v(static_cast<std::size_t>(d));
    for (int& c : v) c = static_cast<int>(rng() & 1);
    std::vector<std::vector<int>> rows{v};
    for (int i = 0; i < d; ++i) {
      rows.push_back(v);
      rows.back()[static_cast<std::size_t>(i)] ^= 1;
    }
    const int a = static_cast<int>(rng() % static_cast<unsigned>(d));
    const int b = (a + 1 + static_cast<int>(rng() % static_cast<unsigned>(d - 1))) % d;
    rows.push_back(v);
    rows.back()[static_cast<std::size_t>(a)] ^= 1;
    rows.back()[static_cast<std::size_t>(b)] ^= 1;
    for (const auto& row : rows)
      for (int c : row) t.coords.push_back(kind == kCube ? double(c) : (c ? 0.3 : 0.1));
  }
  return t;
}

void set_label(benchmark::State& state, int d, Kind kind) {
  state.SetLabel(std::to_string(d) + "D " + kKindNames[kind]);
}

void BM_Orientation(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const Kind kind = static_cast<Kind>(state.range(1));
  const Tuples t = make_tuples(d, kind);
  std::vector<const double*> rows(static_cast<std::size_t>(d));
  std::size_t n = 0;
  for (auto _ : state) {
    const Frame frame{d, d, nullptr, t.point(n, 0)};
    for (int i = 0; i < d; ++i) rows[static_cast<std::size_t>(i)] = t.point(n, i + 1);
    benchmark::DoNotOptimize(drange::geometry::orientation(frame, rows.data()));
    n = (n + 1) % kTuples;
  }
  set_label(state, d, kind);
}

void BM_LiftedSign(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const Kind kind = static_cast<Kind>(state.range(1));
  const Tuples t = make_tuples(d, kind);
  std::vector<const double*> rows(static_cast<std::size_t>(d + 1));
  std::size_t n = 0;
  for (auto _ : state) {
    const Frame frame{d, d, nullptr, t.point(n, 0)};
    for (int i = 0; i <= d; ++i) rows[static_cast<std::size_t>(i)] = t.point(n, i + 1);
    benchmark::DoNotOptimize(drange::geometry::lifted_sign(frame, rows.data()));
    n = (n + 1) % kTuples;
  }
  set_label(state, d, kind);
}

void BM_LiftedSignPerturbed(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const Kind kind = static_cast<Kind>(state.range(1));
  const Tuples t = make_tuples(d, kind);
  std::vector<const double*> rows(static_cast<std::size_t>(d + 1));
  std::vector<std::int64_t> ranks(static_cast<std::size_t>(d + 2));
  std::iota(ranks.begin(), ranks.end(), 0);
  std::mt19937_64 rng(7);
  std::size_t n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::shuffle(ranks.begin(), ranks.end(), rng);
    state.ResumeTiming();
    const Frame frame{d, d, nullptr, t.point(n, 0)};
    for (int i = 0; i <= d; ++i) rows[static_cast<std::size_t>(i)] = t.point(n, i + 1);
    benchmark::DoNotOptimize(drange::geometry::lifted_sign_perturbed(frame, rows.data(), ranks.data()));
    n = (n + 1) % kTuples;
  }
  set_label(state, d, kind);
}

void BM_InSphere(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const Kind kind = static_cast<Kind>(state.range(1));
  const Tuples t = make_tuples(d, kind);
  std::vector<const double*> simplex(static_cast<std::size_t>(d + 1));
  std::size_t n = 0;
  for (auto _ : state) {
    for (int i = 0; i <= d; ++i) simplex[static_cast<std::size_t>(i)] = t.point(n, i);
    benchmark::DoNotOptimize(drange::geometry::in_sphere(d, simplex.data(), t.point(n, d + 1)));
    n = (n + 1) % kTuples;
  }
  set_label(state, d, kind);
}

void predicate_args(benchmark::internal::Benchmark* b) {
  for (int d : {2, 3, 5})
    for (int kind : {kRandom, kCube, kDecimal}) b->Args({d, kind});
}

BENCHMARK(BM_Orientation)->Apply(predicate_args);
BENCHMARK(BM_LiftedSign)->Apply(predicate_args);
BENCHMARK(BM_LiftedSignPerturbed)->Apply(predicate_args);
BENCHMARK(BM_InSphere)->Apply(predicate_args);

// One facet search on interior facets of uniform points (n points, dimension d).
void BM_FacetSearch(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const drange::PointCloud cloud = drange::generate_points(drange::Distribution::Uniform, n, d, 1);
  const drange::Triangulation tri = drange::delaunay(cloud);
  std::vector<drange::Duplicate> duplicates;
  drange::engine::Team team(1);
  const drange::engine::PointStore store =
      drange::engine::prepare_points(cloud, drange::engine::search_leaf_size(d), duplicates, team);  // as the engine
  std::vector<std::int32_t> id_of(n);
  for (std::int32_t id = 0; id < store.size; ++id) id_of[static_cast<std::size_t>(store.input_index[static_cast<std::size_t>(id)])] = id;

  // Facets opposite vertex 0 of simplices spread over the triangulation, with the open side
  // away from that vertex: the search finds the neighbouring simplex (or the hull).
  struct Facet {
    std::vector<std::int32_t> ids;
    int sigma;
  };
  std::vector<Facet> facets;
  const std::size_t stride = std::max<std::size_t>(1, tri.size() / 4096);
  for (std::size_t s = 0; s < tri.size() && facets.size() < 4096; s += stride) {
    const std::int32_t* v = tri.simplex(s);
    Facet f;
    for (int k = 1; k <= d; ++k) f.ids.push_back(id_of[static_cast<std::size_t>(v[k])]);
    std::sort(f.ids.begin(), f.ids.end());
    const std::int32_t apex = id_of[static_cast<std::size_t>(v[0])];
    std::vector<const double*> rows;
    for (int k = 1; k < d; ++k) rows.push_back(store.point(f.ids[static_cast<std::size_t>(k)]));
    rows.push_back(store.point(apex));
    const Frame frame{d, d, nullptr, store.point(f.ids[0])};
    f.sigma = -drange::geometry::orientation(frame, rows.data());
    facets.push_back(f);
  }
  drange::engine::FacetSearch search(store, drange::engine::SearchOptions{});
  drange::engine::SearchCounters counters;
  std::size_t i = 0;
  std::uint64_t searches = 0;
  for (auto _ : state) {
    const Facet& f = facets[i];
    benchmark::DoNotOptimize(search.find_apex(f.ids.data(), f.sigma, counters));
    i = (i + 1) % facets.size();
    ++searches;
  }
  state.counters["calls_per_search"] = searches ? double(counters.calls) / double(searches) : 0.0;
  state.counters["tested_per_search"] = searches ? double(counters.points_tested) / double(searches) : 0.0;
  state.SetLabel(std::to_string(d) + "D uniform " + std::to_string(n));
}
BENCHMARK(BM_FacetSearch)->Args({2, 100000})->Args({3, 100000})->Args({5, 5000});

// The preparation on one thread (duplicates, scaling, the kd-tree and its leaf blocks), and the
// kd-tree's build alone within it, on uniform points (n points, dimension d).
void BM_PreparePoints(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const drange::PointCloud cloud = drange::generate_points(drange::Distribution::Uniform, n, d, 1);
  std::vector<drange::Duplicate> duplicates;
  drange::engine::Team team(1);
  for (auto _ : state)
    benchmark::DoNotOptimize(drange::engine::prepare_points(cloud, drange::engine::search_leaf_size(d), duplicates, team).size);
  state.SetLabel(std::to_string(d) + "D uniform " + std::to_string(n) + ", 1 thread");
}
BENCHMARK(BM_PreparePoints)->Args({2, 1000000})->Args({3, 200000})->Unit(benchmark::kMillisecond);

void BM_KdTreeBuild(benchmark::State& state) {
  const int d = static_cast<int>(state.range(0));
  const auto n = static_cast<std::size_t>(state.range(1));
  const drange::PointCloud cloud = drange::generate_points(drange::Distribution::Uniform, n, d, 1);
  std::vector<double> coords;
  for (auto _ : state) {
    state.PauseTiming();
    coords.assign(cloud.coords.begin(), cloud.coords.end());  // build_and_reorder rewrites them
    drange::spatial::KdTree tree;
    state.ResumeTiming();
    tree.build_and_reorder(coords.data(), static_cast<std::int32_t>(n), d, drange::engine::search_leaf_size(d), 1);
    benchmark::DoNotOptimize(tree.nodes().size());
  }
  state.SetLabel(std::to_string(d) + "D uniform " + std::to_string(n) + ", 1 thread");
}
BENCHMARK(BM_KdTreeBuild)->Args({2, 1000000})->Args({3, 200000})->Unit(benchmark::kMillisecond);

// End to end: the whole triangulation of 10 000 uniform 2D points (seed 1).
void BM_Delaunay2D10k(benchmark::State& state) {
  const drange::PointCloud cloud = drange::generate_points(drange::Distribution::Uniform, 10000, 2, 1);
  for (auto _ : state) benchmark::DoNotOptimize(drange::delaunay(cloud).size());
  state.SetLabel("2D uniform 10000, all phases");
}
BENCHMARK(BM_Delaunay2D10k)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
