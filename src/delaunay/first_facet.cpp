// delaunay/first_facet.cpp: gift wrapping to a supporting hyperplane, and a Delaunay facet on it.
#include "delaunay/first_facet.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <string>

#include "drange/errors.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/minors.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {
namespace {

using Ids = std::vector<std::int32_t>;
using Axes = std::vector<int>;

// The dimension of the affine hull of all points, exactly (only used to word an error).
int affine_dimension(const PointStore& points) {
  const int d = points.dim;
  std::vector<std::vector<mpq_class>> basis;  // echelon rows
  std::vector<int> pivots;
  const double* origin = points.point(0);
  for (std::int32_t id = 1; id < points.size && static_cast<int>(basis.size()) < d; ++id) {
    std::vector<mpq_class> v(static_cast<std::size_t>(d));
    for (int k = 0; k < d; ++k) v[static_cast<std::size_t>(k)] = mpq_class(points.point(id)[k]) - mpq_class(origin[k]);
    for (std::size_t b = 0; b < basis.size(); ++b) {
      const auto c = static_cast<std::size_t>(pivots[b]);
      if (v[c] == 0) continue;
      const mpq_class factor = v[c] / basis[b][c];
      for (int k = 0; k < d; ++k) v[static_cast<std::size_t>(k)] -= factor * basis[b][static_cast<std::size_t>(k)];
    }
    const auto nonzero = std::find_if(v.begin(), v.end(), [](const mpq_class& x) { return x != 0; });
    if (nonzero == v.end()) continue;
    pivots.push_back(static_cast<int>(nonzero - v.begin()));
    basis.push_back(std::move(v));
  }
  return static_cast<int>(basis.size());
}

[[noreturn]] void throw_flat(const PointStore& points) {
  const int k = affine_dimension(points);
  throw DegenerateInputError("all " + std::to_string(points.size) + " distinct points lie in an affine subspace of dimension " +
                             std::to_string(k) + "; a Delaunay triangulation in " + std::to_string(points.dim) +
                             " dimensions needs points that span " + std::to_string(points.dim) + " dimensions");
}

// The scans over all points (gift wrapping's steps, the check of the hyperplane found) run on
// chunks of this many ids, on the team's threads, and their results are combined in chunk
// order. The chunks are the same for every thread count, so the predicates evaluated, and
// the exact fallbacks counted, are too.
constexpr std::size_t kScanChunk = std::size_t{1} << 15;

template <class Result, class Scan>
std::vector<Result> scan_in_chunks(const Ids& ids, Team& team, Scan scan) {
  const std::size_t chunks = std::max<std::size_t>(1, (ids.size() + kScanChunk - 1) / kScanChunk);
  std::vector<Result> results(chunks);
  team.for_each(chunks, [&](std::size_t c) {
    const std::int32_t* first = ids.data() + c * kScanChunk;
    results[c] = scan(first, ids.data() + std::min(ids.size(), (c + 1) * kScanChunk));
  });
  return results;
}

// The orientation of k - 1 fixed points and a varying point x in a frame of k axes,
// det[pi(p_1 - base); ...; pi(p_{k-1} - base); pi(x - base)], as the linear function of x it is:
// its cofactors along the last row are computed once (with their absolute trees), then each x
// costs k products and the certified sign of their sum, as the search's open-side filter does
// (geometry/facet_plane_test.hpp); the scans ask the exact predicate only when that filter cannot decide.
// The value is the Laplace expansion of the whole determinant along its last row, so the
// determinant's error bound applies.
class LinearOrientation {
 public:
  // `fixed`: the k - 1 fixed points; `filter`: false leaves every sign to the exact predicate
  // (as the search does for points that were not scaled, prepare_points.cpp).
  LinearOrientation(int k, const int* axes, const double* base, const double* const* fixed, bool filter)
      : k_(k), axes_(axes, axes + k), base_(base), gamma_(geometry::gamma_bound(geometry::laplace_roundings(k, 1))) {
    geometry::MinorTable minors(k);
    std::array<double, geometry::SubsetTable::kMaxColumns> row{};
    const geometry::FloatingPointWatch watch;
    for (int r = 0; r + 1 < k; ++r) {
      for (int c = 0; c < k; ++c) row[static_cast<std::size_t>(c)] = fixed[r][axes[c]] - base[axes[c]];
      minors.set_row(r, row.data());
    }
    clean_ = filter && watch.clean();
    const std::uint32_t all = (std::uint32_t{1} << k) - 1;
    for (int c = 0; c < k; ++c) {
      const double sign = ((k - 1 + c) & 1) ? -1.0 : 1.0;
      cofactor_[static_cast<std::size_t>(c)] = sign * minors.minor(all & ~(std::uint32_t{1} << c));
      cofactor_abs_[static_cast<std::size_t>(c)] = minors.abs_minor(all & ~(std::uint32_t{1} << c));
    }
  }
  // The certified sign of the determinant with x as last row, or 0 when undecided.
  int sign(const double* x) const {
    if (!clean_) return 0;
    double value = 0.0, abs_tree = 0.0;
    for (int c = 0; c < k_; ++c) {
      const int axis = axes_[static_cast<std::size_t>(c)];
      const double delta = x[axis] - base_[axis];
      value += cofactor_[static_cast<std::size_t>(c)] * delta;
      abs_tree += cofactor_abs_[static_cast<std::size_t>(c)] * std::fabs(delta);
    }
    return geometry::certified_sign_with(value, abs_tree, gamma_);
  }

