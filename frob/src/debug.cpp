#include "frob/debug.hpp"

#include <algorithm>

namespace frob {

const char* toString(TaskEnd end) {
  switch (end) {
    case TaskEnd::Running:
      return "running";
    case TaskEnd::Returned:
      return "returned";
    case TaskEnd::Failed:
      return "failed";
    case TaskEnd::Aborted:
      return "aborted";
    case TaskEnd::Replaced:
      return "replaced";
  }
  return "?";
}

std::int64_t Timeline::start(std::int64_t parent, std::string name, std::string where, double time) {
  std::int64_t id = next_++;
  auto p = running_.find(parent);
  int depth = p == running_.end() ? 0 : p->second.depth + 1;
  const auto at =
      running_.emplace(id, TaskRecord{.id = id, .parent = parent, .depth = depth, .name = std::move(name), .where = std::move(where), .start = time})
          .first;
  if (observer_) observer_(at->second);
  return id;
}

void Timeline::end(std::int64_t id, double time, TaskEnd how, std::string detail) {
  auto it = running_.find(id);
  if (it == running_.end()) return;
  TaskRecord r = std::move(it->second);
  running_.erase(it);
  r.end = time;
  r.how = how;
  r.detail = std::move(detail);
  if (observer_) observer_(r);
  if (ended_.size() == capacity_) {
    ended_.pop_front();
    ++dropped_;
  }
  ended_.push_back(std::move(r));
}

std::vector<TaskRecord> Timeline::running() const {
  std::vector<TaskRecord> out;
  for (const auto& [id, r] : running_) out.push_back(r);
  std::stable_sort(out.begin(), out.end(), [](const TaskRecord& a, const TaskRecord& b) { return a.depth < b.depth; });
  return out;
}

std::string Timeline::current() const {
  const TaskRecord* best = nullptr;
  for (const auto& [id, r] : running_) {
    if (best == nullptr || r.depth > best->depth || (r.depth == best->depth && r.id > best->id)) best = &r;
  }
  return best == nullptr ? std::string() : best->name;
}

std::vector<TaskRecord> Timeline::drainEnded() {
  std::vector<TaskRecord> out(std::make_move_iterator(ended_.begin()), std::make_move_iterator(ended_.end()));
  ended_.clear();
  return out;
}

Picture DebugChannel::picture(const Instant& now) const {
  Picture all;
  for (const auto& [handle, p] : pictures_) all += p.at(now);
  return all;
}

std::int64_t DebugChannel::publish(Behavior<Picture> p) {
  pictures_.emplace_back(nextPicture_, std::move(p));
  return nextPicture_++;
}

void DebugChannel::withdraw(std::int64_t handle) {
  std::erase_if(pictures_, [handle](const auto& e) { return e.first == handle; });
}

}  // namespace frob
