#include "frob/sandbox/wire.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frob::sandbox {

void Writer::put(std::string_view s, std::size_t cap) {
  s = s.substr(0, cap);
  put(static_cast<std::uint32_t>(s.size()));
  if (!fits(s.size()) || s.empty()) return;  // an empty view may hold no pointer at all
  std::memcpy(area_.data() + used_, s.data(), s.size());
  used_ += s.size();
}

bool Reader::fail(std::string why) {
  if (ok_) why_ = std::move(why);
  return ok_ = false;
}

bool Reader::count(std::uint32_t& n, std::uint32_t cap, const char* what) {
  if (!get(n)) return false;
  return n <= cap || fail("more than " + std::to_string(cap) + " " + what);
}

bool Reader::get(std::string& s, std::size_t cap, const char* what) {
  std::uint32_t n = 0;
  if (!get(n)) return false;
  if (n > cap) return fail(std::string(what) + " longer than " + std::to_string(cap) + " bytes");
  if (n > bytes_.size() - used_) return fail("it ends too soon");
  s.assign(reinterpret_cast<const char*>(bytes_.data() + used_), n);
  used_ += n;
  return true;
}

namespace {

void write(Writer& w, const Point2& p) { w.put(p.x()), w.put(p.y()); }
bool read(Reader& r, Point2& p) { return r.get(p.x()) && r.get(p.y()); }
void write(Writer& w, const Pose2& p) { write(w, p.position), w.put(p.heading); }
bool read(Reader& r, Pose2& p) { return read(r, p.position) && r.get(p.heading); }
void put(Writer& w, bool b) { w.put(static_cast<std::uint8_t>(b)); }
bool get(Reader& r, bool& b) {
  std::uint8_t v = 0;
  if (!r.get(v)) return false;
  b = v != 0;
  return v <= 1 || r.fail("a flag that is neither 0 nor 1");
}

// A list: its count (at most `cap`), then each element.
template <class T, class Put>
void writeList(Writer& w, const std::vector<T>& list, std::uint32_t cap, Put put) {
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(list.size(), cap));
  w.put(n);
  for (std::uint32_t i = 0; i < n; ++i) put(list[i]);
}
template <class T, class Get>
bool readList(Reader& r, std::vector<T>& list, std::uint32_t cap, const char* what, Get get) {
  std::uint32_t n = 0;
  if (!r.count(n, cap, what)) return false;
  list.resize(std::min<std::uint32_t>(n, 1024));  // grows only as elements really arrive
  for (std::uint32_t i = 0; i < n; ++i) {
    if (i == list.size()) list.emplace_back();
    if (!get(list[i])) return false;
  }
  list.resize(n);
  return true;
}

void write(Writer& w, const RobotSpec& s) {
  w.put(s.radius);
  writeList(w, s.sonarAngles, kSonars, [&](double v) { w.put(v); });
  w.put(s.sonarMinRange), w.put(s.sonarMaxRange);
}

bool read(Reader& r, RobotSpec& s) {
  return r.get(s.radius) && readList(r, s.sonarAngles, kSonars, "sonars", [&](double& v) { return r.get(v); }) && r.get(s.sonarMinRange) &&
         r.get(s.sonarMaxRange);
}

void write(Writer& w, const Picture& p) {
  writeList(w, p.shapes(), kShapesPerStep, [&](const Shape& s) {
    w.put(static_cast<std::uint8_t>(s.kind));
    writeList(w, s.points, kPointsPerShape, [&](const Point2& q) { write(w, q); });
    w.put(s.radius);
    w.put(s.text, kNameBytes);
    w.put(s.value);
    put(w, s.color.has_value());
    if (s.color) w.put(*s.color);
  });
}

