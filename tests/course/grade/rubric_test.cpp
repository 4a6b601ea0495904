// Rubric files: what they say, and one clear line naming the file, line and field for every mistake.
#include "frob/grade/rubric.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using Kind = Criterion::Kind;

// Writes `text` as rubric.toml (and a world file beside it) in a fresh folder; returns its path.
fs::path rubricFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(::testing::TempDir()) / "rubric_test" / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "worlds");
  std::ofstream(dir / "worlds" / "room.toml") << "size = [4.0, 3.0]\n[[robot]]\nstart = [1.0, 1.0]\n";
  std::ofstream(dir / "rubric.toml") << text;
  return dir / "rubric.toml";
}

constexpr const char* kGood = R"(title = "Go to goal"
seconds = 90

[[check]]
name = "reaches the goal"
points = 4
worlds = ["empty", "worlds/room.toml"]
seeds = [1, 2]
goal = { within = 0.2, by = 60 }
collisions = { max = 0 }

[[check]]
name = "hidden fields"
visibility = "hidden"
points = 2.5
worlds = ["obstacles"]
secret_seeds = 3
seconds = 120
bug1_bound = { point = "goal" }
returns = { value = true }
)";

TEST(Rubric, ReadsChecksWorldsSeedsAndCriteria) {
  const fs::path file = rubricFile("good", kGood);
  Result<Rubric> r = loadRubric(file);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.value().title, "Go to goal");
  EXPECT_DOUBLE_EQ(r.value().points(), 6.5);
  EXPECT_TRUE(r.value().needsSecret());
  ASSERT_EQ(r.value().checks.size(), 2u);
  const Check& a = r.value().checks[0];
  EXPECT_EQ(a.name, "reaches the goal");
  EXPECT_EQ(a.visibility, Visibility::Visible);
  EXPECT_DOUBLE_EQ(a.seconds, 90);
  ASSERT_EQ(a.worlds.size(), 2u);
  EXPECT_TRUE(a.worlds[0].file.empty());  // a reference world
  EXPECT_EQ(a.worlds[1].file, file.parent_path() / "worlds/room.toml");
  EXPECT_EQ(a.seeds, (std::vector<std::uint64_t>{1, 2}));
  ASSERT_EQ(a.criteria.size(), 2u);
  EXPECT_EQ(a.criteria[0].kind, Kind::Goal);
  EXPECT_DOUBLE_EQ(a.criteria[0].distance, 0.2);
  EXPECT_DOUBLE_EQ(a.criteria[0].seconds, 60);
  EXPECT_EQ(a.criteria[1].kind, Kind::Collisions);
  const Check& b = r.value().checks[1];
  EXPECT_EQ(b.visibility, Visibility::Hidden);
  EXPECT_EQ(b.secretSeeds, 3);
  EXPECT_EQ(b.criteria[1].value, "true");
}

TEST(Rubric, SecretSeedsDependOnTheSecretAndTheCheckOnly) {
  Result<Rubric> r = loadRubric(rubricFile("seeds", kGood));
  ASSERT_TRUE(r.ok()) << r.error();
  const Check& hidden = r.value().checks[1];
  const std::vector<std::uint64_t> a = seedsOf(hidden, "s3cret"), again = seedsOf(hidden, "s3cret"), other = seedsOf(hidden, "other");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a, again);
  EXPECT_NE(a, other);
  EXPECT_NE(a[0], a[1]);
  EXPECT_EQ(seedsOf(r.value().checks[0], "s3cret"), (std::vector<std::uint64_t>{1, 2}));
}

