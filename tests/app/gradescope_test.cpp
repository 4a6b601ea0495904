// The Gradescope autograder zip: what it holds, and its run_autograder grading a submission in a
// fake /autograder tree (its root given by FROB_AUTOGRADER_ROOT), with the frob built here.
#include "run_frob.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zip.h>

#include <map>

namespace frob::testing {
namespace {

namespace fs = std::filesystem;

// Unpacks `zipFile` into `dir`, keeping the files' Unix permissions; returns the names.
std::vector<std::string> unzip(const fs::path& zipFile, const fs::path& dir) {
  int error = 0;
  zip_t* z = ::zip_open(zipFile.c_str(), ZIP_RDONLY, &error);
  EXPECT_NE(z, nullptr);
  std::vector<std::string> names;
  for (zip_int64_t i = 0; z != nullptr && i < ::zip_get_num_entries(z, 0); ++i) {
    zip_stat_t st;
    ::zip_stat_index(z, static_cast<zip_uint64_t>(i), 0, &st);
    names.emplace_back(st.name);
    std::string data(st.size, '\0');
    zip_file_t* f = ::zip_fopen_index(z, static_cast<zip_uint64_t>(i), 0);
    ::zip_fread(f, data.data(), st.size);
    ::zip_fclose(f);
    const fs::path out = dir / st.name;
    fs::create_directories(out.parent_path());
    std::ofstream(out, std::ios::binary) << data;
    zip_uint8_t system = 0;
    zip_uint32_t attributes = 0;
    ::zip_file_get_external_attributes(z, static_cast<zip_uint64_t>(i), 0, &system, &attributes);
    ::chmod(out.c_str(), (attributes >> 16) & 07777);
  }
  if (z != nullptr) ::zip_close(z);
  return names;
}

constexpr const char* kRubric = R"(title = "Drive"
reference = "solution.cpp"
seconds = 12
[[check]]
name = "reaches the goal"
points = 3
worlds = ["field.toml"]
goal = { within = 0.3 }
[[check]]
name = "hidden"
points = 1
visibility = "hidden"
worlds = ["field.toml"]
secret_seeds = 1
collisions = { max = 0 }
[[check]]
name = "unseen rooms"
points = 1
visibility = "hidden"
generated = { kind = "rooms", secret = 1 }
collisions = { max = 1000 }
)";

constexpr const char* kWorld = "size = [6.0, 4.0]\n[points]\ngoal = [5.0, 2.0]\n[[robot]]\nname = \"nomad\"\nstart = [1.0, 2.0]\n";

constexpr const char* kGood = R"(#include <frob/frob.hpp>
using namespace frob;
Task<Wheels> toGoal() {
  co_await mkTask([](const TaskState& ts) {
    return std::pair{wheels(0.4, 0.0), predicate(lift([](Point2 p) { return p.x() > 4.8; }, place(ts.robot())))};
  });
}
FROB_CONTROLLER(toGoal)
)";

constexpr const char* kForged = R"(#include <frob/frob.hpp>
#include <cstdio>
#include <unistd.h>
using namespace frob;
Behavior<Wheels> forge(const Robot&) {
  std::FILE* f = std::fopen("/autograder/results/results.json", "w");
  if (f) std::fputs("{\"score\": 100}", f);
  std::printf("{\"score\": 100}\n");
  ::_exit(0);
}
FROB_CONTROLLER(forge)
)";