 private:
  int k_;
  std::vector<int> axes_;
  const double* base_;
  double gamma_;
  bool clean_ = false;
  std::array<double, geometry::SubsetTable::kMaxColumns> cofactor_{}, cofactor_abs_{};
};

class Wrapper {
 public:
  Wrapper(const PointStore& points, Team& team) : points_(points), d_(points.dim), team_(team) {}

  struct Support {
    Ids facet;                 // k ids, a Delaunay simplex of the points on the hyperplane
    std::int32_t off = -1;     // a point strictly off the hyperplane
  };

  // d points spanning a supporting hyperplane of `ids` within their k-flat (k = axes.size()),
  // forming a Delaunay (k-1)-simplex of the points on it.
  Support supporting_facet(const Ids& ids, const Axes& axes);

  // A Delaunay k-simplex (k+1 ids) of `ids` within their k-flat.
  Ids simplex_in_flat(const Ids& ids, const Axes& axes);

 private:
  // What one chunk of ids says in a step of gift wrapping, and in the check of the hyperplane.
  struct StepScan {
    std::int32_t on_hyperplane = -1;  // the first point on F_{j-1} and off G: the step's answer
    int side = 0;                     // the side of F_{j-1} of the chunk's other points
    std::int32_t best = -1;           // the first of them that is furthest in the rotation
  };
  struct SupportScan {
    Ids on;                 // the points on H, in order
    int side = 0;           // the side of H of the others
    std::int32_t off = -1;  // the first of them
  };

  // Orientation in the frame of the first k of `axes`, based at `base`, of the k given points.
  int orient(const int* axes, int k, std::int32_t base, const Ids& others, std::vector<const double*>& scratch) const {
    scratch.clear();
    for (std::int32_t id : others) scratch.push_back(points_.point(id));
    const geometry::Frame frame{d_, k, axes, points_.point(base)};
    return geometry::orientation(frame, scratch.data());
  }
  int orient(const int* axes, int k, std::int32_t base, const Ids& others) { return orient(axes, k, base, others, pointers_); }
  std::int32_t gift_wrap_step(const Ids& ids, const Axes& axes, const Ids& found);
  StepScan scan_step(const std::int32_t* first, const std::int32_t* last, const Axes& axes, const Ids& found) const;
  SupportScan scan_support(const std::int32_t* first, const std::int32_t* last, const Axes& axes, const Ids& found) const;
  std::int32_t lexicographic_minimum(const Ids& ids, const Axes& axes) const;

