#include "frob/worlds/world_file.hpp"

#include "check.hpp"
#include "frob/worlds/maps.hpp"
#include "frob/worlds/toml_reader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

namespace frob::worlds {
namespace {

constexpr double kDeg = pi / 180.0;

// Reads one world file into a WorldDef, stopping at the first error. Every reader returns false
// after recording "file:line: field: message" in `error`.
class Parser : TomlReader {
 public:
  Parser(std::string file, std::filesystem::path base) : TomlReader(file), base_(std::move(base)) { lines_.file = std::move(file); }

  Result<WorldDef> parse(std::string_view text) {
    toml::table root;
    if (!TomlReader::parse(text, root)) return failed(error());
    if (!readWorld(root)) return failed(error());
    if (Status s = detail::checkWorld(world_, lines_); !s) return s;
    return std::move(world_);
  }

 private:
  static Result<WorldDef> failed(std::string e) { return Status::failure(std::move(e)); }
  static int line(const toml::source_region& r) { return static_cast<int>(r.begin.line); }
  using TomlReader::line;

  bool readWorld(const toml::table& root) {
    if (!onlyKeys(root, "",
                  {"description", "size", "enclosed", "seed", "wall", "points", "robot", "key", "bitmap", "mesh", "sonar", "odometry", "drive",
                   "start_spread"}))
      return false;
    if (auto n = root.get("description"); n && !string(*n, "description", world_.description)) return false;
    const toml::node* size = root.get("size");
    if (!size) return fail(1, "size", "missing (expected [width, height] in metres)");
    lines_.size = line(size->source());
    if (!point(*size, "size", world_.size)) return false;
    if (!(world_.size.x() > 0 && world_.size.y() > 0)) return fail(*size, "size", "width and height must be positive");
    if (auto n = root.get("enclosed"); n && !boolean(*n, "enclosed", world_.enclosed)) return false;
    if (auto n = root.get("seed")) {
      auto i = n->as_integer();
      if (!i || i->get() < 0) return fail(*n, "seed", "expected a non-negative integer");
      world_.seed = static_cast<std::uint64_t>(i->get());
    }
    // Defaults shared by every robot, each robot may override them.
    if (auto n = root.get("sonar")) {
      auto t = table(*n, "sonar");
      if (!t || !readSonar(*t, "sonar.", defaults_.sonar)) return false;
    }
    if (auto n = root.get("odometry")) {
      auto t = table(*n, "odometry");
      if (!t || !readOdometry(*t, "odometry.", defaults_.odometry)) return false;
    }
    if (auto n = root.get("drive")) {
      auto t = table(*n, "drive");
      if (!t || !readDrive(*t, "drive.", defaults_.drive)) return false;
    }
    if (auto n = root.get("start_spread")) {
      auto t = table(*n, "start_spread");
      if (!t || !readStartSpread(*t, "start_spread.", defaults_.startSpread)) return false;
    }
    return eachTable(root, "wall", [&](const toml::table& t, const std::string& f) { return readWall(t, f); }) && readPoints(root) &&
           readMap(root, "bitmap") && readMap(root, "mesh") &&
           eachTable(root, "robot", [&](const toml::table& t, const std::string& f) { return readRobot(t, f); }) &&
           eachTable(root, "key", [&](const toml::table& t, const std::string& f) { return readKey(t, f); });
  }

  // Calls `read` for each table of the array of tables `key` ([[key]] in TOML).
  template <class F>
  bool eachTable(const toml::table& root, std::string_view key, F read) {
    const toml::node* n = root.get(key);
    if (!n) return true;
    auto a = n->as_array();
    if (!a) return fail(*n, std::string(key), "expected an array of tables ([[" + std::string(key) + "]])");
    if (a->size() > 100000) return fail(*n, std::string(key), "too many entries");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string field = std::string(key) + "[" + std::to_string(i) + "]";
      auto t = table((*a)[i], field);
      if (!t || !read(*t, field + ".")) return false;
    }
    return true;
  }