// Runs the zip's run_autograder on `submission` in a fresh fake /autograder tree; its results.json.
nlohmann::json runAutograder(const fs::path& zipFile, const std::string& name, const std::string& submission,
                             const std::map<std::string, std::string>& beside = {}) {
  const fs::path root = freshFolder("autograder_" + name);
  const std::vector<std::string> names = unzip(zipFile, root / "source");
  fs::create_directories(root / "submission");
  if (!submission.empty()) std::ofstream(root / "submission" / "controller.cpp") << submission;
  for (const auto& [file, text] : beside) std::ofstream(root / "submission" / file) << text;
  const std::string command = "FROB_AUTOGRADER_ROOT=" + root.string() + " FROB=" FROB_EXECUTABLE " bash " +
                              (root / "source" / "run_autograder").string() + " > " + (root / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << readFile(root / "log.txt");
  std::ifstream in(root / "results" / "results.json");
  return nlohmann::json::parse(in);
}

TEST(GradescopeZip, HoldsTheSourcesTheAssignmentAndTheScripts) {
  const fs::path dir = freshFolder("gradescope_zip");
  fs::create_directories(dir / "drive");
  std::ofstream(dir / "drive" / "rubric.toml") << kRubric;
  std::ofstream(dir / "drive" / "field.toml") << kWorld;
  std::ofstream(dir / "drive" / "solution.cpp") << kGood;
  std::ofstream(dir / "secret.txt") << "course-secret\n";
  const FrobResult r = runFrob(dir, {"grade", "drive", "--gradescope-zip", "autograder.zip", "--secret", "secret.txt"});
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path unpacked = freshFolder("gradescope_zip_unpacked");
  const std::vector<std::string> names = unzip(dir / "autograder.zip", unpacked);
  for (const char* needed : {"setup.sh", "run_autograder", "secret.txt", "CMakeLists.txt", "frob/include/frob/frob.hpp",
                             "course/sandbox/programs/host_main.cpp", "assignments/drive/rubric.toml", "assignments/drive/field.toml"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), needed), names.end()) << needed;
  }
  for (const std::string& n : names) EXPECT_NE(n.rfind("tests/", 0), 0u) << n;  // the autograder builds no tests
  // No reference solution, but the hidden worlds it was found to pass, in the autograder's cache.
  EXPECT_EQ(std::find(names.begin(), names.end(), "assignments/drive/solution.cpp"), names.end());
  const auto kept = std::find_if(names.begin(), names.end(), [](const std::string& n) { return n.rfind("cache/hidden-worlds/", 0) == 0; });
  ASSERT_NE(kept, names.end());
  EXPECT_NE(readFile(unpacked / *kept).find("0 unseen rooms\n"), std::string::npos) << readFile(unpacked / *kept);
  EXPECT_EQ(fs::status(unpacked / "run_autograder").permissions() & fs::perms::owner_exec, fs::perms::owner_exec);
  EXPECT_EQ(fs::status(unpacked / "setup.sh").permissions() & fs::perms::owner_exec, fs::perms::owner_exec);

  // The reference solution goes apart, for setup.sh alone, which grades it with the build it made
  // and fails unless it gets full marks; a build that grades otherwise is caught there.
  EXPECT_NE(std::find(names.begin(), names.end(), "reference/solution.cpp"), names.end());
  const std::string setup = readFile(unpacked / "setup.sh");
  EXPECT_NE(setup.find("check_reference.sh assignments/drive reference/*"), std::string::npos) << setup;
  EXPECT_NE(setup.find("trap 'rm -rf reference"), std::string::npos) << setup;
  const auto checkReference = [&](const std::string& reference) {
    std::ofstream(unpacked / "reference" / "solution.cpp") << reference;
    const fs::path cache = freshFolder("gradescope_zip_cache");
    fs::copy(unpacked / "cache", cache, fs::copy_options::recursive);
    const std::string command =
        "cd " + unpacked.string() + " && FROB=" FROB_EXECUTABLE " FROB_GRADE_SECRET=course-secret FROB_CACHE_DIR=" + cache.string() +
        " bash course/autograder/check_reference.sh assignments/drive reference/solution.cpp > " + (dir / "check.txt").string() + " 2>&1";
    return std::pair{std::system(command.c_str()), readFile(dir / "check.txt")};
  };
  const auto [full, fullSays] = checkReference(kGood);
  EXPECT_EQ(full, 0) << fullSays;
  EXPECT_NE(fullSays.find("check_reference.sh: the reference solution reference/solution.cpp gets full marks"), std::string::npos) << fullSays;
  const auto [lost, lostSays] = checkReference(kForged);
  EXPECT_NE(lost, 0) << lostSays;
  EXPECT_NE(lostSays.find("check_reference.sh: the reference solution reference/solution.cpp lost points here (the checks above)"), std::string::npos)
      << lostSays;

  // The reference solution: full marks, the hidden check graded with the secret in the zip.
  const nlohmann::json good = runAutograder(dir / "autograder.zip", "good", kGood);
  EXPECT_EQ(good["score"], 5.0) << good.dump(1);
  ASSERT_EQ(good["tests"].size(), 3u);
  EXPECT_EQ(good["tests"][1]["visibility"], "hidden");
  // A hostile one that tries to write a perfect result and leave: 0, and the reason.
  const nlohmann::json forged = runAutograder(dir / "autograder.zip", "forged", kForged);
  EXPECT_EQ(forged["score"], 0.0) << forged.dump(1);
  EXPECT_NE(forged["tests"][0]["output"].get<std::string>().find("ended its program with exit status 0"), std::string::npos) << forged.dump(1);

  // The file with FROB_CONTROLLER is graded, whatever the other files are called, and the others
  // compile with it (else loading fails on twice()'s undefined symbol); none or two: 0, and why.
  const std::string helper = "// helpers, no controller (a comment may name FROB_CONTROLLER)\nint twice(int x) { return 2 * x; }\n";
  const std::string usesHelper = std::string("int twice(int x);\nconst int kTwo = twice(1);\n") + kGood;
  const nlohmann::json helped = runAutograder(dir / "autograder.zip", "helped", usesHelper, {{"a_helpers.cpp", helper}});
  EXPECT_EQ(helped["score"], 5.0) << helped.dump(1);
  const nlohmann::json two = runAutograder(dir / "autograder.zip", "two", kGood, {{"another.cpp", kGood}});
  EXPECT_EQ(two["score"], 0.0) << two.dump(1);
  EXPECT_EQ(two["output"], "2 of the submitted .cpp files have a FROB_CONTROLLER(...) line: submit one controller.");
  const nlohmann::json none = runAutograder(dir / "autograder.zip", "none", "", {{"a_helpers.cpp", helper}});
  EXPECT_EQ(none["output"], "None of the submitted .cpp files has a FROB_CONTROLLER(...) line: submit the file that holds your controller.");
  const nlohmann::json nothing = runAutograder(dir / "autograder.zip", "nothing", "");
  EXPECT_EQ(nothing["output"], "No .cpp file was submitted: submit your controller file.");
}

}  // namespace
}  // namespace frob::testing
