// The HTML report: as written (self-contained, escaped, its media inline), and as Debian's headless
// Chromium renders it (a screenshot, its DOM, and the video's state once the page has loaded).
#include "../../support/chromium.hpp"
#include "frob/frob.hpp"
#include "frob/grade/grade_report.hpp"
#include "frob/render/image.hpp"
#include "frob/render/video.hpp"
#include "frob/run/session.hpp"
#include "frob/worlds/world_file.hpp"
#include "grade_samples.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace frob::course {
namespace {

namespace fs = std::filesystem;
using namespace frob::course::testing;
using nlohmann::json;
using support::chromium, support::Ran, support::requireChromium;

// ---- The HTML report, as written ----------------------------------------------------------------

// A grade whose failed run has a hostile reason, with a short MP4 and a PNG plot of distinct colours.
struct Report {
  fs::path dir, html, video, plot;
  Grade grade;
};

constexpr std::uint8_t kVideoColour[3] = {220, 40, 200};  // magenta
constexpr std::uint8_t kPlotColour[3] = {40, 200, 220};   // cyan
constexpr int kVideoW = 160, kVideoH = 96, kVideoFrames = 15, kFps = 30;
constexpr int kPlotW = 120, kPlotH = 80;

render::Image solid(int w, int h, const std::uint8_t (&rgb)[3]) {
  render::Image img{.width = w, .height = h, .rgba = {}};
  for (int i = 0; i < w * h; ++i) img.rgba.insert(img.rgba.end(), {rgb[0], rgb[1], rgb[2], 255});
  return img;
}

Report writeReport(const std::string& name) {
  Report r{.dir = scratch(name), .html = {}, .video = {}, .plot = {}, .grade = sample()};
  r.html = r.dir / "report.html";
  r.video = r.dir / "run.mp4";
  r.plot = r.dir / "plot.png";
  r.grade.checks[1].runs[0].reason = kHostile;
  // Encoded as a report's film is (a capped bitrate, x264's veryfast: High profile, B-frames).
  Result<render::VideoWriter> v = render::VideoWriter::open(
      {.path = r.video.string(), .width = kVideoW, .height = kVideoH, .fps = kFps, .preset = "veryfast", .maxKilobitsPerSecond = 120});
  EXPECT_TRUE(v.ok()) << v.error();
  for (int i = 0; i < kVideoFrames && v.ok(); ++i) EXPECT_TRUE(v.value().write(solid(kVideoW, kVideoH, kVideoColour)).ok());
  if (v.ok()) EXPECT_TRUE(v.value().close().ok());
  EXPECT_TRUE(render::writePng(r.plot.string(), solid(kPlotW, kPlotH, kPlotColour)).ok());
  const Status s = writeHtmlReport(r.grade, {.video = r.video, .plot = r.plot, .caption = "the first failing run: maze, seed 3 <&>"}, r.html);
  EXPECT_TRUE(s.ok()) << s.error();
  return r;
}

// A run viewer page of a short run whose task is named with markup, as the report's film has.
fs::path writeViewer(const fs::path& dir) {
  const fs::path page = dir / "film.html";
  const worlds::WorldDef world = *worlds::parseWorld("size = [4.0, 3.0]\n[[robot]]\nname = \"r\"\nstart = [1.0, 1.5]\n", "w.toml");
  const Controller drive = makeController([] {
    return mkTask([](const TaskState&) { return std::pair{wheels(0.3, 0.2), after(2.0)}; }).named("drive \"</iframe><script>alert(1)</script>");
  });
  const Result<Summary> s = runSession({.world = world,
                                        .worldName = "w",
                                        .controllers = {{.entry = {.name = "inline", .make = drive}, .source = "film.cpp"}},
                                        .seconds = 3,
                                        .outputs = {.html = page.string()}});
  EXPECT_TRUE(s.ok()) << s.error();
  return page;
}

TEST(HtmlReport, SelfContainedAndEscaped) {
  const Report r = writeReport("html_text");
  const std::string page = readFile(r.html);
  EXPECT_NE(page.find("bumped &lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;double&quot; &#39;single&#39; \xEF\xBF\xBD here"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("http:"), std::string::npos);
  EXPECT_EQ(page.find("https:"), std::string::npos);
  // Every src is a data: URI (no file, no protocol-relative URL); CSS loads nothing either.
  std::size_t srcs = 0;
  for (std::size_t at = page.find("src=\""); at != std::string::npos; at = page.find("src=\"", at + 1)) {
    ++srcs;
    EXPECT_EQ(page.compare(at, 10, "src=\"data:"), 0) << page.substr(at, 40);
  }
  EXPECT_EQ(srcs, 2u);
  EXPECT_EQ(page.find("url("), std::string::npos);
  EXPECT_EQ(page.find("@import"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find('\x01'), std::string::npos);
  EXPECT_NE(page.find("<video controls src=\"data:video/mp4;base64,"), std::string::npos);
  EXPECT_NE(page.find("<img src=\"data:image/png;base64,"), std::string::npos);
  EXPECT_NE(page.find("<figcaption>the first failing run: maze, seed 3 &lt;&amp;&gt;</figcaption>"), std::string::npos);
  EXPECT_EQ(filesIn(r.dir), (std::vector<std::string>{"plot.png", "report.html", "run.mp4"}));
}

TEST(HtmlReport, CompileErrorInPreAndNoMedia) {
  const fs::path dir = scratch("html_compile");
  ASSERT_TRUE(writeHtmlReport(uncompiled("bob.cpp:3:1: error: expected '>' in <vector<int>\n"), {}, dir / "r.html").ok());
  const std::string page = readFile(dir / "r.html");
  EXPECT_NE(page.find("<pre class=\"compile-error\">bob.cpp:3:1: error: expected &#39;&gt;&#39; in &lt;vector&lt;int&gt;\n</pre>"),
            std::string::npos);
  EXPECT_EQ(page.find("<figure>"), std::string::npos);
}

TEST(HtmlReport, Base64OfEveryLength) {
  const fs::path dir = scratch("html_base64");
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "iVBORw0KGgo="}, {"a", "iVBORw0KGgph"}, {"ab", "iVBORw0KGgphYg=="}, {"abc", "iVBORw0KGgphYmM="}};
  for (const auto& [tail, encoded] : cases) {
    writeFile(dir / "p.png", signature + tail);
    ASSERT_TRUE(writeHtmlReport(sample(), {.plot = dir / "p.png"}, dir / "r.html").ok());
    EXPECT_NE(readFile(dir / "r.html").find("src=\"data:image/png;base64," + encoded + "\""), std::string::npos) << tail;
  }
}

TEST(HtmlReport, BadMediaAreNamedAndNothingIsWritten) {
  const fs::path dir = scratch("html_bad_media");
  writeFile(dir / "text.mp4", "not a video at all");
  writeFile(dir / "text.png", "not a png");
  const fs::path out = dir / "r.html";
  EXPECT_EQ(writeHtmlReport(sample(), {.video = dir / "none.mp4"}, out).error(),
            "html report: cannot read '" + (dir / "none.mp4").string() + "': No such file or directory");
  EXPECT_EQ(writeHtmlReport(sample(), {.video = dir / "text.mp4"}, out).error(),
            "html report: '" + (dir / "text.mp4").string() + "' is not an MP4 video (it has no ftyp box)");
  EXPECT_EQ(writeHtmlReport(sample(), {.plot = dir / "text.png"}, out).error(),
            "html report: '" + (dir / "text.png").string() + "' is not a PNG image");
  writeFile(dir / "other.html", "<!DOCTYPE html><p>a page, but not a run viewer</p>");
  EXPECT_EQ(writeHtmlReport(sample(), {.viewer = dir / "other.html"}, out).error(),
            "html report: '" + (dir / "other.html").string() + "' is not a run viewer page (frob run --html)");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(writeHtmlReport(sample(), {}, "/nonexistent/r.html").error(),
            "html report: cannot write '/nonexistent/r.html': directory '/nonexistent' does not exist");
}

// ---- The HTML report in Chromium ----------------------------------------------------------------

// Pixels of `img` within 40 of `rgb` in every channel.
int pixelsNear(const render::Image& img, const std::uint8_t (&rgb)[3]) {
  int n = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const std::uint8_t* p = img.pixel(x, y);
      if (std::abs(p[0] - rgb[0]) <= 40 && std::abs(p[1] - rgb[1]) <= 40 && std::abs(p[2] - rgb[2]) <= 40) ++n;
    }
  }
  return n;
}

