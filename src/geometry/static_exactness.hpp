// geometry/static_exactness.hpp: when a floating-point evaluation is provably exact.
//
// With dyadic points (every coordinate an integer multiple of 2^unit_exponent, and the extent
// small in those units), differences of coordinates are exact, and a minor whose columns hold
// `units` such factors is a multiple of unit^units: if its absolute tree is below 2^52 of
// that unit, no operation rounded. This decides the exact ties of integer grids (points on a
// facet's hyperplane, cospherical points) without any exact arithmetic. The lift column
// counts twice (its entries are squares).
#pragma once

#include <array>
#include <cstdint>

#include "drange/points.hpp"
#include "geometry/error_bound.hpp"
#include "geometry/minors.hpp"

namespace drange::geometry {

class StaticExactness {
 public:
  StaticExactness(int d, bool dyadic, int unit_exponent) : dyadic_(dyadic) {
    if (!dyadic) return;
    for (int units = 0; units <= d + 2; ++units)
      limits_[static_cast<std::size_t>(units)] = power_of_two_limit(52 + unit_exponent * units);
  }
  // A value of `units` units whose absolute tree is below this was computed exactly (0 when
  // the points are not dyadic: nothing is proved).
  double limit(int units) const { return limits_[static_cast<std::size_t>(units)]; }

  // Which minors of a facet's lifted rows (`minors`: d - 1 rows of d + 1 columns, the lift
  // last) were computed exactly: all the spatial ones (orientation) and all of them (lifted).
  struct FacetMinors {
    bool orientation, lifted;
  };
  FacetMinors facet_minors(const MinorTable& minors, int d) const {
    FacetMinors exact{dyadic_, dyadic_};
    const auto bit = [](int j) { return std::uint32_t{1} << j; };
    for (std::uint32_t mask = 1; (exact.orientation || exact.lifted) && mask < bit(d + 1); ++mask) {
      const int size = bit_count(mask);
      if (size >= d) continue;  // the facet has d - 1 rows
      const bool lift = (mask & bit(d)) != 0;
      if (minors.abs_minor(mask) < limit(size + lift)) continue;
      exact.lifted = false;
      if (!lift) exact.orientation = false;
    }
    return exact;
  }

 private:
  bool dyadic_;
  std::array<double, kMaxDimension + 4> limits_{};
};

}  // namespace drange::geometry
