#pragma once
/// The debug channel of a controller: pictures its running tasks publish and its task timeline.
/// A simulator draws and records them; on a real robot they can be ignored.

#include "frob/behavior.hpp"
#include "frob/picture.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace frob {

/// How a task ended.
enum class TaskEnd {
  Running,   ///< not ended yet
  Returned,  ///< its event occurred or it returned a value
  Failed,    ///< an error (RoboErr or another exception) left it
  Aborted,   ///< a parent stopped it: withExit, timeLimit, disable, or a parent's error
  Replaced,  ///< it ended by becoming another task (a tail call with become)
};

/// Readable name of a TaskEnd.
[[nodiscard]] const char* toString(TaskEnd end);

/// One task's life, for the timeline.
struct TaskRecord {
  std::int64_t id = 0;       ///< unique within its timeline, in start order
  std::int64_t parent = -1;  ///< the enclosing task's id, or -1 at the top
  int depth = 0;             ///< nesting depth, 0 at the top
  std::string name;          ///< the task's function name, e.g. "goAhead"
  std::string where;         ///< source file and line
  double start = 0.0;        ///< simulated time it started, seconds
  double end = 0.0;          ///< simulated time it ended, seconds (meaningless while Running)
  TaskEnd how = TaskEnd::Running;
  std::string detail;  ///< its result, error message or abort reason, printable
};

/// Every task start and end of one robot's controller. Running tasks are kept until they end;
/// ended ones are kept up to a bound (oldest dropped first) so memory stays bounded when nobody
/// drains them.
class Timeline {
 public:
  /// Keeps at most `capacity` ended records.
  explicit Timeline(std::size_t capacity = 100'000) : capacity_(capacity) {}
  /// Records a start; returns the new record's id.
  std::int64_t start(std::int64_t parent, std::string name, std::string where, double time);
  /// Records the end of task `id`.
  void end(std::int64_t id, double time, TaskEnd how, std::string detail);
  /// The tasks running now, outermost first.
  [[nodiscard]] std::vector<TaskRecord> running() const;
  /// The name of the innermost running task, or "" when none runs.
  [[nodiscard]] std::string current() const;
  /// Ended records not yet drained, oldest first.
  [[nodiscard]] const std::deque<TaskRecord>& ended() const { return ended_; }
  /// Takes the ended records out (a host streaming them to a file calls this each step).
  std::vector<TaskRecord> drainEnded();
  /// How many ended records were dropped because nobody drained them.
  [[nodiscard]] std::int64_t dropped() const { return dropped_; }
  /// Calls `observer` with each record as it starts (how == Running) and as it ends, so that a
  /// host can mirror the timeline elsewhere by replaying start() and end() in the same order.
  void observe(std::function<void(const TaskRecord&)> observer) { observer_ = std::move(observer); }

 private:
  std::size_t capacity_;
  std::function<void(const TaskRecord&)> observer_;
  std::int64_t next_ = 0;
  std::int64_t dropped_ = 0;
  std::map<std::int64_t, TaskRecord> running_;
  std::deque<TaskRecord> ended_;
};

/// What a controller's tasks report while they run: pictures and the timeline.
class DebugChannel {
 public:
  /// The overlay of every picture published now (withPicture), sampled at `now`.
  [[nodiscard]] Picture picture(const Instant& now) const;
  /// The task timeline.
  [[nodiscard]] Timeline& timeline() { return timeline_; }
  [[nodiscard]] const Timeline& timeline() const { return timeline_; }

  /// Publishes `p` until withdrawn; returns a handle for withdraw (used by withPicture).
  std::int64_t publish(Behavior<Picture> p);
  /// Withdraws a published picture.
  void withdraw(std::int64_t handle);

 private:
  std::int64_t nextPicture_ = 0;
  std::vector<std::pair<std::int64_t, Behavior<Picture>>> pictures_;
  Timeline timeline_;
};

}  // namespace frob
