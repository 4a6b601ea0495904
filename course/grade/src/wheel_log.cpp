#include "frob/grade/wheel_log.hpp"

#include "frob/run/format.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <algorithm>
#include <charconv>
#include <cinttypes>
#include <cstdlib>
#include <fstream>
#include <set>

namespace frob::course {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kFirstLine = "frob-replay 3";

std::string hex(const unsigned char* bytes, unsigned int length) {
  std::string out;
  for (unsigned int i = 0; i < length; ++i) out += format("%02x", bytes[i]);
  return out;
}

// HMAC-SHA256 of `text` keyed by the instructor's secret, in hex.
std::string signature(const std::string& secret, std::string_view text) {
  unsigned char mac[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()), reinterpret_cast<const unsigned char*>(text.data()), text.size(), mac, &length);
  return hex(mac, length);
}

// `value` with no byte that could end a record: "\\", "\n", "\xHH".
std::string escaped(std::string_view value) {
  std::string out;
  for (const char c : value) {
    const auto b = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (b < 0x20 || b == 0x7f) {
      out += format("\\x%02x", b);
    } else {
      out += c;
    }
  }
  return out;
}

std::optional<std::string> unescaped(std::string_view value) {
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const auto b = static_cast<unsigned char>(value[i]);
    if (b < 0x20 || b == 0x7f) return std::nullopt;  // a writer never leaves one
    if (value[i] != '\\') {
      out += value[i];
    } else if (i + 1 < value.size() && (value[i + 1] == '\\' || value[i + 1] == 'n')) {
      out += value[++i] == 'n' ? '\n' : '\\';
    } else if (i + 3 < value.size() && value[i + 1] == 'x' && std::isxdigit(static_cast<unsigned char>(value[i + 2])) &&
               std::isxdigit(static_cast<unsigned char>(value[i + 3]))) {
      out += static_cast<char>(std::strtoul(std::string(value.substr(i + 2, 2)).c_str(), nullptr, 16));
      i += 3;
    } else {
      return std::nullopt;
    }
  }
  return out;
}

template <class T>
bool number(std::string_view text, T& out, int base = 10) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out, base);
  return ec == std::errc() && end == text.data() + text.size();
}

// A double as "%a" writes it, the whole of `text`.
bool real(std::string_view text, double& out) {
  if (text.empty() || text.size() > 64) return false;
  const std::string copy(text);
  char* end = nullptr;
  out = std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size();
}

// "<robot> <rest>" with robot < robots.
bool robotAndRest(std::string_view value, std::size_t robots, std::size_t& robot, std::string_view& rest) {
  const std::size_t gap = value.find(' ');
  if (gap == std::string_view::npos || !number(value.substr(0, gap), robot) || robot >= robots) return false;
  rest = value.substr(gap + 1);
  return true;
}

}  // namespace

std::string wheelLogText(const WheelLog& log, const std::string& secret) {
  std::string text = std::string(kFirstLine) + "\n";
  const auto add = [&](std::string_view key, std::string_view value) { text += std::string(key) + " " + escaped(value) + "\n"; };
  add("rubric", log.rubric);
  add("check", log.check);
  add("world", log.world);
  if (!log.generated.empty()) add("generated", log.generated + " " + std::to_string(log.worldSeed));
  add("seed", std::to_string(log.seed));
  add("submission", log.submission);
  add("submission_sha256", log.submissionHash);
  if (!log.student.empty()) add("student", log.student);
  add("steps", std::to_string(log.wheels.size()));
  add("robots", std::to_string(log.robots));
  add("trajectory", format("%016" PRIx64, log.trajectory));
  for (const auto& [i, why] : log.failures) add("failure", std::to_string(i) + " " + why);
  for (const auto& [i, at] : log.returnedAt) add("returned_at", format("%zu %a", i, at));
  for (const auto& [i, value] : log.returned) add("returned", std::to_string(i) + " " + value);
  text += "wheels\n";
  for (const std::vector<Wheels>& step : log.wheels) {
    for (std::size_t i = 0; i < step.size(); ++i) text += format("%s%a %a", i == 0 ? "" : " ", step[i].forward, step[i].turn);
    text += '\n';
  }
  if (!secret.empty()) text += "hmac " + signature(secret, text) + "\n";
  return text;
}

