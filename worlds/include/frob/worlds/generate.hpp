#pragma once
/// Worlds made from a kind and a seed, for hidden checks drawn from an instructor's secret: each
/// is checked for what its kind promises before it is handed out, and writes as a world file that
/// loads back to the same world. The same kind and seed give the same world on every machine.
///
///   Result<WorldDef> w = generateWorld(WorldKind::Obstacles, 42);
///   std::ofstream("field.toml") << toToml(w.value());

#include "frob/base/result.hpp"
#include "frob/worlds/world_def.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frob::worlds {

/// What a generated world is. Every kind promises: the robot's start and the point "goal" have at
/// least 0.1 m of clearance around the body, and the goal can be reached from the start by the body.
enum class WorldKind {
  Obstacles,  ///< 15 x 15 m, start (1.5, 1.5), goal (13.5, 13.5); blocks, pillars and an L-shaped trap, each two more than the robot's diameter apart
  Maze,       ///< a perfect maze of 1.6 m cells; start and goal in opposite corner cells
  Rooms,      ///< a floor of rooms joined by doorways at least 1.2 m wide, with furniture; the goal in the room farthest away
  Loop,       ///< a corridor round a block, 1.2 to 2 m wide, with convex and concave corners; the goal halfway round
};

/// The kinds by name: "obstacles", "maze", "rooms", "loop".
[[nodiscard]] std::optional<WorldKind> worldKind(std::string_view name);
[[nodiscard]] const char* toString(WorldKind kind);
/// Every kind's name, for messages and --help.
[[nodiscard]] std::string worldKindNames();

/// The world of `kind` made from `seed`; fails only if no world keeping the promises was found.
[[nodiscard]] Result<WorldDef> generateWorld(WorldKind kind, std::uint64_t seed);

/// `world` as a world file (walls, points, robots, keys and the seed; the generators' worlds use
/// nothing else) that the loader reads back to the same walls and points.
[[nodiscard]] std::string toToml(const WorldDef& world);

}  // namespace frob::worlds