bool read(Reader& r, Picture& p) {
  std::vector<Shape> shapes;
  const bool ok = readList(r, shapes, kShapesPerStep, "shapes in a picture", [&](Shape& s) {
    std::uint8_t kind = 0;
    bool colored = false;
    if (!r.get(kind)) return false;
    if (kind > static_cast<std::uint8_t>(Shape::Kind::Value)) return r.fail("a shape of no known kind");
    s.kind = static_cast<Shape::Kind>(kind);
    if (!readList(r, s.points, kPointsPerShape, "points in a shape", [&](Point2& q) { return read(r, q); }) || !r.get(s.radius) ||
        !r.get(s.text, kNameBytes, "a label") || !r.get(s.value) || !get(r, colored)) {
      return false;
    }
    if (colored) s.color.emplace();
    return !colored || r.get(*s.color);
  });
  if (ok) p = Picture(std::move(shapes));
  return ok;
}

void write(Writer& w, const TaskRecord& t) {
  w.put(t.id), w.put(t.parent), w.put(t.depth), w.put(t.name, kNameBytes), w.put(t.where, kNameBytes), w.put(t.start), w.put(t.end);
  w.put(static_cast<std::uint8_t>(t.how));
  w.put(t.detail, kMessageBytes);
}

bool read(Reader& r, TaskRecord& t) {
  std::uint8_t how = 0;
  if (!(r.get(t.id) && r.get(t.parent) && r.get(t.depth) && r.get(t.name, kNameBytes, "a task's name") &&
        r.get(t.where, kNameBytes, "a task's place") && r.get(t.start) && r.get(t.end) && r.get(how) &&
        r.get(t.detail, kMessageBytes, "a task's result"))) {
    return false;
  }
  if (how > static_cast<std::uint8_t>(TaskEnd::Replaced)) return r.fail("a task that ended in no known way");
  t.how = static_cast<TaskEnd>(how);
  return true;
}

}  // namespace

void write(Writer& w, const SensorFrame& f) {
  writeList(w, f.sonar, kSonars, [&](double v) { w.put(v); });
  write(w, f.odometry);
  w.put(f.velocity), w.put(f.turnRate);
  writeList(w, f.bumps, kSonars, [&](const BumperHit& b) { w.put(b.bumper), w.put(b.angle); });
  writeList(w, f.keys, kSonars, [&](char k) { w.put(k); });
}

bool read(Reader& r, SensorFrame& f) {
  return readList(r, f.sonar, kSonars, "sonars", [&](double& v) { return r.get(v); }) && read(r, f.odometry) && r.get(f.velocity) &&
         r.get(f.turnRate) && readList(r, f.bumps, kSonars, "bumps", [&](BumperHit& b) { return r.get(b.bumper) && r.get(b.angle); }) &&
         readList(r, f.keys, kSonars, "keys", [&](char& k) { return r.get(k); });
}

void write(Writer& w, const LoadReply& reply) {
  w.put(reply.seccomp.name, kNameBytes), put(w, reply.seccomp.applied), w.put(reply.seccomp.note, kMessageBytes);
  writeList(w, reply.modules, kModules, [&](const LoadReply::Module& m) {
    put(w, m.loaded);
    if (!m.loaded) return w.put(m.error, kMessageBytes);
    w.put(m.name, kNameBytes), w.put(m.world, kMessageBytes), w.put(m.seconds), w.put(m.summary, kMessageBytes);
  });
}

bool read(Reader& r, LoadReply& reply) {
  return r.get(reply.seccomp.name, kNameBytes, "a layer's name") && get(r, reply.seccomp.applied) &&
         r.get(reply.seccomp.note, kMessageBytes, "a layer's note") && readList(r, reply.modules, kModules, "modules", [&](LoadReply::Module& m) {
           if (!get(r, m.loaded)) return false;
           if (!m.loaded) return r.get(m.error, kMessageBytes, "a load error");
           return r.get(m.name, kNameBytes, "a controller's name") && r.get(m.world, kMessageBytes, "a world's name") && r.get(m.seconds) &&
                  r.get(m.summary, kMessageBytes, "a summary");
         });
}

void write(Writer& w, const BuildRequest& request) {
  writeList(w, request.robots, std::numeric_limits<std::uint32_t>::max(), [&](const BuildRequest::Robot& robot) {
    w.put(robot.module);
    write(w, robot.spec);
  });
}

