#include "frob/run/run_record.hpp"

#include <algorithm>
#include <cmath>

namespace frob::course {

RunRecord RunRecord::upTo(double seconds) const {
  RunRecord cut = *this;
  const auto last = static_cast<std::size_t>(std::floor(seconds / dt + 0.5));  // the pose at `seconds`
  const double end = static_cast<double>(last) * dt, half = 0.5 * dt;          // times are steps × dt: compare half a step apart
  for (Track& t : cut.robots) {
    if (t.path.size() > last + 1) t.path.resize(last + 1);
    if (t.heading.size() > last + 1) t.heading.resize(last + 1);
    std::erase_if(t.contacts, [&](const auto& c) { return c.first > end - half; });
    std::erase_if(t.touching, [&](const auto& span) { return span.first > end - half; });
    for (auto& span : t.touching) span.second = std::min(span.second, end);
    if (t.returned && t.returnedAt > end + half) t.returned.reset(), t.returnedAt = 0.0;
  }
  return cut;
}

RunRecorder::RunRecorder(const worlds::Simulation& sim, const worlds::WorldDef& world)
    : record_{.size = world.size,
              .walls = sim.walls(),
              .enclosureWalls = world.enclosed ? 4u : 0u,
              .points = world.points,
              .keys = world.keys,
              .dt = sim.dt()} {
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    record_.robots.push_back(
        {.name = sim.robotName(i), .radius = sim.robot(i).radius, .path = {sim.truePose(i).position}, .heading = {sim.truePose(i).heading}});
  }
}

void RunRecorder::stepped(const worlds::Simulation& sim) {
  const double sensedAt = sim.time() - sim.dt();
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    Track& t = record_.robots[i];
    for (std::size_t b = 0; b < sim.frame(i).bumps.size(); ++b) t.contacts.emplace_back(sensedAt, t.path.back());
    if (sim.touching(i)) {  // touching through this step: extend the span that ended at its start, or begin one
      if (t.touching.empty() || t.touching.back().second < sensedAt - 0.5 * sim.dt()) t.touching.emplace_back(sensedAt, sim.time());
      t.touching.back().second = sim.time();
    }
    t.path.push_back(sim.truePose(i).position);
    t.heading.push_back(sim.truePose(i).heading);
  }
}

void RunRecorder::taskEnded(std::size_t i, const TaskRecord& ended, double now) {
  Track& t = record_.robots.at(i);
  if (ended.parent < 0 && ended.how == TaskEnd::Returned) t.returned = ended.detail, t.returnedAt = now;
}

RunRecord RunRecorder::finish(const std::vector<worlds::ControllerFailure>& failures) && {
  for (const worlds::ControllerFailure& f : failures) record_.robots.at(f.robot).failure = f.message;
  return std::move(record_);
}

}  // namespace frob::course
