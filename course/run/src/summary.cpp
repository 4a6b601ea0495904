#include "frob/run/summary.hpp"

#include "frob/run/terminal_text.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace frob::course {

namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[96];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

// One timeline entry: "  12.30 - 15.00 s  circleOnce  returned: (3.1, 4.2)".
std::string taskLine(const TaskRecord& t) {
  std::string line =
      format("      %7.2f - %7.2f s  ", t.start, t.end) + std::string(static_cast<std::size_t>(2 * t.depth), ' ') + t.name + "  " + toString(t.how);
  if (!t.detail.empty()) line += ": " + t.detail;
  return line + "\n";
}

}  // namespace

std::string formatSummary(const Summary& s, double wallSeconds) {
  std::string text = "world " + s.world + ", seed " + std::to_string(s.seed) + format(", dt %g s: %.2f s simulated", s.dt, s.simulatedSeconds);
  if (wallSeconds > 0) text += format(" in %.3g s wall (%.0fx real time)", wallSeconds, s.simulatedSeconds / wallSeconds);
  text += "\n";
  if (s.settledSeconds > 0)
    text += format("  every task had returned at %.2f s: the robots were commanded still for the last %.2f s\n",
                   s.simulatedSeconds - s.settledSeconds, s.settledSeconds);
  for (const RobotSummary& r : s.robots) {
    text += "  " + r.name + ": " + r.controller + "\n";
    text += format("    distance %.2f m, collisions %.0f", r.distance, r.collisions);
    if (r.goalDistance) {
      text += r.goalTime ? format(", goal reached at %.2f s", *r.goalTime) : format(", goal not reached (closest %.2f m)", *r.goalDistance);
    }
    if (r.finishedAt) text += format(", finished at %.2f s", *r.finishedAt);
    text += "\n";
    if (!r.lastTasks.empty()) text += "    last tasks:\n";
    for (const TaskRecord& t : r.lastTasks) text += taskLine(t);
    if (!r.failure.empty()) text += "    FAILED: " + r.failure + "\n";
    for (const std::string& h : r.hints) text += "    hint: " + h + "\n";
  }
  for (const std::string& w : s.written) text += "  wrote " + w + "\n";
  for (const std::string& n : s.notes) text += "  note: " + n + "\n";
  return terminalSafe(text, true);  // task names and failures are the controller's words
}

std::string summaryJson(const Summary& s, double wallSeconds) {
  nlohmann::ordered_json robots = nlohmann::ordered_json::array();
  for (const RobotSummary& r : s.robots) {
    nlohmann::ordered_json tasks = nlohmann::ordered_json::array();
    for (const TaskRecord& t : r.lastTasks) {
      tasks.push_back({{"name", t.name},
                       {"where", t.where},
                       {"start", t.start},
                       {"end", t.end},
                       {"ended", toString(t.how)},
                       {"detail", t.detail},
                       {"depth", t.depth}});
    }
    auto optional = [](const std::optional<double>& x) { return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(nullptr); };
    robots.push_back({{"name", r.name},
                      {"controller", r.controller},
                      {"distance", r.distance},
                      {"collisions", r.collisions},
                      {"goal_distance", optional(r.goalDistance)},
                      {"goal_reached", r.goalTime.has_value()},
                      {"goal_time", optional(r.goalTime)},
                      {"finished_at", optional(r.finishedAt)},
                      {"last_tasks", tasks},
                      {"failure", r.failure.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.failure)},
                      {"hints", r.hints}});
  }
  nlohmann::ordered_json sandbox = nlohmann::ordered_json::array();
  for (const sandbox::Layer& l : s.sandbox) sandbox.push_back({{"layer", l.name}, {"applied", l.applied}, {"note", l.note}});
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.trajectoryHash));
  nlohmann::ordered_json doc = {{"world", s.world},
                                {"seed", s.seed},
                                {"dt", s.dt},
                                {"simulated_seconds", s.simulatedSeconds},
                                {"settled_seconds", s.settledSeconds},
                                {"steps", s.steps},
                                {"wall_seconds", wallSeconds},
                                {"real_time_factor", wallSeconds > 0 ? s.simulatedSeconds / wallSeconds : 0.0},
                                {"trajectory_hash", hash},
                                {"failed", s.failed()},
                                {"robots", robots},
                                {"written", s.written},
                                {"notes", s.notes},
                                {"sandbox", sandbox}};
  return doc.dump(1) + "\n";
}

std::string determinismNote(std::string_view machine) {
  if (machine == "x86_64") return "";
  return "frob: note: on " + std::string(machine) +
         " the simulator's floating point is not amd64's (the C library's float sine, cosine and arctangent round "
         "otherwise, and Debian builds Box2D there with fused multiply-adds), so runs and grades here are close to the "
         "grader's but not the same to the last bit; for grades identical to the grader's, run the amd64 image "
         "(README, \"Every laptop\")\n";
}

std::string compiledNote(std::string_view name, bool checked, double wallSeconds, double cpuSeconds) {
  std::string note = "frob: compiled " + std::string(name) + (checked ? " with checks" : "") + format(" in %.1f s", wallSeconds);
  // A compile is one process at a time: more than twice its CPU time (and a second) is a queue.
  if (wallSeconds > 2 * cpuSeconds + 1) note += format(" (the compiler worked %.1f s of it; the rest it waited for a busy machine)", cpuSeconds);
  return note + "\n";
}

}  // namespace frob::course
