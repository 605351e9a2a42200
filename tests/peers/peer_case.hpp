// tests/peers/peer_case.hpp: one agreement case (distribution, size, dimension) and its name.
#pragma once

#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "drange/generate.hpp"

namespace drange::test {

struct PeerCase {
  Distribution distribution;
  std::size_t n;
  int d;
};

inline std::string describe(const PeerCase& c) {
  static const char* const names[] = {"uniform", "ball", "sphere", "gaussian", "clustered", "grid"};
  return std::string(names[static_cast<int>(c.distribution)]) + "_d" + std::to_string(c.d) + "_n" + std::to_string(c.n);
}
inline std::string case_name(const ::testing::TestParamInfo<PeerCase>& info) { return describe(info.param); }
inline void PrintTo(const PeerCase& c, std::ostream* os) { *os << describe(c); }

}  // namespace drange::test
