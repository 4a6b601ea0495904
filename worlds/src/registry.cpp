#include "frob/worlds/registry.hpp"

#include "frob/base/layout.hpp"

#include <array>
#include <string>

namespace frob::worlds {
namespace {

constexpr std::array kWorlds = {
    WorldEntry{"empty", "empty_room.toml", "An empty 6 x 4 m room with one robot"},
    WorldEntry{"corridor", "corridor.toml", "A 20 m corridor, 2 m wide, with a bend at the end"},
    WorldEntry{"maze", "maze.toml", "A 20 x 20 m maze of about 200 walls, generated with a fixed seed"},
    WorldEntry{"office", "office.toml", "An office floor plan read from a PNG bitmap (5 cm per pixel)"},
    WorldEntry{"obstacles", "obstacles.toml", "An obstacle field for BUG, with a named goal point"},
    WorldEntry{"mesh", "mesh_rooms.toml", "Two rooms and pillars from an OBJ mesh sliced at sonar height"},
    WorldEntry{"arena", "arena.toml", "A round-cornered 10 x 10 m arena with four robots"},
};

}  // namespace

std::span<const WorldEntry> referenceWorlds() { return kWorlds; }

const WorldEntry* findWorld(std::string_view name) {
  for (const WorldEntry& e : kWorlds)
    if (e.name == name) return &e;
  return nullptr;
}

// Found through the build's or the installed prefix's absolute path, never relative to the working folder.
std::filesystem::path worldDataDir() { return layout().worlds; }

std::filesystem::path worldPath(const WorldEntry& entry) { return worldDataDir() / entry.file; }

Result<WorldDef> loadReferenceWorld(std::string_view name) {
  const WorldEntry* e = findWorld(name);
  if (!e) return Status::failure("no reference world called '" + std::string(name) + "'");
  return loadWorld(worldPath(*e));
}

}  // namespace frob::worlds