  const PointStore& points_;
  int d_;
  Team& team_;
  std::vector<const double*> pointers_;
};

std::int32_t Wrapper::lexicographic_minimum(const Ids& ids, const Axes& axes) const {
  return *std::min_element(ids.begin(), ids.end(), [&](std::int32_t a, std::int32_t b) {
    for (int axis : axes) {
      const double x = points_.point(a)[axis], y = points_.point(b)[axis];
      if (x != y) return x < y;
    }
    return false;
  });
}

// Step j = found.size() of the paper's wrapping: the hyperplane F_{j-1} contains the points
// found and the directions of axes j..k-1, and no point is on its negative side. Rotating it
// about the flat G spanned by the found points and axes j+1..k-1 (dropping axis j), we return a
// point v such that G + v is again a supporting hyperplane.
std::int32_t Wrapper::gift_wrap_step(const Ids& ids, const Axes& axes, const Ids& found) {
  const std::vector<StepScan> chunks = scan_in_chunks<StepScan>(
      ids, team_, [&](const std::int32_t* first, const std::int32_t* last) { return scan_step(first, last, axes, found); });
  const int j = static_cast<int>(found.size());
  Ids rotation_rows(found.begin() + 1, found.end());
  rotation_rows.push_back(-1);
  rotation_rows.push_back(-1);
  int side = 0;
  std::int32_t best = -1;
  for (const StepScan& chunk : chunks) {
    if (chunk.side != 0 && side != 0 && chunk.side != side)
      throw InternalError("gift wrapping: the previous hyperplane is not supporting");
    if (side == 0) side = chunk.side;
    if (chunk.on_hyperplane >= 0) return chunk.on_hyperplane;
    if (chunk.best < 0) continue;
    if (best < 0) {
      best = chunk.best;
      continue;
    }
    // As in scan_step: strictly further in the rotation, so that the first of equals stays.
    rotation_rows[static_cast<std::size_t>(j - 1)] = best;
    rotation_rows[static_cast<std::size_t>(j)] = chunk.best;
    if (side * orient(axes.data(), j + 1, found[0], rotation_rows) > 0) best = chunk.best;
  }
  return best;
}

Wrapper::StepScan Wrapper::scan_step(const std::int32_t* first, const std::int32_t* last, const Axes& axes,
                                     const Ids& found) const {
  const int j = static_cast<int>(found.size());
  const std::int32_t v0 = found[0];
  Ids rows(found.begin() + 1, found.end());
  rows.push_back(-1);  // the point under test
  Ids rotation_rows = rows;
  rotation_rows.push_back(-1);
  Axes without(static_cast<std::size_t>(j));
  std::vector<const double*> scratch;
  // The filters of the two orientations below, linear in x: the side of F_{j-1} (rows found[1..]
  // and x), and the rotation (rows found[1..], the best so far and x), rebuilt when the best
  // changes.
  std::vector<const double*> fixed;
  for (std::size_t i = 1; i < found.size(); ++i) fixed.push_back(points_.point(found[i]));
  const LinearOrientation side_of(j, axes.data(), points_.point(v0), fixed.data(), points_.scaled);
  fixed.push_back(nullptr);
  std::optional<LinearOrientation> rotation;
  StepScan scan;
  for (const std::int32_t* it = first; it != last; ++it) {
    const std::int32_t x = *it;
    rows.back() = x;
    int o = side_of.sign(points_.point(x));  // the side of F_{j-1}
    if (o == 0) o = orient(axes.data(), j, v0, rows, scratch);
    if (o == 0) {
      // x on F_{j-1}: G + x is F_{j-1} itself in the rotation plane, hence supporting, unless x
      // lies in G, which it does exactly when every j x j minor over the first j+1 axes vanishes.
      for (int c = 0; c < j; ++c) {
        std::size_t w = 0;
        for (int i = 0; i <= j; ++i)
          if (i != c) without[w++] = axes[static_cast<std::size_t>(i)];
        if (orient(without.data(), j, v0, rows, scratch) != 0) {
          scan.on_hyperplane = x;
          return scan;
        }
      }
      continue;
    }
    if (scan.side == 0) scan.side = o;
    if (o != scan.side) throw InternalError("gift wrapping: the previous hyperplane is not supporting");
    if (scan.best < 0) {
      scan.best = x;
      continue;
    }
    if (!rotation) {
      fixed.back() = points_.point(scan.best);
      rotation.emplace(j + 1, axes.data(), points_.point(v0), fixed.data(), points_.scaled);
    }
    // All candidates lie strictly on one side of F_{j-1}, within less than half a turn: the
    // rotation order is the orientation of (G, best, x) in the first j+1 axes.
    int turn = rotation->sign(points_.point(x));
    if (turn == 0) {
      rotation_rows[static_cast<std::size_t>(j - 1)] = scan.best;
      rotation_rows[static_cast<std::size_t>(j)] = x;
      turn = orient(axes.data(), j + 1, v0, rotation_rows, scratch);
    }
    if (scan.side * turn > 0) {
      scan.best = x;
      rotation.reset();  // rebuilt for the new best at the next candidate
    }
  }
  return scan;
}

Wrapper::SupportScan Wrapper::scan_support(const std::int32_t* first, const std::int32_t* last, const Axes& axes,
                                           const Ids& found) const {
  const int k = static_cast<int>(axes.size());
  Ids rows(found.begin() + 1, found.end());
  rows.push_back(-1);
  std::vector<const double*> scratch;
  std::vector<const double*> fixed;
  for (std::size_t i = 1; i < found.size(); ++i) fixed.push_back(points_.point(found[i]));
  const LinearOrientation side_of(k, axes.data(), points_.point(found[0]), fixed.data(), points_.scaled);
  SupportScan scan;
  for (const std::int32_t* it = first; it != last; ++it) {
    const std::int32_t x = *it;
    rows.back() = x;
    int o = side_of.sign(points_.point(x));
    if (o == 0) o = orient(axes.data(), k, found[0], rows, scratch);
    if (o == 0) {
      scan.on.push_back(x);
      continue;
    }
    if (scan.side == 0) {
      scan.side = o;
      scan.off = x;
    }
    if (o != scan.side) throw InternalError("gift wrapping: the hyperplane found is not supporting");
  }
  return scan;
}

Wrapper::Support Wrapper::supporting_facet(const Ids& ids, const Axes& axes) {
  const int k = static_cast<int>(axes.size());
  Ids found{lexicographic_minimum(ids, axes)};
  for (int j = 1; j < k; ++j) {
    const std::int32_t v = gift_wrap_step(ids, axes, found);
    if (v < 0) throw_flat(points_);
    found.push_back(v);
  }
  // The points on H = aff(found), and one point off it; H must support all of them.
  Support support;
  Ids on;
  int side = 0;
  for (SupportScan& chunk : scan_in_chunks<SupportScan>(ids, team_, [&](const std::int32_t* first, const std::int32_t* last) {
         return scan_support(first, last, axes, found);
       })) {
    on.insert(on.end(), chunk.on.begin(), chunk.on.end());
    if (chunk.side == 0) continue;
    if (side == 0) {
      side = chunk.side;
      support.off = chunk.off;
    }
    if (chunk.side != side) throw InternalError("gift wrapping: the hyperplane found is not supporting");
  }
  if (side == 0) throw_flat(points_);
  Ids rows(found.begin() + 1, found.end());
  if (static_cast<int>(on.size()) == k) {
    support.facet = found;
    return support;
  }
  // Several points on H: a Delaunay simplex among them, in k-1 axes onto which H projects
  // one-to-one (those whose normal component, a (k-1)-minor, is nonzero).
  for (int drop = 0; drop < k; ++drop) {
    Axes sub;
    for (int i = 0; i < k; ++i)
      if (i != drop) sub.push_back(axes[static_cast<std::size_t>(i)]);
    if (orient(sub.data(), k - 1, found[0], rows) == 0) continue;
    support.facet = simplex_in_flat(on, sub);
    return support;
  }
  throw InternalError("gift wrapping: the hyperplane found has no normal");
}

Ids Wrapper::simplex_in_flat(const Ids& ids, const Axes& axes) {
  const int k = static_cast<int>(axes.size());
  if (k == 1) {
    // Points on a line: the two smallest along it are consecutive, hence a Delaunay edge.
    Ids sorted = ids;
    std::partial_sort(sorted.begin(), sorted.begin() + 2, sorted.end(), [&](std::int32_t a, std::int32_t b) {
      return points_.point(a)[axes[0]] < points_.point(b)[axes[0]];
    });
    return Ids{sorted[0], sorted[1]};
  }
  Ids simplex = supporting_facet(ids, axes).facet;
  // The Delaunay point of that facet inside the flat, by an exact scan (the flat holds few
  // points compared to the input: a face of the hull).
  Ids rows(simplex.begin() + 1, simplex.end());
  rows.push_back(-1);
  std::vector<const double*> lifted(static_cast<std::size_t>(k + 1));
  std::vector<std::int64_t> ranks(static_cast<std::size_t>(k + 2));
  for (int i = 0; i < k; ++i) ranks[static_cast<std::size_t>(i)] = points_.rank(simplex[static_cast<std::size_t>(i)]);
  for (int i = 1; i < k; ++i) lifted[static_cast<std::size_t>(i - 1)] = points_.point(simplex[static_cast<std::size_t>(i)]);
  const geometry::Frame frame{d_, k, axes.data(), points_.point(simplex[0])};
  int sigma = 0;
  std::int32_t apex = -1;
  for (std::int32_t x : ids) {
    rows.back() = x;
    const int o = orient(axes.data(), k, simplex[0], rows);
    if (o == 0) continue;
    if (sigma == 0) sigma = o;
    if (apex < 0) {
      apex = x;
      continue;
    }
    lifted[static_cast<std::size_t>(k - 1)] = points_.point(apex);
    lifted[static_cast<std::size_t>(k)] = points_.point(x);
    ranks[static_cast<std::size_t>(k)] = points_.rank(apex);
    ranks[static_cast<std::size_t>(k + 1)] = points_.rank(x);
    if (sigma * geometry::lifted_sign_perturbed(frame, lifted.data(), ranks.data()) < 0) apex = x;
  }
  if (apex < 0) throw InternalError("first facet: a flat without a point off its facet");
  simplex.push_back(apex);
  return simplex;
}

}  // namespace

FirstFacet find_first_facet(const PointStore& points, Team& team) {
  Ids all(static_cast<std::size_t>(points.size));
  std::iota(all.begin(), all.end(), 0);
  Axes axes(static_cast<std::size_t>(points.dim));
  std::iota(axes.begin(), axes.end(), 0);
  Wrapper wrapper(points, team);
  Wrapper::Support support = wrapper.supporting_facet(all, axes);
  FirstFacet first;
  first.ids = support.facet;
  std::sort(first.ids.begin(), first.ids.end());
  std::vector<const double*> rows;
  for (std::size_t i = 1; i < first.ids.size(); ++i) rows.push_back(points.point(first.ids[i]));
  rows.push_back(points.point(support.off));
  const geometry::Frame frame{points.dim, points.dim, nullptr, points.point(first.ids[0])};
  first.sigma = geometry::orientation(frame, rows.data());
  if (first.sigma == 0) throw InternalError("first facet: the interior point is on the facet");
  return first;
}

}  // namespace drange::engine
