// Each drawn feature appears where it must. One feature at a time on a bare floor (no grid, HUD,
// sonar or paths unless the test is about them), probed at the pixels it must paint, in the colour
// it must paint them: removing any one feature from the renderer fails a test here, however few
// pixels it covers, and a golden regenerated without it would not hide that.
// The top-down view and plots are rasterized on the CPU without antialiasing (render/src/raster.hpp),
// so a pixel well inside a shape has exactly its colour; only text is antialiased.
#include "draw.hpp"  // private: the palette the features are drawn in
#include "frob/render/renderer.hpp"
#include "raster.hpp"  // private: span(), the blend a translucent feature gets

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace frob::render {
namespace {

using detail::Rgba8;
using detail::rgba8;
namespace palette = detail::palette;

const RenderDef kBare{.width = 240, .height = 240, .hud = false, .grid = false, .sonar = false, .paths = false};

FrameScene bareFloor() {
  FrameScene s;
  s.bounds = {Point2(0, 0), Point2(4, 4)};
  return s;
}

// A robot with no sensors to draw, facing `heading`.
RobotView robotAt(Point2 p, double heading) {
  RobotView r;
  r.pose = {p, heading};
  return r;
}

Renderer make(const RenderDef& def) {
  Result<Renderer> r = Renderer::create(def);
  EXPECT_TRUE(r.ok()) << r.error();
  return std::move(r.value());
}

// `top` blended over `under` exactly as the rasterizer blends a translucent triangle.
Rgba8 over(Rgba8 top, Rgba8 under) {
  std::uint8_t px[4] = {under.r, under.g, under.b, 255};
  detail::span(px, 0, 1, top, true);
  return {px[0], px[1], px[2], 255};
}

bool near(const std::uint8_t* p, Rgba8 c, int tol) {
  return std::abs(p[0] - c.r) <= tol && std::abs(p[1] - c.g) <= tol && std::abs(p[2] - c.b) <= tol;
}

// How many pixels of the box [x0, x1] x [y0, y1] (clipped to the image) are within `tol` of `c`.
int countNear(const Image& img, int x0, int y0, int x1, int y1, Rgba8 c, int tol = 0) {
  int n = 0;
  for (int y = std::max(y0, 0); y <= std::min(y1, img.height - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, img.width - 1); ++x) n += near(img.pixel(x, y), c, tol);
  return n;
}

// Pixel `at` (continuous pixel coordinates, as worldToPixel gives) has colour `c`, or within one
// pixel of it: probes sit inside features at least 1.5 pixels wide, so one pixel of slack absorbs
// where an edge rounds without letting a missing feature pass.
::testing::AssertionResult paints(const Image& img, Vec2 at, Rgba8 c, int tol = 0) {
  const int x = static_cast<int>(std::floor(at.x())), y = static_cast<int>(std::floor(at.y()));
  if (countNear(img, x - 1, y - 1, x + 1, y + 1, c, tol) > 0) return ::testing::AssertionSuccess();
  const std::uint8_t* p = img.pixel(std::clamp(x, 0, img.width - 1), std::clamp(y, 0, img.height - 1));
  return ::testing::AssertionFailure() << "no pixel near (" << x << ", " << y << ") is (" << int(c.r) << ", " << int(c.g) << ", " << int(c.b)
                                       << "); it is (" << int(p[0]) << ", " << int(p[1]) << ", " << int(p[2]) << ")";
}

const Rgba8 kFloor = rgba8(palette::floor);

// --- Pictures: every kind of shape a task can publish. ---

TEST(Features, PictureShapesAreDrawnWhereAndAsTheyAreDefined) {
  Renderer r = make(kBare);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(0.5, 3.5), 0);
  v.picture = withColor(blue, polyline({Point2(0.5, 3.0), Point2(2.0, 3.0), Point2(3.5, 2.5)})) +
              withColor(red, paintAt(Point2(1.0, 1.0), circle(0.5))) + withColor(green, paintAt(Point2(3.0, 1.0), disc(0.3))) +
              arrow(Point2(0.3, 2.0), Point2(2.0, 2.0)) +  // no colour of its own: the picture colour
              withColor(orange, polygon({Point2(2.5, 0.2), Point2(3.8, 0.2), Point2(3.8, 0.6)}));
  s.robots.push_back(v);
  const Image img = r.render(s);
  auto px = [&](double x, double y) { return r.worldToPixel(s, Point2(x, y)); };
  EXPECT_TRUE(paints(img, px(1.25, 3.0), rgba8(blue))) << "polyline, first segment";
  EXPECT_TRUE(paints(img, px(2.75, 2.75), rgba8(blue))) << "polyline, second segment";
  EXPECT_TRUE(paints(img, px(1.5, 1.0), rgba8(red))) << "circle outline";
  EXPECT_TRUE(paints(img, px(1.0, 1.0), kFloor)) << "a circle is not filled";
  EXPECT_TRUE(paints(img, px(3.0, 1.0), rgba8(green))) << "disc";
  EXPECT_TRUE(paints(img, px(1.0, 2.0), rgba8(palette::picture))) << "arrow shaft";
  EXPECT_TRUE(paints(img, px(1.95, 2.05), rgba8(palette::picture))) << "arrow head";
  EXPECT_TRUE(paints(img, px(3.6, 0.35), rgba8(orange))) << "polygon";
}

TEST(Features, PictureTextIsDrawnFromItsAnchor) {
  Renderer r = make(kBare);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(0.5, 3.5), 0);
  v.picture = withColor(black, paintAt(Point2(1.0, 2.0), text("Frob!")));
  s.robots.push_back(v);
  const Image img = r.render(s);
  // Text sits on its anchor's baseline and runs right: 13 px DejaVu "Frob!" is about 35 x 10 px.
  // Only pixels a glyph covers fully are exactly black: 19 of them here, and none without the text.
  const Vec2 a = r.worldToPixel(s, Point2(1.0, 2.0));
  const int x = static_cast<int>(a.x()), y = static_cast<int>(a.y());
  EXPECT_GE(countNear(img, x, y - 14, x + 40, y + 1, rgba8(black)), 10);
  EXPECT_EQ(countNear(img, x - 40, y - 14, x - 1, y + 1, rgba8(black)), 0) << "nothing left of the anchor";
}

