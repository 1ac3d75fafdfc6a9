// A small random number generator whose sequence is the same on every platform and compiler.
//
// Generated scenes must be identical byte for byte wherever they are built, and the standard
// library's distributions (std::uniform_int_distribution, ...) are not specified exactly: libstdc++
// and libc++ give different numbers from the same engine. SplitMix64 (Steele, Lea and Flood,
// "Fast splittable pseudorandom number generators", 2014) is fully specified by the few lines
// below, and `below` draws bounded integers by rejection with no modulo bias.
#pragma once

#include <cstdint>

namespace datomsim::scene {

class SplitMix64 {
 public:
  explicit constexpr SplitMix64(uint64_t seed) : state_(seed) {}

  // The next 64 random bits.
  constexpr uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // A uniform integer in [0, bound); bound must be positive. Draws are rejected below
  // 2^64 mod bound, so that every result is equally likely.
  constexpr uint64_t below(uint64_t bound) {
    const uint64_t threshold = (0 - bound) % bound;
    while (true) {
      const uint64_t r = next();
      if (r >= threshold) return r % bound;
    }
  }

 private:
  uint64_t state_;
};

}  // namespace datomsim::scene
