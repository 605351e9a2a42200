// delaunay/closure_predictor.hpp: with threads, each search thread's guess that a facet it is
// about to search is closed already, by a simplex that thread found lately and that the
// calling thread has not recorded yet; the guess spares the search (SearchPipeline). Reads the
// simplices from derived_facets.hpp's blocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::engine {

// The simplices one search thread found lately, by facet. Let S = A + x be the simplex found
// for a facet A and B another facet of S, whose turn comes after A's, that S did not open (its
// owner's vertex opposite B is not the vertex of S off B). Then S is recorded by the end of A's
// turn (from A's own result, or earlier, which is what closed A), and B is in the table by
// then, so B is closed when its turn comes: its search can be skipped. A thread takes its
// facets in increasing turn order, so everything it found came from facets with earlier turns. This
// catches what the closed marks cannot: facets closed by a simplex found moments before, not
// yet recorded. A direct-mapped cache: a collision only loses a prediction.
class ClosurePredictor {
 public:
  explicit ClosurePredictor(int d) : d_(d), keys_(kSize * static_cast<std::size_t>(d), -1), off_(kSize) {}

  // S = facet + apex: remembers S's other facets, from derive_other_facets' block (its facet
  // f omits the recorded simplex's vertex f: facet[f], or facet[1 - f] when sigma < 0 and f < 2).
  void found(const std::int32_t* facet, int sigma, const std::int32_t* derived) {
    const int d = d_;
    for (int f = 0; f < d; ++f) {
      const std::int32_t* ids = derived + f * d;
      const std::size_t slot = slot_of(static_cast<std::uint32_t>(derived[d * d + d + f]));
      std::int32_t* key = &keys_[slot * static_cast<std::size_t>(d)];
      for (int k = 0; k < d; ++k) key[k] = ids[k];  // loops: std::copy and std::equal of a few ints call libc
      off_[slot] = facet[(sigma < 0 && f < 2) ? 1 - f : f];
    }
  }
  // True when a simplex found earlier closes the queued facet.
  bool closes(const std::int32_t* ids, std::uint32_t hash, std::int32_t opposite) const {
    const std::size_t slot = slot_of(hash);
    const std::int32_t* key = &keys_[slot * static_cast<std::size_t>(d_)];
    for (int k = 0; k < d_; ++k)
      if (ids[k] != key[k]) return false;
    return off_[slot] != opposite;
  }

 private:
  static constexpr int kBits = 10;
  static constexpr std::size_t kSize = std::size_t{1} << kBits;
  // The facet hash's high bits: the table's slots use the low ones.
  static std::size_t slot_of(std::uint32_t hash) { return hash >> (32 - kBits); }
  int d_;
  std::vector<std::int32_t> keys_;  // kSize * d sorted ids
  std::vector<std::int32_t> off_;   // the vertex of S off the key facet
};

}  // namespace drange::engine
