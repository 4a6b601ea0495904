#pragma once
/// A run's wheel log, as frob grade --logs writes it and --replay reads it back: what to rebuild the
/// run from, whose submission it was, what the controller said, the graded trajectory's hash and
/// every step's wheels, signed with the instructor's secret (HMAC-SHA256 over its text).
///
/// One record a line, "key value". A value is escaped (a backslash as "\\", a line feed as "\n",
/// any other control byte as "\xHH"), so that no text, not even one a controller chose (a failure,
/// a returned value), can end its record and add another; reading refuses any other escape.

#include "frob/base/result.hpp"
#include "frob/frob.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frob::course {

/// Everything a log holds but its signature.
struct WheelLog {
  std::string rubric;            ///< the rubric file by its assignment's folder ("go_to_goal/rubric.toml"; older logs: its absolute path)
  std::string check;             ///< the check's name
  std::string world;             ///< the world as the rubric names it
  std::string generated;         ///< the generator's kind, for a generated world; "" otherwise
  std::uint64_t worldSeed = 0;   ///< the generator's seed, for a generated world
  std::uint64_t seed = 0;        ///< the run's simulation seed
  std::string submission;        ///< the submission graded, as given
  std::string submissionHash;    ///< SHA-256 of its files (submissionHash()), in hex
  std::string student;           ///< who submitted it, where known; "" otherwise
  std::uint64_t trajectory = 0;  ///< the graded trajectory's hash
  std::size_t robots = 0;
  std::vector<std::pair<std::size_t, std::string>> failures;  ///< robot, why its controller failed
  std::vector<std::pair<std::size_t, std::string>> returned;  ///< robot, what its top task returned (reported by the controller)
  std::vector<std::pair<std::size_t, double>> returnedAt;     ///< robot, when it returned, seconds
  std::vector<std::vector<Wheels>> wheels;                    ///< per step, per robot
};

/// Most robots a log may hold.
inline constexpr std::size_t kLogRobots = 64;

/// `log` as text, signed with `secret` (unsigned when `secret` is empty).
[[nodiscard]] std::string wheelLogText(const WheelLog& log, const std::string& secret);
/// The log in `text` (signed text, as wheelLogText() writes it), once its signature is checked with `secret`; or why it is refused.
[[nodiscard]] Result<WheelLog> readWheelLog(std::string_view text, const std::string& secret);
/// The log in `body` (text without its signature line); or which record cannot be read. Never throws, whatever `body` holds.
[[nodiscard]] Result<WheelLog> parseWheelLog(std::string_view body);
/// SHA-256, in hex, of a submission: a file's bytes, or a folder's regular .cpp, .h and .hpp files by name (not following links).
[[nodiscard]] std::string submissionHash(const std::filesystem::path& submission);

}  // namespace frob::course