// A check that names no seeds runs with one drawn from its name, not with the world's own seed
// (which `frob run` uses, so a run recorded there would replay here); a hidden one's from the secret too.
TEST(Rubric, ACheckWithoutSeedsGetsADrawnOne) {
  Result<Rubric> r = loadRubric(rubricFile("drawn", kGood));
  ASSERT_TRUE(r.ok()) << r.error();
  Check visible = r.value().checks[0];
  visible.seeds.clear();
  const std::vector<std::uint64_t> drawn = seedsOf(visible, "s3cret");
  ASSERT_EQ(drawn.size(), 1u);
  EXPECT_EQ(drawn, seedsOf(visible, "other"));  // a student can rerun it with frob run --seed
  EXPECT_LT(drawn[0], 1000000000u);             // short enough to type
  Check renamed = visible;
  renamed.name = "another check";
  EXPECT_NE(seedsOf(renamed, "s3cret"), drawn);
  Check hidden = r.value().checks[1];
  hidden.secretSeeds = 0;
  ASSERT_EQ(seedsOf(hidden, "s3cret").size(), 1u);
  EXPECT_NE(seedsOf(hidden, "s3cret"), seedsOf(hidden, "other"));
}

// A leaderboard after the checks (line 21 on): kGood plus this, edited by the mistakes below.
constexpr const char* kBoard = R"toml(
[[leaderboard]]
name = "Time to the goal (s)"
check = "reaches the goal"
criterion = "goal"
measure = "time"
)toml";

TEST(Rubric, ALeaderboardRanksAVisibleChecksCriterion) {
  Result<Rubric> r = loadRubric(rubricFile(
      "leaderboard", std::string(kGood) + kBoard + "[[leaderboard]]\nname = \"Spare\"\ncheck = \"reaches the goal\"\ncriterion = \"collisions\"\n"));
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r.value().leaderboard.size(), 2u);
  const LeaderboardMetric& time = r.value().leaderboard[0];
  EXPECT_EQ(time.name, "Time to the goal (s)");
  EXPECT_EQ(time.check, "reaches the goal");
  EXPECT_EQ(time.criterion, Kind::Goal);
  EXPECT_EQ(time.measure, LeaderboardMetric::Measure::Time);
  EXPECT_TRUE(time.ascending);  // a time: the smaller the better
  const LeaderboardMetric& spare = r.value().leaderboard[1];
  EXPECT_EQ(spare.criterion, Kind::Collisions);
  EXPECT_EQ(spare.measure, LeaderboardMetric::Measure::Margin);
  EXPECT_FALSE(spare.ascending);  // a margin: the larger the better
}

struct Mistake {
  std::string replace, with;  // an edit of kGood
  std::string error;          // the whole message after "<file>:"
};

void PrintTo(const Mistake& m, std::ostream* os) { *os << m.with; }

class RubricMistake : public ::testing::TestWithParam<Mistake> {};

TEST_P(RubricMistake, IsOneLineNamingFileLineAndField) {
  std::string text = std::string(kGood) + kBoard;
  const std::size_t at = text.find(GetParam().replace);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, GetParam().replace.size(), GetParam().with);
  // A folder of its own: ctest runs the cases at the same time.
  const fs::path file = rubricFile("mistake_" + std::to_string(std::hash<std::string>{}(GetParam().with)), text);
  Result<Rubric> r = loadRubric(file);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), file.string() + ":" + GetParam().error);
}

