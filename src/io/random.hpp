// io/random.hpp: a small random number generator whose output is fixed by its seed on every
// machine, unlike std::*_distribution (whose algorithms the standard leaves open).
//
// Generator: xoshiro256** (Blackman and Vigna, "Scrambled linear pseudorandom number
// generators", 2021), its state filled from the seed by splitmix64 (Steele, Lea and Flood,
// "Fast splittable pseudorandom number generators", 2014), as its authors recommend.
// Normal deviates: Marsaglia and Bray's polar method, with the portable log of
// portable_math.hpp.
#pragma once

#include <cmath>
#include <cstdint>

#include "io/portable_math.hpp"

namespace drange::io {

class Random {
 public:
  explicit Random(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (std::uint64_t& word : state_) word = splitmix64(x);
  }

  // A generator in a given state (not all zero), to check against published test vectors.
  static Random from_state(const std::uint64_t (&state)[4]) {
    Random random(0);
    for (int i = 0; i < 4; ++i) random.state_[i] = state[i];
    return random;
  }

  std::uint64_t next() {
    const std::uint64_t result = rotate_left(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotate_left(state_[3], 45);
    return result;
  }

  // Uniform in [0, 1): the top 53 bits as a fraction, every value equally likely.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Uniform integer in [0, bound), bound >= 1, without modulo bias (rejection of the few
  // values that would over-represent the small residues).
  std::uint64_t below(std::uint64_t bound) {
    const std::uint64_t threshold = (0 - bound) % bound;  // 2^64 mod bound
    for (;;) {
      const std::uint64_t x = next();
      if (x >= threshold) return x % bound;
    }
  }

  // Standard normal deviate. The polar method makes them in pairs; the second is kept.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0, v = 0, s = 0;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * portable_log(s) / s);
    spare_ = v * factor;
    has_spare_ = true;
    return u * factor;
  }

  // One step of splitmix64: advances x, returns the next output.
  static std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9e3779b97f4a7c15);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9;
    z = (z ^ (z >> 27)) * 0x94d049bb133111eb;
    return z ^ (z >> 31);
  }

 private:
  static std::uint64_t rotate_left(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

  std::uint64_t state_[4];
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace drange::io
