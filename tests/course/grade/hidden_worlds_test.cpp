// The worlds hidden checks draw from the secret: fair to the reference and the starter, found once
// and cached; each check's own draws, or those of the check whose runs it judges (runs_of).
#include "frob/grade/grade.hpp"
#include "frob/run/format.hpp"
#include "frob/run/host.hpp"
#include "frob/worlds/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

// A controller that stands still.
constexpr const char* kStill =
    "#include <frob/frob.hpp>\nusing namespace frob;\nBehavior<Wheels> still(const Robot&) { return wheels(0.0, 0.0); }\n"
    "FROB_CONTROLLER(still)\n";

class HiddenWorlds : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / "hidden_worlds_test" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "assignment");
    std::ofstream(dir_ / "assignment" / "still.cpp") << kStill;
    def_ = {.assignment = "hidden", .secret = "test-secret"};
    def_.compiler.cacheDir = fs::path(FROB_TEST_CACHE_DIR);
  }
  fs::path dir_;
  GradeDef def_;
};

// How far a robot standing still is from the crossing's centre in each of the first 40 draws of
// `check` (the farthest robot's distance): at its start as the run's seed draws it.
std::vector<double> fromTheCentre(const GradeDef& def, const Check& check) {
  std::vector<double> far;
  for (int k = 0; k < 40; ++k) {
    const worlds::WorldDef w = worlds::generateWorld(worlds::WorldKind::Crossing, drawnWorldSeed(check, def.secret, k)).value();
    const worlds::Simulation still(w, {.dt = def.rubric.dt, .seed = seedsOf(check, def.secret).at(0)});
    double farthest = 0;
    for (std::size_t i = 0; i < w.robots.size(); ++i)
      farthest = std::max(farthest, (*worlds::findPoint(w, "centre") - still.truePose(i).position).norm());
    far.push_back(farthest);
  }
  return far;
}

// A distance some of the first eight draws meet and some not: their median, to the centimetre.
double medianOfTheFirstEight(const std::vector<double>& far) {
  std::vector<double> first(far.begin(), far.begin() + 8);
  std::nth_element(first.begin(), first.begin() + 4, first.end());
  return std::round(first[4] * 100) / 100 + 0.005;
}

// No student meets a hidden world the reference solution fails: the hidden worlds are the first
// draws from the secret in which it meets every criterion, found once and kept in the cache. Here
// the reference stands still and the criterion asks for the crossing's centre within some 3 m of
// every robot's start, which the crossings' drawn starts meet only now and then.
TEST_F(HiddenWorlds, AreTheFirstDrawsTheReferencePasses) {
  const auto rubricWith = [&](double within) {
    std::ofstream(dir_ / "assignment" / "fair.toml")
        << "title = \"Fair\"\nreference = \"still.cpp\"\nseconds = 0.5\n[[check]]\nname = \"near the centre\"\n"
           "visibility = \"hidden\"\ngenerated = { kind = \"crossing\", secret = 3, pool = 4 }\n"
           "goal = { point = \"centre\", within = "
        << within << ", by = 60 }\n";
    return loadRubric(dir_ / "assignment" / "fair.toml").value();
  };
  GradeDef def = def_;
  def.rubric = rubricWith(1.0);  // its check names the draws and seeds; the distance is chosen below
  def.compiler.cacheDir = dir_ / "cache";
  const std::vector<double> far = fromTheCentre(def, def.rubric.checks[0]);
  const double within = medianOfTheFirstEight(far);
  def.rubric = rubricWith(within);
  std::vector<int> expected, skipped;
  for (int k = 0; expected.size() < 4; ++k) (far.at(k) <= within ? expected : skipped).push_back(k);  // the pool's
  ASSERT_FALSE(skipped.empty()) << "this secret draws no world the reference fails: nothing is tested";
  Result<KeptWorlds> kept = fairHiddenWorlds(def);
  ASSERT_TRUE(kept.ok()) << kept.error();
  EXPECT_EQ(kept.value(), (KeptWorlds{{"near the centre", expected}}));
  const Grade g = grade(def, dir_ / "assignment" / "still.cpp");
  EXPECT_EQ(g.score(), g.maxScore()) << g.checks[0].output();
  // A class grades in them too, each student in draws of their own (checked beside the compiles).
  fs::create_directories(dir_ / "class");
  for (const char* student : {"ann", "ben", "cat"})
    std::ofstream(dir_ / "class" / (std::string(student) + ".cpp")) << "// " << student << "\n" << kStill;
  fs::remove_all(dir_ / "cache" / "hidden-worlds");
  for (const Grade& k : gradeAll(def, submissionsIn(dir_ / "class"), 2)) EXPECT_EQ(k.score(), k.maxScore()) << k.submission << k.checks[0].output();

  // Kept for this reference and this simulation: what another build of the simulation kept is drawn anew.
  const fs::path cache = keptWorldsFile(def);
  std::stringstream text;
  text << std::ifstream(cache).rdbuf();
  const std::string fingerprint = format("simulation %016" PRIx64, worlds::simulationFingerprint());
  ASSERT_NE(text.str().find(fingerprint), std::string::npos) << text.str();
  std::string stale = text.str().replace(text.str().find(fingerprint), fingerprint.size(), "simulation 0000000000000000");
  std::ofstream(cache) << stale.substr(0, stale.find('\n') + 1) << "99 near the centre\n";
  EXPECT_EQ(fairHiddenWorlds(def).value(), kept.value());
  // ... and so is what another generator of the worlds kept (its first draw stands for it).
  text.str(""), text << std::ifstream(cache).rdbuf();
  const std::size_t worldsAt = text.str().find(" worlds ");
  ASSERT_NE(worldsAt, std::string::npos) << text.str();
  stale = text.str().replace(worldsAt, 24, " worlds 0000000000000000");
  std::ofstream(cache) << stale.substr(0, stale.find('\n') + 1) << "99 near the centre\n";
  EXPECT_EQ(fairHiddenWorlds(def).value(), kept.value());

  // Kept in the cache: used as it is where the reference is absent (a Gradescope zip).
  fs::rename(dir_ / "assignment" / "still.cpp", dir_ / "still.cpp");
  EXPECT_EQ(fairHiddenWorlds(def).value(), kept.value());

  // A secret whose draws the reference cannot pass is refused, naming the check.
  fs::rename(dir_ / "still.cpp", dir_ / "assignment" / "still.cpp");
  def.rubric = rubricWith(0.01);
  EXPECT_EQ(fairHiddenWorlds(def).error(),
            "only 0 of the 40 worlds drawn for check 'near the centre' from this secret let the reference solution pass: choose another secret");
  // In a class, each grade says so.
  for (const Grade& k : gradeAll(def, submissionsIn(dir_ / "class"), 2)) {
    EXPECT_EQ(k.notes.at(0),
              "the hidden worlds were not checked against the reference solution: only 0 of the 40 worlds drawn for check 'near the centre' "
              "from this secret let the reference solution pass: choose another secret");
  }

  // Nor may a hidden world let the starter pass: one that stands still as well passes every draw
  // the reference does, so none is kept.
  def.rubric = rubricWith(within);
  def.rubric.starter = dir_ / "assignment" / "still.cpp";
  EXPECT_EQ(fairHiddenWorlds(def).error(),
            "only 0 of the 40 worlds drawn for check 'near the centre' from this secret let the reference "
            "solution pass and the starter fail: choose another secret");
}

