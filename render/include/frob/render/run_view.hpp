#pragma once
/// Joins the renderer to a running simulation: a RunView follows a worlds::Run step by step and keeps
/// the FrameScene and the PlotSet of its latest instant, growing paths and plots as the run goes.
///
///   worlds::Run run(world, {}, {controller});
///   RunView view(run, {.plotSeconds = 60});
///   while (run.simulation().time() < 60) {
///     run.step();
///     view.update(run);                        // after every step: paths, plots, task switches
///     renderer.renderInto(view.scene(), view.plots(), frame);  // as often as frames are wanted
///   }

#include "frob/render/plot.hpp"
#include "frob/render/scene.hpp"
#include "frob/worlds/run.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace frob::render {

/// A further plotted signal, computed from each recorded instant, shown in a chart of its own.
struct RunSignal {
  std::string name;                                        ///< chart title and legend, with its unit
  std::function<double(const worlds::StepRecord&)> value;  ///< its value at a recorded instant
};

/// What a RunView collects. Fill with designated initializers.
struct RunViewDef {
  std::size_t plotRobot = 0;       ///< robot whose signals are plotted and whose task switches are marked
  bool frontSonar = true;          ///< chart "range": the front sonar's reading, m
  std::string goal = "goal";       ///< chart "range": distance to this named point, m; empty or absent: none
  bool wheels = true;              ///< chart "wheels": forward (m/s) and turn (rad/s) commands
  std::vector<RunSignal> signals;  ///< more signals, one chart each
  /// Values the plotted robot's tasks publish (withPlot) to chart, by name, one chart each as they
  /// first appear; unset: every one.
  std::optional<std::vector<std::string>> published;
  double sampleSeconds = 0.05;  ///< least simulated time between plot samples, s (a chart is a few hundred pixels wide)
  double pathSpacing = 0.05;    ///< least distance between kept path points, m (the newest position is always kept)
  double plotSeconds = 0.0;     ///< right end of the plots' time axis, s (e.g. the run's length); 0: the latest sample
};

/// The world's static shapes as the renderer draws them: segment and polyline walls become Walls,
/// rectangles Blocks, circles Pillars; named points are labelled; bounds are the world's size.
[[nodiscard]] FrameScene staticScene(const worlds::Simulation& sim);

/// Follows a run and keeps what the renderer needs of it. Walls and points are taken once; each
/// update() appends only the new instants, so a long run costs time linear in its steps.
class RunView {
 public:
  /// Takes the static world, robot names and specs from `run`. The run must keep every step since
  /// the last update (RecorderOptions: all of them, the default, or a window of 1 when updated
  /// after every step).
  explicit RunView(const worlds::Run& run, RunViewDef def = {});

  /// Takes in every instant `run` recorded since the last call: poses and paths, and plot samples;
  /// then sensors, wheels, picture and current task of the latest. Call it after every run.step():
  /// task switches are read from the robots' timelines, which only tell what runs now.
  void update(const worlds::Run& run);

  /// The latest recorded instant (before the first update(): the world with robots at their starts).
  [[nodiscard]] const FrameScene& scene() const { return scene_; }
  /// Sets the line the HUD shows under the time from now on (FrameScene::note).
  void setNote(std::string note) { scene_.note = std::move(note); }
  /// The plots up to the latest instant, with the task switches of the plotted robot.
  [[nodiscard]] const PlotSet& plots() const { return plots_; }
  /// The names of the values the plotted robot's tasks published, charted or not, in order of appearance.
  [[nodiscard]] const std::vector<std::string>& publishedNames() const { return publishedNames_; }
  /// Instants taken in so far.
  [[nodiscard]] std::int64_t instants() const { return taken_; }

 private:
  void takeInstant(const worlds::StepRecord& rec);
  void markTasks(const worlds::Run& run, double now);

  RunViewDef def_;
  FrameScene scene_;
  PlotSet plots_;
  std::int64_t taken_ = 0;           // instants taken in so far
  std::vector<char> pathHeadLoose_;  // per robot: the path's last point is the newest position, not a kept one
  std::vector<char> odomHeadLoose_;  // the same for the odometry path
  int frontSonar_ = -1;              // index of the plotted robot's front sonar
  std::optional<Point2> goal_;       // the goal the distance is measured to
  double lastSample_ = 0.0;
  bool sampled_ = false;
  std::int64_t lastTaskId_ = -1;  // innermost running task of the plotted robot at the last update
  struct Slot {                   // where each plotted signal goes
    std::size_t plot, series;
  };
  Slot sonarSlot_{}, goalSlot_{}, forwardSlot_{}, turnSlot_{};
  std::vector<Slot> signalSlots_;
  std::vector<std::string> publishedNames_;
  std::unordered_map<std::string, std::size_t> publishedPlots_;  // per published name: its chart, or npos when not charted
};

}  // namespace frob::render