INSTANTIATE_TEST_SUITE_P(
    Rubric, RubricMistake,
    ::testing::Values(
        Mistake{"collisions = {", "colisions = {",
                "10: check[0].colisions: unknown key: a check has name, points, visibility, worlds, generated, seeds, secret_seeds, "
                "seconds, runs_of and criteria (goal, waypoints, stopped, collisions, clearance, wall_distance, coverage, robots_apart, "
                "path_ratio, bug1_bound, returns)"},
        Mistake{"within = 0.2, by", "withn = 0.2, by", "9: check[0].goal.withn: unknown key (expected one of within, by, point)"},
        Mistake{"within = 0.2", "within = -1", "9: check[0].goal.within: must be positive"},
        Mistake{"collisions = { max = 0 }", "collisions = { max = 2, seconds = 0 }", "10: check[0].collisions.seconds: must be positive"},
        Mistake{"collisions = { max = 0 }", "wall_distance = { target = 0.4, tolerance = 0.1, fraction = 0.5, side = \"up\" }",
                "10: check[0].wall_distance.side: expected \"right\" or \"left\""},
        Mistake{"collisions = { max = 0 }", "coverage = { fraction = 0.5, away = -0.5 }", "10: check[0].coverage.away: must not be negative"},
        Mistake{"\"worlds/room.toml\"", "\"worlds/missing.toml\"",
                "7: check[0].worlds[1]: 'worlds/missing.toml' is neither a reference world (see frob list) nor a file beside the rubric"},
        Mistake{"visibility = \"hidden\"", "visibility = \"secret\"",
                "14: check[1].visibility: expected \"visible\", \"hidden\" or \"after_due_date\""},
        Mistake{"points = 4", "points = \"four\"", "6: check[0].points: expected a number"},
        Mistake{"name = \"hidden fields\"", "name = \"reaches the goal\"", "12: check[1].name: 'reaches the goal' names two checks"},
        Mistake{"goal = { within = 0.2, by = 60 }\ncollisions = { max = 0 }\n", "", "4: check[0].name: check 'reaches the goal' has no criterion"},
        Mistake{"returns = { value = true }", "goal = { within = 0.3 }",
                "20: check[1].goal.by: missing: a check that is not visible must give the time allowed"},
        Mistake{"returns = { value = true }", "waypoints = { points = [\"a\"], within = 0.3 }",
                "20: check[1].waypoints.by: missing: a check that is not visible must give the time allowed"},
        Mistake{"check = \"reaches the goal\"\ncriterion", "check = \"hidden fields\"\ncriterion",
                "24: leaderboard[0].check: 'hidden fields' is not visible: every student reads a leaderboard, and a hidden check's numbers are "
                "chosen by the controller"},
        Mistake{"criterion = \"goal\"", "criterion = \"coverage\"",
                "25: leaderboard[0].criterion: check 'reaches the goal' has no coverage criterion"},
        Mistake{"check = \"reaches the goal\"\ncriterion", "check = \"reaches\"\ncriterion", "24: leaderboard[0].check: no check is named 'reaches'"},
        Mistake{"goal = { within = 0.2, by = 60 }", "goal = { within = 0.2 }",
                "26: leaderboard[0].measure: \"time\" is when a goal or the last waypoint was reached: the criterion must be one with `by`"},
        Mistake{"measure = \"time\"", "measure = \"time\"\norder = \"up\"", "27: leaderboard[0].order: expected \"asc\" (smaller first) or \"desc\""},
        Mistake{"measure = \"time\"", "measure = \"speed\"", "26: leaderboard[0].measure: expected \"time\" or \"margin\""},
        Mistake{"worlds = [\"obstacles\"]\nsecret_seeds = 3\nseconds = 120\n", "runs_of = \"hidden fields\"\n",
                "16: check[1].runs_of: no earlier check is named 'hidden fields'"},
        Mistake{"worlds = [\"obstacles\"]\nsecret_seeds = 3\nseconds = 120\n", "runs_of = \"reaches the goal\"\n",
                "16: check[1].runs_of: 'reaches the goal' is visible and this check is hidden: a check judges the runs of a check as visible "
                "as itself"},
        Mistake{"worlds = [\"obstacles\"]\nsecret_seeds = 3\n", "runs_of = \"reaches the goal\"\nseeds = [4]\n",
                "17: check[1].seeds: this check judges the runs of 'reaches the goal' (runs_of): it has that check's worlds, seeds and seconds"},
        Mistake{"seconds = 90", "seconds = [", "4: syntax error: Error while parsing value: could not determine value type"}));

