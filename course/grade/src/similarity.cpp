// Copies in a class: winnowed token fingerprints of the code, and trajectories of the runs.
#include "frob/grade/similarity.hpp"

#include "frob/worlds/fnv.hpp"

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <set>

namespace frob::course {

namespace {

constexpr std::size_t kGram = 15;    // tokens hashed together
constexpr std::size_t kWindow = 10;  // hashes a fingerprint is chosen from
constexpr double kFlagShare = 0.5;   // of the smaller one's fingerprints
constexpr std::size_t kFlagCount = 8;

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// C++'s keywords stay themselves: they are the code's shape; every other name is one token.
bool isKeyword(std::string_view word) {
  static const std::set<std::string_view> keywords{
      "auto",      "bool",     "break",    "case",   "catch",   "char",      "class",  "co_await", "co_return", "co_yield", "const",
      "constexpr", "continue", "default",  "delete", "do",      "double",    "else",   "enum",     "false",     "float",    "for",
      "if",        "inline",   "int",      "long",   "mutable", "namespace", "new",    "nullptr",  "operator",  "private",  "public",
      "return",    "short",    "signed",   "sizeof", "static",  "struct",    "switch", "template", "this",      "throw",    "true",
      "try",       "typename", "unsigned", "using",  "virtual", "void",      "while"};
  return keywords.contains(word);
}

// The tokens of `text`, each as a small hash.
std::vector<std::uint64_t> tokensOf(std::string_view text) {
  std::vector<std::uint64_t> tokens;
  const auto add = [&](std::string_view token) { tokens.push_back(worlds::Fnv1a().add(token).value()); };
  std::size_t i = 0;
  bool lineStart = true;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      lineStart = true, ++i;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      ++i;
      continue;
    }
    if (lineStart && c == '#') {  // a preprocessor line (and its continuations)
      while (i < text.size() && !(text[i] == '\n' && text[i - 1] != '\\')) ++i;
      continue;
    }
    lineStart = false;
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 2;
    } else if (c == '"' || c == '\'') {
      for (++i; i < text.size() && text[i] != c && text[i] != '\n'; ++i) {
        if (text[i] == '\\') ++i;
      }
      ++i;
      add(c == '"' ? "\"s\"" : "'c'");
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0 ||
               (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0)) {
      while (i < text.size() && (identifierChar(text[i]) || text[i] == '.' || text[i] == '\'' ||
                                 ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E')))) {
        ++i;
      }
      add("0");
    } else if (identifierChar(c)) {
      const std::size_t start = i;
      while (i < text.size() && identifierChar(text[i])) ++i;
      const std::string_view word = text.substr(start, i - start);
      add(isKeyword(word) ? word : "x");
    } else {
      add(text.substr(i++, 1));
    }
  }
  return tokens;
}

}  // namespace

std::vector<std::uint64_t> codeFingerprints(std::string_view text) {
  const std::vector<std::uint64_t> tokens = tokensOf(text);
  std::vector<std::uint64_t> grams;
  for (std::size_t k = 0; k + kGram <= tokens.size(); ++k) {
    worlds::Fnv1a h;
    for (std::size_t j = k; j < k + kGram; ++j) h.add(tokens[j]);
    grams.push_back(h.value());
  }
  std::vector<std::uint64_t> chosen;
  if (!grams.empty() && grams.size() < kWindow) chosen.push_back(*std::min_element(grams.begin(), grams.end()));
  for (std::size_t k = 0; k + kWindow <= grams.size(); ++k) chosen.push_back(*std::min_element(grams.begin() + k, grams.begin() + k + kWindow));
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
  return chosen;
}

std::vector<SimilarPair> similarPairs(const std::vector<StudentWork>& students) {
  // Trajectories so common that sharing one says nothing.
  std::map<std::uint64_t, std::size_t> holders;
  for (const StudentWork& s : students) {
    for (std::uint64_t t : std::set<std::uint64_t>(s.trajectories.begin(), s.trajectories.end())) ++holders[t];
  }
  const std::size_t common = std::max<std::size_t>(3, students.size() / 10);
  std::vector<SimilarPair> pairs;
  char text[160];
  for (std::size_t i = 0; i < students.size(); ++i) {
    for (std::size_t j = i + 1; j < students.size(); ++j) {
      const StudentWork &a = students[i], &b = students[j];
      std::vector<std::uint64_t> shared;
      std::set_intersection(a.fingerprints.begin(), a.fingerprints.end(), b.fingerprints.begin(), b.fingerprints.end(), std::back_inserter(shared));
      const std::size_t smaller = std::min(a.fingerprints.size(), b.fingerprints.size());
      const double share = smaller == 0 ? 0.0 : static_cast<double>(shared.size()) / static_cast<double>(smaller);
      const auto& [first, second] = std::minmax(a.student, b.student);
      if (shared.size() >= kFlagCount && share >= kFlagShare) {
        std::snprintf(text, sizeof text, "%zu of %zu fingerprints of the smaller shared (the same code up to names, layout and order)", shared.size(),
                      smaller);
        pairs.push_back({first, second, "code", share, text});
      }
      std::size_t same = 0;
      const std::size_t runs = std::min(a.trajectories.size(), b.trajectories.size());
      for (std::size_t k = 0; k < runs; ++k) same += a.trajectories[k] == b.trajectories[k] && holders[a.trajectories[k]] < common ? 1 : 0;
      if (runs >= 2 && same == runs && a.trajectories.size() == b.trajectories.size()) {
        std::snprintf(text, sizeof text, "the same trajectory, to the last bit, in all %zu graded runs", runs);
        pairs.push_back({first, second, "behaviour", 1.0, text});
      }
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const SimilarPair& x, const SimilarPair& y) { return x.score > y.score; });
  return pairs;
}

}  // namespace frob::course
