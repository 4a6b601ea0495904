#pragma once
/// One run of controllers in a world, with the files it writes and a summary: what `frob run` does.
///
///   RunDef def{.world = *worlds::loadReferenceWorld("obstacles"), .worldName = "obstacles",
///              .controllers = {*loadExample(*findExample("bug"))}, .seconds = 120,
///              .outputs = {.video = "bug.mp4"}};
///   Result<Summary> s = runSession(def);   // a failed controller: s->failed(), and no files written

#include "frob/debug.hpp"
#include "frob/render/renderer.hpp"
#include "frob/run/controller_file.hpp"
#include "frob/run/fork.hpp"
#include "frob/run/host.hpp"
#include "frob/run/run_record.hpp"
#include "frob/worlds/run.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace frob::course {

/// The files a run writes; an empty path is not written. Each appears only once the run has
/// completed: a run whose controller fails leaves none of them behind.
struct RunOutputs {
  std::string video;             ///< MP4 of the run
  std::uint64_t videoBytes = 0;  ///< 0: any size; else the video's bitrate is capped so that the whole run fits in about this many bytes
  std::string frames;            ///< folder for one PNG per video frame, frame_000000.png on (made if missing)
  std::string plot;              ///< PNG of the plotted signals over the whole run
  std::string trace;             ///< CSV, one row per robot per step: poses, wheels, sonars, bumper, current task
  std::string timeline;          ///< task timeline as Chrome/Perfetto trace-event JSON
  std::string html;              ///< the run viewer: one self-contained page that replays the run in a browser, with a time slider
  /// More charts in the plots and the video: "s4" for sonar 4, or the name of a value the tasks
  /// publish (withPlot). Empty: every published value.
  std::vector<std::string> plotSignals;
  /// True when no file is asked for.
  [[nodiscard]] bool empty() const { return video.empty() && frames.empty() && plot.empty() && trace.empty() && timeline.empty() && html.empty(); }
};

/// A run to make. Fill with designated initializers.
struct RunDef {
  worlds::WorldDef world;                     ///< the world, loaded
  std::string worldName;                      ///< how the world was named, for the summary
  worlds::SimOptions options;                 ///< dt, seed, scripted keys
  std::vector<LoadedController> controllers;  ///< one per robot, or one for all robots
  std::optional<HostDef> host;                ///< set: the controllers run in a sandboxed host (each needs its module)
  double seconds = 60.0;                      ///< simulated seconds at most; ends sooner once every controller's task returned
  bool wholeTime = false;                     ///< run all `seconds` even after every task returned, as a graded run does
  double settleSeconds = 0.0;                 ///< once every controller's task returned, the run goes on this long, the robots commanded still
  bool keepRecord = false;                    ///< keep the grader's record of the run in the summary, to judge it against a rubric
  /// With keepRecord: what an assignment's criteria measure along the record, added as columns to the
  /// trace and as plots with their bands to the page.
  std::function<std::vector<Measured>(const RunRecord&)> measure;
  bool meantToRunForever = false;  ///< the controller's task is meant never to return (Diagnosis::hints)
  std::optional<ForkPoint> fork;   ///< set: the run is an earlier one's up to its instant, the controllers' from then on
  RunOutputs outputs;              ///< files to write
  int fps = 30;                    ///< frames per second of the video and frames
  double speed = 1.0;              ///< the video plays this many times faster than simulated time
  render::RenderDef view{.width = 854, .height = 480, .layout = render::PanelLayout::PlotRight};  ///< how frames look
  std::function<void(double done)> progress;  ///< told the share of the run done (0 to 1) after each step
  /// Told each frame drawn of the video or frames, which are drawn after the run (frames drawn, of how many).
  std::function<void(std::size_t drawn, std::size_t frames)> drawing;
};

/// How close to the world's point named "goal" counts as reaching it, metres (true position).
inline constexpr double kGoalRadius = 0.5;

/// How one robot did.
struct RobotSummary {
  std::string name;                    ///< the robot's name in the world
  std::string controller;              ///< its controller's function and file
  double distance = 0.0;               ///< length of its true path, metres
  int collisions = 0;                  ///< bumper contacts
  std::optional<double> goalDistance;  ///< its closest true approach to the goal, metres; empty without a goal
  std::optional<double> goalTime;      ///< when it first came within kGoalRadius of the goal, seconds
  std::optional<double> finishedAt;    ///< when its controller's task returned, seconds
  std::vector<TaskRecord> lastTasks;   ///< the last tasks that ended, oldest first, then those still running
  std::string failure;                 ///< why its controller failed; empty when it did not
  std::vector<std::string> hints;      ///< what went wrong that is common, in words that name the fix
};

/// What a run did.
struct Summary {
  std::string world;                    ///< the world's name as given
  std::uint64_t seed = 0;               ///< the seed used
  double dt = 0.0;                      ///< step, seconds
  double simulatedSeconds = 0.0;        ///< logical time reached
  double settledSeconds = 0.0;          ///< of those, how long the run went on after every controller's task returned (RunDef::settleSeconds)
  std::int64_t steps = 0;               ///< steps taken
  std::uint64_t trajectoryHash = 0;     ///< hash of every true pose (equal runs, equal hashes)
  std::vector<RobotSummary> robots;     ///< one per robot
  std::vector<std::string> written;     ///< the files written, in order
  std::vector<std::string> notes;       ///< what is worth saying besides, e.g. that output was cut
  std::vector<sandbox::Layer> sandbox;  ///< the controller host's layers (empty when not in a sandbox)
  std::optional<RunRecord> record;      ///< what a rubric's criteria judge, when RunDef::keepRecord asked for it
  /// True when a controller failed.
  [[nodiscard]] bool failed() const;
};

/// Checks `def` before anything runs: controllers for the robots, times, frame size and output paths.
[[nodiscard]] Status validate(const RunDef& def);
/// Runs `def` and writes its outputs. Bad definitions and unwritable outputs give an error; a
/// controller that fails ends the run, writes nothing, and is reported in the summary.
[[nodiscard]] Result<Summary> runSession(const RunDef& def);

}  // namespace frob::course
