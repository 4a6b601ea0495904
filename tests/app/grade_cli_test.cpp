// frob grade from the command line: exit statuses, reports, lateness, replays of logged runs,
// generated worlds, and the assignments frob list shows (a class: grade_cli_class_test.cpp).
#include "grade_cli.hpp"

#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

TEST(GradeCli, ARubricMistakeIsOneLineAndStatus2) {
  const fs::path dir = assignment("grade_cli_mistake");
  std::ofstream(dir / "forward" / "rubric.toml") << "[[check]]\nname = \"x\"\nworlds = [\"room.toml\"]\ngoal = { witihn = 1 }\n";
  std::ofstream(dir / "sub.cpp") << driver("0.5");
  const FrobResult r = runFrob(dir, {"grade", "forward", "sub.cpp"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "frob: forward/rubric.toml:4: check[0].goal.witihn: unknown key (expected one of within, by, point)\n");
  EXPECT_EQ(runFrob(dir, {"grade", "nowhere", "sub.cpp"}).err,
            "frob: unknown assignment 'nowhere': not a folder of assignments/ (see frob list), and no rubric.toml there\n");
}

// The hidden worlds cannot be checked for a fault of the machine (a controller cache that cannot be
// made, so the reference cannot be compiled): the grader's failure, status 1, not a rubric's mistake.
TEST(GradeCli, AGraderFailureCheckingTheHiddenWorldsIsStatus1) {
  const fs::path dir = assignment("grade_cli_unchecked");
  std::ofstream(dir / "forward" / "rubric.toml")
      << "reference = \"reference.cpp\"\n[[check]]\nname = \"hidden\"\nvisibility = \"hidden\"\n"
         "generated = { kind = \"crossing\", secret = 1 }\ngoal = { point = \"centre\", within = 100, by = 60 }\n";
  std::ofstream(dir / "forward" / "reference.cpp") << driver("0.5");
  std::ofstream(dir / "sub.cpp") << driver("0.5");
  std::ofstream(dir / "secret.txt") << "course secret\n";
  const FrobResult r = runFrob(dir, {"grade", "forward", "sub.cpp", "--secret", "secret.txt"}, "/dev/null/cache");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("frob: the grader failed: cannot create the controller cache '/dev/null/cache'", 0), 0u) << r.err;
}

