// voronoi/flag_volumes.cpp: see flag_volumes.hpp.
//
// Per simplex: the circumcentres of all its 2^(d+1) faces, built up face by face, then the
// signed height of every step (face -> face + one vertex), then for each interior vertex a
// sum over the subsets of the other vertices (2^d partial sums, not the d! orders).
//
// Precision: in double, relative to the simplex's first vertex, the pieces are accurate
// (3e-13 relative against an exact rational volume on huge, far 4D cells). But a simplex
// with a nearly flat face (nearly cospherical input: any triangulation of the sphere's points
// is Delaunay, slivers included) has far-away face centres whose big signed pieces cancel;
// a review found cells off by several percent. Such a simplex (a face whose new vertex is
// closer than kFlatFace of its distance to the face's hull) is redone in extended precision
// (extended_real.hpp: quad where the compiler has it, else double-double).
#include "voronoi/flag_volumes.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "util/for_ranges.hpp"
#include "voronoi/extended_real.hpp"

namespace drange::diagram {
namespace {

constexpr double kFlatFace = 1e-2;

// The pieces of one simplex's flags, in arithmetic Real.
template <class Real>
class SimplexPieces {
 public:
  explicit SimplexPieces(int d)
      : d_(static_cast<std::size_t>(d)), width_(d_ + 1), subsets_(std::size_t{1} << width_),
        centre_(subsets_ * d_), basis_(subsets_ * d_ * d_), corner_(width_ * d_), height_(subsets_ * width_),
        partial_(subsets_) {}

  // Computes the face centres and step heights of `simplex`. Returns the smallest ratio, over
  // the steps that add a vertex v to a face F with first vertex p0, of v's distance to F's
  // affine hull to |v - p0|: how flat the flattest face is.
  double compute(PointsView points, const std::int32_t* simplex) {
    const double* origin = points.point(static_cast<std::size_t>(simplex[0]));
    for (std::size_t i = 0; i < width_; ++i) {
      const double* p = points.point(static_cast<std::size_t>(simplex[i]));
      for (std::size_t k = 0; k < d_; ++k) corner_[i * d_ + k] = Real(p[k]) - Real(origin[k]);
    }
    const double flatness = compute_centres();
    compute_heights();
    return flatness;
  }

  // The volume of the pieces of vertex i's cell inside this simplex.
  Real cell_part(int i) {
    std::fill(partial_.begin(), partial_.end(), Real(0));
    const std::size_t own = std::size_t{1} << i;
    partial_[own] = 1;
    // Masks holding i, in increasing order: every subset comes before its supersets.
    for (std::size_t mask = own; mask < subsets_; ++mask) {
      if (!(mask & own) || partial_[mask] == 0) continue;
      for (std::size_t j = 0; j < width_; ++j)
        if (!(mask >> j & 1)) partial_[mask | std::size_t{1} << j] += partial_[mask] * height_[mask * width_ + j];
    }
    Real factorial = 1;
    for (std::size_t k = 2; k <= d_; ++k) factorial *= Real(k);
    return partial_[subsets_ - 1] / factorial;
  }

 private:
  // Adding vertex v to a face F moves F's centre along the unit vector e orthogonal to F's
  // affine hull toward v, by t = (|c - v|^2 - |c - p0|^2) / (2 e.(v - p0)), which keeps it
  // equidistant from F's vertices and makes it so from v; e extends F's orthonormal basis
  // (Gram-Schmidt). O(d k) per face instead of a k x k solve.
  double compute_centres() {
    double flatness = 1;
    for (std::size_t mask = 1; mask < subsets_; ++mask) {
      Real* c = &centre_[mask * d_];
      const int high = 63 - __builtin_clzll(mask);
      const std::size_t rest = mask & ~(std::size_t{1} << high);
      const Real* v = &corner_[static_cast<std::size_t>(high) * d_];
      if (rest == 0) {
        std::copy(v, v + d_, c);
        continue;
      }
      const auto rank = static_cast<std::size_t>(__builtin_popcountll(rest) - 1);  // rest's basis vectors
      const Real* c0 = &centre_[rest * d_];
      const Real* p0 = &corner_[static_cast<std::size_t>(__builtin_ctzll(rest)) * d_];
      Real* basis = &basis_[mask * d_ * d_];
      std::copy(&basis_[rest * d_ * d_], &basis_[rest * d_ * d_] + rank * d_, basis);
      Real* e = basis + rank * d_;
      Real full2 = 0;
      for (std::size_t k = 0; k < d_; ++k) {
        e[k] = v[k] - p0[k];
        full2 += e[k] * e[k];
      }
      for (std::size_t b = 0; b < rank; ++b) {
        const Real* q = basis + b * d_;
        Real dot = 0;
        for (std::size_t k = 0; k < d_; ++k) dot += e[k] * q[k];
        for (std::size_t k = 0; k < d_; ++k) e[k] -= dot * q[k];
      }
      Real norm2 = 0;
      for (std::size_t k = 0; k < d_; ++k) norm2 += e[k] * e[k];
      const Real norm = root(norm2);
      flatness = std::min(flatness, static_cast<double>(norm / root(full2)));
      for (std::size_t k = 0; k < d_; ++k) e[k] /= norm;
      Real to_v = 0, to_p0 = 0;
      for (std::size_t k = 0; k < d_; ++k) {
        to_v += (c0[k] - v[k]) * (c0[k] - v[k]);
        to_p0 += (c0[k] - p0[k]) * (c0[k] - p0[k]);
      }
      const Real step = (to_v - to_p0) / (2 * norm);
      for (std::size_t k = 0; k < d_; ++k) c[k] = c0[k] + step * e[k];
    }
    return flatness;
  }

