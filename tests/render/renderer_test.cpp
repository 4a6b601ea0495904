// The renderer draws FrameScenes faithfully and purely, and rejects bad setups up front.
#include "frob/render/renderer.hpp"

#include "golden.hpp"
#include "scenes.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace frob::render {
namespace {

using testing::kOverlayAt;
using testing::matchesGolden;
using testing::roomPlots;
using testing::roomScene;

Renderer make(RenderDef def) {
  Result<Renderer> r = Renderer::create(def);
  EXPECT_TRUE(r.ok()) << r.error();
  return std::move(r.value());
}

TEST(Renderer, TopDownWithPictureOverlayMatchesGolden) {
  Renderer r = make({.width = 320, .height = 240, .hud = false});
  const FrameScene scene = roomScene();
  const Image img = r.render(scene);
  EXPECT_TRUE(matchesGolden(img, "top_down_overlay"));

  // The overlay disc sits where the camera puts its world point, in the overlay's colour.
  const Vec2 px = r.worldToPixel(scene, kOverlayAt);
  const std::uint8_t* p = img.pixel(static_cast<int>(px.x()), static_cast<int>(px.y()));
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 255);
  EXPECT_EQ(p[2], 255);
  // 0.25 m away (beyond the 0.15 m disc) the floor shows instead.
  const Vec2 off = r.worldToPixel(scene, kOverlayAt + Vec2(0.25, 0));
  EXPECT_NE(img.pixel(static_cast<int>(off.x()), static_cast<int>(off.y()))[0], 0);
}

TEST(Renderer, CameraFitsBoundsWithYUp) {
  Renderer r = make({.width = 320, .height = 240, .margin = 0.0});
  FrameScene scene;
  scene.bounds = {Point2(0, 0), Point2(4, 3)};
  // 4 x 3 m fills 320 x 240 exactly: 80 px per metre, origin at the bottom-left corner.
  EXPECT_NEAR(r.worldToPixel(scene, {0, 0}).x(), 0.0, 1e-9);
  EXPECT_NEAR(r.worldToPixel(scene, {0, 0}).y(), 240.0, 1e-9);
  EXPECT_NEAR(r.worldToPixel(scene, {4, 3}).x(), 320.0, 1e-9);
  EXPECT_NEAR(r.worldToPixel(scene, {4, 3}).y(), 0.0, 1e-9);
}

TEST(Renderer, HudMatchesGolden) {
  Renderer r = make({.width = 320, .height = 240, .hud = true});
  const Image img = r.render(roomScene());
  EXPECT_TRUE(matchesGolden(img, "top_down_hud"));
  // The HUD box darkens the top-left corner, over the floor.
  EXPECT_LT(img.pixel(10, 10)[0], 100);
}

TEST(Renderer, PlotPanelBesideTheWorldMatchesGolden) {
  Renderer r = make({.width = 480, .height = 240, .layout = PanelLayout::PlotRight, .plotShare = 0.45});
  const FrameScene scene = roomScene();
  const Image img = r.render(scene, roomPlots());
  EXPECT_TRUE(matchesGolden(img, "plot_right"));
  // The world is fitted into the left part only.
  EXPECT_LT(r.worldToPixel(scene, scene.bounds.max).x(), 480 * 0.55 + 1);
}

TEST(Renderer, StandalonePlotsMatchGolden) {
  Renderer r = make({.width = 320, .height = 200});
  EXPECT_TRUE(matchesGolden(r.renderPlots(roomPlots()), "plots"));
}

// A value that is not finite (a sonar's no echo) is a gap in its line, not a stroke across it; a
// plot's levels (what an assignment wants) are dashed across it in green.
TEST(Renderer, APlotLeavesAGapWhereAValueIsNotFiniteAndMarksItsLevels) {
  Renderer r = make({.width = 320, .height = 200});
  const auto chart = [](bool gap, std::vector<double> levels) {
    Series s{"value", {}, Color{0, 0, 1}};
    for (int i = 0; i <= 200; ++i) {
      const double t = i * 0.1;
      if (!gap || t < 8 || t > 12)
        s.samples.push_back({t, 1.0});
      else
        s.samples.push_back({t, std::numeric_limits<double>::quiet_NaN()});
    }
    PlotSet p;
    p.plots = {{"chart", {s}, 0.0, 2.0, std::move(levels)}};
    p.tEnd = 20.0;
    return p;
  };
  const auto count = [](const Image& img, auto is) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) n += is(img.pixel(x, y));
    return n;
  };
  const auto pureBlue = [](const std::uint8_t* p) { return p[2] > 200 && p[0] < 60 && p[1] < 60; };
  const auto greenish = [](const std::uint8_t* p) { return p[1] > 120 && p[0] < 90 && p[2] < 110; };
  const int whole = count(r.renderPlots(chart(false, {})), pureBlue), broken = count(r.renderPlots(chart(true, {})), pureBlue);
  // 4 s of 20 s missing: about a fifth of the line's length (the chart is about 270 pixels wide).
  EXPECT_GT(whole, 200);
  EXPECT_NEAR(static_cast<double>(broken) / whole, 0.8, 0.05);
  EXPECT_EQ(count(r.renderPlots(chart(false, {})), greenish), 0);
  EXPECT_GT(count(r.renderPlots(chart(false, {0.5, 1.5})), greenish), 200) << "two dashed lines across the chart";
}