Result<WheelLog> parseWheelLog(std::string_view body) {
  WheelLog log;
  std::size_t at = 0, steps = 0;
  bool sawSteps = false, sawRobots = false;
  const auto nextLine = [&](std::string_view& line) {
    if (at >= body.size()) return false;
    const std::size_t end = body.find('\n', at);
    if (end == std::string_view::npos) return false;  // every record ends its line
    line = body.substr(at, end - at);
    at = end + 1;
    return true;
  };
  const auto bad = [](std::string_view line) { return Status::failure("the record '" + std::string(line.substr(0, 80)) + "' cannot be read"); };
  std::set<std::pair<std::string, std::size_t>> said;  // one failure, result and time per robot
  std::string_view line;
  if (!nextLine(line) || line != kFirstLine) return Status::failure("its first line is not '" + std::string(kFirstLine) + "'");
  while (nextLine(line) && line != "wheels") {
    const std::size_t space = line.find(' ');
    if (space == std::string_view::npos) return bad(line);
    const std::string_view key = line.substr(0, space);
    const std::optional<std::string> value = unescaped(line.substr(space + 1));
    if (!value) return bad(line);
    const std::string_view v = *value;
    std::size_t robot = 0;
    std::string_view rest;
    bool ok = true;
    if (key == "rubric") {
      log.rubric = v;
    } else if (key == "check") {
      log.check = v;
    } else if (key == "world") {
      log.world = v;
    } else if (key == "submission") {
      log.submission = v;
    } else if (key == "submission_sha256") {
      log.submissionHash = v;
    } else if (key == "student") {
      log.student = v;
    } else if (key == "seed") {
      ok = number(v, log.seed);
    } else if (key == "steps") {
      ok = number(v, steps) && !sawSteps && (sawSteps = true);
    } else if (key == "robots") {
      ok = number(v, log.robots) && log.robots >= 1 && log.robots <= kLogRobots && !sawRobots && (sawRobots = true);
    } else if (key == "trajectory") {
      ok = number(v, log.trajectory, 16);
    } else if (key == "generated") {
      const std::size_t gap = v.find(' ');
      ok = gap != std::string_view::npos && number(v.substr(gap + 1), log.worldSeed);
      if (ok) log.generated = v.substr(0, gap);
    } else if ((key == "failure" || key.starts_with("returned")) &&
               !(sawRobots && robotAndRest(v, log.robots, robot, rest) && said.emplace(key, robot).second)) {
      ok = false;
    } else if (key == "failure") {
      log.failures.emplace_back(robot, rest);
    } else if (key == "returned") {
      log.returned.emplace_back(robot, rest);
    } else if (key == "returned_at") {
      double when = 0.0;
      ok = real(rest, when);
      log.returnedAt.emplace_back(robot, when);
    } else {
      ok = false;
    }
    if (!ok) return bad(line);
  }
  if (line != "wheels" || !sawSteps || !sawRobots) return Status::failure("it ends before its wheels");
  while (log.wheels.size() < steps && nextLine(line)) {
    std::vector<Wheels>& step = log.wheels.emplace_back(log.robots);
    std::size_t from = 0;
    for (Wheels& w : step) {
      for (double* d : {&w.forward, &w.turn}) {
        const std::size_t end = std::min(line.find(' ', from), line.size());
        if (from > line.size() || !real(line.substr(from, end - from), *d)) return bad(line);
        from = end + 1;
      }
    }
    if (from <= line.size()) return bad(line);  // more numbers than robots
  }
  if (log.wheels.size() != steps) return Status::failure("it ends before its last step's wheels");
  if (at != body.size()) return Status::failure("it holds more than its steps");
  return log;
}

Result<WheelLog> readWheelLog(std::string_view text, const std::string& secret) {
  // Only a log signed with the secret is read: anything else could have been edited.
  const std::size_t signedAt = text.rfind("\nhmac ");
  if (signedAt == std::string_view::npos)
    return Status::failure("the log is not signed (graded without the instructor's secret, or cut short), so nothing vouches for it");
  if (secret.empty()) return Status::failure("give the secret it was graded with (--secret FILE or $FROB_GRADE_SECRET) to check its signature");
  const std::string_view body = text.substr(0, signedAt + 1), given = text.substr(signedAt + 6);
  const std::string expected = signature(secret, body) + "\n";
  if (given.size() != expected.size() || CRYPTO_memcmp(given.data(), expected.data(), given.size()) != 0)
    return Status::failure("the log was changed after grading, or signed with another secret: its signature does not match");
  Result<WheelLog> log = parseWheelLog(body);
  if (!log) return Status::failure("not a wheel log of frob grade (" + log.error() + ")");
  return log;
}

std::string submissionHash(const fs::path& submission) {
  std::vector<fs::path> files;
  std::error_code ec;
  if (fs::is_directory(fs::symlink_status(submission, ec))) {
    for (const fs::directory_entry& e : fs::directory_iterator(submission, ec)) {
      const std::string ext = e.path().extension().string();
      if (fs::is_regular_file(e.symlink_status(ec)) && (ext == ".cpp" || ext == ".h" || ext == ".hpp")) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
  } else if (fs::is_regular_file(fs::symlink_status(submission, ec))) {
    files.push_back(submission);
  }
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string head = f.filename().string() + '\0' + std::to_string(text.size()) + '\0';
    EVP_DigestUpdate(ctx, head.data(), head.size());
    EVP_DigestUpdate(ctx, text.data(), text.size());
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx, digest, &length);
  EVP_MD_CTX_free(ctx);
  return hex(digest, length);
}

}  // namespace frob::course