// A check that judges another's runs (runs_of) has its worlds, seeds and seconds, and draws what it
// draws by that check's name (through a chain, by the first's), so that both judge the same runs.
TEST(Rubric, AJudgeOfAnotherChecksRunsHasItsWorldsSeedsAndSeconds) {
  const fs::path file = rubricFile("runs_of", R"(title = "Shared"
seconds = 90
[[check]]
name = "reaches"
worlds = ["worlds/room.toml"]
seeds = [1, 2]
seconds = 30
goal = { within = 0.2 }
[[check]]
name = "on time"
runs_of = "reaches"
goal = { within = 0.2, by = 20 }
[[check]]
name = "fields"
visibility = "hidden"
generated = { kind = "obstacles", secret = 2 }
collisions = { max = 0 }
[[check]]
name = "fields, quickly"
visibility = "hidden"
runs_of = "fields"
goal = { within = 0.3, by = 60 }
[[check]]
name = "fields, bound"
visibility = "hidden"
runs_of = "fields, quickly"
bug1_bound = { point = "goal" }
)");
  Result<Rubric> r = loadRubric(file);
  ASSERT_TRUE(r.ok()) << r.error();
  const std::vector<Check>& c = r.value().checks;
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[1].runsOf, "reaches");
  ASSERT_EQ(c[1].worlds.size(), 1u);
  EXPECT_EQ(c[1].worlds[0].file, c[0].worlds[0].file);
  EXPECT_EQ(c[1].seeds, (std::vector<std::uint64_t>{1, 2}));
  EXPECT_DOUBLE_EQ(c[1].seconds, 30);
  EXPECT_EQ(c[1].criteria.size(), 1u);
  EXPECT_DOUBLE_EQ(c[1].criteria[0].seconds, 20);
  for (std::size_t k : {3u, 4u}) {
    EXPECT_EQ(c[k].drawName(), "fields") << k;
    EXPECT_DOUBLE_EQ(c[k].seconds, 90) << k;
    EXPECT_EQ(seedsOf(c[k], "s"), seedsOf(c[2], "s")) << k;
    const std::vector<WorldRef> theirs = worldsOf(c[2], "s", {}, "a submission"), mine = worldsOf(c[k], "s", {}, "a submission");
    ASSERT_EQ(mine.size(), 2u);
    for (std::size_t w = 0; w < mine.size(); ++w) EXPECT_EQ(mine[w].worldSeed, theirs[w].worldSeed) << k;
  }
  // Drawn by their own names, they would run elsewhere.
  EXPECT_EQ(drawnWorldSeed(c[3], "s", 0), drawnWorldSeed(c[2], "s", 0));
  EXPECT_NE(drawnWorldSeed(Check{.name = "fields, quickly"}, "s", 0), drawnWorldSeed(c[2], "s", 0));
}

TEST(Rubric, GeneratedWorldsFromSeedsAndFromTheSecret) {
  const fs::path file = rubricFile("generated", R"(title = "Fields"
[[check]]
name = "fields"
generated = { kind = "obstacles", seeds = [4], secret = 2 }
goal = { within = 0.5 }
)");
  Result<Rubric> r = loadRubric(file);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_TRUE(r.value().needsSecret());
  const std::vector<WorldRef> worlds = worldsOf(r.value().checks[0], "s3cret");
  ASSERT_EQ(worlds.size(), 3u);
  EXPECT_EQ(worlds[0].name, "generated obstacles, seed 4");
  EXPECT_EQ(worlds[0].worldSeed, 4u);
  EXPECT_EQ(worlds[1].name, "generated obstacles, hidden world 1");  // the name does not give the seed away
  EXPECT_NE(worlds[1].worldSeed, worldsOf(r.value().checks[0], "other")[1].worldSeed);
  EXPECT_EQ(worlds[1].worldSeed, worldsOf(r.value().checks[0], "s3cret")[1].worldSeed);
  Result<worlds::WorldDef> w = loadWorldRef(worlds[0]);
  ASSERT_TRUE(w.ok()) << w.error();
  EXPECT_EQ(worlds::toToml(w.value()), worlds::toToml(worlds::generateWorld(worlds::WorldKind::Obstacles, 4).value()));

  const fs::path bad = rubricFile("generated_bad", "[[check]]\nname = \"x\"\ngenerated = { kind = \"forest\", seeds = [1] }\nstopped = {}\n");
  EXPECT_EQ(loadRubric(bad).error(), bad.string() + ":3: check[0].generated.kind: unknown kind 'forest' (one of " + worlds::worldKindNames() + ")");
}