  bool readWall(const toml::table& t, const std::string& f) {
    if (!onlyKeys(t, f, {"from", "to", "polyline", "closed", "rect", "circle", "radius"})) return false;
    const int l = line(t.source());
    const int kinds = int(t.contains("from") || t.contains("to")) + int(t.contains("polyline")) + int(t.contains("rect")) + int(t.contains("circle"));
    if (kinds != 1) return fail(l, f.substr(0, f.size() - 1), "give exactly one of from/to, polyline, rect, circle");
    WallDef w;
    if (t.contains("from") || t.contains("to")) {
      if (!t.contains("from")) return fail(l, f + "from", "missing (a segment needs from and to)");
      if (!t.contains("to")) return fail(l, f + "to", "missing (a segment needs from and to)");
      Point2 a, b;
      if (!point(*t.get("from"), f + "from", a) || !point(*t.get("to"), f + "to", b)) return false;
      w = segmentWall(a, b);
    } else if (auto n = t.get("polyline")) {
      auto arr = n->as_array();
      if (!arr || arr->size() < 2) return fail(*n, f + "polyline", "expected [[x, y], [x, y], ...] with 2 or more points");
      w.shape = WallShape::Polyline;
      for (std::size_t i = 0; i < arr->size(); ++i) {
        Point2 p;
        if (!point((*arr)[i], f + "polyline[" + std::to_string(i) + "]", p)) return false;
        w.points.push_back(p);
      }
      if (auto c = t.get("closed"); c && !boolean(*c, f + "closed", w.closed)) return false;
    } else if (auto r = t.get("rect")) {
      auto arr = r->as_array();
      if (!arr || arr->size() != 2) return fail(*r, f + "rect", "expected [[x0, y0], [x1, y1]] (two corners)");
      Point2 a, b;
      if (!point((*arr)[0], f + "rect[0]", a) || !point((*arr)[1], f + "rect[1]", b)) return false;
      w = rectangleWall(a.cwiseMin(b), a.cwiseMax(b));
    } else {
      Point2 c;
      if (!point(*t.get("circle"), f + "circle", c)) return false;
      const toml::node* rad = t.get("radius");
      if (!rad) return fail(l, f + "radius", "missing (a circle needs a radius)");
      double radius = 0;
      if (!number(*rad, f + "radius", radius)) return false;
      if (radius <= 0) return fail(*rad, f + "radius", "must be positive");
      w = circleWall(c, radius);
    }
    if (w.shape != WallShape::Circle && t.contains("radius")) return fail(l, f + "radius", "only a circle has a radius");
    if (w.shape != WallShape::Polyline && t.contains("closed")) return fail(l, f + "closed", "only a polyline can be closed");
    world_.walls.push_back(std::move(w));
    lines_.walls.push_back(l);
    return true;
  }

  bool readPoints(const toml::table& root) {
    const toml::node* n = root.get("points");
    if (!n) return true;
    auto t = table(*n, "points");
    if (!t) return false;
    for (auto&& [k, v] : *t) {
      Landmark p{.name = std::string(k.str())};
      if (!point(v, "points." + p.name, p.position)) return false;
      world_.points.push_back(std::move(p));
      lines_.points.push_back(line(v.source()));
    }
    return true;
  }

