// One self-contained HTML page of the grade, with its media embedded.

#include "frob/grade/grade_report.hpp"
#include "frob/run/format.hpp"
#include "markup.hpp"
#include "writers.hpp"

namespace frob::course {

using namespace detail;

Status writeHtmlReport(const Grade& g, const HtmlMedia& media, const std::filesystem::path& path) {
  // The media first: a missing or wrong file is reported before anything is written.
  std::string video, plot;
  if (!media.video.empty()) {
    Result<std::string> bytes = readWhole(media.video, "html report");
    if (!bytes) return bytes.status();
    if (bytes.value().size() < 12 || bytes.value().compare(4, 4, "ftyp") != 0) {
      return Status::failure("html report: '" + media.video.string() + "' is not an MP4 video (it has no ftyp box)");
    }
    video = base64(bytes.value());
  }
  if (!media.plot.empty()) {
    Result<std::string> bytes = readWhole(media.plot, "html report");
    if (!bytes) return bytes.status();
    if (bytes.value().compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) {
      return Status::failure("html report: '" + media.plot.string() + "' is not a PNG image");
    }
    plot = base64(bytes.value());
  }

  // The run viewer's page keeps its own policy; the frame inherits this page's, which must let
  // exactly the viewer's script run too (named by the hash in the viewer's policy).
  std::string viewer, viewerScript;
  if (!media.viewer.empty()) {
    Result<std::string> page = readWhole(media.viewer, "html report");
    if (!page) return page.status();
    const std::size_t at = page.value().find("script-src 'sha256-"), end = page.value().find('\'', at + 19);
    if (page.value().compare(0, 15, "<!DOCTYPE html>") != 0 || at == std::string::npos || end == std::string::npos) {
      return Status::failure("html report: '" + media.viewer.string() + "' is not a run viewer page (frob run --html)");
    }
    viewerScript = page.value().substr(at + 11, end + 1 - (at + 11));
    // The instant to open at, on the page's body (outside its script, so its hash holds).
    if (const std::size_t body = page.value().find("<body>"); media.openAt && body != std::string::npos) {
      page.value().replace(body, 6, format("<body data-open-at=\"%.3f\">", *media.openAt));
    }
    viewer = markupEscape(page.value(), true);
  }

  const std::string title = markupEscape(g.assignment + ": " + g.submission);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      // Nothing from elsewhere and no script but the viewer's, even if something slipped past the escaping.
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; media-src data:; "
      "style-src 'unsafe-inline'" +
      (viewerScript.empty() ? std::string() : "; script-src " + viewerScript) +
      "\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>" +
      title +
      "</title>\n"
      "<style>\n"
      "body { font-family: sans-serif; margin: 1.5em; color: #222; }\n"
      "table { border-collapse: collapse; }\n"
      "th, td { border: 1px solid #bbb; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }\n"
      "td.num { text-align: right; font-variant-numeric: tabular-nums; }\n"
      "tr.PASS td.status { color: #146c2e; } tr.FAIL td.status { color: #b3261e; } tr.PARTIAL td.status { color: #8a5a00; }\n"
      ".visibility { color: #666; font-size: 0.85em; }\n"
      "pre { background: #f4f4f4; padding: 0.8em; overflow-x: auto; }\n"
      "figure { margin: 1.5em 0; } video, img { display: block; max-width: 100%; margin-bottom: 0.5em; }\n"
      "iframe.viewer { display: block; width: 100%; height: 90vh; border: 1px solid #bbb; margin-bottom: 0.5em; }\n"
      "</style>\n</head>\n<body>\n";
  html += "<h1>" + title + "</h1>\n";
  html += "<p class=\"total\">Total: <strong>" + number(g.score()) + " / " + number(g.maxScore()) + "</strong> points</p>\n";
  html += "<table>\n<thead><tr><th>Check</th><th>Score</th><th>Points</th><th>Status</th><th>Reasons</th></tr></thead>\n<tbody>\n";
  for (const CheckGrade& c : g.checks) {
    const char* status = toString(outcomeOf(c));
    html += "<tr class=\"" + std::string(status) + "\"><td>" + markupEscape(c.name);
    if (c.visibility != Visibility::Visible) {
      html += " <span class=\"visibility\">(" + std::string(course::toString(c.visibility)) + ")</span>";
    }
    html += "</td><td class=\"num\">" + number(c.score) + "</td><td class=\"num\">" + number(c.points) + "</td><td class=\"status\">" + status +
            "</td><td>";
    const std::vector<std::string> reasons = linesOf(c.output());
    for (std::size_t i = 0; i < reasons.size(); ++i) html += (i > 0 ? "<br>" : "") + markupEscape(reasons[i]);
    html += "</td></tr>\n";
  }
  html += "</tbody>\n</table>\n";
  if (!g.compileError.empty()) {
    html += "<h2>The submission did not compile</h2>\n<pre class=\"compile-error\">" + markupEscape(g.compileError) + "</pre>\n";
  }
  if (!g.notes.empty()) {
    html += "<h2>Notes</h2>\n<ul class=\"notes\">\n";
    for (const std::string& note : g.notes) html += "<li>" + markupEscape(note) + "</li>\n";
    html += "</ul>\n";
  }
  if (!video.empty() || !plot.empty() || !viewer.empty()) {
    html += "<figure>\n";
    // Scripts only, in an opaque origin: the viewer can reach neither this page nor anything else.
    if (!viewer.empty())
      html += "<iframe class=\"viewer\" sandbox=\"allow-scripts\" title=\"the run, to step through\" srcdoc=\"" + viewer + "\"></iframe>\n";
    if (!video.empty()) html += "<video controls src=\"data:video/mp4;base64," + video + "\"></video>\n";
    if (!plot.empty()) html += "<img src=\"data:image/png;base64," + plot + "\" alt=\"plot of the run\">\n";
    if (!media.caption.empty()) html += "<figcaption>" + markupEscape(media.caption) + "</figcaption>\n";
    html += "</figure>\n";
  }
  html += "</body>\n</html>\n";
  return writeWhole(path, "html report", html);
}

}  // namespace frob::course
