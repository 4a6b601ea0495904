#pragma once
// What every world generator shares (private to worlds/src): the random stream, millimetre
// snapping, and distances between walls.

#include "frob/worlds/world_def.hpp"

#include <cstdint>
#include <vector>

namespace frob::worlds::kit {

constexpr double kRadius = 0.23;    // the Nomad's body, which the promises are kept for
constexpr double kClearance = 0.1;  // around the body at every start and named point

// SplitMix64, with reals from the top 53 bits: the same numbers from every standard library.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53; }
  int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
  bool coin() { return next() % 2 == 0; }

 private:
  std::uint64_t state_;
};

/// A length or coordinate to the millimetre, so that a world file reads back exactly.
[[nodiscard]] double mm(double v);
/// A world with one robot, "nomad", at `start`.
[[nodiscard]] WorldDef base(const char* what, const Vec2& size, std::uint64_t seed, const Point2& start, double headingDeg);
/// Every robot of `w` starts within `metres` and `degrees` of its start, drawn in each run and known
/// to it (StartSpreadDef): as the handed-out worlds of its assignment do, so that no start tells a
/// generated world from a handed-out one.
void knownSpread(WorldDef& w, double metres, double degrees);
/// The walls of `w` with its enclosure, as the simulator builds them.
[[nodiscard]] std::vector<WallDef> allWalls(const WorldDef& w);
/// Nearest distance between two walls (0 when they touch or overlap), sampled along the edges of `a`.
[[nodiscard]] double gapBetween(const WallDef& a, const WallDef& b);
/// The smaller of gapBetween both ways: the distance between two walls, to about a centimetre.
[[nodiscard]] double gap(const WallDef& a, const WallDef& b);

// The assignments' families (families.cpp), each made from its own stream.
WorldDef furnishedRoom(Random& r, std::uint64_t seed);
WorldDef outline(Random& r, std::uint64_t seed);
WorldDef lounge(Random& r, std::uint64_t seed);
WorldDef warehouseKeys(Random& r, std::uint64_t seed);
WorldDef warehouseBox(Random& r, std::uint64_t seed);
WorldDef crossing(Random& r, std::uint64_t seed);

}  // namespace frob::worlds::kit
