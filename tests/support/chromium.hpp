#pragma once
// Debian's headless Chromium, run on a page for its screenshot or its DOM (tests of HTML pages).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace frob::support {

inline constexpr const char* kChromium = "/usr/bin/chromium";

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Ran {
  int status = -1;
  std::string err;
};

// Runs headless Chromium on `page` (with a `fragment` such as "#t=3" after its URL) with `flags`,
// stdout to `out`, at most 60 s (then it and its children are killed by timeout(1), which gives
// them a process group of their own).
inline Ran chromium(const std::filesystem::path& dir, const std::vector<std::string>& flags, const std::filesystem::path& page,
                    const std::filesystem::path& out, const std::string& fragment = "") {
  std::vector<std::string> all{"/usr/bin/timeout",
                               "-k",
                               "10",
                               "60",
                               kChromium,
                               "--headless",
                               "--no-sandbox",
                               "--disable-gpu",
                               "--no-first-run",
                               "--user-data-dir=" + (dir / "profile").string()};
  all.insert(all.end(), flags.begin(), flags.end());
  all.push_back("file://" + std::filesystem::absolute(page).string() + fragment);
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string err = (dir / "chromium_stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  Ran r;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  r.err = readText(err);
  return r;
}

// Fails (never skips) when Chromium is missing: the pages would go untested.
inline void requireChromium() {
  ASSERT_TRUE(std::filesystem::exists(kChromium)) << kChromium << " is missing: HTML pages are tested in headless Chromium; "
                                                  << "install it with `apt-get install chromium` (cmake/install-deps.sh lists it)";
}

}  // namespace frob::support
