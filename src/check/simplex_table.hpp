// check/simplex_table.hpp: the validator's view of the input simplices: each row with its
// vertex ids sorted (so a facet is a sorted key), and the exact orientation of that sorted row.
//
// Working on sorted rows throughout makes every side test free: for a simplex with sorted
// vertices v_0 < ... < v_d and orientation sigma = sign det[v_1 - v_0, ..., v_d - v_0], the
// facet without v_j (vertices in increasing order) sees v_j on the side
// sigma * (-1)^(d - j), because moving v_j to the end of the row takes d - j transpositions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "check/problem_log.hpp"
#include "drange/points.hpp"

namespace drange::check {

// Orientation codes in SimplexTable::sign.
constexpr std::int8_t kFlat = 0;     // distinct valid vertices, zero volume
constexpr std::int8_t kBroken = 2;   // an index out of range or a repeated vertex

struct SimplexTable {
  int dim = 0;
  std::size_t count = 0;
  std::vector<std::int32_t> sorted;  // count rows of dim+1 ids, each row increasing
  std::vector<std::int8_t> sign;     // +1 / -1 orientation of the sorted row, kFlat or kBroken

  const std::int32_t* row(std::size_t s) const { return sorted.data() + s * static_cast<std::size_t>(dim + 1); }
  bool usable(std::size_t s) const { return sign[s] == 1 || sign[s] == -1; }
  // Enters the facet table (valid distinct ids), even if flat.
  bool combinatorial(std::size_t s) const { return sign[s] != kBroken; }
};

// Builds the table and reports, per simplex, out-of-range indices, repeated vertices and zero
// volume. With `geometry` false (non-finite coordinates), orientations are not computed and
// every combinatorially valid simplex is marked kFlat.
SimplexTable build_simplex_table(PointsView points, const std::vector<std::int32_t>& simplices, bool geometry,
                                 ProblemLog& log);

// A facet of a simplex: the sorted row of `simplex` without position `omit`.
struct FacetRef {
  std::int32_t simplex;
  std::int32_t omit;
};

// The facet's vertex i (0 <= i < dim), in increasing order.
inline std::int32_t facet_vertex(const SimplexTable& t, FacetRef f, int i) {
  return t.row(static_cast<std::size_t>(f.simplex))[i + (i >= f.omit ? 1 : 0)];
}
// The vertex of the simplex opposite the facet.
inline std::int32_t opposite_vertex(const SimplexTable& t, FacetRef f) {
  return t.row(static_cast<std::size_t>(f.simplex))[f.omit];
}
// The side of the facet's hyperplane (sign of det[f_1 - f_0, ..., f_{d-1} - f_0, x - f_0] with
// the facet's vertices in increasing order) on which its simplex lies: the inner side.
inline int inner_side(const SimplexTable& t, FacetRef f) {
  const int sigma = t.sign[static_cast<std::size_t>(f.simplex)];
  return ((t.dim - f.omit) & 1) ? -sigma : sigma;
}
// The facet's vertex ids, for messages.
std::vector<std::int32_t> facet_ids(const SimplexTable& t, FacetRef f);

}  // namespace drange::check