// --- The robot: body, heading tick, bumper markers, where odometry believes it is. ---

TEST(Features, RobotBodyHeadingTickAndBumperMarkers) {
  Renderer r = make(kBare);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(2.0, 2.0), 0.5);
  v.bumps = {{.bumper = 1, .angle = 2.0}};
  s.robots.push_back(v);
  const Image img = r.render(s);
  const double rad = v.spec.radius;
  auto along = [&](double angle, double d) { return r.worldToPixel(s, v.pose.position + d * unitVector(angle)); };
  const Color body = palette::robot(v, 0);
  EXPECT_TRUE(paints(img, along(0.5 + pi, 0.5 * rad), rgba8(body))) << "body, behind the centre";
  EXPECT_TRUE(paints(img, along(0.5, 0.6 * rad), rgba8(white))) << "heading tick";
  EXPECT_TRUE(paints(img, along(0.5 - pi / 2, 0.5 * rad), rgba8(body))) << "no tick sideways";
  EXPECT_TRUE(paints(img, along(0.5 - pi / 2, rad), rgba8({body.r * 0.6f, body.g * 0.6f, body.b * 0.6f}))) << "the body's darker rim";
  EXPECT_TRUE(paints(img, along(0.5 + 2.0, rad), rgba8(palette::bump))) << "bumper marker where it was hit";
  EXPECT_TRUE(paints(img, along(0.5 - 2.0, rad + 0.02), kFloor)) << "and nowhere else";
}

TEST(Features, OdometryOutlineWithItsHeadingTick) {
  Renderer r = make(kBare);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(1.0, 1.0), 0.0);
  v.odometry = Pose2{Point2(3.0, 3.0), pi / 2};  // far from the true pose, so nothing covers it
  s.robots.push_back(v);
  const Image img = r.render(s);
  const double rad = v.spec.radius;
  const Rgba8 outline = over(rgba8(palette::robot(v, 0), 0.7), kFloor);
  auto odo = [&](Vec2 d) { return r.worldToPixel(s, v.odometry->position + d); };
  EXPECT_TRUE(paints(img, odo(Vec2(0, -rad)), outline)) << "outline, behind";
  EXPECT_TRUE(paints(img, odo(Vec2(rad, 0)), outline)) << "outline, right";
  EXPECT_TRUE(paints(img, odo(Vec2(0, 0.6 * rad)), outline)) << "heading tick";
  EXPECT_TRUE(paints(img, odo(Vec2(0, -0.6 * rad)), kFloor)) << "an outline only";
}

