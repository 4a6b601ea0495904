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

/// What a generated world is. Every kind promises: each robot's start and every named point have at
/// least 0.1 m of clearance around the body, and the body can reach every point from the first start.
/// The kinds after Loop are the assignments' hidden families: each keeps what its handout promises.
enum class WorldKind {
  Obstacles,  ///< 15 x 15 m, start (1.5, 1.5), goal (13.5, 13.5); blocks, pillars, an L-shaped trap and a spur from each wall beside the start (no
              ///< way along the walls), each two more than the robot's diameter apart (bug)
  Maze,       ///< a perfect maze of 1.6 m cells; start and goal in opposite corner cells
  Rooms,      ///< a floor of rooms joined by doorways at least 1.2 m wide, with furniture; the goal in the room farthest away
  Loop,       ///< a corridor round a block, 1.2 to 2 m wide, with convex and concave corners; the goal halfway round
  FurnishedRoom,  ///< a 5.5-7.5 x 4.5-6.5 m room entered from a hall; point "room" 1 m inside; furniture 0.8 m from everything, or against the walls
                  ///< (wander)
  Outline,        ///< a closed room with alcoves and pillars (concave and convex corners); points a-f on the path 40 cm from the wall on the right
                  ///< (wall_follow)
  Lounge,  ///< 12 x 10 m, the handout's waypoints wp1-wp4; a piece across each leg, shelves anywhere along the walls and pieces anywhere else: no
           ///< fixed way stays clear (go_to_goal)
  WarehouseKeys,  ///< the warehouse patrol p1-p4; other keys pressed, then "s" between 14 and 24 s (parallel)
  WarehouseBox,   ///< the warehouse patrol p1-p4; a box across one of its legs (parallel)
  Crossing,  ///< 10 x 10 m, 2-4 robots ada, bob, cy, dee 2-4 m from "centre" (5, 5), goal_<name> opposite each start through it; each robot with a
             ///< start delay (0-4 s) and top speed (0.4-0.6 m/s) of its own; 4-6 round pillars round the middle, every circle of 1-3 m round the
             ///< centre blocked (multi_robot)
};

/// The kinds by name: "obstacles", "maze", "rooms", "loop", "furnished_room", ...
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
