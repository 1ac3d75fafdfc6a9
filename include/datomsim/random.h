// SplitMix64 (Steele, Lea and Flood, 2014): a small random generator with the same sequence on
// every platform and standard library, which std::uniform_int_distribution does not promise.
#pragma once

#include <cstdint>

namespace datomsim {

class SplitMix64 {
 public:
  explicit SplitMix64(uint64_t seed) : state_(seed) {}

  // A stream for one consumer (a module, a generator) derived from a seed and a stream number,
  // independent of the order in which streams are created.
  static SplitMix64 stream(uint64_t seed, uint64_t stream) {
    SplitMix64 mixer(seed ^ (stream * 0xd1b54a32d192ed03ULL));
    return SplitMix64(mixer.next());
  }

  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, bound) for bound > 0. Draws below 2^64 mod bound are thrown away, so that
  // every result is equally likely.
  uint64_t below(uint64_t bound) {
    const uint64_t threshold = (0 - bound) % bound;
    uint64_t draw = next();
    while (draw < threshold) draw = next();
    return draw % bound;
  }

  // Uniform in [low, high].
  int64_t between(int64_t low, int64_t high) {
    return low + static_cast<int64_t>(below(static_cast<uint64_t>(high - low) + 1));
  }

 private:
  uint64_t state_;
};

// Module programs and generators draw from this one generator.
using Random = SplitMix64;

}  // namespace datomsim