  // [bitmap] or [mesh]: loads the map file (relative to the world file) and appends its walls.
  bool readMap(const toml::table& root, std::string_view key) {
    const toml::node* n = root.get(key);
    if (!n) return true;
    const std::string f(key);
    auto t = table(*n, f);
    if (!t) return false;
    const bool bitmap = key == "bitmap";
    if (!(bitmap ? onlyKeys(*t, f + ".", {"file", "scale", "origin", "threshold"})
                 : onlyKeys(*t, f + ".", {"file", "height", "scale", "origin", "up"})))
      return false;
    const int l = line(t->source());
    const toml::node* file = t->get("file");
    if (!file) return fail(l, f + ".file", "missing (the path of the map, relative to this world file)");
    std::string name;
    if (!string(*file, f + ".file", name)) return false;
    const std::filesystem::path path = base_ / name;
    Result<std::vector<WallDef>> walls = Status::failure("no map");  // one of the branches below sets it
    if (bitmap) {
      BitmapDef d;
      if (!optNumber(*t, "scale", f + ".scale", d.scale) || !optPoint(*t, "origin", f + ".origin", d.origin) ||
          !optInteger(*t, "threshold", f + ".threshold", 0, 256, d.threshold))
        return false;
      if (!(d.scale > 0 && d.scale <= 10)) return fail(l, f + ".scale", "must lie in (0, 10] metres per pixel");
      walls = wallsFromBitmap(path, d);
    } else {
      MeshDef d;
      if (!optNumber(*t, "height", f + ".height", d.height) || !optNumber(*t, "scale", f + ".scale", d.scale) ||
          !optPoint(*t, "origin", f + ".origin", d.origin))
        return false;
      if (!(d.scale > 0 && d.scale <= 1e6)) return fail(l, f + ".scale", "must be positive");
      if (auto up = t->get("up")) {
        std::string axis;
        if (!string(*up, f + ".up", axis)) return false;
        if (axis != "y" && axis != "z") return fail(*up, f + ".up", "expected \"z\" or \"y\"");
        d.yUp = axis == "y";
      }
      walls = wallsFromMesh(path, d);
    }
    if (!walls) return fail(*file, f + ".file", walls.error());
    for (auto& w : walls.value()) {
      world_.walls.push_back(std::move(w));
      lines_.walls.push_back(l);
    }
    return true;
  }

  bool readSonar(const toml::table& t, const std::string& f, SonarDef& s) {
    if (!onlyKeys(t, f, {"count", "angles_deg", "cone_deg", "rays", "min_range", "max_range", "specular_cutoff_deg", "noise"})) return false;
    if (!optInteger(t, "count", f + "count", 0, 64, s.count) || !optInteger(t, "rays", f + "rays", 1, 64, s.rays) ||
        !optNumber(t, "cone_deg", f + "cone_deg", s.cone, kDeg) || !optNumber(t, "min_range", f + "min_range", s.minRange) ||
        !optNumber(t, "max_range", f + "max_range", s.maxRange) ||
        !optNumber(t, "specular_cutoff_deg", f + "specular_cutoff_deg", s.specularCutoff, kDeg) || !optNumber(t, "noise", f + "noise", s.noise))
      return false;
    if (auto n = t.get("angles_deg")) {
      auto a = n->as_array();
      if (!a || a->size() > 64) return fail(*n, f + "angles_deg", "expected an array of at most 64 angles in degrees");
      s.angles.clear();
      for (std::size_t i = 0; i < a->size(); ++i) {
        double v = 0;
        if (!number((*a)[i], f + "angles_deg[" + std::to_string(i) + "]", v)) return false;
        s.angles.push_back(wrapAngle(v * kDeg));
      }
      if (t.contains("count") && static_cast<std::size_t>(s.count) != s.angles.size())
        return fail(*n, f + "angles_deg", "has " + std::to_string(a->size()) + " angles but count is " + std::to_string(s.count));
    }
    return true;
  }

  bool readOdometry(const toml::table& t, const std::string& f, OdometryDef& o) {
    return onlyKeys(t, f, {"translation", "heading", "turn"}) && optNumber(t, "translation", f + "translation", o.translation) &&
           optNumber(t, "heading", f + "heading", o.heading) && optNumber(t, "turn", f + "turn", o.turn);
  }

  bool readDrive(const toml::table& t, const std::string& f, DriveDef& d) {
    return onlyKeys(t, f, {"max_speed", "max_turn_rate", "acceleration", "turn_acceleration", "slip", "slip_time", "start_delay"}) &&
           optNumber(t, "max_speed", f + "max_speed", d.maxSpeed) && optNumber(t, "max_turn_rate", f + "max_turn_rate", d.maxTurnRate) &&
           optNumber(t, "acceleration", f + "acceleration", d.acceleration) &&
           optNumber(t, "turn_acceleration", f + "turn_acceleration", d.turnAcceleration) && optNumber(t, "slip", f + "slip", d.slip) &&
           optNumber(t, "slip_time", f + "slip_time", d.slipTime) && optNumber(t, "start_delay", f + "start_delay", d.startDelay);
  }

