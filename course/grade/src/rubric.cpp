#include "frob/grade/rubric.hpp"

#include "frob/worlds/fnv.hpp"
#include "frob/worlds/registry.hpp"
#include "frob/worlds/toml_reader.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace frob::course {

namespace fs = std::filesystem;
using Kind = Criterion::Kind;

namespace {

constexpr int kPoolPerWorld = 8;  // a submission's hidden worlds are chosen among 8 fair draws per world, by default

// The criteria a check may name, with the keys each takes.
struct CriterionSpec {
  std::string_view key;
  Kind kind;
  std::initializer_list<std::string_view> fields;
};
const CriterionSpec kCriteria[] = {
    {"goal", Kind::Goal, {"within", "by", "point"}},
    {"waypoints", Kind::Waypoints, {"points", "within", "by"}},
    {"stopped", Kind::Stopped, {"speed", "after_key", "after_contact", "within"}},
    {"collisions", Kind::Collisions, {"max", "seconds"}},
    {"clearance", Kind::Clearance, {"min"}},
    {"wall_distance", Kind::WallDistance, {"target", "tolerance", "fraction", "after", "side"}},
    {"coverage", Kind::Coverage, {"fraction", "cell", "away"}},
    {"robots_apart", Kind::RobotsApart, {"min"}},
    {"path_ratio", Kind::PathRatio, {"max", "point", "within"}},
    {"bug1_bound", Kind::Bug1Bound, {"point", "within"}},
    {"returns", Kind::Returns, {"value", "after_key", "after_contact", "after_distance", "within"}},
};

class RubricReader : worlds::TomlReader {
 public:
  RubricReader(const fs::path& file) : TomlReader(file.string()), dir_(file.parent_path()) { rubric_.file = file; }

  Result<Rubric> read(std::string_view text) {
    toml::table root;
    if (!parse(text, root) || !readRubric(root)) return Status::failure(error());
    return std::move(rubric_);
  }

 private:
  bool readRubric(const toml::table& root) {
    if (!onlyKeys(root, "", {"title", "reference", "starter", "dt", "seconds", "late", "check", "leaderboard"})) return false;
    if (const toml::node* late = root.get("late")) {
      const toml::table* t = table(*late, "late");
      if (t == nullptr || !onlyKeys(*t, "late.", {"per_day", "most"}) || !need(*t, "per_day", "late.", rubric_.latePerDay) ||
          !optNumber(*t, "most", "late.most", rubric_.lateMost)) {
        return false;
      }
      if (!(rubric_.latePerDay <= 1)) return fail(*t->get("per_day"), "late.per_day", "must lie in (0, 1]: a share of the score");
      if (!(rubric_.lateMost > 0 && rubric_.lateMost <= 1)) return fail(*t->get("most"), "late.most", "must lie in (0, 1]: a share of the score");
    }
    double seconds = 60.0;
    std::string reference, starter;
    if (!optString(root, "title", "title", rubric_.title) || !optNumber(root, "dt", "dt", rubric_.dt) ||
        !optNumber(root, "seconds", "seconds", seconds) || !optString(root, "reference", "reference", reference) ||
        !optString(root, "starter", "starter", starter)) {
      return false;
    }
    if (!reference.empty()) rubric_.reference = dir_ / reference;  // may be missing: a Gradescope zip carries none
    if (!starter.empty()) rubric_.starter = dir_ / starter;
    if (!(rubric_.dt > 0 && rubric_.dt <= 0.1)) return fail(*root.get("dt"), "dt", "must lie in (0, 0.1] seconds");
    if (!(seconds > 0)) return fail(*root.get("seconds"), "seconds", "must be positive");
    const toml::array* checks = root.get("check") ? root.get("check")->as_array() : nullptr;
    if (checks == nullptr || checks->empty()) return fail(1, "check", "no [[check]] given: a rubric needs at least one");
    for (std::size_t i = 0; i < checks->size(); ++i) {
      const std::string field = "check[" + std::to_string(i) + "].";
      const toml::table* t = table((*checks)[i], field);
      Check c{.seconds = seconds, .line = line((*checks)[i])};
      if (t == nullptr || !readCheck(*t, field, c)) return false;
      for (const Check& other : rubric_.checks) {
        if (other.name == c.name) return fail(c.line, field + "name", "'" + c.name + "' names two checks");
      }
      rubric_.checks.push_back(std::move(c));
    }
    return readLeaderboard(root);
  }

