#pragma once
// Private: the random streams of a world. One seed per world; each robot's sensors get their own
// streams derived from it, so results do not depend on which thread senses which robot.

#include <cmath>
#include <cstdint>

namespace frob::worlds::detail {

// SplitMix64: mixes a 64-bit value; used to derive seeds and to fill xoshiro's state.
[[nodiscard]] inline std::uint64_t splitMix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Which stream of a robot a generator feeds.
enum class Stream : std::uint64_t { Sonar = 1, Odometry = 2, Slip = 3, Start = 4, KnownStart = 5 };

// xoshiro256**: small, fast and the same on every platform (unlike std:: distributions).
class Rng {
 public:
  Rng() : Rng(0, 0, Stream::Sonar) {}
  // The stream `stream` of robot `robot` in a world seeded with `seed`.
  Rng(std::uint64_t seed, std::uint64_t robot, Stream stream) {
    std::uint64_t x = seed;
    x = splitMix64(x) ^ (robot * 0xd1b54a32d192ed03ULL);
    x = splitMix64(x) ^ (static_cast<std::uint64_t>(stream) * 0x8cb92ba72f3d8dd7ULL);
    for (auto& s : s_) s = splitMix64(x);
  }
  // Uniform 64 bits.
  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in (0, 1].
  double uniform() { return (static_cast<double>(next() >> 11) + 1.0) * 0x1.0p-53; }
  // Standard normal (Marsaglia's polar method: a point uniform in the unit disc gives two values;
  // the second is kept for the next call). Half the cost of Box-Muller: one log, no sine or cosine.
  double gaussian() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double m = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * m;
    hasSpare_ = true;
    return u * m;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
  double spare_ = 0.0;
  bool hasSpare_ = false;
};

}  // namespace frob::worlds::detail