// --- Sensors and history: sonar cones with echo arcs, true and odometry paths. ---

TEST(Features, SonarConesAndEchoArcs) {
  RenderDef def = kBare;
  def.sonar = true;
  Renderer r = make(def);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(0.6, 2.0), 0.0);
  v.spec.sonarAngles = {0.0, pi / 2};
  v.sonar = {2.0, v.spec.sonarMaxRange};  // ahead an echo at 2 m; to the left none
  s.robots.push_back(v);
  const Image img = r.render(s);
  const Color col = palette::robot(v, 0);
  auto at = [&](double x, double y) { return r.worldToPixel(s, Point2(x, y)); };
  const Rgba8 echoCone = over(rgba8(col, 0.16), kFloor), silentCone = over(rgba8(col, 0.06), kFloor);
  EXPECT_TRUE(paints(img, at(1.6, 2.0), echoCone)) << "cone of the sonar with an echo";
  const double rim = 0.6 + v.spec.radius;  // ranges are measured from the sonar's place on the rim
  EXPECT_TRUE(paints(img, at(rim + 2.0, 2.0), over(rgba8({col.r * 0.6f, col.g * 0.6f, col.b * 0.6f}, 0.85), echoCone))) << "echo arc at the reading";
  EXPECT_TRUE(paints(img, at(rim + 2.3, 2.0), kFloor)) << "the cone ends at the echo";
  EXPECT_TRUE(paints(img, at(0.6, 3.5), silentCone)) << "cone of the sonar with no echo, to the edge";
}

TEST(Features, TruePathSolidAndOdometryPathDashed) {
  RenderDef def = kBare;
  def.paths = true;
  Renderer r = make(def);
  FrameScene s = bareFloor();
  RobotView v = robotAt(Point2(3.6, 3.6), 0.0);
  v.path = {Point2(0.5, 1.0), Point2(3.5, 1.0)};
  v.odometryPath = {Point2(0.5, 2.5), Point2(3.5, 2.5)};
  s.robots.push_back(v);
  const Image img = r.render(s);
  const Color col = palette::robot(v, 0);
  EXPECT_TRUE(paints(img, r.worldToPixel(s, Point2(2.0, 1.0)), rgba8({col.r * 0.8f, col.g * 0.8f, col.b * 0.8f})));
  // Dashes of 12 px with gaps of 7 px along a 156 px line: most of its pixels, not all.
  const Rgba8 dash = over(rgba8(col, 0.75), kFloor);
  const int y = static_cast<int>(r.worldToPixel(s, Point2(0, 2.5)).y());
  const int x0 = static_cast<int>(r.worldToPixel(s, Point2(0.5, 0)).x()), x1 = static_cast<int>(r.worldToPixel(s, Point2(3.5, 0)).x());
  const int dashed = countNear(img, x0, y, x1, y, dash), floor = countNear(img, x0, y, x1, y, kFloor);
  EXPECT_GT(dashed, (x1 - x0) / 2);
  EXPECT_GT(floor, (x1 - x0) / 5) << "the odometry path is dashed";
}

// --- The world: walls, blocks, pillars, named points, the grid. ---

TEST(Features, WallsObstaclesAndNamedPoints) {
  Renderer r = make(kBare);
  FrameScene s = bareFloor();
  s.walls = {{Point2(0.5, 3.5), Point2(3.5, 3.5)}};
  s.blocks = {{.center = Point2(1.0, 1.0), .halfExtents = Vec2(0.3, 0.2)}};
  s.pillars = {{Point2(3.0, 1.0), 0.15}};
  s.points = {{"goal", Point2(2.0, 2.0), {}}};
  const Image img = r.render(s);
  auto px = [&](double x, double y) { return r.worldToPixel(s, Point2(x, y)); };
  EXPECT_TRUE(paints(img, px(2.0, 3.5), rgba8(palette::wall))) << "wall";
  EXPECT_TRUE(paints(img, px(1.2, 1.1), rgba8(palette::obstacle))) << "block";
  EXPECT_TRUE(paints(img, px(3.0, 1.0), rgba8(palette::obstacle))) << "pillar";
  EXPECT_TRUE(paints(img, px(2.0, 2.0), rgba8(palette::point))) << "named point's marker";
  // Its label starts 7 px right of the marker, in the marker's colour darkened; glyph cores only.
  const Vec2 a = px(2.0, 2.0);
  const Rgba8 label = rgba8({palette::point.r * 0.6f, palette::point.g * 0.6f, palette::point.b * 0.6f});
  EXPECT_GE(countNear(img, int(a.x()) + 6, int(a.y()) - 14, int(a.x()) + 40, int(a.y()) + 2, label), 10) << "label";
}