// The viewer opens where the check was decided: the instant on its page's body, outside the script
// its hash allows (the page in a browser: run_page_test.cpp).
TEST(HtmlReport, TheViewerOpensAtTheInstantGiven) {
  const fs::path dir = scratch("html_open_at");
  const fs::path viewer = writeViewer(dir), html = dir / "report.html";
  ASSERT_TRUE(writeHtmlReport(sample(), {.viewer = viewer, .openAt = 1.5}, html).ok());
  const Doc dom = parseHtml(readFile(html));
  ASSERT_TRUE(dom);
  std::string expected = readFile(viewer);
  expected.replace(expected.find("<body>"), 6, "<body data-open-at=\"1.500\">");
  EXPECT_TRUE(one(dom.get(), "//iframe/@srcdoc") == expected) << "the frame's page is not the viewer's with the instant on its body";
}

TEST(HtmlReportInChromium, ScreenshotShowsTheTableAndThePlot) {
  requireChromium();
  const Report r = writeReport("chromium_screenshot");
  const fs::path shot = r.dir / "shot.png";
  const Ran ran = chromium(r.dir, {"--screenshot=" + shot.string(), "--window-size=1000,800", "--hide-scrollbars"}, r.html, r.dir / "stdout.txt");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Result<render::Image> img = render::readPng(shot.string());
  ASSERT_TRUE(img.ok()) << img.error() << "\n" << ran.err;
  ASSERT_EQ(img.value().width, 1000);
  ASSERT_EQ(img.value().height, 800);
  // Not blank: much of the page differs from its background, the top left pixel.
  const std::uint8_t* bg = img.value().pixel(0, 0);
  const std::uint8_t background[3] = {bg[0], bg[1], bg[2]};
  EXPECT_LT(pixelsNear(img.value(), background), 1000 * 800 * 98 / 100);
  EXPECT_GT(1000 * 800 - pixelsNear(img.value(), background), 5000);
  // The plot is drawn whole. (The video's frame is not checked here: --screenshot does not wait for
  // media, and under load it shot the video before its metadata had loaded, 1 in 30 runs; the
  // load event does wait for it, and VideoDecodesInTheBrowser checks the video there.)
  EXPECT_GE(pixelsNear(img.value(), kPlotColour), kPlotW * kPlotH * 9 / 10);
}

