#include "session_outputs.hpp"

#include "frob/render/output_file.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace frob::course {

namespace {

// `x` in the shortest text that reads back as the same double.
void appendNumber(std::string& line, double x) {
  char buf[32];
  line.append(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

// `text` as one CSV field, quoted when it holds a comma, a quote or a line break.
void appendField(std::string& line, const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) {
    line += text;
    return;
  }
  line += '"';
  for (char c : text) line += c == '"' ? std::string("\"\"") : std::string(1, c);
  line += '"';
}

}  // namespace

Result<TraceFile> TraceFile::open(const std::string& path, std::size_t sonars) {
  if (Status s = render::checkWritable(path, "trace"); !s) return s;
  std::FILE* f = std::fopen(render::partialPath(path).c_str(), "w");
  if (f == nullptr) return Status::failure("trace: cannot write '" + path + "': " + std::strerror(errno));
  TraceFile t(path, sonars, f);
  std::string header = "time,robot,true_x,true_y,true_heading,odom_x,odom_y,odom_heading,forward,turn";
  for (std::size_t i = 0; i < sonars; ++i) header += ",s" + std::to_string(i);
  header += ",bumper,task\n";
  std::fputs(header.c_str(), f);
  return t;
}

TraceFile::TraceFile(TraceFile&& other) noexcept
    : path_(std::move(other.path_)), sonars_(other.sonars_), file_(std::exchange(other.file_, nullptr)) {}

TraceFile::~TraceFile() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  render::discardPartial(path_);
}

void TraceFile::row(double time, std::size_t robot, const worlds::RobotRecord& rec, const std::string& task) {
  std::string& l = line_;
  l.clear();
  for (double x : {time, static_cast<double>(robot), rec.truePose.position.x(), rec.truePose.position.y(), rec.truePose.heading,
                   rec.odometry.position.x(), rec.odometry.position.y(), rec.odometry.heading, rec.wheels.forward, rec.wheels.turn}) {
    appendNumber(l, x);
    l += ',';
  }
  for (std::size_t i = 0; i < sonars_; ++i) {
    if (i < rec.sonar.size()) appendNumber(l, rec.sonar[i]);
    l += ',';
  }
  if (!rec.bumps.empty()) appendNumber(l, rec.bumps.front().angle);  // the contact angle, radians from the heading
  l += ',';
  appendField(l, task);
  l += '\n';
  std::fwrite(l.data(), 1, l.size(), file_);
}

Status TraceFile::commit(const std::vector<Measured>& measured) {
  bool written = std::ferror(file_) == 0;
  bool closed = std::fclose(std::exchange(file_, nullptr)) == 0;
  if (written && closed && !measured.empty()) {  // each row again, with the measures after it
    std::vector<std::string> names;
    for (const Measured& m : measured) {
      if (std::find(names.begin(), names.end(), m.name) == names.end()) names.push_back(m.name);
    }
    const std::string partial = render::partialPath(path_), rows = partial + ".rows";
    std::error_code ec;
    std::filesystem::rename(partial, rows, ec);
    std::ifstream in(rows);
    std::FILE* out = ec ? nullptr : std::fopen(partial.c_str(), "w");
    written = out != nullptr && in.good();
    std::string line;
    for (bool header = true; written && std::getline(in, line); header = false) {
      for (const std::string& name : names) {
        line += ',';
        if (header) {
          line += name;
          continue;
        }
        const double time = std::strtod(line.c_str(), nullptr), robot = std::strtod(line.c_str() + line.find(',') + 1, nullptr);
        for (const Measured& m : measured) {
          const double k = std::round(time / m.dt);
          if (m.name == name && static_cast<double>(m.robot) == robot && k >= 0 && k < static_cast<double>(m.values.size())) {
            appendNumber(line, m.values[static_cast<std::size_t>(k)]);
          }
        }
      }
      line += '\n';
      written = std::fputs(line.c_str(), out) >= 0;
    }
    closed = out != nullptr && std::fclose(out) == 0;
    std::filesystem::remove(rows, ec);
  }
  if (!written || !closed) {
    render::discardPartial(path_);
    return Status::failure("trace: writing '" + path_ + "' failed (disk full?)");
  }
  return render::commitPartial(path_, "trace");
}

Status writeTimeline(const std::string& path, const std::vector<std::string>& robots, const std::vector<std::vector<TaskRecord>>& records) {
  if (Status s = render::checkWritable(path, "timeline"); !s) return s;
  nlohmann::json events = nlohmann::json::array();
  for (std::size_t pid = 0; pid < records.size(); ++pid) {
    events.push_back({{"ph", "M"}, {"name", "process_name"}, {"pid", pid}, {"args", {{"name", robots.at(pid)}}}});
    // Tasks sorted by start, outer first (a task and the one it wraps may share their start and end),
    // go on the first track where they nest inside what is open.
    std::vector<const TaskRecord*> tasks;
    for (const TaskRecord& r : records[pid]) tasks.push_back(&r);
    std::stable_sort(tasks.begin(), tasks.end(), [](const TaskRecord* a, const TaskRecord* b) {
      return a->start != b->start ? a->start < b->start : a->end != b->end ? a->end > b->end : a->depth < b->depth;
    });
    std::vector<std::vector<double>> openEnds;  // per track, the ends of the tasks open on it, innermost last
    for (const TaskRecord* t : tasks) {
      std::size_t track = 0;
      for (; track < openEnds.size(); ++track) {
        std::vector<double>& open = openEnds[track];
        while (!open.empty() && open.back() <= t->start) open.pop_back();
        if (open.empty() || t->end <= open.back()) break;
      }
      if (track == openEnds.size()) openEnds.emplace_back();
      openEnds[track].push_back(t->end);
      events.push_back({{"ph", "X"},
                        {"name", t->name},
                        {"cat", "task"},
                        {"pid", pid},
                        {"tid", track},
                        {"ts", std::llround(t->start * 1e6)},
                        {"dur", std::llround((t->end - t->start) * 1e6)},
                        {"args", {{"where", t->where}, {"ended", toString(t->how)}, {"detail", t->detail}, {"depth", t->depth}}}});
    }
  }
  const nlohmann::json doc = {{"displayTimeUnit", "ms"}, {"traceEvents", events}};
  {
    std::ofstream out(render::partialPath(path));
    out << doc.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';  // a task name that is not UTF-8 gets U+FFFD
    if (!out) {
      render::discardPartial(path);
      return Status::failure("timeline: writing '" + path + "' failed");
    }
  }
  return render::commitPartial(path, "timeline");
}

Result<FrameFolder> FrameFolder::open(const std::string& dir) {
  std::error_code ec;
  const bool made = std::filesystem::create_directories(dir, ec);
  if (ec) return Status::failure("frames: cannot make the folder '" + dir + "': " + ec.message());
  FrameFolder folder(dir, made);
  if (Status s = render::validateOutputDirectory(dir); !s) {
    folder.discard();
    return s;
  }
  return folder;
}

Status FrameFolder::write(const render::Image& frame) { return render::writePng(render::framePath(dir_, next_++), frame); }

void FrameFolder::discard() {
  std::error_code ec;
  for (long i = 0; i < next_; ++i) std::filesystem::remove(render::framePath(dir_, i), ec);
  next_ = 0;
  if (made_) std::filesystem::remove(dir_, ec);
}

}  // namespace frob::course
