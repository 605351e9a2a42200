// util/union_find.hpp: disjoint sets over 0..n-1 (path halving; the smallest index of a set
// represents it, so the representative does not depend on the order of the unions).
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace drange::util {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace drange::util
