// delaunay/facet_search.cpp: the shrinking kd-tree search for the Delaunay point of a facet.
#include "delaunay/facet_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/error_bound.hpp"
#include "geometry/predicates.hpp"

namespace drange::engine {

using geometry::certified_sign_with;

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline std::uint32_t bit(int j) { return std::uint32_t{1} << j; }
}  // namespace

FacetSearch::FacetSearch(const PointStore& points, const SearchOptions& options)
    : points_(points),
      options_(options),
      d_(points.dim),
      orient_gamma_(geometry::gamma_bound(geometry::laplace_roundings(points.dim, 1))),
      lifted_gamma_(geometry::gamma_bound(
          geometry::laplace_roundings(points.dim + 1, geometry::lifted_entry_roundings(points.dim)))),
      minors_(points.dim + 1),
      a_(static_cast<std::size_t>(d_)),
      a_abs_(static_cast<std::size_t>(d_)),
      centroid_(static_cast<std::size_t>(d_)),
      rows_(static_cast<std::size_t>(d_ + 1)),
      ranks_(static_cast<std::size_t>(d_ + 2)),
      w_(static_cast<std::size_t>(d_ + 1)),
      w_abs_(static_cast<std::size_t>(d_ + 1)),
      centre_(static_cast<std::size_t>(d_)),
      lower_(static_cast<std::size_t>(d_)),
      upper_(static_cast<std::size_t>(d_)),
      row_(static_cast<std::size_t>(d_ + 1)) {}

void FacetSearch::set_facet(const std::int32_t* facet, int sigma) {
  facet_ = facet;
  sigma_ = sigma;
  f0_ = points_.point(facet[0]);
  ranks_[0] = points_.rank[static_cast<std::size_t>(facet[0])];
  std::fill(centroid_.begin(), centroid_.end(), 0.0);
  const geometry::FloatingPointWatch watch;
  for (int i = 0; i < d_; ++i) {
    const double* f = points_.point(facet[i]);
    for (int k = 0; k < d_; ++k) centroid_[static_cast<std::size_t>(k)] += f[k] / d_;
    if (i == 0) continue;
    rows_[static_cast<std::size_t>(i - 1)] = f;
    ranks_[static_cast<std::size_t>(i)] = points_.rank[static_cast<std::size_t>(facet[i])];
    double lift = 0.0;
    for (int k = 0; k < d_; ++k) {
      row_[static_cast<std::size_t>(k)] = f[k] - f0_[k];
      lift += row_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    }
    row_[static_cast<std::size_t>(d_)] = lift;
    minors_.set_row(i - 1, row_.data());
  }
  // This facet's own flags (the static exactness test below depends on them; reading them
  // later left the previous facet's value there, which made exact fallbacks depend on the
  // order in which one FacetSearch met its facets).
  facet_clean_ = points_.scaled && watch.clean();
  // O(x) = det[f_1 - f_0; ...; x - f_0]: Laplace along the last row over the spatial columns.
  const std::uint32_t spatial = bit(d_) - 1;
  // Static exactness (as in geometry/predicates.cpp): with dyadic points, every spatial minor
  // of the facet rows is a multiple of unit^size; if each is below 2^52 of that unit, none was
  // rounded, and a later dot product a . (x - f0) is exact when its absolute tree is below
  // 2^52 unit^d. This decides points and kd-tree boxes lying exactly on the facet's hyperplane,
  // which integer grids have in every hull face.
  orientation_exact_ = points_.dyadic && facet_clean_;
  for (std::uint32_t mask = 1; orientation_exact_ && mask <= spatial; ++mask) {
    const int size = __builtin_popcount(mask);
    if (size < d_ && !(minors_.abs_minor(mask) < std::ldexp(1.0, 52 + points_.unit_exponent * size)))
      orientation_exact_ = false;
  }
  orient_exact_limit_ = std::ldexp(1.0, 52 + points_.unit_exponent * d_);
  for (int j = 0; j < d_; ++j) {
    const double sign = ((d_ - 1 + j) & 1) ? -1.0 : 1.0;
    a_[static_cast<std::size_t>(j)] = sigma * sign * minors_.minor(spatial & ~bit(j));
    a_abs_[static_cast<std::size_t>(j)] = minors_.abs_minor(spatial & ~bit(j));
  }
}

