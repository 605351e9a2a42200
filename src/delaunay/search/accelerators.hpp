// delaunay/search/accelerators.hpp: the search's accelerators behind one interface.
//
// An accelerator proves that some point or node cannot be the answer, or offers a first
// candidate; none ever changes the point a search finds (the Delaunay point of a facet is
// unique under the perturbation), only how many points and nodes the search meets. The kernel
// (search_kernel.hpp) asks this object alone, at these moments of a search:
//   - skips(facet):              before anything, may the whole search be skipped;
//   - start_facet / seeds:       a new facet; the first candidates to try;
//   - start_candidate / centred: a new candidate and its query ball;
//   - beyond_candidate(node):    may this node hold a point that beats the candidate;
//   - closed_side(node):         is every point of this node on the facet's closed side;
//   - scan_leaf / sign:          a leaf's points, and a point's sign, by an accelerator's means;
//   - found(facet, apex):        the search's answer, for later searches.
// Each accelerator lives in its own file and is registered here by one member; removing one
// means deleting its file and its lines below. Each is off when its SearchOptions switch is
// off or its data is empty; prepare_points.cpp builds the hull and shell data only when their
// switches are on (the seed memory is sized by its owner, FacetSearch or the pipeline).
//
// Registered:
//   known hull facets (known_hull.hpp)       a clean hull facet's outer side is empty   no-hull
//   seed memory (seed_memory.hpp)            the last apexes around the facet's vertices no-seed
//   sphere shell (shell_pruner.hpp)          points near spheres                         no-shell
#pragma once

#include <cstdint>
#include <string>

#include "delaunay/known_hull.hpp"
#include "delaunay/point_store.hpp"
#include "delaunay/search/shell_pruner.hpp"
#include "delaunay/seed_memory.hpp"
#include "delaunay/search_options.hpp"
#include "drange/errors.hpp"

namespace drange::engine {

template <int D>
class Accelerators {
 public:
  Accelerators(const PointStore& points, const SearchOptions& options, SeedMemory& seeds)
      : d_(points.dim),
        hull_(options.known_hull_facets && points.hull.active() ? &points.hull : nullptr),
        seeds_(options.seed_candidate ? &seeds : nullptr),
        shell_(points.dim, options.use_kdtree && options.sphere_shell && points.shell.active() ? &points.shell : nullptr,
               points.tree, points.coords.data()) {
    // seed<kSeeds>() and remember<kSeeds>() take the memory's layout on trust.
    if (kSeeds > 0 && seeds.seeds_per_point() != kSeeds)
      throw InternalError("facet search: a seed memory of " + std::to_string(seeds.seeds_per_point()) +
                          " seeds per point for a kernel of " + std::to_string(kSeeds));
  }

  // Whether the facet's search may be skipped: it is a clean hull facet searched on its outer
  // side, which holds no point.
  bool skips(const std::int32_t* facet, int sigma) const { return hull_ != nullptr && hull_->outer_sigma(facet) == sigma; }

  // A new facet (sorted ids, f0, the plane's coefficients a of sigma O(x) = a . (x - f0)).
  void start_facet(const std::int32_t* facet, const double* f0, const double* plane) {
    if (shell_.enabled()) shell_.start_facet(facet, f0, plane);
  }
  // Calls consider(id) for each first candidate of the facet.
  template <class Consider>
  void seeds(const std::int32_t* facet, const Consider& consider) const {
    if (seeds_ == nullptr) return;
    for (int i = 0; i < dim(); ++i)
      for (int k = 0; k < (kSeeds > 0 ? kSeeds : seeds_->seeds_per_point()); ++k) {
        const std::int32_t seed = seeds_->template seed<kSeeds>(facet[i], k);
        if (seed >= 0) consider(seed);
      }
  }
  // The search's answer for the facet, when it found one.
  void found(const std::int32_t* facet, std::int32_t apex) {
    if (seeds_ == nullptr || apex < 0) return;
    for (int i = 0; i < dim(); ++i) seeds_->template remember<kSeeds>(facet[i], apex);
  }

  // A new candidate (its id, sigma, the rows f_1, ..., f_{d-1}, p), and its query ball's
  // centre once it has one.
  void start_candidate(std::int32_t candidate, int sigma, const double* const* rows) { shell_.start_candidate(candidate, sigma, rows); }
  void centred(const double* centre) { shell_.ball_centred(centre); }

  // Whether the node can hold no point that beats the candidate: outside its sphere.
  bool beyond_candidate(std::int32_t node) const { return shell_.scanning() && shell_.prunes(node); }
  // Whether every point of the node is on the facet's closed side, where the plane's own test
  // over the node's box could not tell (its absolute tree box_abs and factor box_gamma).
  bool closed_side(std::int32_t node, double box_gamma, double box_abs) const {
    return shell_.enabled() && shell_.on_closed_side(node, box_gamma, box_abs);
  }

  // The leaf's points, when an accelerator scans them itself (true); consider(id) tests one.
  template <class Consider>
  bool scan_leaf(std::int32_t leaf, std::int32_t end, const Consider& consider, std::uint64_t& tested) {
    return shell_.scanning() && shell_.scan_leaf(leaf, end, consider, tested);
  }
  // A certified sign of sigma I(p, x) for the candidate p and the point id, or 0.
  int sign(std::int32_t id) const { return shell_.sign(id); }

 private:
  static constexpr int kSeeds = D > 0 ? SeedMemory::per_point_in(D) : 0;  // per point; 0: the memory's
  int dim() const { return D > 0 ? D : d_; }

  int d_;
  const KnownHull* hull_;
  SeedMemory* seeds_;
  ShellPruner<D> shell_;
};

}  // namespace drange::engine