TEST(GradeCli, ASubmissionThatFailsStillExitsZeroWithItsScore) {
  const fs::path dir = assignment("grade_cli_one");
  std::ofstream(dir / "slow.cpp") << driver("0.1");
  const FrobResult r = runFrob(dir, {"grade", "forward", "slow.cpp", "--results", "r.json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(readFile(dir / "r.json"));
  EXPECT_EQ(j["score"], 1.0);  // no bumps, but never near the goal
  EXPECT_NE(r.out.find("never came within 0.40 m of goal"), std::string::npos) << r.out;
}

// The report's film is the first failing visible run, filmed again and proven the graded one by its
// hash: its video, its plot, and the run viewer of that run in a frame; the films' files go away.
TEST(GradeCli, TheReportShowsTheFailingRunInTheViewer) {
  const fs::path dir = assignment("grade_cli_report");
  std::ofstream(dir / "slow.cpp") << driver("0.1");
  // A film's folder that a killed frob left (no one holds its lock) is swept, and this one's removed.
  const fs::path temp = dir / "tmp";
  fs::create_directories(temp / "frob-report-left");
  const FrobResult r = runFrob(dir, {"grade", "forward", "slow.cpp", "--report", "r.html"}, FROB_TEST_CACHE_DIR, temp);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_empty(temp)) << "a folder was left in " << temp;
  const std::string page = readFile(dir / "r.html");
  EXPECT_NE(page.find("<video controls src=\"data:video/mp4;base64,"), std::string::npos);
  EXPECT_NE(page.find("<iframe class=\"viewer\" sandbox=\"allow-scripts\""), std::string::npos);
  EXPECT_NE(page.find("id=&quot;run-data&quot;"), std::string::npos) << "the frame holds no viewer page with its run";
  EXPECT_NE(page.find("The run shown is the graded run"), std::string::npos);
}

// PrairieLearn's results carry the first failing visible run's plot on that check's test, and no other.
TEST(GradeCli, PrairieLearnShowsTheFailingRunsPlotOnItsCheck) {
  const fs::path dir = assignment("grade_cli_prairielearn");
  std::ofstream(dir / "slow.cpp") << driver("0.1");
  const FrobResult r = runFrob(dir, {"grade", "forward", "slow.cpp", "--prairielearn", "pl/results.json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(readFile(dir / "pl" / "results.json"));
  ASSERT_EQ(j["tests"].size(), 2u) << j.dump(1);
  ASSERT_EQ(j["tests"][0]["images"].size(), 1u) << j.dump(1);
  EXPECT_EQ(j["tests"][0]["images"][0]["label"], "The first failing run, room.toml with seed 1");
  const std::string url = j["tests"][0]["images"][0]["url"];
  EXPECT_EQ(url.rfind("data:image/png;base64,iVBORw0KGgo", 0), 0u) << url.substr(0, 60);  // PNG's signature, in base64
  EXPECT_FALSE(j["tests"][1].contains("images")) << "the check that passed shows no picture";
}

// A machine that cannot make namespaces (here a user namespace that allows none inside it, as a
// chroot or a container's seccomp profile may) still grades, and the instructor is told on stderr;
// nothing a student reads (results, scores) says which layer is missing.
TEST(GradeCli, ASandboxLayerThisMachineLacksIsSaidToTheInstructorOnly) {
  const fs::path dir = assignment("grade_cli_layers");
  std::ofstream(dir / "fast.cpp") << driver("0.5");
  const std::string noNamespaces = "echo 0 > /proc/sys/user/max_user_namespaces && exec \"$0\" \"$@\"";
  const FrobResult r = runCommand(dir, {"/usr/bin/unshare", "--user", "--map-root-user", "sh", "-c", noNamespaces, FROB_EXECUTABLE, "grade",
                                        "forward", "fast.cpp", "--results", "r.json"});
  if (r.status != 0 && r.err.find("unshare: ") == 0) GTEST_SKIP() << "no user namespace to test in: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("frob: the controllers ran with parts of their sandbox missing on this machine:\n"), 0u) << r.err;
  EXPECT_NE(r.err.find("\nnamespaces: NOT applied (not available: unshare: No space left on device"), std::string::npos) << r.err;
  // Root there, but the host's own user has no uid in that namespace: the controller stays root, and that is said too.
  EXPECT_NE(r.err.find("\nunprivileged user: NOT applied"), std::string::npos) << r.err;
  const std::string results = readFile(dir / "r.json");
  EXPECT_EQ(nlohmann::json::parse(results)["score"], 3.0);
  EXPECT_EQ(results.find("namespaces"), std::string::npos) << results;
  EXPECT_EQ(r.out.find("namespaces"), std::string::npos) << r.out;
  // Where every layer is there, nothing is said.
  const FrobResult whole = runFrob(dir, {"grade", "forward", "fast.cpp"});
  EXPECT_EQ(whole.err.find("sandbox missing"), std::string::npos) << whole.err;
}

// A task that never ends gets a hint, unless the assignment never waits for one to return: a wall
// follower is meant to follow for ever (wall_follow has no `returns` criterion).
TEST(GradeCli, AnAssignmentWhoseTasksRunForEverGetsNoHintThatTheyNeverEnded) {
  const fs::path dir = freshFolder("grade_cli_forever");
  std::ofstream(dir / "creep.cpp")
      << "#include <frob/frob.hpp>\nusing namespace frob;\nTask<Wheels> creep() {\n"
         "  co_await mkTask([](const TaskState&) { return std::pair{wheels(0.1, 0.0), never<Unit>()}; }).named(\"inch\");\n"
         "}\nFROB_CONTROLLER(creep)\n";
  const std::string world = FROB_SOURCE_DIR "/assignments/wall_follow/worlds/l_room.toml";
  const std::string hint = "nomad's task 'inch' ran from 0.0 s to the end of the run: the event that should end it never occurred";
  const FrobResult plain = runFrob(dir, {"run", "creep.cpp", "--world", world, "--seconds", "10"});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.out.find(hint), std::string::npos) << plain.out;
  const FrobResult judged = runFrob(dir, {"run", "creep.cpp", "--world", world, "--seconds", "10", "--assignment", "wall_follow"});
  ASSERT_EQ(judged.status, 0) << judged.err;
  EXPECT_NE(judged.out.find("Against wall_follow's checks"), std::string::npos) << judged.out;
  EXPECT_EQ(judged.out.find("never occurred"), std::string::npos) << judged.out;
}

// A student checks a run against the assignment in any world, with the judge frob grade uses: each
// criterion's verdict and reason, the same words a grade gives for a run with that world and seed.
// "quickly" is judged on its own 1 s of the 3 s run (the longest check's time).
TEST(GradeCli, FrobRunJudgesARunAgainstTheChecksAsAGradeDoes) {
  const fs::path dir = assignment("grade_cli_run_assignment");
  std::ofstream(dir / "forward" / "rubric.toml", std::ios::app) << R"([[check]]
name = "quickly"
worlds = ["room.toml"]
seeds = [1]
seconds = 1
goal = { within = 0.4 }
[[check]]
name = "elsewhere"
worlds = ["other.toml"]
clearance = { min = 0.1 }
)";
  fs::copy_file(dir / "forward" / "room.toml", dir / "forward" / "other.toml");
  std::ofstream(dir / "fast.cpp") << driver("0.5");
  const FrobResult graded = runFrob(dir, {"grade", "forward", "fast.cpp", "--results", "r.json"});
  ASSERT_EQ(graded.status, 0) << graded.err;
  const nlohmann::json results = nlohmann::json::parse(readFile(dir / "r.json"));
  const std::string output = markdownRead(results["tests"][2]["output"]);
  const std::string prefix = "- **room.toml, seed 1**: failed: ";
  ASSERT_EQ(output.find(prefix), 0u) << output;
  const std::string reason = output.substr(prefix.size(), output.find('\n') - prefix.size());
  EXPECT_NE(reason.find("never came within 0.40 m of goal"), std::string::npos) << reason;
  // How near the edge, as the grade says it: the run says the same.
  const std::string marginsPrefix = "\n  - margins: goal ";
  const std::size_t m = output.find(marginsPrefix);
  ASSERT_NE(m, std::string::npos) << output;
  const std::string margin = output.substr(m + marginsPrefix.size(), output.find('\n', m + 1) - m - marginsPrefix.size());
  EXPECT_EQ(margin, "failed by 0.24 m (closest 0.64 m to goal; 0.40 m needed)");

  const FrobResult run = runFrob(dir, {"run", "fast.cpp", "--world", "forward/room.toml", "--seed", "1", "--assignment", "forward", "--quiet"});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("Against forward's checks (judged as frob grade judges a run; a grade runs other worlds and seeds too):\n"
                         "  PASS  goes forward: goal\n"
                         "        passed by "),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("  PASS  no bumps: collisions\n"
                         "        passed by 0 collisions (no collision; at most 0)\n"
                         "  FAIL  quickly: goal: " +
                         reason + " (on its first 1.0 s)\n        " + margin + "\n"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("3.00 s simulated"), std::string::npos) << run.out;

  const FrobResult json = runFrob(dir, {"run", "fast.cpp", "--world", "forward/room.toml", "--seed", "1", "--assignment", "forward", "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  const nlohmann::json checks = nlohmann::json::parse(json.out)["assignment"]["checks"];
  ASSERT_EQ(checks.size(), 3u) << json.out;  // "elsewhere" runs in another world
  nlohmann::json quickly = checks[2];
  EXPECT_EQ(quickly["margin"]["text"], "closest 0.64 m to goal; 0.40 m needed");
  EXPECT_EQ(quickly["margin"]["unit"], "m");
  EXPECT_NEAR(quickly["margin"]["value"].get<double>(), -0.24, 0.005) << "as its text says, to the centimetre";
  EXPECT_EQ(quickly["margin"]["at"], 1.0);
  quickly.erase("margin");
  EXPECT_EQ(quickly, (nlohmann::json{{"check", "quickly"}, {"criterion", "goal"}, {"seconds", 1.0}, {"passed", false}, {"reason", reason}}));
  EXPECT_EQ(checks[0]["passed"], true);
  // In a world of the student's own, every check is judged.
  fs::copy_file(dir / "forward" / "room.toml", dir / "mine.toml");
  const FrobResult own = runFrob(dir, {"run", "fast.cpp", "--world", "mine.toml", "--assignment", "forward", "--json"});
  ASSERT_EQ(own.status, 0) << own.err;
  EXPECT_EQ(nlohmann::json::parse(own.out)["assignment"]["checks"].size(), 4u) << own.out;

  EXPECT_EQ(runFrob(dir, {"run", "fast.cpp", "--world", "forward/room.toml", "--assignment", "nowhere"}).err,
            "frob: unknown assignment 'nowhere': not a folder of assignments/ (see frob list), and no rubric.toml there\n");
}

// With --assignment, the trace has a column per quantity the checks judge: here the distance to the
// goal the "goal" criteria measure, equal at every row to the distance from the row's true position.
TEST(GradeCli, FrobRunTracesWhatTheAssignmentJudges) {
  const fs::path dir = assignment("grade_cli_measured");
  std::ofstream(dir / "fast.cpp") << driver("0.5");
  const FrobResult run =
      runFrob(dir, {"run", "fast.cpp", "--world", "forward/room.toml", "--seed", "1", "--assignment", "forward", "--trace", "t.csv", "--quiet"});
  ASSERT_EQ(run.status, 0) << run.err;
  std::istringstream trace(readFile(dir / "t.csv"));
  std::string line;
  std::getline(trace, line);
  ASSERT_TRUE(line.ends_with(",bumper,task,goal_distance")) << line;
  int rows = 0;
  while (std::getline(trace, line)) {
    std::vector<std::string> f;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) f.push_back(cell);
    ASSERT_GE(f.size(), 4u);
    EXPECT_NEAR(std::stod(f.back()), std::hypot(std::stod(f[2]) - 2.0, std::stod(f[3]) - 1.5), 1e-6) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 300) << "a row per step of 3 s at 100 Hz";
  // Without an assignment, no such column.
  ASSERT_EQ(runFrob(dir, {"run", "fast.cpp", "--world", "forward/room.toml", "--seconds", "0.5", "--trace", "u.csv", "--quiet"}).status, 0);
  const std::string plain = readFile(dir / "u.csv");
  EXPECT_TRUE(plain.substr(0, plain.find('\n')).ends_with(",bumper,task"));
}

// A rubric's late penalty, from Gradescope's submission metadata: a share of the score per day begun,
// at most `most`; on time, nothing; a time that is not one is the autograder's error, not a grade.
TEST(GradeCli, ALateSubmissionLosesItsShareAndSaysSo) {
  const fs::path dir = assignment("grade_cli_late");
  std::ofstream(dir / "forward" / "rubric.toml") << "late = { per_day = 0.1, most = 0.25 }\n" << kRubric;  // a top-level key: before the checks
  std::ofstream(dir / "fast.cpp") << driver("0.5");
  const auto metadata = [&](const std::string& name, const std::string& created) {
    std::ofstream(dir / name) << R"({"id": 1, "created_at": ")" << created
                              << R"(", "assignment": {"due_date": "2026-12-05T23:59:00.000000-08:00", "title": "Forward"}, "users": []})";
    return name;
  };
  const auto score = [&](const std::string& meta) {
    const FrobResult r = runFrob(dir, {"grade", "forward", "fast.cpp", "--results", "r.json", "--submission-metadata", meta});
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(readFile(dir / "r.json"));
  };
  EXPECT_EQ(score(metadata("early.json", "2026-12-05T23:58:59.5-08:00"))["score"], 3.0);
  // 2026-12-06T09:00:00Z is 1:01 after the due date: one day begun, 10% of 3 points.
  const nlohmann::json late = score(metadata("late.json", "2026-12-06T09:00:00Z"));
  EXPECT_EQ(late["score"], 2.7);
  EXPECT_NE(late["output"].get<std::string>().find("Note: submitted 1 day late: 10% of the score taken (10% a day begun, at most 25%)"),
            std::string::npos)
      << late["output"];
  EXPECT_EQ(score(metadata("later.json", "2026-12-09T10:00:00+02:00"))["score"], 2.25);  // 3 days begun: 30%, at most 25%
  const FrobResult broken =
      runFrob(dir, {"grade", "forward", "fast.cpp", "--results", "x.json", "--submission-metadata", metadata("bad.json", "yesterday")});
  EXPECT_EQ(broken.status, 2);
  EXPECT_NE(broken.err.find("bad.json: created_at: not an ISO 8601 time with its offset: 'yesterday'"), std::string::npos) << broken.err;
  EXPECT_FALSE(fs::exists(dir / "x.json"));
  // Without a late penalty in the rubric, the metadata is not read at all.
  std::ofstream(dir / "forward" / "rubric.toml") << kRubric;
  EXPECT_EQ(runFrob(dir, {"grade", "forward", "fast.cpp", "--results", "x.json", "--submission-metadata", "bad.json"}).status, 0);
}