  // `[[leaderboard]]`: each names a criterion of a visible check and what of it to rank by.
  bool readLeaderboard(const toml::table& root) {
    const toml::node* n = root.get("leaderboard");
    if (n == nullptr) return true;
    const toml::array* list = n->as_array();
    if (list == nullptr) return fail(*n, "leaderboard", "expected [[leaderboard]] tables");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string field = "leaderboard[" + std::to_string(i) + "].";
      const toml::table* t = table((*list)[i], field);
      if (t == nullptr || !onlyKeys(*t, field, {"name", "check", "criterion", "measure", "order"})) return false;
      LeaderboardMetric m{.line = line((*list)[i])};
      std::string criterion, measure = "margin", order;
      for (const char* key : {"name", "check", "criterion"}) {
        if (t->get(key) == nullptr) return fail(m.line, field + key, "missing");
      }
      if (!string(*t->get("name"), field + "name", m.name) || !string(*t->get("check"), field + "check", m.check) ||
          !string(*t->get("criterion"), field + "criterion", criterion) || !optString(*t, "measure", field + "measure", measure) ||
          !optString(*t, "order", field + "order", order))
        return false;
      const auto check = std::find_if(rubric_.checks.begin(), rubric_.checks.end(), [&](const Check& c) { return c.name == m.check; });
      if (check == rubric_.checks.end()) return fail(*t->get("check"), field + "check", "no check is named '" + m.check + "'");
      if (check->visibility != Visibility::Visible) {
        return fail(*t->get("check"), field + "check",
                    "'" + m.check + "' is not visible: every student reads a leaderboard, and a hidden check's numbers are chosen by the controller");
      }
      const auto given =
          std::find_if(check->criteria.begin(), check->criteria.end(), [&](const Criterion& c) { return toString(c.kind) == criterion; });
      if (given == check->criteria.end())
        return fail(*t->get("criterion"), field + "criterion", "check '" + m.check + "' has no " + criterion + " criterion");
      m.criterion = given->kind;
      if (measure == "time") {
        m.measure = LeaderboardMetric::Measure::Time;
        if ((m.criterion != Kind::Goal && m.criterion != Kind::Waypoints) || given->seconds <= 0)
          return fail(*t->get("measure"), field + "measure",
                      "\"time\" is when a goal or the last waypoint was reached: the criterion must be one with `by`");
      } else if (measure != "margin") {
        return fail(*t->get("measure"), field + "measure", "expected \"time\" or \"margin\"");
      }
      m.ascending = m.measure == LeaderboardMetric::Measure::Time;
      if (order == "asc" || order == "desc") {
        m.ascending = order == "asc";
      } else if (!order.empty()) {
        return fail(*t->get("order"), field + "order", "expected \"asc\" (smaller first) or \"desc\"");
      }
      rubric_.leaderboard.push_back(std::move(m));
    }
    return true;
  }

