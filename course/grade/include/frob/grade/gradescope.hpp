#pragma once
/// Gradescope's autograder zip for an assignment: setup.sh builds frob on Gradescope's image,
/// proves the build by grading the reference solution, run_autograder grades /autograder/submission
/// into /autograder/results/results.json.

#include "frob/base/result.hpp"

#include <filesystem>
#include <string>

namespace frob::course {

/// What goes into the zip.
struct GradescopeZipDef {
  std::filesystem::path rubric;      ///< the assignment's rubric.toml; its whole folder goes in
  std::string assignment;            ///< the assignment's name (its folder under assignments/ in the zip)
  std::string secret;                ///< the instructor's secret for hidden seeds, kept in the zip (which only staff see); "" for none
  std::filesystem::path reference;   ///< the rubric's reference solution: only for setup.sh, which removes it
  std::filesystem::path keptWorlds;  ///< the hidden worlds the reference passes (keptWorldsFile), shipped in the autograder's cache; empty: none
};

/// Writes the zip: frob's sources (without tests), the assignment without its reference solution,
/// which goes apart for setup.sh alone, the hidden worlds found fair for the secret, setup.sh and
/// run_autograder.
[[nodiscard]] Status writeGradescopeZip(const GradescopeZipDef& def, const std::filesystem::path& out);

}  // namespace frob::course
