// tests/oracle.hpp: brute-force references for the tests, independent of the library's
// geometry: exact determinants by Gaussian elimination on GMP rationals, the Delaunay
// triangulation by its definition, and a small deterministic random generator.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drange/points.hpp"

namespace drange::test {

// ---- Exact reference predicates (every double is an exact rational). ----

// Determinant of the n x n matrix `a` (row-major), by Gaussian elimination over the rationals.
mpq_class reference_determinant(std::vector<mpq_class> a, int n);
// Sign of det[p_1 - p_0, ..., p_d - p_0] (d + 1 points of dimension d).
int reference_orientation(int dim, const std::vector<const double*>& simplex);
// Sign of the (d+1)x(d+1) determinant with rows [p_i - b, |p_i - b|^2], i = 1..d+1, for the
// base b and d + 1 further points (geometry::lifted_sign with the full frame).
int reference_lifted_sign(int dim, const double* base, const std::vector<const double*>& points);
// +1 if q is strictly inside the circumsphere of the simplex, 0 on it, -1 outside.
int reference_in_sphere(int dim, const std::vector<const double*>& simplex, const double* q);
// The perturbed lifted sign (the lifts |p|^2 + eps^(N - rank)), computed from its definition:
// the determinant is linear in the lifted column, so the perturbed determinant is
// det + sum_i eps_i * cofactor_i, and the largest eps_i with a nonzero cofactor decides.
int reference_lifted_sign_perturbed(int dim, const double* base, const std::vector<const double*>& points,
                                    const std::vector<std::int64_t>& ranks);

// ---- Brute-force Delaunay. ----

using Simplex = std::vector<std::int32_t>;  // sorted vertex ids

// Every (d+1)-subset of nonzero volume whose circumsphere has no other point inside or on it.
// For points in general position (no d+2 on a sphere, no d+1 on a hyperplane) this is the
// Delaunay triangulation. O(n^(d+2)): for n up to about 12 in d <= 5. Sorted.
std::vector<Simplex> brute_force_delaunay(const PointCloud& points);

// A flat m*(d+1) array as a sorted list of sorted tuples, for comparing triangulations.
std::vector<Simplex> canonical(const std::vector<std::int32_t>& simplices, int dim);
// The inverse: a flat array (in the given order).
std::vector<std::int32_t> flatten(const std::vector<Simplex>& simplices);

// ---- Deterministic randomness (fixed seeds; printed by the tests on failure). ----

// SplitMix64 (Steele, Lea, Flood, "Fast splittable pseudorandom number generators", 2014).
class TestRandom {
 public:
  explicit TestRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform();                           // in [0, 1), 53 random bits
  std::int64_t integer(std::int64_t lo, std::int64_t hi);  // in [lo, hi]

 private:
  std::uint64_t state_;
};

// n points uniform in [0, 1)^dim.
PointCloud random_points(std::size_t n, int dim, std::uint64_t seed);
// n points with integer coordinates in [lo, hi]^dim (ties are likely: for degenerate cases).
PointCloud random_integer_points(std::size_t n, int dim, std::int64_t lo, std::int64_t hi, std::uint64_t seed);

// Every integer point (x, y) with x^2 + y^2 = radius^2: exactly cocircular points (1105 =
// 5 * 13 * 17 has 108), so every triangle among them is a tie the perturbation breaks.
PointCloud integer_circle_points(std::int64_t radius);

// Pointers to the points with the given ids, for the predicates' interfaces.
std::vector<const double*> corners(const PointCloud& points, const std::vector<std::int32_t>& ids);

}  // namespace drange::test
