// tests/oracle.cpp: the brute-force references of oracle.hpp. Deliberately the plainest code:
// rational Gaussian elimination and the definition of a Delaunay simplex.
#include "oracle.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace drange::test {

mpq_class reference_determinant(std::vector<mpq_class> a, int n) {
  auto at = [&](int r, int c) -> mpq_class& { return a[static_cast<std::size_t>(r * n + c)]; };
  mpq_class det = 1;
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    while (pivot < n && at(pivot, k) == 0) ++pivot;
    if (pivot == n) return 0;
    if (pivot != k) {
      for (int c = 0; c < n; ++c) std::swap(at(k, c), at(pivot, c));
      det = -det;
    }
    det *= at(k, k);
    for (int r = k + 1; r < n; ++r) {
      if (at(r, k) == 0) continue;
      const mpq_class factor = at(r, k) / at(k, k);
      for (int c = k; c < n; ++c) at(r, c) -= factor * at(k, c);
    }
  }
  return det;
}

int reference_orientation(int dim, const std::vector<const double*>& simplex) {
  std::vector<mpq_class> a;
  for (int r = 1; r <= dim; ++r)
    for (int c = 0; c < dim; ++c) a.push_back(mpq_class(simplex[static_cast<std::size_t>(r)][c]) - mpq_class(simplex[0][c]));
  return sgn(reference_determinant(a, dim));
}

namespace {

// Rows [p - b, |p - b|^2] for each point p.
std::vector<mpq_class> lifted_rows(int dim, const double* base, const std::vector<const double*>& points) {
  std::vector<mpq_class> a;
  for (const double* p : points) {
    mpq_class lift = 0;
    for (int c = 0; c < dim; ++c) {
      const mpq_class delta = mpq_class(p[c]) - mpq_class(base[c]);
      a.push_back(delta);
      lift += delta * delta;
    }
    a.push_back(lift);
  }
  return a;
}

}  // namespace

int reference_lifted_sign(int dim, const double* base, const std::vector<const double*>& points) {
  return sgn(reference_determinant(lifted_rows(dim, base, points), dim + 1));
}

int reference_in_sphere(int dim, const std::vector<const double*>& simplex, const double* q) {
  // The lifted determinant, as a function of q, is O * (|q - c|^2 - r^2), where O is the
  // orientation (the cofactor of q's lift): inside exactly when lifted * O < 0.
  std::vector<const double*> rows(simplex.begin() + 1, simplex.end());
  rows.push_back(q);
  return -reference_lifted_sign(dim, simplex[0], rows) * reference_orientation(dim, simplex);
}

int reference_lifted_sign_perturbed(int dim, const double* base, const std::vector<const double*>& points,
                                    const std::vector<std::int64_t>& ranks) {
  // Homogeneous form: rows [x_i, |x_i|^2, 1] for base and points, (d+2)x(d+2). Subtracting the
  // base row from the others and expanding along the last column shows that the relative
  // determinant equals (-1)^(d+1) times this one; both are linear in the lift column.
  std::vector<const double*> all{base};
  all.insert(all.end(), points.begin(), points.end());
  const int n = dim + 2;
  std::vector<mpq_class> m;
  for (const double* p : all) {
    mpq_class lift = 0;
    for (int c = 0; c < dim; ++c) {
      m.push_back(mpq_class(p[c]));
      lift += mpq_class(p[c]) * mpq_class(p[c]);
    }
    m.push_back(lift);
    m.push_back(1);
  }
  const int relative_sign = (dim + 1) % 2 == 0 ? 1 : -1;
  const mpq_class det = reference_determinant(m, n);
  if (det != 0) return relative_sign * sgn(det);
  // Cofactor of the lift entry of row i: (-1)^(i + dim) * minor without row i, column dim.
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ranks[static_cast<std::size_t>(a)] > ranks[static_cast<std::size_t>(b)]; });
  for (int i : order) {
    std::vector<mpq_class> minor;
    for (int r = 0; r < n; ++r) {
      if (r == i) continue;
      for (int c = 0; c < n; ++c)
        if (c != dim) minor.push_back(m[static_cast<std::size_t>(r * n + c)]);
    }
    const int cofactor = ((i + dim) % 2 == 0 ? 1 : -1) * sgn(reference_determinant(minor, n - 1));
    if (cofactor != 0) return relative_sign * cofactor;
  }
  return 0;
}