void FacetSearch::reset_box() {
  std::fill(lower_.begin(), lower_.end(), -kInfinity);
  std::fill(upper_.begin(), upper_.end(), kInfinity);
}

void FacetSearch::set_candidate(std::int32_t id) {
  candidate_ = id;
  ++counters_->candidates;
  const double* p = points_.point(id);
  rows_[static_cast<std::size_t>(d_ - 1)] = p;
  const geometry::FloatingPointWatch watch;
  ranks_[static_cast<std::size_t>(d_)] = points_.rank[static_cast<std::size_t>(id)];
  double lift = 0.0;
  for (int k = 0; k < d_; ++k) {
    row_[static_cast<std::size_t>(k)] = p[k] - f0_[k];
    lift += row_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
  }
  row_[static_cast<std::size_t>(d_)] = lift;
  minors_.set_row(d_ - 1, row_.data());
  // I(p, x) = det[...; r_p; r_x]: Laplace along the last row over all d+1 columns.
  const std::uint32_t all = bit(d_ + 1) - 1;
  for (int j = 0; j <= d_; ++j) {
    const double sign = ((d_ + j) & 1) ? -1.0 : 1.0;
    w_[static_cast<std::size_t>(j)] = sigma_ * sign * minors_.minor(all & ~bit(j));
    w_abs_[static_cast<std::size_t>(j)] = minors_.abs_minor(all & ~bit(j));
  }
  // The sphere through F and p is {x : I(p, x) / O(p) = 0}; I(p, x) / O(p) is the power of x,
  // so its centre is f0 - w_spatial / (2 w_lift) and it passes through f0. The box is the
  // sphere's bounding box, enlarged by the effect of the minors' error bounds on the centre.
  candidate_clean_ = facet_clean_ && watch.clean();
  const double gamma = lifted_gamma_;
  const double wd = w_[static_cast<std::size_t>(d_)];
  const double ewd = gamma * w_abs_[static_cast<std::size_t>(d_)];
  if (!candidate_clean_ || !(std::fabs(wd) > 2 * ewd) || !std::isfinite(wd)) {  // no trustworthy box
    reset_box();
    return;
  }
  double radius2 = 0.0, error2 = 0.0, magnitude = 0.0;
  for (int k = 0; k < d_; ++k) {
    const double dc = -w_[static_cast<std::size_t>(k)] / (2 * wd);
    const double err = (gamma * w_abs_[static_cast<std::size_t>(k)] + 2 * std::fabs(dc) * ewd) / (2 * (std::fabs(wd) - ewd));
    centre_[static_cast<std::size_t>(k)] = f0_[k] + dc;
    radius2 += dc * dc;
    error2 += err * err;
    magnitude = std::max(magnitude, std::fabs(centre_[static_cast<std::size_t>(k)]));
  }
  const double radius = std::sqrt(radius2);
  // Twice the centre's error (the radius moves by at most as much), plus the roundings of
  // computing the centre, the radius and the box bounds.
  const double reach = radius + 2 * std::sqrt(error2) * (1 + 1e-6) +
                       8 * (d_ + 4) * geometry::kUnitRoundoff * (magnitude + radius);
  if (!std::isfinite(reach)) {
    reset_box();
    return;
  }
  for (int k = 0; k < d_; ++k) {
    lower_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] - reach;
    upper_[static_cast<std::size_t>(k)] = centre_[static_cast<std::size_t>(k)] + reach;
  }
}

int FacetSearch::orientation_sign(double value, double abs_tree) const {
  const int s = facet_clean_ ? certified_sign_with(value, abs_tree, orient_gamma_) : 0;
  if (s != 0 || !orientation_exact_ || !(abs_tree < orient_exact_limit_)) return s;
  return value > 0 ? 1 : -1;  // exact: 0 counts as the closed side, like negative values
}

