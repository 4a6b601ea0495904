#pragma once
// Runs the built `frob` command in a fresh folder of its own and keeps what it printed.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

extern char** environ;

namespace frob::testing {

struct FrobResult {
  int status = -1;  // exit status
  std::string out;  // stdout
  std::string err;  // stderr
};

// A folder under the build's temp dir, emptied, named after the test.
inline std::filesystem::path freshFolder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(FROB_TEST_WORK_DIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Markdown's text as it reads: each backslash escape of a punctuation mark undone (Gradescope's test output).
inline std::string markdownRead(const std::string& markdown) {
  std::string text;
  for (std::size_t i = 0; i < markdown.size(); ++i) {
    if (markdown[i] == '\\' && i + 1 < markdown.size() && std::ispunct(static_cast<unsigned char>(markdown[i + 1])) != 0) ++i;
    text += markdown[i];
  }
  return text;
}

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `command` (a program's path, then its arguments) as runFrob() runs frob.
inline FrobResult runCommand(const std::filesystem::path& dir, std::vector<std::string> all, const std::string& cache = FROB_TEST_CACHE_DIR,
                             const std::filesystem::path& temp = {}) {
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> env{"FROB_CACHE_DIR=" + cache};
  if (!temp.empty()) env.push_back("TMPDIR=" + temp.string());
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string var(*e);
    if (var.rfind("FROB_CACHE_DIR=", 0) != 0 && (temp.empty() || var.rfind("TMPDIR=", 0) != 0)) env.push_back(var);
  }
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  pid_t pid = 0;
  FrobResult r;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0) {
    int status = 0;
    waitpid(pid, &status, 0);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  posix_spawn_file_actions_destroy(&actions);
  r.out = readFile(out);
  r.err = readFile(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// Runs `frob args...` with `dir` as its working folder; controllers compile into `cache`; its
// temporary folder is `temp` when given.
inline FrobResult runFrob(const std::filesystem::path& dir, const std::vector<std::string>& args, const std::string& cache = FROB_TEST_CACHE_DIR,
                          const std::filesystem::path& temp = {}) {
  std::vector<std::string> all{FROB_EXECUTABLE};
  all.insert(all.end(), args.begin(), args.end());
  return runCommand(dir, std::move(all), cache, temp);
}

// The files in `dir`, by name.
inline std::vector<std::string> filesIn(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace frob::testing