TEST(HtmlReportInChromium, DomHasTheRowsTheTextAndTheDataUris) {
  requireChromium();
  const Report r = writeReport("chromium_dom");
  const Ran ran = chromium(r.dir, {"--dump-dom"}, r.html, r.dir / "dom.html");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Doc dom = parseHtml(readFile(r.dir / "dom.html"));
  ASSERT_TRUE(dom);
  EXPECT_EQ(one(dom.get(), "//title"), "go_to_goal: students/alice.cpp");
  EXPECT_EQ(one(dom.get(), "//p[@class='total']"), "Total: 2.5 / 5 points");
  EXPECT_EQ(select(dom.get(), "//table/thead/tr/th"), (std::vector<std::string>{"Check", "Score", "Points", "Status", "Reasons"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[1]"), (std::vector<std::string>{"reaches the goal", "avoids walls", "secret worlds (hidden)"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[2]"), (std::vector<std::string>{"2", "0.5", "0"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[3]"), (std::vector<std::string>{"2", "1", "2"}));
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[4]"), (std::vector<std::string>{"PASS", "PARTIAL", "FAIL"}));
  // The hostile reason is text in its cell, not markup: the browser made no <script> of it.
  EXPECT_EQ(select(dom.get(), "//table/tbody/tr/td[5]"),
            (std::vector<std::string>{"", "in maze, seed 3: " + kHostileRead,
                                      "in hidden world 1: it failed the rubric's \"goal\" criterion" + kNoDetails}));
  EXPECT_TRUE(select(dom.get(), "//script").empty());
  EXPECT_EQ(select(dom.get(), "//ul[@class='notes']/li"), std::vector<std::string>{"the controller printed more than 1 MB; the rest was cut"});
  // The media are data: URIs holding exactly the files' bytes.
  const std::string video = one(dom.get(), "//video/@src"), plot = one(dom.get(), "//img/@src");
  const std::string videoPrefix = "data:video/mp4;base64,", plotPrefix = "data:image/png;base64,";
  ASSERT_EQ(video.substr(0, videoPrefix.size()), videoPrefix);
  ASSERT_EQ(plot.substr(0, plotPrefix.size()), plotPrefix);
  EXPECT_TRUE(unbase64(std::string_view(video).substr(videoPrefix.size())) == readFile(r.video)) << "the video's data URI is not the MP4";
  EXPECT_TRUE(unbase64(std::string_view(plot).substr(plotPrefix.size())) == readFile(r.plot)) << "the plot's data URI is not the PNG";
  EXPECT_EQ(select(dom.get(), "//video/@controls").size(), 1u);
  EXPECT_EQ(one(dom.get(), "//figcaption"), "the first failing run: maze, seed 3 <&>");
}

// The run viewer is the page's one script: in a frame with scripts but no origin of its own, its
// page whole in the frame's srcdoc (the task named with markup stays inside it), allowed by its hash.
TEST(HtmlReportInChromium, TheRunViewerRunsInItsFrame) {
  requireChromium();
  const fs::path dir = scratch("chromium_viewer");
  const fs::path viewer = writeViewer(dir), html = dir / "report.html";
  ASSERT_TRUE(writeHtmlReport(sample(), {.viewer = viewer, .caption = "the first failing run"}, html).ok());
  const Ran dump = chromium(dir, {"--dump-dom"}, html, dir / "dom.html");
  ASSERT_EQ(dump.status, 0) << dump.err;
  const Doc dom = parseHtml(readFile(dir / "dom.html"));
  ASSERT_TRUE(dom);
  EXPECT_EQ(select(dom.get(), "//iframe/@sandbox"), std::vector<std::string>{"allow-scripts"});
  EXPECT_TRUE(one(dom.get(), "//iframe/@srcdoc") == readFile(viewer)) << "the frame does not hold the viewer's page as written";
  EXPECT_TRUE(select(dom.get(), "//script").empty());
  // The frame shares the page's renderer (no site isolation), so the virtual time budget covers its
  // script too: the viewer has drawn its floor (#f7f5ed) over much of the frame.
  const fs::path shot = dir / "shot.png";
  const Ran ran = chromium(dir,
                           {"--screenshot=" + shot.string(), "--window-size=1000,1400", "--hide-scrollbars", "--virtual-time-budget=20000",
                            "--disable-site-isolation-trials", "--disable-features=IsolateOrigins,site-per-process"},
                           html, dir / "stdout.txt");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Result<render::Image> img = render::readPng(shot.string());
  ASSERT_TRUE(img.ok()) << img.error();
  constexpr std::uint8_t kFloor[3] = {247, 245, 237};
  int floor = 0;
  for (int y = 0; y < img.value().height; ++y) {
    for (int x = 0; x < img.value().width; ++x) {
      const std::uint8_t* p = img.value().pixel(x, y);
      if (p[0] == kFloor[0] && p[1] == kFloor[1] && p[2] == kFloor[2]) ++floor;
    }
  }
  EXPECT_GT(floor, 50'000) << "the viewer drew no floor: its script did not run";
}

// The page has no scripts (its Content-Security-Policy forbids them). A test copy adds one that, at
// the load event, writes the video's and the plot's state into the DOM. A media element delays the
// load event until its first frame is decoded (HTML: "delaying the load event"), and --dump-dom
// serializes after that event, so what the script reads does not depend on timing.
TEST(HtmlReportInChromium, VideoDecodesInTheBrowser) {
  requireChromium();
  const Report r = writeReport("chromium_video");
  std::string page = readFile(r.html);
  const std::string policy = "style-src 'unsafe-inline'";
  const std::size_t at = page.find(policy);
  ASSERT_NE(at, std::string::npos);
  page.insert(at + policy.size(), "; script-src 'unsafe-inline'");
  const std::string probe = R"(<script>
window.addEventListener('load', () => {
  const v = document.querySelector('video'), img = document.querySelector('img');
  const out = document.createElement('pre');
  out.id = 'probe';
  out.textContent = JSON.stringify({readyState: v.readyState, duration: v.duration, width: v.videoWidth, height: v.videoHeight,
                                    error: v.error ? v.error.code : 0, plotWidth: img.naturalWidth, plotHeight: img.naturalHeight,
                                    boxWidth: v.getBoundingClientRect().width, boxHeight: v.getBoundingClientRect().height,
                                    shown: getComputedStyle(v).display !== 'none' && getComputedStyle(v).visibility === 'visible'});
  document.body.appendChild(out);
});
</script>
)";
  const std::size_t end = page.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  page.insert(end, probe);
  const fs::path copy = r.dir / "probe.html";
  writeFile(copy, page);
  const Ran ran = chromium(r.dir, {"--dump-dom"}, copy, r.dir / "dom.html");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const Doc dom = parseHtml(readFile(r.dir / "dom.html"));
  ASSERT_TRUE(dom);
  const json state = json::parse(one(dom.get(), "//pre[@id='probe']"), nullptr, false);
  ASSERT_TRUE(state.is_object()) << readFile(r.dir / "dom.html").substr(0, 2000);
  EXPECT_EQ(state["error"], 0) << state.dump();
  EXPECT_GE(state["readyState"], 2) << "HAVE_CURRENT_DATA: the first frame is decoded; " << state.dump();
  ASSERT_TRUE(state["duration"].is_number()) << state.dump();
  EXPECT_NEAR(state["duration"].get<double>(), static_cast<double>(kVideoFrames) / kFps, 0.05) << state.dump();
  EXPECT_EQ(state["width"], kVideoW);
  EXPECT_EQ(state["height"], kVideoH);
  // Laid out at its own size and shown, so the page shows its frame.
  EXPECT_EQ(state["boxWidth"], kVideoW) << state.dump();
  EXPECT_EQ(state["boxHeight"], kVideoH) << state.dump();
  EXPECT_EQ(state["shown"], true) << state.dump();
  EXPECT_EQ(state["plotWidth"], kPlotW);
  EXPECT_EQ(state["plotHeight"], kPlotH);
}

}  // namespace
}  // namespace frob::course
