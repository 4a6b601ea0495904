#pragma once
// Small FrameScenes shared by the render tests: a 4 m x 3 m room with one robot.

#include "frob/render/plot.hpp"
#include "frob/render/scene.hpp"

#include <cmath>

namespace frob::render::testing {

// A colour no other element of the scene uses, for overlay pixel checks.
inline constexpr Color kOverlayCyan{0.0f, 1.0f, 1.0f};
inline const Point2 kOverlayAt{3.2, 0.8};

inline RobotSpec sixteenSonars() {
  RobotSpec spec;
  for (int i = 0; i < 16; ++i) spec.sonarAngles.push_back(2 * pi * i / 16);
  return spec;
}

inline FrameScene roomScene() {
  FrameScene s;
  s.time = 12.5;
  s.bounds = {Point2(0, 0), Point2(4, 3)};
  s.walls = {{Point2(0, 0), Point2(4, 0)},
             {Point2(4, 0), Point2(4, 3)},
             {Point2(4, 3), Point2(0, 3)},
             {Point2(0, 3), Point2(0, 0)},
             {Point2(2.5, 3), Point2(2.5, 1.8), 0.08}};
  s.blocks = {{.center = Point2(1.0, 2.4), .halfExtents = Vec2(0.3, 0.15), .angle = 0.3}};
  s.pillars = {{Point2(3.4, 2.4), 0.12}};
  s.points = {{"goal", Point2(3.2, 1.9), {}}};
  RobotView r;
  r.name = "nomad";
  r.pose = {Point2(1.2, 1.0), 0.5};
  r.odometry = Pose2{Point2(1.28, 0.93), 0.45};
  r.spec = sixteenSonars();
  for (int i = 0; i < 16; ++i) r.sonar.push_back(i % 5 == 0 ? r.spec.sonarMaxRange : 0.6 + 0.1 * i);
  r.bumps = {{.bumper = 1, .angle = 0.8}};
  for (int i = 0; i <= 40; ++i) {
    const double t = i / 40.0;
    r.path.emplace_back(0.4 + 0.8 * t, 0.5 + 0.5 * t * t);
    r.odometryPath.emplace_back(0.4 + 0.88 * t, 0.5 + 0.43 * t * t);
  }
  r.picture = withColor(red, paintAt(Point2(3.2, 1.9), circle(0.2))) + arrow(Point2(1.2, 1.0), Point2(3.0, 1.8)) +
              withColor(kOverlayCyan, paintAt(kOverlayAt, disc(0.15))) +
              withColor(blue, polyline({Point2(0.3, 2.8), Point2(0.8, 2.6), Point2(1.3, 2.8)})) +
              withColor(black, paintAt(Point2(2.7, 0.3), text("Frob!")));
  r.task = "driveTo(goal)";
  r.wheels = {0.35, -0.2};
  s.robots.push_back(r);
  return s;
}

inline PlotSet roomPlots() {
  PlotSet p;
  Series sonar{"front sonar (m)", {}, {}}, dist{"to goal (m)", {}, {}}, fwd{"forward (m/s)", {}, {}}, turn{"turn (rad/s)", {}, {}};
  for (int i = 0; i <= 200; ++i) {
    const double t = i * 0.1;
    sonar.samples.push_back({t, 2.0 + std::sin(t) * 0.8});
    dist.samples.push_back({t, std::max(0.0, 3.0 - 0.15 * t)});
    fwd.samples.push_back({t, t < 8 ? 0.4 : 0.2});
    turn.samples.push_back({t, std::cos(t * 0.7) * 0.5});
  }
  p.plots = {{"range", {sonar, dist}, 0.0, {}}, {"wheels", {fwd, turn}, {}, {}}};
  p.taskMarks = {{0.0, "wander"}, {8.0, "driveTo"}, {15.0, "stop"}};
  p.tEnd = 20.0;
  return p;
}

}  // namespace frob::render::testing
