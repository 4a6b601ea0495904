#pragma once
// The text files of a run (trace CSV, timeline JSON) and its frame folder, each written aside and
// moved into place only when complete.

#include "frob/base/result.hpp"
#include "frob/debug.hpp"
#include "frob/render/image.hpp"
#include "frob/run/run_record.hpp"
#include "frob/worlds/recorder.hpp"

#include <cstdio>
#include <string>
#include <vector>

namespace frob::course {

// One CSV row per robot per step: time, robot, true pose, odometry, wheels, sonars, bumper, task.
class TraceFile {
 public:
  // Opens `path`.partial and writes the header for robots with up to `sonars` sonars.
  [[nodiscard]] static Result<TraceFile> open(const std::string& path, std::size_t sonars);
  // Appends robot `robot`'s row at `time`; `task` is its innermost running task.
  void row(double time, std::size_t robot, const worlds::RobotRecord& rec, const std::string& task);
  // Finishes the file, with a column per `measured` name (its robot's value at each row's time, blank
  // for other robots), and moves it into place.
  [[nodiscard]] Status commit(const std::vector<Measured>& measured = {});
  TraceFile(TraceFile&& other) noexcept;
  TraceFile& operator=(TraceFile&&) = delete;
  ~TraceFile();  // removes the partial file unless committed

 private:
  TraceFile(std::string path, std::size_t sonars, std::FILE* f) : path_(std::move(path)), sonars_(sonars), file_(f) {}
  std::string path_;
  std::size_t sonars_;
  std::FILE* file_;
  std::string line_;
};

// Writes the task records of each robot as Chrome/Perfetto trace events (one process per robot,
// nested tasks on one track, overlapping parallel tasks on tracks of their own).
[[nodiscard]] Status writeTimeline(const std::string& path, const std::vector<std::string>& robots,
                                   const std::vector<std::vector<TaskRecord>>& records);

// A folder of numbered frames; discard() removes the frames written so far.
class FrameFolder {
 public:
  // Makes `dir` if needed and checks it is writable.
  [[nodiscard]] static Result<FrameFolder> open(const std::string& dir);
  // Writes the next frame.
  [[nodiscard]] Status write(const render::Image& frame);
  // Removes every frame written, and the folder if open() made it.
  void discard();
  // Frames written.
  [[nodiscard]] long count() const { return next_; }

 private:
  FrameFolder(std::string dir, bool made) : dir_(std::move(dir)), made_(made) {}
  std::string dir_;
  bool made_;
  long next_ = 0;
};

}  // namespace frob::course
