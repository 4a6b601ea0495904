#pragma once
// Private: the run viewer (frob run --html), one self-contained HTML page that draws a run in the
// browser: the world, robots, trails, sonar, pictures, a time slider, the task stack and values at
// its instant, the timeline and plots. It keeps every step compactly as the run goes.

#include "frob/debug.hpp"
#include "frob/errors.hpp"
#include "frob/run/run_record.hpp"
#include "frob/worlds/recorder.hpp"
#include "frob/worlds/simulation.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace frob::course {

/// What the page says of the run besides its steps.
struct RunPageEnd {
  std::string title;                              ///< the page's heading: the controller and world
  std::string subtitle;                           ///< seed, steps, trajectory hash
  std::vector<std::string> controllers;           ///< per robot, its controller
  std::vector<std::optional<double>> finishedAt;  ///< per robot, when its task returned
  std::vector<std::vector<TaskRecord>> tasks;     ///< per robot, every task (still running: TaskEnd::Running)
  std::vector<Measured> measured;                 ///< what an assignment's criteria measure, plotted with their bands
};

/// Collects a run's steps, then writes the page whole (a .partial file, then renamed).
class RunPage {
 public:
  /// Checks that `path` can be written and takes the static world and robots of `sim`.
  [[nodiscard]] static Result<RunPage> open(const std::string& path, const worlds::Simulation& sim, double sonarHalfAngle);
  /// Takes in one recorded instant (every robot's pose, odometry, wheels, sonar, bumps, keys, picture).
  void step(const worlds::StepRecord& rec);
  /// Writes the page; gives its size in bytes.
  [[nodiscard]] Result<std::uint64_t> write(const RunPageEnd& end) const;

 private:
  // A number per instant in whole thousandths, each stored as its difference from the one before.
  struct Column {
    std::vector<std::int64_t> deltas;
    std::int64_t last = 0;
    void add(double v);
  };
  // A value the robot's tasks publish (withPlot): its changes.
  struct Published {
    std::string name;
    std::optional<Color> color;
    std::vector<std::pair<std::int64_t, double>> changes;  // sample, value
  };
  // One robot's instants.
  struct Track {
    Column x, y, h, ox, oy, oh, forward, turn;
    std::vector<Wheels> wheels;  // exact, for a run forked from the page (frob run --from page.html#t=T)
    std::vector<Column> sonar;
    std::vector<std::pair<std::int64_t, std::int64_t>> bumps;  // sample, contact angle in thousandths of a radian
    std::vector<std::pair<std::int64_t, std::string>> keys;    // sample, key
    Picture shown;                                             // the last picture kept, without its values
    std::vector<std::pair<std::int64_t, nlohmann::json>> pictures;
    std::vector<Published> published;
    std::unordered_map<std::string, std::size_t> publishedIndex;
  };
  RunPage(std::string path, const worlds::Simulation& sim, double sonarHalfAngle);
  void keepPicture(Track& t, const Picture& picture);

  std::string path_;
  nlohmann::json world_;  // the static world and robots, as the page's JSON fields
  std::vector<Track> robots_;
  double dt_ = 0.01;
  std::optional<double> t0_;  // time of the first instant taken in
  std::int64_t samples_ = 0;
  std::uint64_t pictureBytes_ = 0;  // a rough size of the pictures kept so far, to cap them
  bool picturesStopped_ = false;    // a picture changed past the cap and was not kept
};

}  // namespace frob::course
