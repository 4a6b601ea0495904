// What a host may learn of other hosts, and leave for them: it touches no file outside its scratch
// folder, sees nothing of another process's scheduling, the machine's threads or the page cache, and
// cannot tell one kind of run from another (each of these a note one robot, run or student could
// pass another).
#include "host_testing.hpp"

#include <filesystem>

namespace frob::course {
namespace {

namespace fs = std::filesystem;

// Why the namespaces layer was not applied in a run ("" when it was).
std::string withoutNamespaces(const Outcome& o) {
  for (const sandbox::Layer& l : o.layers) {
    if (l.name == "namespaces") return l.applied ? "" : l.note;
  }
  return "no namespaces layer";
}

TEST(Sandbox, NothingOutsideItsScratchFolderIsReadOrWritten) {
  fs::remove("/tmp/frob-hostile-was-here");
  EXPECT_EQ(runHostile({"writes_outside"}).failures.size(), 1u);
  EXPECT_FALSE(fs::exists("/tmp/frob-hostile-was-here"));
  const Outcome read = runHostile({"reads_outside"});
  EXPECT_EQ(read.output.find("root:"), std::string::npos) << read.output;
}

TEST(Sandbox, ItsOwnScratchFolderCanBeWrittenAndReadBack) {
  const Outcome o = runHostile({"writes_scratch"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.25, 0.0}));
}

// A host cannot read what the kernel shows of another process's scheduling, nor lock a file every
// host may read: two hosts could pass notes through either.
TEST(Sandbox, AHostSeesNothingOfAnotherProcessesSchedulingAndTakesNoLock) {
  const Outcome o = runHostile({"reads_others_scheduling"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.1, 0.0}));
}

// Nor count the machine's threads, or read its uptime and load: sysinfo gives every host the same figures.
TEST(Sandbox, AHostCountsNoThreadsButItsOwnThroughSysinfo) {
  const Outcome o = runHostile({"counts_threads_by_sysinfo"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.1, 0.0}));
}

// Nor see or change which pages of a library every host may read the kernel caches, or watch
// files: notes between hosts (robots, runs, students) again. The turn's
// bits name the calls the kernel carried out (sees_the_page_cache.cpp).
TEST(Sandbox, AHostSeesNothingOfThePageCacheNorWatchesFiles) {
  const Outcome o = runHostile({"sees_the_page_cache"});
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_EQ(o.lastWheels, (Wheels{0.1, 0.0}));
}

// Its working folder holds 64 MB in all, whatever the size of each file.
TEST(Sandbox, TheScratchFolderIsBoundedInTotal) {
  const Outcome o = runHostile({"fills_scratch"});
  if (const std::string why = withoutNamespaces(o); !why.empty()) GTEST_SKIP() << "the namespaces layer is not applied here: " << why;
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  // The 64 MiB tmpfs takes four 15 MB files and 4 MB of the fifth (a megabyte is a whole write).
  EXPECT_NEAR(o.lastWheels.forward / 0.01, 64.0, 1e-9);
}

// Processes and threads at once are bounded: 64, the host's own thread among them.
TEST(Sandbox, ThreadsAreBoundedInNumber) {
  const Outcome o = runHostile({"starts_many_threads"});
  if (const std::string why = withoutNamespaces(o); !why.empty()) GTEST_SKIP() << "the namespaces layer is not applied here: " << why;
  EXPECT_TRUE(o.failures.empty()) << o.failures[0].message;
  EXPECT_NEAR(o.lastWheels.forward / 0.001, 63.0, 1e-6);
}

// Pictures are sampled in every run, filmed or not: a controller cannot drive one way for the film
// and another for the grade.
TEST(Sandbox, AControllerCannotTellAFilmedRunFromAGradedOne) {
  for (const bool filmed : {false, true}) {
    std::shared_ptr<ControllerHost> host = startHost({testing::hostileModule("careful_when_filmed")});
    ASSERT_NE(host, nullptr);
    worlds::Run run(room(), {}, host->driver({0}, filmed));
    run.runUntil(0.5);
    EXPECT_EQ(run.recorder().steps().back().robots[0].wheels, (Wheels{0.1, 0.0})) << (filmed ? "filmed" : "graded");
  }
}

// Nor from what the channel's header says: it reads the same in a run graded alone, one graded in a
// class (where the grader does not spin) and a filmed one. (The grader's spin was in it once.)
TEST(Sandbox, TheHeaderReadsTheSameInEveryKindOfRun) {
  std::vector<Wheels> seen;
  for (const auto& [spin, filmed] : {std::pair{50'000, false}, std::pair{0, false}, std::pair{50'000, true}}) {
    std::shared_ptr<ControllerHost> host = startHost({testing::hostileModule("reads_header")}, {.spinNanoseconds = std::uint64_t(spin)});
    ASSERT_NE(host, nullptr);
    worlds::Run run(room(), {}, host->driver({0}, filmed));
    run.runUntil(0.5);
    seen.push_back(run.recorder().steps().back().robots[0].wheels);
  }
  EXPECT_GT(seen[0].forward, 0.0) << "it could not read the header, so this proves nothing";
  EXPECT_EQ(seen[1], seen[0]);
  EXPECT_EQ(seen[2], seen[0]);
}

}  // namespace
}  // namespace frob::course
