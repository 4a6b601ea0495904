#pragma once
/// Copies in a class, as a reader of copies finds them: code the same up to renaming, layout and
/// order (token fingerprints, winnowed as in Schleimer, Wilkerson and Aiken's MOSS), and runs that
/// are the same to the last bit in every graded world.
///
///   std::vector<std::uint64_t> f = codeFingerprints(text);   // per student, minus the starter's
///   std::vector<SimilarPair> flagged = similarPairs(students);

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace frob::course {

/// The fingerprints of C++ source `text`, sorted and unique: its tokens with every identifier as one
/// token, every number as one and every string or character as one (comments, layout and
/// preprocessor lines dropped); a hash of each 15 tokens in a row; of each 10 such hashes in a row,
/// the least. Any 24 tokens in a row that two texts share give both a fingerprint in common.
[[nodiscard]] std::vector<std::uint64_t> codeFingerprints(std::string_view text);

/// What similarPairs compares of one student.
struct StudentWork {
  std::string student;
  std::vector<std::uint64_t> fingerprints;  ///< sorted, unique, without the starter's
  std::vector<std::uint64_t> trajectories;  ///< the graded runs' trajectory hashes, in the rubric's order
};

/// Two students whose work is alike.
struct SimilarPair {
  std::string a, b;      ///< the students, a before b
  std::string kind;      ///< "code" or "behaviour"
  double score = 0.0;    ///< 0 to 1: the share of the smaller one's fingerprints, or of the runs, they share
  std::string evidence;  ///< what they share, in words
};

/// The pairs of `students` whose code shares at least half of the smaller one's fingerprints (and at
/// least 8 of them), or whose every graded run (at least two) has the same trajectory as the other's,
/// leaving out trajectories so common in the class (a tenth of it, and at least 3 students) that they
/// are no sign of copying (the starter as handed out, a robot that never moves). Sorted by score.
[[nodiscard]] std::vector<SimilarPair> similarPairs(const std::vector<StudentWork>& students);

}  // namespace frob::course
