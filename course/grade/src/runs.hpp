#pragma once
// One run of a check, made and judged (grade.cpp): what grading and the check of the hidden worlds
// (hidden_worlds.cpp) share.

#include "frob/grade/grade.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace frob::course::detail {

/// What a run made: the grader's record of it, and the wheels applied at every step (when kept).
struct Ran {
  RunRecord record;
  std::vector<std::string> hints;
  std::vector<std::vector<Wheels>> wheels;
  std::uint64_t trajectoryHash = 0;
};

/// What makes a run of a grading: its world (a generated kind and seed, or a file), its seed, its
/// steps and its hints' kind. Checks that name the same world and seeds for as long judge one run
/// each (bit-identical runs).
using RunKey = std::tuple<std::string, std::uint64_t, std::uint64_t, std::int64_t, bool>;
[[nodiscard]] RunKey runKey(const Check& check, const WorldRef& ref, std::uint64_t seed, double dt);

/// The runs of a grading that more than one check judges: how many checks are still to judge each,
/// and those made and still to be judged again.
struct SharedRuns {
  std::map<RunKey, int> judges;
  std::map<RunKey, Ran> made;
};

/// Run `r` (its world and seed set) of `check` by the compiled controller, judged; the host's notes
/// and the sandbox's missing layers added to `g`. With `shared`, a run made for another check is
/// judged again instead of made twice.
void runCheck(const GradeDef& def, const CompiledController& compiled, const Check& check, const WorldRef& ref, const worlds::WorldDef& world,
              RunGrade& r, Grade& g, SharedRuns* shared = nullptr);

/// The hidden worlds `def` grades in: its own, none for the visible checks alone, else fairHiddenWorlds().
[[nodiscard]] Result<KeptWorlds> hiddenWorldsOf(const GradeDef& def);
/// grade(), in the hidden worlds `kept` (hiddenWorldsOf(): a class checks them once for all its grades).
[[nodiscard]] Grade gradeWith(const GradeDef& def, const std::filesystem::path& submission, const Result<KeptWorlds>& kept);

/// A file's bytes; empty when it cannot be read.
[[nodiscard]] std::string fileText(const std::filesystem::path& file);

}  // namespace frob::course::detail