bool FacetSearch::on_open_side(std::int32_t id) {
  double o = 0.0, o_abs = 0.0;
  for (int k = 0; k < d_; ++k) {
    o += a_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    o_abs += a_abs_[static_cast<std::size_t>(k)] * std::fabs(row_[static_cast<std::size_t>(k)]);
  }
  int s = orientation_sign(o, o_abs);
  if (s == 0) {
    rows_[static_cast<std::size_t>(d_ - 1)] = points_.point(id);
    const geometry::Frame frame{d_, d_, nullptr, f0_};
    s = sigma_ * geometry::orientation(frame, rows_.data());
    if (candidate_ >= 0) rows_[static_cast<std::size_t>(d_ - 1)] = points_.point(candidate_);
  }
  return s > 0;
}

bool FacetSearch::beats_candidate(std::int32_t id) {
  double v = 0.0, v_abs = 0.0;
  for (int k = 0; k <= d_; ++k) {
    v += w_[static_cast<std::size_t>(k)] * row_[static_cast<std::size_t>(k)];
    v_abs += w_abs_[static_cast<std::size_t>(k)] * std::fabs(row_[static_cast<std::size_t>(k)]);
  }
  int s = candidate_clean_ ? certified_sign_with(v, v_abs, lifted_gamma_) : 0;
  if (s == 0) {
    rows_[static_cast<std::size_t>(d_)] = points_.point(id);
    ranks_[static_cast<std::size_t>(d_ + 1)] = points_.rank[static_cast<std::size_t>(id)];
    const geometry::Frame frame{d_, d_, nullptr, f0_};
    s = sigma_ * geometry::lifted_sign_perturbed(frame, rows_.data(), ranks_.data());
  }
  return s < 0;
}

void FacetSearch::consider(std::int32_t id) {
  const double* x = points_.point(id);
  for (int k = 0; k < d_; ++k)
    if (x[k] < lower_[static_cast<std::size_t>(k)] || x[k] > upper_[static_cast<std::size_t>(k)]) return;
  // The facet's own vertices lie on its hyperplane (O = 0 exactly, which no filter certifies).
  for (int i = 0; i < d_; ++i)
    if (facet_[i] == id) return;
  ++counters_->points_tested;
  double lift = 0.0;
  for (int k = 0; k < d_; ++k) {
    const double delta = x[k] - f0_[k];
    row_[static_cast<std::size_t>(k)] = delta;
    lift += delta * delta;
  }
  row_[static_cast<std::size_t>(d_)] = lift;
  if (!on_open_side(id)) return;
  if (candidate_ < 0 || beats_candidate(id)) set_candidate(id);
}

bool FacetSearch::prune(std::int32_t node) const {
  if (!options_.prune_closed_side || !facet_clean_) return false;
  // The largest value of sigma O over the node's box, at the corner that maximises each term.
  const double* lo = points_.tree.lower(node);
  const double* hi = points_.tree.upper(node);
  double m = 0.0, m_abs = 0.0;
  for (int k = 0; k < d_; ++k) {
    const double a = a_[static_cast<std::size_t>(k)];
    const double dlo = lo[k] - f0_[k], dhi = hi[k] - f0_[k];
    m += std::max(a * dlo, a * dhi);
    m_abs += a_abs_[static_cast<std::size_t>(k)] * std::max(std::fabs(dlo), std::fabs(dhi));
  }
  return orientation_sign(m, m_abs) < 0;
}

std::int32_t FacetSearch::find_apex(const std::int32_t* facet, int sigma, SearchCounters& counters) {
  counters_ = &counters;
  set_facet(facet, sigma);
  candidate_ = -1;
  reset_box();
  if (options_.use_kdtree) {
    counters.calls += points_.tree.search(*this);
  } else {
    ++counters.calls;
    for (std::int32_t id = 0; id < points_.size; ++id) consider(id);
  }
  return candidate_;
}

}  // namespace drange::engine