// Where frob or the machine keeps the hidden worlds from being checked (here no controller host can
// start), no grade stands on worlds no one checked, not even a 0 for a file that does not compile.
TEST_F(HiddenWorlds, AGraderFailureInTheirCheckLeavesNoGrade) {
  std::ofstream(dir_ / "assignment" / "fair.toml") << "title = \"Fair\"\nreference = \"still.cpp\"\nseconds = 0.5\n[[check]]\nname = \"anywhere\"\n"
                                                      "visibility = \"hidden\"\ngenerated = { kind = \"crossing\", secret = 1 }\n"
                                                      "goal = { point = \"centre\", within = 100, by = 60 }\n";
  std::ofstream(dir_ / "broken.cpp") << "not C++\n";
  GradeDef def = def_;
  def.rubric = loadRubric(dir_ / "assignment" / "fair.toml").value();
  def.compiler.cacheDir = dir_ / "cache";
  def.host.program = dir_ / "no-such-host";
  const Result<KeptWorlds> kept = fairHiddenWorlds(def);
  ASSERT_FALSE(kept.ok());
  EXPECT_TRUE(isGraderFailure(kept.status())) << kept.error();
  for (const Grade& g : {grade(def, dir_ / "broken.cpp"), gradeAll(def, {dir_ / "broken.cpp"}, 1).at(0)}) {
    const std::string cause = "the grader failed: cannot run " + def.host.program.string() + ": No such file or directory";
    EXPECT_EQ(g.graderFailure.substr(0, cause.size()), cause);
    EXPECT_TRUE(g.checks.empty());
  }
  // Graded in the visible checks alone, it needs no hidden worlds: its compile error stands.
  def.visibleOnly = true;
  for (const Grade& g : {grade(def, dir_ / "broken.cpp"), gradeAll(def, {dir_ / "broken.cpp"}, 1).at(0)}) {
    EXPECT_EQ(g.graderFailure, "");
    EXPECT_NE(g.compileError, "");
  }
  // So too where the reference cannot be compiled for want of a compiler.
  def.compiler.compiler = (dir_ / "no-such-compiler").string();
  EXPECT_TRUE(isGraderFailure(fairHiddenWorlds(def).status())) << fairHiddenWorlds(def).error();
}