  bool readCheck(const toml::table& t, const std::string& field, Check& c) {
    for (auto&& [k, v] : t) {
      static constexpr std::string_view own[] = {"name",  "points",       "visibility", "worlds", "generated",
                                                 "seeds", "secret_seeds", "seconds",    "runs_of"};
      const std::string_view key = k.str();  // not the binding itself: clang 15 cannot capture a structured binding in a lambda
      if (std::find(std::begin(own), std::end(own), key) != std::end(own)) continue;
      const auto spec = std::find_if(std::begin(kCriteria), std::end(kCriteria), [&](const CriterionSpec& s) { return s.key == key; });
      if (spec == std::end(kCriteria)) {
        std::string list;
        for (const CriterionSpec& s : kCriteria) list += (list.empty() ? "" : ", ") + std::string(s.key);
        return fail(static_cast<int>(k.source().begin.line), field + std::string(k.str()),
                    "unknown key: a check has name, points, visibility, worlds, generated, seeds, secret_seeds, seconds, runs_of and criteria (" +
                        list + ")");
      }
      const toml::table* params = table(v, field + std::string(k.str()));
      if (params == nullptr) return false;
      Criterion criterion{.kind = spec->kind, .line = line(v)};
      if (!readCriterion(*params, field + std::string(k.str()) + ".", *spec, criterion)) return false;
      c.criteria.push_back(std::move(criterion));
    }
    const toml::node* name = t.get("name");
    if (name == nullptr) return fail(c.line, field + "name", "missing: every check needs a name");
    if (!string(*name, field + "name", c.name)) return false;
    if (c.name.empty()) return fail(*name, field + "name", "must not be empty");
    if (!optNumber(t, "points", field + "points", c.points) || !optNumber(t, "seconds", field + "seconds", c.seconds) ||
        !optInteger(t, "secret_seeds", field + "secret_seeds", 0, 1000, c.secretSeeds)) {
      return false;
    }
    if (!(c.points >= 0)) return fail(*t.get("points"), field + "points", "must not be negative");
    if (!(c.seconds > 0 && c.seconds <= 24 * 3600)) return fail(*t.get("seconds"), field + "seconds", "must lie in (0, 86400]");
    if (const toml::node* v = t.get("visibility")) {
      std::string text;
      if (!string(*v, field + "visibility", text)) return false;
      if (text == "visible")
        c.visibility = Visibility::Visible;
      else if (text == "hidden")
        c.visibility = Visibility::Hidden;
      else if (text == "after_due_date")
        c.visibility = Visibility::AfterDueDate;
      else
        return fail(*v, field + "visibility", "expected \"visible\", \"hidden\" or \"after_due_date\"");
    }
    if (t.get("runs_of") != nullptr) {
      if (!readRunsOf(t, field, c)) return false;
    } else if (!readGenerated(t, field, c) || !readWorlds(t, field, c) || !readSeeds(t, field, c)) {
      return false;
    }
    if (c.criteria.empty()) return fail(c.line, field + "name", "check '" + c.name + "' has no criterion");
    // Unbounded, a place is reached by anything that wanders long enough: a check students cannot see must say by when.
    for (const Criterion& k : c.criteria) {
      if (c.visibility != Visibility::Visible && (k.kind == Kind::Goal || k.kind == Kind::Waypoints) && k.seconds <= 0)
        return fail(k.line, field + std::string(toString(k.kind)) + ".by", "missing: a check that is not visible must give the time allowed");
    }
    // In the order written (TOML tables list their keys sorted): the first that fails gives the reason.
    std::stable_sort(c.criteria.begin(), c.criteria.end(), [](const Criterion& a, const Criterion& b) { return a.line < b.line; });
    return true;
  }

  // `runs_of = "NAME"`: the runs of an earlier check of the same visibility, judged by this one's
  // criteria; it names none of its own.
  bool readRunsOf(const toml::table& t, const std::string& field, Check& c) {
    std::string name;
    const toml::node& n = *t.get("runs_of");
    if (!string(n, field + "runs_of", name)) return false;
    for (const char* key : {"worlds", "generated", "seeds", "secret_seeds", "seconds"}) {
      if (const toml::node* own = t.get(key))
        return fail(*own, field + key, "this check judges the runs of '" + name + "' (runs_of): it has that check's worlds, seeds and seconds");
    }
    const auto other = std::find_if(rubric_.checks.begin(), rubric_.checks.end(), [&](const Check& o) { return o.name == name; });
    if (other == rubric_.checks.end()) return fail(n, field + "runs_of", "no earlier check is named '" + name + "'");
    if (other->visibility != c.visibility) {
      return fail(n, field + "runs_of",
                  "'" + name + "' is " + toString(other->visibility) + " and this check is " + toString(c.visibility) +
                      ": a check judges the runs of a check as visible as itself");
    }
    c.worlds = other->worlds;
    c.generated = other->generated;
    c.seeds = other->seeds;
    c.secretSeeds = other->secretSeeds;
    c.seconds = other->seconds;
    c.runsOf = other->drawName();
    return true;
  }