bool read(Reader& r, BuildRequest& request) {
  return readList(r, request.robots, std::numeric_limits<std::uint32_t>::max(), "robots",
                  [&](BuildRequest::Robot& robot) { return r.get(robot.module) && read(r, robot.spec); });
}

void write(Writer& w, const StepReply& reply) {
  w.put(reply.state);
  w.put(reply.wheels.forward), w.put(reply.wheels.turn);
  if (reply.state == StepReply::State::FailedNow) w.put(reply.failure, kMessageBytes);
  writeList(w, reply.records, kRecordsPerStep, [&](const TaskRecord& t) { write(w, t); });
  put(w, reply.hasPicture);
  if (reply.hasPicture) write(w, reply.picture);
}

bool read(Reader& r, StepReply& reply) {
  if (!r.get(reply.state)) return false;
  if (reply.state > StepReply::State::Done) return r.fail("a controller state of no known kind");
  if (!r.get(reply.wheels.forward) || !r.get(reply.wheels.turn)) return false;
  if (reply.state == StepReply::State::FailedNow && !r.get(reply.failure, kMessageBytes, "a failure")) return false;
  if (!readList(r, reply.records, kRecordsPerStep, "task starts and ends in one step", [&](TaskRecord& t) { return read(r, t); })) return false;
  if (!get(r, reply.hasPicture)) return false;
  return !reply.hasPicture || read(r, reply.picture);
}

namespace {

template <class Message>
bool writeFramedMessage(std::span<std::byte> area, const Message& message) {
  Writer w(area.subspan(sizeof(std::uint32_t)));
  write(w, message);
  const auto length = static_cast<std::uint32_t>(w.size());
  std::memcpy(area.data(), &length, sizeof length);
  return w.ok();
}

// Its length read once, then that many bytes copied: the host may change the area meanwhile.
template <class Message>
Status readFramedMessage(std::span<const std::byte> area, std::vector<std::byte>& copy, Message& message) {
  std::uint32_t length = 0;
  std::memcpy(&length, area.data(), sizeof length);
  if (length > area.size() - sizeof length) return Status::failure("a reply longer than its area");
  copy.assign(area.begin() + sizeof length, area.begin() + sizeof length + length);
  Reader r(copy);
  if (!read(r, message)) return Status::failure(r.why());
  return {};
}

}  // namespace

bool writeFramed(std::span<std::byte> area, const StepReply& reply) { return writeFramedMessage(area, reply); }
bool writeFramed(std::span<std::byte> area, const LoadReply& reply) { return writeFramedMessage(area, reply); }

Status readFramed(std::span<const std::byte> area, std::vector<std::byte>& copy, StepReply& reply) { return readFramedMessage(area, copy, reply); }
Status readFramed(std::span<const std::byte> area, std::vector<std::byte>& copy, LoadReply& reply) { return readFramedMessage(area, copy, reply); }

Status RunBudget::take(const StepReply& reply) {
  for (const TaskRecord& t : reply.records) {
    bytes_ += sizeof t + t.name.size() + t.where.size() + t.detail.size();
    if (t.how != TaskEnd::Running) {
      if (open_.erase(t.id) == 0) return Status::failure("ended a task that was not running");
      continue;
    }
    if (t.id != started_) return Status::failure("started a task out of order");
    if (open_.size() == kOpenTasks) return Status::failure("more than " + std::to_string(kOpenTasks) + " tasks running at once");
    ++started_;
    open_.insert(t.id);
  }
  if (reply.hasPicture) {
    for (const Shape& s : reply.picture.shapes()) {
      bytes_ += sizeof s + s.points.size() * sizeof(Point2) + s.text.size();
      if (s.kind != Shape::Kind::Value || plotNames_.contains(s.text)) continue;
      if (plotNames_.size() == kPlotNames) return Status::failure("more than " + std::to_string(kPlotNames) + " names of plotted values");
      plotNames_.insert(s.text);
    }
  }
  if (bytes_ > kRunBytes) return Status::failure("more than " + std::to_string(kRunBytes >> 20) + " MB of task records and pictures in one run");
  return {};
}

}  // namespace frob::sandbox