  bool readStartSpread(const toml::table& t, const std::string& f, StartSpreadDef& s) {
    return onlyKeys(t, f, {"position", "heading_deg", "known_position", "known_heading_deg"}) &&
           optNumber(t, "position", f + "position", s.position) && optNumber(t, "heading_deg", f + "heading_deg", s.heading, kDeg) &&
           optNumber(t, "known_position", f + "known_position", s.knownPosition) &&
           optNumber(t, "known_heading_deg", f + "known_heading_deg", s.knownHeading, kDeg);
  }

  bool readRobot(const toml::table& t, const std::string& f) {
    if (!onlyKeys(t, f, {"name", "start", "heading_deg", "radius", "density", "bumpers", "sonar", "odometry", "drive", "start_spread"})) return false;
    RobotDef r = defaults_;
    const toml::node* start = t.get("start");
    if (!start) return fail(line(t.source()), f + "start", "missing (expected [x, y] in metres)");
    if (!point(*start, f + "start", r.start.position)) return false;
    if (auto n = t.get("name"); n && !string(*n, f + "name", r.name)) return false;
    if (!optNumber(t, "heading_deg", f + "heading_deg", r.start.heading, kDeg) || !optNumber(t, "radius", f + "radius", r.radius) ||
        !optNumber(t, "density", f + "density", r.density) || !optInteger(t, "bumpers", f + "bumpers", 1, 64, r.bumpers))
      return false;
    r.start.heading = wrapAngle(r.start.heading);
    if (auto n = t.get("sonar")) {
      auto s = table(*n, f + "sonar");
      if (!s || !readSonar(*s, f + "sonar.", r.sonar)) return false;
    }
    if (auto n = t.get("odometry")) {
      auto s = table(*n, f + "odometry");
      if (!s || !readOdometry(*s, f + "odometry.", r.odometry)) return false;
    }
    if (auto n = t.get("drive")) {
      auto s = table(*n, f + "drive");
      if (!s || !readDrive(*s, f + "drive.", r.drive)) return false;
    }
    if (auto n = t.get("start_spread")) {
      auto s = table(*n, f + "start_spread");
      if (!s || !readStartSpread(*s, f + "start_spread.", r.startSpread)) return false;
    }
    world_.robots.push_back(std::move(r));
    lines_.robots.push_back(line(start->source()));
    return true;
  }

  bool readKey(const toml::table& t, const std::string& f) {
    if (!onlyKeys(t, f, {"time", "key", "robot"})) return false;
    KeyEventDef k;
    const toml::node* time = t.get("time");
    const toml::node* key = t.get("key");
    if (!time) return fail(line(t.source()), f + "time", "missing (seconds)");
    if (!key) return fail(line(t.source()), f + "key", "missing (a one-character string)");
    std::string s;
    if (!number(*time, f + "time", k.time) || !string(*key, f + "key", s)) return false;
    if (s.size() != 1) return fail(*key, f + "key", "expected exactly one character");
    k.key = s[0];
    if (!optInteger(t, "robot", f + "robot", -1, 999, k.robot)) return false;
    world_.keys.push_back(k);
    lines_.keys.push_back(line(t.source()));
    return true;
  }

  std::filesystem::path base_;
  detail::SourceLines lines_;
  WorldDef world_;
  RobotDef defaults_;
};

}  // namespace

Result<WorldDef> parseWorld(std::string_view text, std::string_view fileName, const std::filesystem::path& baseDir) {
  try {
    return Parser(std::string(fileName), baseDir).parse(text);
  } catch (const std::exception& e) {  // e.g. out of memory: still a message, never an escape
    return Status::failure(std::string(fileName) + ": " + e.what());
  }
}

Result<WorldDef> loadWorld(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::failure(path.string() + ": cannot open the world file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseWorld(text.str(), path.filename().string(), path.parent_path());
}

}  // namespace frob::worlds