// Issue 30: a task that marks a waypoint with its name (go_to_goal's "wp1") wrote it over the
// world's own label of that point, a few pixels apart. The picture's label is drawn alone. (A
// longer name than "wp1" here: more glyph cores to count.)
TEST(Features, APointsLabelIsDrawnOnceWhenAPictureWritesItThere) {
  Renderer r = make(kBare);
  const Rgba8 label = rgba8({palette::point.r * 0.6f, palette::point.g * 0.6f, palette::point.b * 0.6f});
  const auto labelPixels = [&](const std::string& written, Point2 where) {
    FrameScene s = bareFloor();
    s.points = {{"goal", Point2(2.0, 2.0), {}}};
    RobotView v = robotAt(Point2(0.5, 3.5), 0);
    v.picture = withColor(red, paintAt(where, text(written)));
    s.robots.push_back(v);
    const Image img = r.render(s);
    const Vec2 a = r.worldToPixel(s, Point2(2.0, 2.0));
    return std::pair{countNear(img, int(a.x()) + 6, int(a.y()) - 14, int(a.x()) + 40, int(a.y()) + 2, label),
                     countNear(img, int(a.x()), int(a.y()) - 14, int(a.x()) + 40, int(a.y()) + 2, rgba8(red))};
  };
  const auto [worldLabel, pictureLabel] = labelPixels("goal", Point2(2.0, 2.0));
  EXPECT_EQ(worldLabel, 0) << "the world's label under the picture's";
  EXPECT_GE(pictureLabel, 5) << "the picture's label";
  EXPECT_GE(labelPixels("wp1", Point2(1.0, 1.0)).first, 10) << "a picture writing something else leaves the world's label";
  EXPECT_GE(labelPixels("goal", Point2(1.0, 1.0)).first, 10) << "and so does one writing it elsewhere";
}

TEST(Features, GridLinesAndTheirLabels) {
  RenderDef def = kBare;
  def.grid = true;
  Renderer r = make(def);
  const FrameScene s = bareFloor();
  const Image img = r.render(s);
  EXPECT_TRUE(paints(img, r.worldToPixel(s, Point2(2.0, 2.5)), rgba8(palette::grid))) << "the line x = 2 m";
  EXPECT_TRUE(paints(img, r.worldToPixel(s, Point2(2.5, 3.0)), rgba8(palette::grid))) << "the line y = 3 m";
  const Vec2 corner = r.worldToPixel(s, Point2(0, 0));
  // Labels in grey text along the bottom and left edges: antialiased, so count darkish pixels.
  const int x = static_cast<int>(corner.x()), y = static_cast<int>(corner.y());
  int ink = 0;
  for (int yy = y - 14; yy <= y; ++yy)
    for (int xx = x; xx <= x + 200; ++xx) ink += img.pixel(xx, yy)[0] < 160;
  EXPECT_GE(ink, 20) << "axis labels";
}

// --- The heads-up display. ---

TEST(Features, HudBoxTextAndRobotSwatch) {
  RenderDef def = kBare;
  def.hud = true;
  Renderer r = make(def);
  FrameScene s = bareFloor();
  s.robots.push_back(robotAt(Point2(3.5, 0.5), 0.0));
  const Image img = r.render(s);
  // In the frame's top-left corner (the margin around the floor) the box is black at 62%; its text
  // is white; each robot's line has a swatch of the robot's colour.
  const Rgba8 box = over(rgba8(black, 0.62), rgba8(palette::background));
  EXPECT_TRUE(paints(img, {8, 8}, box, 1)) << "box (composited on the CPU, rounded its own way)";
  EXPECT_GE(countNear(img, 20, 6, 120, 50, rgba8(white)), 30) << "text";
  EXPECT_GE(countNear(img, 6, 6, 20, 50, rgba8(palette::robot(s.robots[0], 0))), 20) << "swatch";
}

// --- Plots: series, task switches with their names, the cursor, the value and time labels. ---