// Each submission runs in `secret` worlds of the pool, chosen by its hash: the same files the same
// worlds, other files others, every pool member someone's, none outside the pool.
TEST(Rubric, EachSubmissionIsGradedInHiddenWorldsOfItsOwnFromThePool) {
  const auto checkWith = [](const std::string& generated) {
    const fs::path file = rubricFile("pool", "[[check]]\nname = \"fields\"\nvisibility = \"hidden\"\ngenerated = { kind = \"obstacles\", " +
                                                 generated + " }\ngoal = { within = 0.5, by = 60 }\n");
    Result<Rubric> r = loadRubric(file);
    EXPECT_TRUE(r.ok()) << r.error();
    return r.value().checks.at(0);
  };
  const Check check = checkWith("secret = 2");
  EXPECT_EQ(check.generated->pool, 16);  // 8 per world a submission runs in
  std::set<std::uint64_t> pool;
  for (int k = 0; k < 16; ++k) pool.insert(drawnWorldSeed(check, "s3cret", k));
  const auto hidden = [&](const Check& c, const std::string& submission, const KeptWorlds& kept = {}) {
    std::vector<std::uint64_t> seeds;
    for (const WorldRef& w : worldsOf(c, "s3cret", kept, submission)) seeds.push_back(w.worldSeed);
    return seeds;
  };
  std::set<std::uint64_t> used;
  std::set<std::vector<std::uint64_t>> draws;
  for (int k = 0; k < 40; ++k) {
    const std::string submission = "sha256 of submission " + std::to_string(k);
    const std::vector<std::uint64_t> mine = hidden(check, submission);
    ASSERT_EQ(mine.size(), 2u);
    EXPECT_NE(mine[0], mine[1]);
    for (std::uint64_t seed : mine) EXPECT_TRUE(pool.contains(seed)) << seed;
    EXPECT_EQ(hidden(check, submission), mine);  // reproducible
    used.insert(mine.begin(), mine.end());
    draws.insert(mine);
  }
  EXPECT_EQ(used, pool);
  EXPECT_GE(draws.size(), 30u);  // of 240 ordered pairs, 40 submissions rarely share one
  // The pool is the draws kept fair for the check, where there are some.
  const KeptWorlds kept{{"fields", {3, 5, 7, 9}}};
  for (std::uint64_t seed : hidden(check, "another submission", kept)) {
    EXPECT_TRUE(seed == drawnWorldSeed(check, "s3cret", 3) || seed == drawnWorldSeed(check, "s3cret", 5) ||
                seed == drawnWorldSeed(check, "s3cret", 7) || seed == drawnWorldSeed(check, "s3cret", 9))
        << seed;
  }
  // A pool of as many as a submission runs in: every submission in the same worlds, the first draws.
  const Check shared = checkWith("secret = 2, pool = 2");
  EXPECT_EQ(hidden(shared, "one"), hidden(shared, "two"));
  EXPECT_EQ(hidden(shared, "one"), (std::vector<std::uint64_t>{drawnWorldSeed(shared, "s3cret", 0), drawnWorldSeed(shared, "s3cret", 1)}));

  const fs::path bad = rubricFile("pool_bad", "[[check]]\nname = \"x\"\ngenerated = { kind = \"obstacles\", secret = 3, pool = 2 }\nstopped = {}\n");
  EXPECT_EQ(loadRubric(bad).error(), bad.string() + ":3: check[0].generated.pool: must lie in [3, 1000]");
}

