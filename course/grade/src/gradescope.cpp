#include "frob/grade/gradescope.hpp"

#include "frob/base/layout.hpp"
#include "frob/render/output_file.hpp"
#include "writers.hpp"

#include <zip.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>

namespace frob::course {

namespace fs = std::filesystem;

namespace {

// Gradescope runs it once on its base image, Ubuntu 22.04 unless the course chose another. It
// assumes apt-get and Debian's or Ubuntu's package names; it takes the newest clang from 15 up
// (GCC 12 and older clangs mishandle coroutines, see README). Nothing here can run Ubuntu, so it
// proves itself: the reference solution, shipped for this alone, must get full marks.
constexpr const char* kSetup = R"sh(#!/usr/bin/env bash
# Builds frob for the autograder (Gradescope runs this once, as root, on its base image), then
# grades the reference solution: a build that does not give it full marks fails here, with the reason.
set -euo pipefail
cd /autograder/source
scratch=$(mktemp -d)
trap 'rm -rf reference "$scratch"' EXIT  # no submission may read the reference solution
apt-get update -qq
# The newest clang from 15 up among the system's packages (Ubuntu 22.04: 15, Debian 12: 16, Debian 13: 19).
clang=
for version in $(seq 40 -1 15); do
  if apt-cache show "clang-$version" > /dev/null 2>&1; then clang=$version && break; fi
done
if [ -z "$clang" ]; then
  echo "setup.sh: this system's packages hold no clang from 15 up, which frob needs (GCC and older clangs mishandle coroutines)" >&2
  exit 1
fi
echo "setup.sh: building frob with clang-$clang"
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  cmake ninja-build pkg-config "clang-$clang" libeigen3-dev libbox2d-dev libassimp-dev libosmesa6-dev libpng-dev \
  libfreetype-dev fonts-dejavu-core libavcodec-dev libavformat-dev libavutil-dev libswscale-dev \
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libseccomp-dev libzip-dev libssl-dev zlib1g-dev
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER="clang-$clang" -DCMAKE_CXX_COMPILER="clang++-$clang" \
  -DFROB_BUILD_TESTS=OFF
cmake --build build --target frob_app  # frob, its sandbox and host: what grading runs (not the examples)
if [ -z "$(ls reference 2> /dev/null)" ]; then
  echo "setup.sh: the rubric names no reference solution: nothing proves that this build grades" >&2
  exit 0
fi
if [ -d cache ]; then cp -r cache/. "$scratch/"; fi  # the fair hidden worlds
if [ -f secret.txt ]; then export FROB_GRADE_SECRET="$(head -n 1 secret.txt)"; fi
FROB=build/app/frob FROB_CACHE_DIR="$scratch" bash course/autograder/check_reference.sh assignments/ASSIGNMENT reference/*
)sh";

// Gradescope runs it for each submission; the script it calls finds the controller (PrairieLearn's
// entrypoint calls it too). FROB_AUTOGRADER_ROOT and FROB let a test run it on a fake /autograder
// tree with a frob built elsewhere.
constexpr const char* kRun = R"sh(#!/usr/bin/env bash
# Grades the submission into results/results.json, Gradescope's layout.
set -u
root="${FROB_AUTOGRADER_ROOT:-/autograder}"
export FROB="${FROB:-$root/source/build/app/frob}"
export FROB_CACHE_DIR="$root/cache"
if [ -d "$root/source/cache" ]; then mkdir -p "$root/cache" && cp -r "$root/source/cache/." "$root/cache/"; fi  # the fair hidden worlds
if [ -f "$root/source/secret.txt" ]; then export FROB_GRADE_SECRET="$(head -n 1 "$root/source/secret.txt")"; fi
late=()  # when the rubric takes points for lateness, Gradescope's times say how late
if [ -f "$root/submission_metadata.json" ]; then late=(--submission-metadata "$root/submission_metadata.json"); fi
exec bash "$root/source/course/autograder/grade_submission.sh" gradescope "$root/source/assignments/ASSIGNMENT" "$root/submission" \
  "$root/results/results.json" "${late[@]}"
)sh";

// What of frob's sources the autograder builds from: everything but tests, builds and the other assignments.
bool wanted(const fs::path& relative) {
  const std::string top = relative.begin()->string();
  static const char* kept[] = {"frob", "worlds", "render", "course", "app", "cmake", "CMakeLists.txt", "LICENSE", "README.md"};
  return std::find(std::begin(kept), std::end(kept), top) != std::end(kept);
}

class Zip {
 public:
  explicit Zip(const std::string& path) {
    int error = 0;
    zip_ = ::zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  }
  ~Zip() {
    if (zip_ != nullptr) ::zip_discard(zip_);
  }
  [[nodiscard]] bool ok() const { return zip_ != nullptr; }
  bool addText(const std::string& name, const std::string& text, bool executable) {
    zip_source_t* src = ::zip_source_buffer(zip_, copy(text), text.size(), 1);
    return add(name, src, executable);
  }
  bool addFile(const std::string& name, const fs::path& file) { return add(name, ::zip_source_file(zip_, file.c_str(), 0, -1), false); }
  // Writes the archive; false with the reason in `error`.
  bool close(std::string& error) {
    if (::zip_close(zip_) == 0) return zip_ = nullptr, true;
    error = ::zip_strerror(zip_);
    return false;
  }

 private:
  static void* copy(const std::string& text) {
    void* p = std::malloc(text.size());
    std::memcpy(p, text.data(), text.size());
    return p;
  }
  bool add(const std::string& name, zip_source_t* src, bool executable) {
    if (src == nullptr) return false;
    const zip_int64_t at = ::zip_file_add(zip_, name.c_str(), src, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8);
    if (at < 0) return ::zip_source_free(src), false;
    const zip_uint32_t mode = (executable ? 0100755u : 0100644u) << 16;  // Unix permissions in the high bits
    return ::zip_file_set_external_attributes(zip_, static_cast<zip_uint64_t>(at), 0, ZIP_OPSYS_UNIX, mode) == 0;
  }
  zip_t* zip_ = nullptr;
};

}  // namespace

Status writeGradescopeZip(const GradescopeZipDef& def, const fs::path& out) {
  const fs::path source = layout().sourceTree;
  if (source.empty())
    return Status::failure("the Gradescope autograder is built from Frob Sandbox's source tree, and this frob is installed without one");
  if (Status s = render::checkWritable(out.string(), "zip"); !s) return s;
  const std::string partial = render::partialPath(out.string());
  Zip zip(partial);
  if (!zip.ok()) return Status::failure(out.string() + ": cannot write the zip");
  std::string setup = kSetup, run = kRun;
  setup.replace(setup.find("ASSIGNMENT"), 10, def.assignment);
  run.replace(run.find("ASSIGNMENT"), 10, def.assignment);
  bool ok = zip.addText("setup.sh", setup, true) && zip.addText("run_autograder", run, true);
  // The reference solution, which setup.sh grades and then removes: never among the assignment's files.
  if (!def.reference.empty() && fs::is_regular_file(def.reference))
    ok = ok && zip.addFile("reference/" + def.reference.filename().string(), def.reference);
  if (!def.secret.empty()) ok = ok && zip.addText("secret.txt", def.secret + "\n", false);
  if (!def.keptWorlds.empty() && fs::is_regular_file(def.keptWorlds)) {
    ok = ok && zip.addFile("cache/hidden-worlds/" + def.keptWorlds.filename().string(), def.keptWorlds);
  }
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(source, ec); ok && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path relative = fs::relative(it->path(), source);
    if (it->is_directory() && !wanted(relative)) it.disable_recursion_pending();
    if (it->is_regular_file() && wanted(relative)) ok = zip.addFile(relative.generic_string(), it->path());
  }
  const fs::path assignment = def.rubric.parent_path();
  for (auto it = fs::recursive_directory_iterator(assignment, ec); ok && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const bool reference = !def.reference.empty() && fs::equivalent(it->path(), def.reference, ec);
    if (it->is_regular_file() && !reference)
      ok = zip.addFile("assignments/" + def.assignment + "/" + fs::relative(it->path(), assignment).generic_string(), it->path());
  }
  std::string error;
  if (!ok || !zip.close(error)) {
    fs::remove(partial, ec);
    return Status::failure(out.string() + ": cannot write the zip" + (error.empty() ? "" : ": " + error));
  }
  return render::commitPartial(out.string(), "zip");
}

namespace {

// Seconds since 1970 of an ISO 8601 time with its offset ("2026-12-05T23:59:00.123456-08:00", or "Z"),
// by the days-from-civil count (Howard Hinnant's), so that no time zone of this machine plays a part.
std::optional<double> isoSeconds(const std::string& text) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, used = 0;
  double sec = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%n", &y, &mo, &d, &h, &mi, &sec, &used) != 6) return std::nullopt;
  if (mo < 1 || mo > 12 || d < 1 || d > 31 || h > 23 || mi > 59 || sec < 0 || sec >= 61) return std::nullopt;
  const std::string zone = text.substr(static_cast<std::size_t>(used));
  int zh = 0, zm = 0;
  char sign = '+';
  if (zone != "Z" && (std::sscanf(zone.c_str(), "%c%2d:%2d", &sign, &zh, &zm) != 3 || (sign != '+' && sign != '-'))) return std::nullopt;
  const int yy = y - (mo <= 2 ? 1 : 0);
  const int era = (yy >= 0 ? yy : yy - 399) / 400;
  const int yoe = yy - era * 400, doy = (153 * (mo + (mo > 2 ? -3 : 9)) + 2) / 5 + d - 1, doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  const double days = static_cast<double>(era) * 146097 + doe - 719468;
  const double offset = (sign == '-' ? -1 : 1) * (zh * 3600.0 + zm * 60.0);
  return days * 86400 + h * 3600.0 + mi * 60.0 + sec - offset;
}

}  // namespace

Result<double> submissionLateness(const fs::path& metadata) {
  Result<std::string> text = detail::readWhole(metadata, "submission metadata");
  if (!text) return text.status();
  const detail::Json doc = detail::Json::parse(text.value(), nullptr, false);
  const auto field = [&](const detail::Json& j, const char* key) -> std::string {
    return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
  };
  if (doc.is_discarded() || !doc.is_object()) return Status::failure(metadata.string() + ": not JSON (Gradescope's submission_metadata.json)");
  const std::string created = field(doc, "created_at"), due = field(doc.value("assignment", detail::Json()), "due_date");
  const std::optional<double> at = isoSeconds(created), by = isoSeconds(due);
  if (!at) return Status::failure(metadata.string() + ": created_at: not an ISO 8601 time with its offset: '" + created + "'");
  if (!by) return Status::failure(metadata.string() + ": assignment.due_date: not an ISO 8601 time with its offset: '" + due + "'");
  return (*at - *by) / 86400.0;
}

}  // namespace frob::course
