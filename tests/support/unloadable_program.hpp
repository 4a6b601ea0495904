#pragma once
// A host program that cannot start: for the tests that a grader's own failure is never a grade.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace frob::testing {

// A copy of /usr/bin/true in `dir` whose loader cannot find its C library: it ends with exit status
// 127 before its first instruction, as a host program does whose libraries are missing or replaced.
inline std::filesystem::path unloadableProgram(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::ifstream in("/usr/bin/true", std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  for (std::size_t at; (at = bytes.find(std::string("libc.so.6\0", 10))) != std::string::npos;) bytes[at + 3] = 'q';
  const fs::path program = dir / "unloadable";
  std::ofstream(program, std::ios::binary) << bytes;
  fs::permissions(program, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec | fs::perms::others_read);
  return program;
}

}  // namespace frob::testing