namespace {

// Calls f(subset) for every k-subset of {0..n-1}, in lexicographic order.
template <class F>
void for_each_subset(int n, int k, F f) {
  std::vector<std::int32_t> subset(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i) subset[static_cast<std::size_t>(i)] = i;
  while (true) {
    f(subset);
    int i = k - 1;
    while (i >= 0 && subset[static_cast<std::size_t>(i)] == n - k + i) --i;
    if (i < 0) return;
    ++subset[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < k; ++j) subset[static_cast<std::size_t>(j)] = subset[static_cast<std::size_t>(j - 1)] + 1;
  }
}

}  // namespace

std::vector<Simplex> brute_force_delaunay(const PointCloud& points) {
  const int d = points.dim;
  const int n = static_cast<int>(points.size());
  std::vector<Simplex> result;
  if (n < d + 1) return result;
  for_each_subset(n, d + 1, [&](const std::vector<std::int32_t>& subset) {
    const std::vector<const double*> simplex = corners(points, subset);
    if (reference_orientation(d, simplex) == 0) return;
    for (int q = 0; q < n; ++q) {
      if (std::find(subset.begin(), subset.end(), q) != subset.end()) continue;
      if (reference_in_sphere(d, simplex, points.point(static_cast<std::size_t>(q))) >= 0) return;
    }
    result.push_back(subset);
  });
  return result;
}

std::vector<Simplex> canonical(const std::vector<std::int32_t>& simplices, int dim) {
  const std::size_t width = static_cast<std::size_t>(dim + 1);
  std::vector<Simplex> result;
  for (std::size_t s = 0; s + width <= simplices.size(); s += width) {
    Simplex simplex(simplices.begin() + static_cast<std::ptrdiff_t>(s), simplices.begin() + static_cast<std::ptrdiff_t>(s + width));
    std::sort(simplex.begin(), simplex.end());
    result.push_back(simplex);
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<std::int32_t> flatten(const std::vector<Simplex>& simplices) {
  std::vector<std::int32_t> flat;
  for (const Simplex& s : simplices) flat.insert(flat.end(), s.begin(), s.end());
  return flat;
}

std::uint64_t TestRandom::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double TestRandom::uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }

std::int64_t TestRandom::integer(std::int64_t lo, std::int64_t hi) {
  const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
  return lo + static_cast<std::int64_t>(next() % span);  // the bias is irrelevant for tests
}

PointCloud random_points(std::size_t n, int dim, std::uint64_t seed) {
  TestRandom random(seed);
  PointCloud cloud;
  cloud.dim = dim;
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i) cloud.coords.push_back(random.uniform());
  return cloud;
}

PointCloud random_integer_points(std::size_t n, int dim, std::int64_t lo, std::int64_t hi, std::uint64_t seed) {
  TestRandom random(seed);
  PointCloud cloud;
  cloud.dim = dim;
  for (std::size_t i = 0; i < n * static_cast<std::size_t>(dim); ++i)
    cloud.coords.push_back(static_cast<double>(random.integer(lo, hi)));
  return cloud;
}

PointCloud integer_circle_points(std::int64_t radius) {
  PointCloud circle;
  circle.dim = 2;
  for (std::int64_t x = -radius; x <= radius; ++x) {
    const std::int64_t y2 = radius * radius - x * x;
    const auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(y2))));
    if (y * y != y2) continue;
    circle.coords.insert(circle.coords.end(), {double(x), double(y)});
    if (y != 0) circle.coords.insert(circle.coords.end(), {double(x), double(-y)});
  }
  return circle;
}

std::vector<const double*> corners(const PointCloud& points, const std::vector<std::int32_t>& ids) {
  std::vector<const double*> result;
  for (const std::int32_t i : ids) result.push_back(points.point(static_cast<std::size_t>(i)));
  return result;
}

}  // namespace drange::test
