// A small portable random generator (SplitMix64): the same sequence on every platform and
// standard library, which std::uniform_int_distribution does not promise.
#pragma once

#include <cstdint>

namespace datomsim {

class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}

  // A stream for one consumer (a module, a generator) derived from a seed and a stream number,
  // independent of the order in which streams are created.
  static Random stream(uint64_t seed, uint64_t stream) {
    Random mixer(seed ^ (stream * 0xd1b54a32d192ed03ULL));
    return Random(mixer.next());
  }

  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, bound) for bound > 0, without modulo bias: draws above the largest multiple
  // of bound are thrown away.
  uint64_t below(uint64_t bound) {
    const uint64_t limit = UINT64_MAX - UINT64_MAX % bound;
    uint64_t draw = next();
    while (draw >= limit) draw = next();
    return draw % bound;
  }

  // Uniform in [low, high].
  int64_t between(int64_t low, int64_t high) {
    return low + static_cast<int64_t>(below(static_cast<uint64_t>(high - low) + 1));
  }

 private:
  uint64_t state_;
};

}  // namespace datomsim