// Two checks that draw worlds of one kind from the secret run each in its own draws: one check's
// "hidden world 1" is not the other's (they were once loaded by name, so the second check ran in
// the first one's worlds, not in those the reference was checked in). A robot standing still at
// the drawn start leaves another trace in each.
TEST_F(HiddenWorlds, EachCheckRunsInItsOwnDraws) {
  std::ofstream(dir_ / "assignment" / "two.toml")
      << "title = \"Two\"\nseconds = 0.5\n"
         "[[check]]\nname = \"first\"\nvisibility = \"hidden\"\nseeds = [1]\n"
         "generated = { kind = \"furnished_room\", secret = 1 }\ngoal = { point = \"room\", within = 100, by = 60 }\n"
         "[[check]]\nname = \"second\"\nvisibility = \"hidden\"\nseeds = [1]\n"
         "generated = { kind = \"furnished_room\", secret = 1 }\ngoal = { point = \"room\", within = 100, by = 60 }\n";
  GradeDef def = def_;
  def.rubric = loadRubric(dir_ / "assignment" / "two.toml").value();
  const Grade g = grade(def, dir_ / "assignment" / "still.cpp");
  ASSERT_EQ(g.checks.size(), 2u);
  ASSERT_EQ(g.checks[0].runs.size(), 1u);
  ASSERT_EQ(g.checks[1].runs.size(), 1u);
  EXPECT_EQ(g.checks[0].runs[0].world, g.checks[1].runs[0].world);                    // the same name...
  EXPECT_NE(g.checks[0].runs[0].trajectoryHash, g.checks[1].runs[0].trajectoryHash);  // ...another world
}

// A check that judges the runs of another (runs_of) is judged in its worlds with its seeds, each run
// made once for both (a host started for each robot of a run); the draws kept are those in
// which the reference passes both checks: here only the judging check asks the still reference to
// stand near the centre, and the draws that fail it are skipped for both.
TEST_F(HiddenWorlds, AJudgeOfAnotherChecksRunsSharesItsFairDraws) {
  std::ofstream(dir_ / "counted.cpp") << "#include <frob/frob.hpp>\nusing namespace frob;\n"
                                         "Behavior<Wheels> still(const Robot&) { return wheels(0.0, 0.0); }\nFROB_CONTROLLER(still)\n";
  const auto rubricWith = [&](double within) {
    std::ofstream(dir_ / "assignment" / "shared.toml")
        << "title = \"Shared\"\nreference = \"still.cpp\"\nseconds = 0.5\n"
           "[[check]]\nname = \"anywhere\"\nvisibility = \"hidden\"\ngenerated = { kind = \"crossing\", secret = 3, pool = 4 }\n"
           "goal = { point = \"centre\", within = 100, by = 60 }\n"
           "[[check]]\nname = \"near the centre\"\nvisibility = \"hidden\"\nruns_of = \"anywhere\"\n"
           "goal = { point = \"centre\", within = "
        << within << ", by = 60 }\n";
    return loadRubric(dir_ / "assignment" / "shared.toml").value();
  };
  GradeDef def = def_;
  def.rubric = rubricWith(1.0);
  def.compiler.cacheDir = dir_ / "cache";
  const Check &anywhere = def.rubric.checks[0], &near = def.rubric.checks[1];
  EXPECT_EQ(near.drawName(), "anywhere");
  EXPECT_EQ(seedsOf(near, def.secret), seedsOf(anywhere, def.secret));
  const std::vector<double> far = fromTheCentre(def, anywhere);
  const double within = medianOfTheFirstEight(far);
  def.rubric = rubricWith(within);
  std::vector<int> expected, skipped;
  for (int k = 0; expected.size() < 4; ++k) (far.at(k) <= within ? expected : skipped).push_back(k);
  ASSERT_FALSE(skipped.empty()) << "this secret draws no world the reference fails: nothing is tested";
  Result<KeptWorlds> kept = fairHiddenWorlds(def);
  ASSERT_TRUE(kept.ok()) << kept.error();
  EXPECT_EQ(kept.value(), (KeptWorlds{{"anywhere", expected}}));
  def.kept = kept.value();
  const std::vector<WorldRef> worlds = worldsOf(def.rubric.checks[1], def.secret, def.kept.value(), submissionHash(dir_ / "counted.cpp"));
  ASSERT_EQ(worlds.size(), 3u);
  std::size_t robots = 0;  // a host each
  for (std::size_t k = 0; k < worlds.size(); ++k) {
    EXPECT_EQ(worlds[k].worldSeed, worldsOf(def.rubric.checks[0], def.secret, def.kept.value(), submissionHash(dir_ / "counted.cpp"))[k].worldSeed);
    robots += loadWorldRef(worlds[k]).value().robots.size();
  }

  const std::uint64_t before = ControllerHost::started();
  const Grade g = grade(def, dir_ / "counted.cpp");
  ASSERT_EQ(g.compileError, "");
  EXPECT_EQ(g.score(), g.maxScore()) << g.checks[1].output();
  EXPECT_EQ(ControllerHost::started() - before, robots);  // three hidden worlds, one seed, two checks: a run each
  ASSERT_EQ(g.checks[1].runs.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(g.checks[1].runs[k].world, worlds[k].name);
    EXPECT_EQ(g.checks[0].runs[k].trajectoryHash, g.checks[1].runs[k].trajectoryHash);
  }
}

}  // namespace
}  // namespace frob::course
