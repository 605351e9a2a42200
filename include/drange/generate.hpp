// drange/generate.hpp: the test distributions, reproducible from a seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "drange/points.hpp"

namespace drange {

enum class Distribution {
  Uniform,    // uniform in the unit cube [0,1)^d
  Ball,       // uniform in the unit ball
  Sphere,     // uniform on the unit sphere (cospherical up to rounding: a degenerate input)
  Gaussian,   // standard normal in every coordinate
  Clustered,  // gaussian clusters of small radius around uniform centres
  Grid,       // the integer grid {0..k-1}^d with k^d >= n, first n points (degenerate input)
};

// Parses "uniform", "ball", "sphere", "gaussian", "clustered", "grid"; throws UsageError.
Distribution distribution_from_name(const std::string& name);
const char* distribution_names();

// n points of the distribution in dimension d, the same for the same (n, d, seed) on every
// machine (a fixed generator, not std::*_distribution, whose output is unspecified).
PointCloud generate_points(Distribution distribution, std::size_t n, int d, std::uint64_t seed);

}  // namespace drange
