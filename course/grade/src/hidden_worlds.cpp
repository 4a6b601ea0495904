// Which worlds a hidden check draws from the secret are fair: the reference solution passes them
// and the starter fails them, found once per rubric, secret, reference, starter and simulation and
// kept in the controller cache.
#include "frob/grade/grade.hpp"
#include "frob/run/format.hpp"
#include "frob/worlds/fnv.hpp"
#include "frob/worlds/simulation.hpp"
#include "runs.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdlib>
#include <fstream>
#include <optional>

namespace frob::course {

namespace fs = std::filesystem;

using namespace detail;

namespace {

// The cache of fairHiddenWorlds: "reference <hash> starter <hash> simulation <fingerprint>", then
// "<draw> <check>" lines.
std::optional<KeptWorlds> readKept(const fs::path& file, const std::string& reference) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line) || (!reference.empty() && line != "reference " + reference)) return std::nullopt;
  KeptWorlds kept;
  while (std::getline(in, line)) {
    const std::size_t gap = line.find(' ');
    if (gap == std::string::npos) return std::nullopt;
    kept[line.substr(gap + 1)].push_back(std::atoi(line.c_str()));
  }
  return kept;
}

void writeKept(const fs::path& file, const std::string& reference, const KeptWorlds& kept) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  const fs::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial);
    out << "reference " << reference << "\n";
    for (const auto& [check, draws] : kept) {
      for (int k : draws) out << k << ' ' << check << "\n";
    }
  }
  fs::rename(partial, file, ec);
}

}  // namespace

fs::path keptWorldsFile(const GradeDef& def) {
  return def.compiler.cacheDir / "hidden-worlds" /
         (format("%016" PRIx64, worlds::Fnv1a().add(std::string_view(fileText(def.rubric.file) + "\n" + def.secret)).value()) + ".txt");
}

Result<KeptWorlds> fairHiddenWorlds(const GradeDef& def) {
  const Rubric& rubric = def.rubric;
  if (def.secret.empty() || rubric.reference.empty() || !rubric.needsSecret()) return KeptWorlds{};
  const fs::path cache = keptWorldsFile(def);
  if (std::error_code ec; !fs::is_regular_file(rubric.reference, ec)) return readKept(cache, "").value_or(KeptWorlds{});
  // Kept for this reference, starter, simulation and generator (each check's first draw stands for
  // it): a change of any may change which draws are fair.
  const auto hashOf = [](const fs::path& file) { return file.empty() ? 0 : worlds::Fnv1a().add(std::string_view(fileText(file))).value(); };
  worlds::Fnv1a generated;
  for (const Check& check : rubric.checks) {
    if (!check.generated || check.generated->secret == 0) continue;
    const Result<worlds::WorldDef> first = worlds::generateWorld(check.generated->kind, drawnWorldSeed(check, def.secret, 0));
    generated.add(std::string_view(first ? worlds::toToml(first.value()) : first.error()));
    generated.add(std::string_view(" pool " + std::to_string(check.generated->poolSize())));
  }
  const std::string reference = format("%016" PRIx64 " starter %016" PRIx64 " simulation %016" PRIx64 " worlds %016" PRIx64, hashOf(rubric.reference),
                                       hashOf(rubric.starter), worlds::simulationFingerprint(), generated.value());
  if (std::optional<KeptWorlds> known = readKept(cache, reference)) return *known;

  std::string messages;
  Result<CompiledController> compiled = compileSubmission(rubric.reference, def.compiler, &messages);
  if (!compiled && isGraderFailure(compiled.status())) return compiled.status();
  if (!compiled)
    return Status::failure("the reference solution " + rubric.reference.string() + " does not compile: " + compiled.error() + "\n" + messages);
  std::optional<CompiledController> starter;
  if (!rubric.starter.empty()) {
    Result<CompiledController> s = compileSubmission(rubric.starter, def.compiler, &messages);
    if (!s && isGraderFailure(s.status())) return s.status();
    if (!s) return Status::failure("the starter " + rubric.starter.string() + " does not compile: " + s.error() + "\n" + messages);
    starter = s.value();
  }
  KeptWorlds kept;
  Grade scratch;         // the reference's runs' notes, unused
  GradeDef quiet = def;  // the reference's runs leave no logs
  quiet.logs.clear();
  for (const Check& check : rubric.checks) {
    if (!check.generated || check.generated->secret == 0 || !check.runsOf.empty()) continue;
    // Judged in the same draws: this check and those that judge its runs.
    std::vector<const Check*> judges;
    for (const Check& c : rubric.checks) {
      if (c.drawName() == check.name) judges.push_back(&c);
    }
    const int wanted = check.generated->poolSize(), tries = 10 * wanted;
    std::vector<int>& mine = kept[check.name];
    for (int k = 0; static_cast<int>(mine.size()) < wanted && k < tries; ++k) {
      const WorldRef ref{.name = "draw " + std::to_string(k), .generated = check.generated->kind, .worldSeed = drawnWorldSeed(check, def.secret, k)};
      const Result<worlds::WorldDef> world = loadWorldRef(ref);
      // Which of the judging checks `controller` passes in every run (each run made once for all).
      const auto passed = [&](const CompiledController& controller) {
        std::vector<bool> all(judges.size(), true);
        for (std::uint64_t seed : seedsOf(check, def.secret)) {
          SharedRuns shared;
          for (const Check* c : judges) ++shared.judges[runKey(*c, ref, seed, rubric.dt)];
          for (std::size_t j = 0; j < judges.size(); ++j) {
            RunGrade r{.world = ref.name, .seed = seed};
            runCheck(quiet, controller, *judges[j], ref, world.value(), r, scratch, &shared);
            all[j] = all[j] && r.passed;
          }
        }
        return all;
      };
      // Fair: the reference passes every check in every run, and the starter (no answer yet) fails
      // each check in one.
      const auto fair = [&] {
        const std::vector<bool> reference = passed(compiled.value());
        if (std::find(reference.begin(), reference.end(), false) != reference.end()) return false;
        if (!starter) return true;
        const std::vector<bool> byStarter = passed(*starter);
        return std::find(byStarter.begin(), byStarter.end(), true) == byStarter.end();
      };
      if (world.ok() && fair()) mine.push_back(k);
      if (!scratch.graderFailure.empty()) return Status::failure(scratch.graderFailure);
    }
    if (static_cast<int>(mine.size()) < wanted) {
      return Status::failure("only " + std::to_string(mine.size()) + " of the " + std::to_string(tries) + " worlds drawn for check '" + check.name +
                             "' from this secret let the reference solution pass" + (starter ? " and the starter fail" : "") +
                             ": choose another secret");
    }
  }
  writeKept(cache, reference, kept);
  return kept;
}

}  // namespace frob::course
