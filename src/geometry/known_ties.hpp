// geometry/known_ties.hpp: points that exact evaluations proved to lie on one hyperplane, or on
// one sphere, remembered so that a later test of the same fact needs no exact arithmetic.
//
// Why. Where ties are exact but the coordinates are not dyadic, no floating-point filter can
// certify a zero: every such test went to the double-double stage and to GMP. A grid in
// cylindrical coordinates (r, theta, z) is the common case: any two of its vertical lines of
// points lie in one plane, and any four corners of a vertical face on one circle. Every facet
// in such a plane meets the plane's other points as ties, so the neighbouring facets' searches
// prove the same facts again, each time with another subset of the same points (10 x 40 x 50
// points: 724 517 exact evaluations).
//
// Soundness. A surface is a hyperplane (defined by `defining` = d affinely independent points:
// a facet's vertices) or a sphere (d + 1 affinely independent points: a facet and its
// candidate), and such points define exactly one. Each set holds points on one surface: it
// starts as a defining simplex and a point proved on that simplex's surface, and grows by
// points proved on the surface of a defining simplex whose points are all in the set, which is
// the set's surface again. So when a defining simplex and a point are all in one set, the
// point is on the simplex's surface: the determinant is exactly zero. The caller must pass
// affinely independent simplices; it never learns a fact that no exact evaluation proved.
//
// The sets are found from their points: each point lists the sets it is in. An input without
// exact ties records nothing and pays nothing; one with many forgets everything when the sets
// reach max_links_ members in all, and learns again (the searches are spatially coherent).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::geometry {

class KnownTies {
 public:
  // A set stops growing here, which bounds a lookup's binary searches.
  static constexpr int kMaxMembers = 1024;
  // The most links (a point in a set) before all is forgotten: one per point, and some to
  // start with, so that the memory stays small beside the triangulation's own (on a cylindrical
  // grid, twice as many links spared few exact evaluations, for more peak memory).
  static constexpr std::size_t kMinLinks = std::size_t{1} << 15;
  static constexpr std::size_t kLinksPerPoint = 1;

  // `defining`: the number of points that define a surface (d for hyperplanes, d + 1 for
  // spheres); point ids are below `points`.
  KnownTies(int defining, std::int32_t points);

  // Whether `id` is known to lie on the surface of `simplex` (`defining` ids).
  bool holds(const std::int32_t* simplex, std::int32_t id) const;
  // Records that `id` lies on the surface of `simplex`, which an exact evaluation proved.
  void record(const std::int32_t* simplex, std::int32_t id);

 private:
  // A set that holds every point of `simplex`, or -1.
  std::int32_t find(const std::int32_t* simplex) const;
  bool member(std::int32_t set, std::int32_t id) const;
  void link(std::int32_t set, std::int32_t id);
  void forget();

  struct Link {
    std::int32_t set, next;  // a set the point is in, and the point's next link (-1: none)
  };
  int defining_;
  std::int32_t points_;
  // The last simplex looked up and its set (-1: none), until the next record: a search asks
  // about one facet (and candidate) many times (on the rings of a cylinder, repeated lookups
  // were a visible share of the time).
  mutable std::vector<std::int32_t> last_simplex_;
  mutable std::int32_t last_set_ = -1;
  std::size_t max_links_;
  std::vector<std::vector<std::int32_t>> sets_;  // each sorted
  // Per set, a bit per member (signature_bit): a set whose signature lacks a point's bit does
  // not hold it, so find() skips most of a point's sets without a binary search (a point of a
  // 5D grid is in dozens of sets, and find showed in a 5D grid's profile).
  std::vector<std::uint64_t> signatures_;
  static std::uint64_t signature_bit(std::int32_t id) {
    return std::uint64_t{1} << ((static_cast<std::uint32_t>(id) * 0x9E3779B9u) >> 26);
  }
  std::vector<std::int32_t> first_link_;         // per point, -1: in no set (empty until a record)
  std::vector<Link> links_;
};

}  // namespace drange::geometry