// A reference solution beside the rubric; the events a stopped or returns criterion follows.
TEST(Rubric, ReadsTheReferenceAndTheEventsCriteriaFollow) {
  const fs::path file = rubricFile("events", R"(title = "Patrol"
reference = "solution.cpp"
[[check]]
name = "stops on s"
generated = { kind = "warehouse_keys", secret = 2 }
stopped = { speed = 0.02, after_key = "s", within = 2 }
returns = { value = "key", after_key = "s" }
[[check]]
name = "stops at the box"
generated = { kind = "warehouse_box", secret = 1 }
stopped = { after_contact = true, within = 1.5 }
returns = { value = "budget", after_distance = 20 }
)");
  Result<Rubric> r = loadRubric(file);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r.value().reference, file.parent_path() / "solution.cpp");
  const Criterion& stopped = r.value().checks[0].criteria[0];
  EXPECT_EQ(stopped.afterKey, 's');
  EXPECT_EQ(stopped.within, 2.0);
  EXPECT_EQ(r.value().checks[0].criteria[1].afterKey, 's');
  EXPECT_TRUE(r.value().checks[1].criteria[0].afterContact);
  EXPECT_EQ(r.value().checks[1].criteria[0].within, 1.5);
  EXPECT_EQ(r.value().checks[1].criteria[1].afterDistance, 20.0);

  const fs::path twoKeys = rubricFile("events_bad", "[[check]]\nname = \"x\"\nworlds = [\"empty\"]\nstopped = { after_key = \"sx\" }\n");
  EXPECT_EQ(loadRubric(twoKeys).error(), twoKeys.string() + ":4: check[0].stopped.after_key: expected one key, e.g. \"s\"");
  const fs::path both =
      rubricFile("events_both", "[[check]]\nname = \"x\"\nworlds = [\"empty\"]\nstopped = { after_key = \"s\", after_contact = true }\n");
  EXPECT_EQ(loadRubric(both).error(), both.string() + ":4: check[0].stopped.after_contact: give after_key or after_contact, not both");
}

// Practice: the checks that draw worlds from the secret, visible, in worlds of their kind drawn
// from the student's seed; nothing of the secret in them.
TEST(Rubric, PracticeDrawsTheHiddenChecksWorldsFromTheStudentsSeed) {
  const fs::path file = rubricFile("practice", std::string(kGood) + R"(
[[check]]
name = "unseen rooms"
visibility = "hidden"
generated = { kind = "furnished_room", secret = 2 }
collisions = { max = 0 }
)");
  Result<Rubric> r = loadRubric(file);
  ASSERT_TRUE(r.ok()) << r.error();
  const Rubric practice = practiceRubric(r.value(), 3, 7);
  ASSERT_EQ(practice.checks.size(), 1u);  // the named-world checks are left out
  const Check& c = practice.checks[0];
  EXPECT_EQ(c.name, "unseen rooms");
  EXPECT_EQ(c.visibility, Visibility::Visible);
  EXPECT_FALSE(practice.needsSecret());
  const std::vector<WorldRef> worlds = worldsOf(c, "");
  ASSERT_EQ(worlds.size(), 3u);
  EXPECT_EQ(worlds[0].generated, worlds::WorldKind::FurnishedRoom);
  EXPECT_EQ(worlds[0].name, "generated furnished_room, seed " + std::to_string(worlds[0].worldSeed));    // rebuilt with frob world generate
  EXPECT_EQ(worldsOf(practiceRubric(r.value(), 3, 7).checks[0], "")[2].worldSeed, worlds[2].worldSeed);  // the same seed, the same worlds
  EXPECT_NE(worldsOf(practiceRubric(r.value(), 3, 8).checks[0], "")[0].worldSeed, worlds[0].worldSeed);
  for (const WorldRef& w : worldsOf(r.value().checks.back(), "any secret")) EXPECT_NE(w.worldSeed, worlds[0].worldSeed);
}

TEST(Rubric, AMissingFileIsNamed) {
  Result<Rubric> r = loadRubric("/no/such/rubric.toml");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "/no/such/rubric.toml: cannot open the rubric");
}

// A rubric's world with no robot is refused when it is loaded, naming it as reports do.
TEST(Rubric, AWorldWithNoRobotIsRefused) {
  const fs::path dir = fs::path(::testing::TempDir()) / "rubric_test" / "no_robot";
  fs::create_directories(dir);
  std::ofstream(dir / "empty.toml") << "size = [4.0, 4.0]\n";
  Result<worlds::WorldDef> w = loadWorldRef({.name = "worlds/empty.toml", .file = dir / "empty.toml"});
  ASSERT_FALSE(w.ok());
  EXPECT_EQ(w.error(),
            "worlds/empty.toml: the world has no robot to drive: add one, e.g. a [[robot]] table with start = [1, 1] "
            "(the world format: worlds/data/README.md)");
}

}  // namespace
}  // namespace frob::course