  // The signed height of each step mask -> mask + j. It does not depend on which vertex of
  // `mask` is the cell's point: u is orthogonal to mask's affine hull, so u.(v_j - x) is the
  // same for every x in it.
  void compute_heights() {
    for (std::size_t mask = 1; mask < subsets_; ++mask) {
      const Real* from = &centre_[mask * d_];
      const Real* x = &centre_[(std::size_t{1} << __builtin_ctzll(mask)) * d_];
      for (std::size_t j = 0; j < width_; ++j) {
        if (mask >> j & 1) continue;
        const Real* to = &centre_[(mask | std::size_t{1} << j) * d_];
        const Real* v = &centre_[(std::size_t{1} << j) * d_];
        Real length2 = 0, toward = 0;
        for (std::size_t k = 0; k < d_; ++k) {
          const Real u = to[k] - from[k];
          length2 += u * u;
          toward += u * (v[k] - x[k]);
        }
        height_[mask * width_ + j] = toward >= 0 ? root(length2) : -root(length2);
      }
    }
  }

  std::size_t d_, width_, subsets_;
  std::vector<Real> centre_, basis_, corner_, height_, partial_;
};

}  // namespace

struct SimplexCellParts::Pieces {
  explicit Pieces(int d) : fast(d), careful(d) {}
  SimplexPieces<double> fast;
  SimplexPieces<ExtendedReal> careful;
};

SimplexCellParts::SimplexCellParts(int d) : d_(d), pieces_(std::make_unique<Pieces>(d)) {}
SimplexCellParts::~SimplexCellParts() = default;

void SimplexCellParts::compute(PointsView points, const std::int32_t* simplex, double* parts) {
  const bool flat = pieces_->fast.compute(points, simplex) < kFlatFace;
  if (flat) pieces_->careful.compute(points, simplex);
  for (int k = 0; k <= d_; ++k)
    parts[k] = flat ? static_cast<double>(pieces_->careful.cell_part(k)) : pieces_->fast.cell_part(k);
}

std::vector<double> flag_cell_volumes(PointsView points, const Triangulation& t, const std::vector<char>& on_hull,
                                      engine::Team& team) {
  const int width = t.dim + 1;
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> volume(t.num_points, 0.0);
  // The pieces of a block of simplices are computed on the team's threads, then added to the
  // cells in simplex order, so that every sum (and its rounding) is the same for every thread
  // count; the block bounds the memory of the pieces.
  constexpr std::size_t kBlock = std::size_t{1} << 16;
  std::vector<double> parts(std::min(kBlock, t.size()) * w);
  for (std::size_t first = 0; first < t.size(); first += kBlock) {
    const std::size_t count = std::min(kBlock, t.size() - first);
    util::for_ranges(count, team, [&](std::size_t, std::size_t begin, std::size_t end) {
      SimplexCellParts cell_parts(t.dim);
      for (std::size_t i = begin; i < end; ++i) {
        const std::int32_t* row = t.simplex(first + i);
        bool any_interior = false;
        for (int k = 0; k < width; ++k) any_interior |= !on_hull[static_cast<std::size_t>(row[k])];
        if (any_interior) cell_parts.compute(points, row, &parts[i * w]);  // else nothing of it is added
      }
    }, kSimplicesPerRange);
    for (std::size_t i = 0; i < count; ++i) {
      const std::int32_t* row = t.simplex(first + i);
      for (int k = 0; k < width; ++k)
        if (!on_hull[static_cast<std::size_t>(row[k])]) volume[static_cast<std::size_t>(row[k])] += parts[i * w + static_cast<std::size_t>(k)];
    }
  }
  return volume;
}

}  // namespace drange::diagram
