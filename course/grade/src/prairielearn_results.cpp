// PrairieLearn's external grader results.json, as its documentation says
// (https://prairielearn.readthedocs.io/en/latest/externalGrading/#grading-results): "score" in [0, 1];
// "gradable": false for a submission that could not be compiled (no attempt is used up) with
// "format_errors"; a test's "images" are {label, url} with data: URLs; the file must stay under 1 MB.

#include "frob/grade/grade_report.hpp"
#include "markup.hpp"
#include "writers.hpp"

#include <algorithm>

namespace frob::course {

using namespace detail;

namespace {

// `text` cut to at most `limit` bytes (at a character boundary), saying how much was cut.
std::string clip(const std::string& text, std::size_t limit) {
  if (text.size() <= limit) return text;
  std::size_t end = limit;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end) + "\n[... " + std::to_string(text.size() - end) + " more bytes cut]\n";
}

// The images of check `name`, as data: URLs; an image that cannot be read is left out.
Json imagesOf(const std::string& name, const std::vector<CheckImage>& images) {
  Json list = Json::array();
  for (const CheckImage& i : images) {
    if (i.check != name) continue;
    if (Result<std::string> png = readWhole(i.png, "image"))
      list.push_back(Json{{"label", i.label}, {"url", "data:image/png;base64," + base64(png.value())}});
  }
  return list;
}

Json prairieLearnResults(const Grade& g, std::size_t limit, const std::vector<CheckImage>& images) {
  Json doc;
  const bool gradable = g.compileError.empty();
  const double max = g.maxScore();
  double fraction = 0.0;
  if (gradable && max > 0.0) {
    fraction = std::clamp(g.score() / max, 0.0, 1.0);
  } else if (gradable) {  // nothing to earn: all or nothing on the checks' outcomes
    fraction = std::all_of(g.checks.begin(), g.checks.end(), [](const CheckGrade& c) { return outcomeOf(c) == Outcome::Pass; }) ? 1.0 : 0.0;
  }
  doc["gradable"] = gradable;
  doc["score"] = fraction;
  std::string notes;
  for (const std::string& note : g.notes) notes += "Note: " + note + "\n";
  if (!gradable) {
    doc["message"] = "The submission did not compile; it was not graded and no attempt was used up.";
    doc["output"] = clip(g.compileError, limit) + notes;
    doc["format_errors"] = clip(g.compileError, limit);
    doc["tests"] = Json::array();
    return doc;
  }
  doc["message"] = clip(summaryOf(g), limit);
  doc["output"] = notes;
  // PrairieLearn shows every test to the student: checks that are not visible are summed into one.
  Json tests = Json::array();
  double hiddenPoints = 0.0, hiddenMax = 0.0;
  std::size_t hidden = 0;
  for (const CheckGrade& c : g.checks) {
    if (c.visibility != Visibility::Visible) {
      ++hidden;
      hiddenPoints += c.score;
      hiddenMax += c.points;
      continue;
    }
    Json t;
    t["name"] = c.name;
    t["points"] = rounded(c.score);
    t["max_points"] = rounded(c.points);
    t["output"] = clip(c.output(), limit);
    t["message"] = c.runs.empty() ? std::string("not run") : std::to_string(passedRuns(c)) + " of " + std::to_string(c.runs.size()) + " runs passed";
    if (Json shown = imagesOf(c.name, images); !shown.empty()) t["images"] = std::move(shown);
    tests.push_back(std::move(t));
  }
  if (hidden > 0) {
    Json t;
    t["name"] = "Hidden checks";
    t["points"] = rounded(hiddenPoints);
    t["max_points"] = rounded(hiddenMax);
    t["output"] = "";
    t["message"] = std::to_string(hidden) + (hidden == 1 ? " check whose result is" : " checks whose results are") + " not shown";
    tests.push_back(std::move(t));
  }
  doc["tests"] = std::move(tests);
  return doc;
}

}  // namespace

Status writePrairieLearn(const Grade& g, const std::filesystem::path& path, const std::vector<CheckImage>& images) {
  // PrairieLearn rejects results over 1 MB: the images go first, then long texts are cut until the file fits.
  constexpr std::size_t kMaxBytes = 1'000'000;
  std::size_t limit = kMaxBytes;
  std::string text = jsonText(prairieLearnResults(g, limit, images));
  if (text.size() > kMaxBytes) text = jsonText(prairieLearnResults(g, limit, {}));
  while (text.size() > kMaxBytes && limit > 1000) {
    limit /= 2;
    text = jsonText(prairieLearnResults(g, limit, {}));
  }
  if (text.size() > kMaxBytes) {
    return Status::failure("prairielearn results: cannot write '" + path.string() + "': the results take " + std::to_string(text.size()) +
                           " bytes, more than PrairieLearn's 1 MB");
  }
  return writeWhole(path, "prairielearn results", text);
}

}  // namespace frob::course