  bool readGenerated(const toml::table& t, const std::string& field, Check& c) {
    const toml::node* n = t.get("generated");
    if (n == nullptr) return true;
    const toml::table* g = table(*n, field + "generated");
    if (g == nullptr || !onlyKeys(*g, field + "generated.", {"kind", "seeds", "secret", "pool"})) return false;
    GeneratedWorlds gen;
    std::string kind;
    const toml::node* k = g->get("kind");
    if (k == nullptr) return fail(*n, field + "generated.kind", "missing (one of " + worlds::worldKindNames() + ")");
    if (!string(*k, field + "generated.kind", kind)) return false;
    if (!worlds::worldKind(kind)) return fail(*k, field + "generated.kind", "unknown kind '" + kind + "' (one of " + worlds::worldKindNames() + ")");
    gen.kind = *worlds::worldKind(kind);
    if (!seedList(*g, "seeds", field + "generated.seeds", gen.seeds) || !optInteger(*g, "secret", field + "generated.secret", 0, 1000, gen.secret))
      return false;
    if (gen.seeds.empty() && gen.secret == 0) return fail(*n, field + "generated", "give seeds, or a number of secret ones");
    gen.pool = std::min(1000, kPoolPerWorld * gen.secret);  // each submission its own draws: probing by resubmitting learns little
    if (!optInteger(*g, "pool", field + "generated.pool", gen.secret, 1000, gen.pool)) return false;
    c.generated = gen;
    return true;
  }

  bool readWorlds(const toml::table& t, const std::string& field, Check& c) {
    const toml::node* n = t.get("worlds");
    if (n == nullptr && c.generated) return true;
    const toml::array* list = n != nullptr ? n->as_array() : nullptr;
    if (list == nullptr || list->empty()) {
      return fail(n != nullptr ? line(*n) : c.line, field + "worlds", "expected a list of reference worlds or world files (or generated worlds)");
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      WorldRef w;
      const std::string f = field + "worlds[" + std::to_string(i) + "]";
      if (!string((*list)[i], f, w.name)) return false;
      if (worlds::findWorld(w.name) == nullptr) {
        w.file = dir_ / w.name;
        if (!fs::is_regular_file(w.file)) {
          return fail((*list)[i], f, "'" + w.name + "' is neither a reference world (see frob list) nor a file beside the rubric");
        }
      }
      c.worlds.push_back(std::move(w));
    }
    return true;
  }

  bool readSeeds(const toml::table& t, const std::string& field, Check& c) { return seedList(t, "seeds", field + "seeds", c.seeds); }

  // An optional list of non-negative integers.
  bool seedList(const toml::table& t, std::string_view key, const std::string& field, std::vector<std::uint64_t>& out) {
    const toml::node* n = t.get(key);
    if (n == nullptr) return true;
    const toml::array* list = n->as_array();
    if (list == nullptr) return fail(*n, field, "expected a list of seeds");
    for (std::size_t i = 0; i < list->size(); ++i) {
      long long seed = 0;
      if (!integer((*list)[i], field + "[" + std::to_string(i) + "]", 0, std::numeric_limits<long long>::max(), seed)) return false;
      out.push_back(static_cast<std::uint64_t>(seed));
    }
    return true;
  }

  // A required positive (or non-negative) number.
  bool need(const toml::table& t, std::string_view key, const std::string& field, double& out, bool zeroAllowed = false) {
    const toml::node* n = t.get(key);
    if (n == nullptr) return fail(0, field + std::string(key), "missing");
    if (!number(*n, field + std::string(key), out)) return false;
    if (zeroAllowed ? out < 0 : out <= 0) return fail(*n, field + std::string(key), zeroAllowed ? "must not be negative" : "must be positive");
    return true;
  }