TEST(Renderer, ChaseViewMatchesGolden) {
  Renderer r = make({.width = 320, .height = 240, .view = ViewMode::Chase});
  const Image img = r.render(roomScene());
  EXPECT_TRUE(matchesGolden(img, "chase", testing::kLlvmpipe));
}

TEST(Renderer, SameSceneGivesIdenticalPixels) {
  Renderer r = make({.width = 200, .height = 150, .layout = PanelLayout::PlotBelow});
  const FrameScene scene = roomScene();
  const PlotSet plots = roomPlots();
  const Image first = r.render(scene, plots);
  FrameScene other = scene;
  other.robots[0].pose.position.x() += 0.5;
  const Image between = r.render(other, plots);  // state from another frame must not leak
  const Image second = r.render(scene, plots);
  EXPECT_EQ(first.rgba, second.rgba);
  EXPECT_NE(first.rgba, between.rgba);
  // A second renderer of the same definition agrees too.
  Renderer r2 = make({.width = 200, .height = 150, .layout = PanelLayout::PlotBelow});
  EXPECT_EQ(r2.render(scene, plots).rgba, first.rgba);
}

TEST(Renderer, ChaseViewIsPureToo) {
  Renderer r = make({.width = 160, .height = 120, .view = ViewMode::Chase});
  const FrameScene scene = roomScene();
  FrameScene other = scene;
  other.robots[0].pose.heading += 1.0;
  const Image first = r.render(scene);
  EXPECT_NE(r.render(other).rgba, first.rgba);
  EXPECT_EQ(r.render(scene).rgba, first.rgba);
}

TEST(Renderer, EmptySceneAndOddInputsDoNotCrash) {
  Renderer r = make({.width = 64, .height = 48, .view = ViewMode::Chase, .layout = PanelLayout::PlotRight});
  FrameScene scene;
  RobotView odd;
  odd.sonar = {1.0, 2.0};  // more readings than sonars: extra ones are ignored
  odd.picture = Picture({Shape{.kind = Shape::Kind::Polygon, .points = {Point2(0, 0), Point2(1, 1)}}});
  scene.robots.push_back(odd);
  const Image img = r.render(scene, PlotSet{});
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.rgba.size(), 64u * 48u * 4u);
}

TEST(Renderer, NonFiniteValuesFromAMisbehavingControllerDoNotHang) {
  Renderer r = make({.width = 64, .height = 48, .layout = PanelLayout::PlotBelow});
  FrameScene scene = roomScene();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  scene.robots[0].pose.position = Point2(nan, 1.0);
  scene.robots[0].odometryPath.push_back(Point2(inf, 0.0));
  scene.robots[0].picture += circle(inf) + paintAt(Point2(nan, nan), text("?"));
  scene.robots[0].wheels = {nan, inf};
  PlotSet plots = roomPlots();
  plots.plots[0].series[0].samples.push_back({20.5, nan});
  const Image img = r.render(scene, plots);
  EXPECT_EQ(img.rgba.size(), 64u * 48u * 4u);
}

TEST(RendererErrors, MissingFontIsNamed) {
  const RenderDef def{.fontFile = "/nonexistent/NoSuchFont.ttf"};
  const Status s = validate(def);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("cannot load font '/nonexistent/NoSuchFont.ttf'"), std::string::npos) << s.error();
  Result<Renderer> r = Renderer::create(def);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), s.error());
}

TEST(RendererErrors, MissingModelIsNamedForTheChaseView) {
  const RenderDef def{.view = ViewMode::Chase, .robotModelFile = "/nonexistent/robot.obj"};
  const Status s = validate(def);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "render: robot model '/nonexistent/robot.obj' does not exist (set RenderDef::robotModelFile)");
  // The top-down view needs no model.
  EXPECT_TRUE(validate(RenderDef{.view = ViewMode::TopDown, .robotModelFile = "/nonexistent/robot.obj"}).ok());
}

TEST(RendererErrors, UnreadableModelIsNamed) {
  const Status s = validate(RenderDef{.view = ViewMode::Chase, .robotModelFile = FROB_FONT_FILE});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("cannot load robot model"), std::string::npos) << s.error();
}

TEST(RendererErrors, BadFrameSizeIsRejected) {
  const Status s = validate(RenderDef{.width = 0, .height = 480});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "render: frame size 0x480 is outside 16..8192 pixels");
}

}  // namespace
}  // namespace frob::render