PlotSet onePlot() {
  PlotSet p;
  Series line{"level", {}, red};
  for (int i = 0; i <= 100; ++i) line.samples.push_back({i * 0.1, 1.0});
  p.plots = {{"chart", {line}, 0.0, 2.0}};
  p.tEnd = 10.0;
  return p;
}

TEST(Features, PlotSeriesAndCursor) {
  Renderer r = make({.width = 320, .height = 200});
  const Image img = r.renderPlots(onePlot(), 5.0);
  // The series is drawn up to `now` (the left half) and no further.
  EXPECT_GE(countNear(img, 40, 90, 170, 110, rgba8(red)), 100) << "series";
  EXPECT_EQ(countNear(img, 190, 90, 320, 110, rgba8(red)), 0) << "nothing after now";
  // The cursor: a red line at 70% over the chart, top to bottom.
  const Rgba8 cursor = over(rgba8(red, 0.7), rgba8(palette::chart));
  EXPECT_GE(countNear(img, 0, 0, 319, 199, cursor), 100) << "cursor";
}

TEST(Features, TaskSwitchLinesAndNamesInPlots) {
  Renderer r = make({.width = 320, .height = 200});
  PlotSet p = onePlot();
  p.taskMarks = {{2.5, "wander"}, {7.5, "home"}};
  const Image img = r.renderPlots(p);
  const Image without = r.renderPlots(onePlot());
  // Each switch is a dashed purple line through the chart, at 80% over the chart's background;
  // 4 px dashes, 3 px gaps over about 150 px: well over 60 pixels each.
  const Rgba8 dash = over(rgba8(purple, 0.8), rgba8(palette::chart));
  EXPECT_GE(countNear(img, 0, 0, 159, 199, dash), 60) << "the line at 2.5 s";
  EXPECT_GE(countNear(img, 160, 0, 319, 199, dash), 60) << "the line at 7.5 s";
  EXPECT_EQ(countNear(without, 0, 0, 319, 199, dash), 0);
  // Their names above the charts, in purple text.
  EXPECT_GE(countNear(img, 0, 0, 319, 16, rgba8(purple)), 20) << "names";
  EXPECT_EQ(countNear(without, 0, 0, 319, 16, rgba8(purple)), 0);
}

TEST(Features, PlotAxesAndLabels) {
  Renderer r = make({.width = 320, .height = 200});
  const Image img = r.renderPlots(onePlot());
  // Value labels left of the chart, time labels below it: black antialiased text.
  int left = 0, below = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 40; ++x) left += img.pixel(x, y)[0] < 100;
  for (int y = 185; y < 200; ++y)
    for (int x = 0; x < 320; ++x) below += img.pixel(x, y)[0] < 100;
  EXPECT_GE(left, 15) << "value labels";
  EXPECT_GE(below, 15) << "time labels";
  EXPECT_GE(countNear(img, 40, 0, 50, 199, rgba8(gray)), 100) << "value axis";
  // The chart's first line: its title in black, then the legend in each series' colour.
  EXPECT_GE(countNear(img, 45, 0, 319, 40, rgba8(black)), 10) << "title";
  EXPECT_GE(countNear(img, 45, 0, 319, 40, rgba8(red)), 10) << "legend";
}

// Issue 30: a value near the top of the range ran through the legend. The rows the legend's text
// covers (red text, left half: the series has no samples there) and the rows the series covers
// (right part, no text there) must not meet.
TEST(Features, NoSeriesRunsThroughTheLegend) {
  Renderer r = make({.width = 320, .height = 200});
  PlotSet p;
  Series high{"level", {}, red};
  for (int i = 80; i <= 100; ++i) high.samples.push_back({i * 0.1, 1.9});  // 5% below the top of 0..2, from 8 s
  p.plots = {{"chart", {high}, 0.0, 2.0}};
  p.tEnd = 10.0;
  const Image img = r.renderPlots(p);
  const auto redRows = [&](int x0, int x1) {
    std::vector<int> rows;
    for (int y = 0; y < img.height; ++y) {
      if (countNear(img, x0, y, x1, y, rgba8(red), 40) > 0) rows.push_back(y);  // antialiased edges too
    }
    return rows;
  };
  const std::vector<int> legend = redRows(44, 160), series = redRows(260, 310);
  ASSERT_FALSE(legend.empty());
  ASSERT_FALSE(series.empty());
  EXPECT_LT(legend.back(), series.front()) << "the legend's last row " << legend.back() << ", the series' first " << series.front();
}

}  // namespace
}  // namespace frob::render
