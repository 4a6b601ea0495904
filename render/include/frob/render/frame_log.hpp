#pragma once
/// FrameLog: the frames of a run, noted as the run goes and drawn after it ends. Nothing is drawn
/// between the controllers' steps, so a filmed run paces them as an unfilmed (graded) one does, and a
/// run that fails wastes no drawing.
///
///   RunView view(run);
///   FrameLog film;
///   while (...) {
///     run.step();
///     view.update(run);
///     for (int k = picker.framesAt(step); k > 0; --k) film.note(view);
///   }
///   film.replay(view, [&](const FrameScene& scene, const PlotSet& plots) { ... draw and write ...; return Status(); });

#include "frob/base/result.hpp"
#include "frob/render/run_view.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace frob::render {

/// Keeps what each frame shows that a RunView at the run's end no longer does: the moving parts of
/// every robot, how far its paths and the plots had grown, and pictures (each shared while unchanged).
class FrameLog {
 public:
  /// Notes a frame of `view`'s latest instant.
  void note(const RunView& view);
  /// Frames noted.
  [[nodiscard]] std::size_t size() const { return frames_.size(); }
  /// Calls `draw` with each noted frame in order, its scene and plots exactly as `end` (the same view,
  /// updated to the run's end) showed them when the frame was noted, then `more` (charts made once the
  /// run was over: what an assignment measures) up to the frame's instant; stops at the first failure.
  [[nodiscard]] Status replay(const RunView& end, const std::function<Status(const FrameScene&, const PlotSet&)>& draw,
                              const std::vector<Plot>& more = {}) const;

 private:
  struct Robot {
    Pose2 pose;
    std::optional<Pose2> odometry;
    std::vector<double> sonar;
    std::vector<BumperHit> bumps;
    std::size_t path = 0, odometryPath = 0;  // points of each path then; the last may have moved since
    Point2 pathEnd = Point2::Zero(), odometryPathEnd = Point2::Zero();
    std::shared_ptr<const Picture> picture;
    std::string task;
    Wheels wheels;
  };
  struct Frame {
    double time = 0.0;
    std::string note;
    std::vector<Robot> robots;
    std::size_t taskMarks = 0;
    std::vector<std::uint32_t> samples;  // per series of each plot shown then, in order; its size says how many plots
  };
  std::vector<Frame> frames_;
};

}  // namespace frob::render