  bool readCriterion(const toml::table& t, const std::string& field, const CriterionSpec& spec, Criterion& c) {
    if (!onlyKeys(t, field, spec.fields)) return false;
    const auto fraction = [&](double& out) {
      if (!need(t, "fraction", field, out)) return false;
      return out <= 1 || fail(*t.get("fraction"), field + "fraction", "must lie in (0, 1]");
    };
    switch (c.kind) {
      case Kind::Goal:
        return need(t, "within", field, c.distance) && optNumber(t, "by", field + "by", c.seconds) && optString(t, "point", field + "point", c.point);
      case Kind::Waypoints: {
        const toml::node* n = t.get("points");
        const toml::array* list = n != nullptr ? n->as_array() : nullptr;
        if (list == nullptr || list->empty()) return fail(n != nullptr ? line(*n) : c.line, field + "points", "expected a list of point names");
        for (std::size_t i = 0; i < list->size(); ++i) {
          if (!string((*list)[i], field + "points[" + std::to_string(i) + "]", c.points.emplace_back())) return false;
        }
        return need(t, "within", field, c.distance) && optNumber(t, "by", field + "by", c.seconds);
      }
      case Kind::Stopped:
        return optNumber(t, "speed", field + "speed", c.speed) && readEvent(t, field, c) && optNumber(t, "within", field + "within", c.within);
      case Kind::Collisions:
        return optInteger(t, "max", field + "max", 0, 1'000'000, c.count) && (t.get("seconds") == nullptr || need(t, "seconds", field, c.seconds));
      case Kind::Clearance:
        return need(t, "min", field, c.distance, true);
      case Kind::WallDistance:
        if (!optString(t, "side", field + "side", c.side)) return false;
        if (!c.side.empty() && c.side != "right" && c.side != "left") return fail(*t.get("side"), field + "side", "expected \"right\" or \"left\"");
        return need(t, "target", field, c.distance) && need(t, "tolerance", field, c.tolerance) && fraction(c.fraction) &&
               optNumber(t, "after", field + "after", c.after);
      case Kind::Coverage:
        return fraction(c.fraction) && optNumber(t, "cell", field + "cell", c.cell) &&
               (t.get("away") == nullptr || need(t, "away", field, c.distance, true));
      case Kind::RobotsApart:
        return optNumber(t, "min", field + "min", c.distance);
      case Kind::PathRatio:
        return need(t, "max", field, c.ratio) && optString(t, "point", field + "point", c.point) &&
               optNumber(t, "within", field + "within", c.distance);
      case Kind::Bug1Bound:
        return optString(t, "point", field + "point", c.point) && optNumber(t, "within", field + "within", c.distance);
      case Kind::Returns: {
        const toml::node* n = t.get("value");
        if (n == nullptr) return fail(c.line, field + "value", "missing");
        if (!readEvent(t, field, c) || !optNumber(t, "after_distance", field + "after_distance", c.afterDistance) ||
            !optNumber(t, "within", field + "within", c.within))
          return false;
        if (const auto* b = n->as_boolean()) return c.value = b->get() ? "true" : "false", true;
        if (const auto* i = n->as_integer()) return c.value = std::to_string(i->get()), true;
        return string(*n, field + "value", c.value);
      }
    }
    return true;
  }

  // The event a criterion follows: a key's first press or the robot's first contact (at most one).
  bool readEvent(const toml::table& t, const std::string& field, Criterion& c) {
    std::string key;
    if (!optString(t, "after_key", field + "after_key", key)) return false;
    if (t.get("after_key") != nullptr && key.size() != 1) return fail(*t.get("after_key"), field + "after_key", "expected one key, e.g. \"s\"");
    c.afterKey = key.empty() ? 0 : key[0];
    if (const toml::node* n = t.get("after_contact")) {
      const auto* b = n->as_boolean();
      if (b == nullptr) return fail(*n, field + "after_contact", "expected true or false");
      c.afterContact = b->get();
      if (c.afterContact && c.afterKey != 0) return fail(*n, field + "after_contact", "give after_key or after_contact, not both");
    }
    return true;
  }

  fs::path dir_;
  Rubric rubric_;
};

}  // namespace

double Rubric::points() const {
  double total = 0;
  for (const Check& c : checks) total += c.points;
  return total;
}

bool Rubric::needsSecret() const {
  return std::any_of(checks.begin(), checks.end(), [](const Check& c) { return c.secretSeeds > 0 || (c.generated && c.generated->secret > 0); });
}

Result<Rubric> loadRubric(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Status::failure(file.string() + ": cannot open the rubric");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return RubricReader(file).read(text.str());
  } catch (const std::exception& e) {
    return Status::failure(file.string() + ": " + e.what());
  }
}

namespace {
// The k-th seed of `what` in `check` from the secret: reproducible for the instructor, unguessable
// without the secret (at most 2^63 - 1, as a rubric's seeds).
std::uint64_t secretSeed(const std::string& secret, const std::string& what, const Check& check, int k) {
  return worlds::Fnv1a().add(std::string_view(secret + "\n" + what + check.drawName() + "\n" + std::to_string(k))).value() >> 1;
}
}  // namespace

