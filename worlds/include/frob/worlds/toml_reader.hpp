#pragma once
/// Reading a TOML file field by field, where every mistake becomes one message naming the file, the
/// line and the field: "maze.toml:12: robot[0].start: expected [x, y]". World files and rubrics
/// are read with it.

#include "frob/geometry.hpp"

#include <toml++/toml.h>

#include <initializer_list>
#include <string>
#include <string_view>

namespace frob::worlds {

/// Reads fields of one TOML document. Every reader returns false after recording the first error.
class TomlReader {
 public:
  /// A reader for the file named `file` in messages.
  explicit TomlReader(std::string file) : file_(std::move(file)) {}

  /// Parses `text` into `root`; false on a syntax error.
  bool parse(std::string_view text, toml::table& root);
  /// The first error, "file:line: field: message"; empty while there is none.
  [[nodiscard]] const std::string& error() const { return error_; }
  /// "file:line: " (or "file: " for line 0).
  [[nodiscard]] std::string where(int line) const;
  /// The line a node was written on.
  [[nodiscard]] static int line(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

  bool fail(int line, const std::string& field, const std::string& message);
  bool fail(const toml::node& n, const std::string& field, const std::string& message) { return fail(line(n), field, message); }
  /// Unknown keys are errors: a typo must not be silently ignored.
  bool onlyKeys(const toml::table& t, const std::string& prefix, std::initializer_list<std::string_view> allowed);

  bool number(const toml::node& n, const std::string& field, double& out);
  bool integer(const toml::node& n, const std::string& field, long long lo, long long hi, long long& out);
  bool integer(const toml::node& n, const std::string& field, long long lo, long long hi, int& out);
  bool point(const toml::node& n, const std::string& field, Point2& out);
  bool string(const toml::node& n, const std::string& field, std::string& out);
  bool boolean(const toml::node& n, const std::string& field, bool& out);
  /// `n` as a table, or nullptr after recording an error.
  const toml::table* table(const toml::node& n, const std::string& field);

  // Optional keys: absent leaves `out` as it was.
  bool optNumber(const toml::table& t, std::string_view key, const std::string& field, double& out, double unit = 1);
  bool optInteger(const toml::table& t, std::string_view key, const std::string& field, long long lo, long long hi, int& out);
  bool optPoint(const toml::table& t, std::string_view key, const std::string& field, Point2& out);
  bool optString(const toml::table& t, std::string_view key, const std::string& field, std::string& out);

 private:
  std::string file_;
  std::string error_;
};

}  // namespace frob::worlds