TEST(GradeCli, AReplayFromTheCommandLineGivesTheVerdictAndHashAgain) {
  const fs::path dir = assignment("grade_cli_replay");
  std::ofstream(dir / "slow.cpp") << driver("0.1");
  std::ofstream(dir / "secret.txt") << "course secret\n";
  ASSERT_EQ(runFrob(dir, {"grade", "forward", "slow.cpp", "--logs", "logs", "--secret", "secret.txt"}).status, 0);
  EXPECT_EQ(runFrob(dir, {"grade", "--replay", "logs/goes_forward__room__1.log"}).status, 1);  // the secret checks its signature
  const FrobResult r = runFrob(dir, {"grade", "--replay", "logs/goes_forward__room__1.log", "--secret", "secret.txt"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("the log of slow.cpp (SHA-256 ", 0), 0u) << r.out;  // whose run it replays
  EXPECT_NE(r.out.find("\ncheck goes forward, world room.toml, seed 1: FAILED: never came within 0.40 m of goal"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("trajectory "), std::string::npos);
  // Presented for another submission, it is refused.
  std::ofstream(dir / "fast.cpp") << driver("0.3");
  const FrobResult other = runFrob(dir, {"grade", "--replay", "logs/goes_forward__room__1.log", "--secret", "secret.txt", "fast.cpp"});
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.err.find("this is the log of another submission (slow.cpp, SHA-256 "), std::string::npos) << other.err;
  EXPECT_EQ(runFrob(dir, {"grade", "--replay", "logs/goes_forward__room__1.log", "--secret", "secret.txt", "slow.cpp"}).status, 0);
}

TEST(WorldGenerate, WritesAWorldThatRuns) {
  const fs::path dir = freshFolder("world_generate");
  const FrobResult made = runFrob(dir, {"world", "generate", "maze", "--seed", "4", "--out", "m.toml"});
  ASSERT_EQ(made.status, 0) << made.err;
  EXPECT_EQ(made.out, "wrote m.toml: Generated perfect maze of 1.6 m cells\n");
  EXPECT_EQ(runFrob(dir, {"run", "bug", "--world", "m.toml", "--seconds", "1", "--quiet"}).status, 0);
  EXPECT_EQ(runFrob(dir, {"world", "generate", "forest", "--out", "f.toml"}).err,
            "frob: unknown kind of world 'forest': one of obstacles, maze, rooms, loop, furnished_room, outline, lounge, warehouse_keys, "
            "warehouse_box, crossing\n");
}

// A student practises the hidden checks on worlds of their family drawn from a seed of their own:
// the same seed, the same worlds, each one a world frob world generate rebuilds; no secret needed,
// and none used when one is set.
TEST(GradeCli, PractiseTheHiddenChecksOnTheirFamily) {
  const fs::path dir = assignment("grade_cli_practice");
  std::ofstream(dir / "forward" / "rubric.toml")
      << std::string(kRubric) +
             "[[check]]\nname = \"unseen warehouses\"\nvisibility = \"hidden\"\n"
             "generated = { kind = \"warehouse_box\", secret = 2 }\ngoal = { point = \"p3\", within = 0.1, by = 60 }\n";
  std::ofstream(dir / "sub.cpp") << driver("0.0");
  const FrobResult r = runFrob(dir, {"grade", "forward", "sub.cpp", "--practice", "2", "--seed", "5"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("unseen warehouses"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("goes forward"), std::string::npos) << r.out;          // only the hidden checks are practised
  EXPECT_NE(r.out.find("0 / 1"), std::string::npos) << r.out;                 // standing still gets nowhere near p3 ...
  const std::size_t first = r.out.find("in generated warehouse_box, seed ");  // ... in two worlds named for frob world generate
  ASSERT_NE(first, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in generated warehouse_box, seed ", first + 1), std::string::npos) << r.out;
  const FrobResult withSecret = runFrob(dir, {"grade", "forward", "sub.cpp", "--practice", "2", "--seed", "5", "--secret", "/no/such/file"});
  EXPECT_EQ(withSecret.out, r.out);
  const FrobResult other = runFrob(dir, {"grade", "forward", "sub.cpp", "--practice", "2", "--seed", "6"});
  EXPECT_NE(other.out, r.out);
}

TEST(FrobList, NamesEveryAssignmentWithItsTitle) {
  const FrobResult r = runFrob(freshFolder("list_assignments"), {"list"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string listed = r.out.substr(r.out.find("Assignments"));
  for (const fs::directory_entry& e : fs::directory_iterator(FROB_SOURCE_DIR "/assignments")) {
    if (!fs::exists(e.path() / "rubric.toml")) continue;
    const std::string rubric = readFile(e.path() / "rubric.toml");
    const std::size_t at = rubric.find("title = \"");
    ASSERT_NE(at, std::string::npos) << e.path();
    const std::string title = rubric.substr(at + 9, rubric.find('"', at + 9) - at - 9);
    EXPECT_NE(listed.find("  " + e.path().filename().string() + " "), std::string::npos) << e.path();
    EXPECT_NE(listed.find(title), std::string::npos) << title;
  }
}

}  // namespace
}  // namespace frob::testing