std::vector<std::uint64_t> seedsOf(const Check& check, const std::string& secret) {
  std::vector<std::uint64_t> seeds = check.seeds;
  for (int k = 0; k < check.secretSeeds; ++k) seeds.push_back(secretSeed(secret, "", check, k));
  // None named: one drawn from the check's name (and the secret, when hidden), never the world's
  // own seed, which `frob run` uses: a run recorded there does not replay here.
  const bool hidden = check.visibility != Visibility::Visible;
  if (seeds.empty()) seeds.push_back(secretSeed(hidden ? secret : std::string(), "run\n", check, 0) % 1000000000);
  return seeds;
}

std::uint64_t drawnWorldSeed(const Check& check, const std::string& secret, int k) { return secretSeed(secret, "world\n", check, k); }

std::vector<WorldRef> worldsOf(const Check& check, const std::string& secret, const KeptWorlds& kept, const std::string& submission) {
  std::vector<WorldRef> all = check.worlds;
  if (!check.generated) return all;
  const GeneratedWorlds& g = *check.generated;
  const std::string kind = toString(g.kind);
  for (std::uint64_t seed : g.seeds)
    all.push_back({.name = "generated " + kind + ", seed " + std::to_string(seed), .generated = g.kind, .worldSeed = seed});
  std::vector<int> draws(static_cast<std::size_t>(g.poolSize()));
  for (std::size_t k = 0; k < draws.size(); ++k) draws[k] = static_cast<int>(k);
  if (const auto it = kept.find(check.drawName()); it != kept.end()) draws = it->second;
  // The submission's own: the first `secret` of a shuffle of the pool keyed by the secret and the
  // submission (Fisher-Yates, one hash per place); a pool of no more is every submission's, in order.
  const std::size_t wanted = std::min(draws.size(), static_cast<std::size_t>(g.secret));
  for (std::size_t k = 0; k < wanted && draws.size() > wanted && !submission.empty(); ++k) {
    const std::uint64_t h = secretSeed(secret, "submission\n" + submission + "\n", check, static_cast<int>(k));
    std::swap(draws[k], draws[k + h % (draws.size() - k)]);
  }
  for (std::size_t k = 0; k < wanted; ++k) {
    all.push_back({.name = "generated " + kind + ", hidden world " + std::to_string(k + 1),
                   .generated = g.kind,
                   .worldSeed = drawnWorldSeed(check, secret, draws[k])});
  }
  return all;
}

bool Check::waitsForAReturn() const {
  return std::any_of(criteria.begin(), criteria.end(), [](const Criterion& c) { return c.kind == Criterion::Kind::Returns; });
}

Rubric practiceRubric(const Rubric& rubric, int worlds, std::uint64_t seed) {
  Rubric practice = rubric;
  practice.checks.clear();
  for (Check c : rubric.checks) {
    if (!c.generated || c.generated->secret == 0) continue;
    c.visibility = Visibility::Visible;
    c.generated->seeds.clear();
    c.generated->secret = 0;
    c.secretSeeds = 0;
    for (int k = 0; k < worlds; ++k) c.generated->seeds.push_back(secretSeed("practice " + std::to_string(seed), "world\n", c, k) % 1000000000);
    practice.checks.push_back(std::move(c));
  }
  return practice;
}

Result<worlds::WorldDef> loadWorldRef(const WorldRef& w) {
  if (w.generated) return worlds::generateWorld(*w.generated, w.worldSeed);
  Result<worlds::WorldDef> loaded = w.file.empty() ? worlds::loadReferenceWorld(w.name) : worlds::loadWorld(w.file);
  if (!loaded) return Status::failure(loaded.error());
  if (Status s = worlds::checkRunnable(*loaded); !s) return Status::failure(w.name + ": " + s.error());
  return *loaded;
}

std::string_view toString(Criterion::Kind kind) {
  for (const CriterionSpec& c : kCriteria) {
    if (c.kind == kind) return c.key;
  }
  return "criterion";
}

const char* toString(Visibility v) {
  switch (v) {
    case Visibility::Visible:
      return "visible";
    case Visibility::Hidden:
      return "hidden";
    case Visibility::AfterDueDate:
      return "after_due_date";
  }
  return "visible";
}

}  // namespace frob::course
