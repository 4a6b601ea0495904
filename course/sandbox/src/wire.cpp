#include "frob/sandbox/wire.hpp"

#include <cmath>

namespace frob::sandbox {

void Writer::put(std::string_view s) {
  s = s.substr(0, kMaxString);
  put(static_cast<std::uint32_t>(s.size()));
  if (!fits(s.size())) return;
  std::memcpy(area_.data() + used_, s.data(), s.size());
  used_ += s.size();
}

bool Reader::get(std::string& s) {
  std::uint32_t n = 0;
  if (!count(n, kMaxString) || n > bytes_.size() - used_) return ok_ = false;
  s.assign(reinterpret_cast<const char*>(bytes_.data() + used_), n);
  used_ += n;
  return true;
}

bool Reader::count(std::uint32_t& n, std::uint32_t max) { return get(n) && (n <= max || fail()); }

namespace {

void write(Writer& w, const Point2& p) { w.put(p.x()), w.put(p.y()); }
bool read(Reader& r, Point2& p) { return r.get(p.x()) && r.get(p.y()); }
void write(Writer& w, const Pose2& p) { write(w, p.position), w.put(p.heading); }
bool read(Reader& r, Pose2& p) { return read(r, p.position) && r.get(p.heading); }

// A list: its count, then each element.
template <class T, class Put>
void writeList(Writer& w, const std::vector<T>& list, Put put) {
  w.put(static_cast<std::uint32_t>(list.size()));
  for (const T& v : list) put(v);
}
template <class T, class Get>
bool readList(Reader& r, std::vector<T>& list, Get get) {
  std::uint32_t n = 0;
  if (!r.count(n)) return false;
  list.resize(std::min<std::uint32_t>(n, 1024));  // grows only as elements really arrive
  for (std::uint32_t i = 0; i < n; ++i) {
    if (i == list.size()) list.emplace_back();
    if (!get(list[i])) return false;
  }
  list.resize(n);
  return true;
}

}  // namespace

void write(Writer& w, const SensorFrame& f) {
  writeList(w, f.sonar, [&](double v) { w.put(v); });
  write(w, f.odometry);
  w.put(f.velocity), w.put(f.turnRate);
  writeList(w, f.bumps, [&](const BumperHit& b) { w.put(b.bumper), w.put(b.angle); });
  writeList(w, f.keys, [&](char k) { w.put(k); });
}

bool read(Reader& r, SensorFrame& f) {
  return readList(r, f.sonar, [&](double& v) { return r.get(v); }) && read(r, f.odometry) && r.get(f.velocity) && r.get(f.turnRate) &&
         readList(r, f.bumps, [&](BumperHit& b) { return r.get(b.bumper) && r.get(b.angle); }) &&
         readList(r, f.keys, [&](char& k) { return r.get(k); });
}

void write(Writer& w, const RobotSpec& s) {
  w.put(s.radius);
  writeList(w, s.sonarAngles, [&](double v) { w.put(v); });
  w.put(s.sonarMinRange), w.put(s.sonarMaxRange);
}

bool read(Reader& r, RobotSpec& s) {
  return r.get(s.radius) && readList(r, s.sonarAngles, [&](double& v) { return r.get(v); }) && r.get(s.sonarMinRange) && r.get(s.sonarMaxRange);
}

void write(Writer& w, const Picture& p) {
  writeList(w, p.shapes(), [&](const Shape& s) {
    w.put(static_cast<std::uint8_t>(s.kind));
    writeList(w, s.points, [&](const Point2& q) { write(w, q); });
    w.put(s.radius);
    w.put(s.text);
    w.put(s.value);
    w.put(static_cast<std::uint8_t>(s.color.has_value()));
    if (s.color) w.put(*s.color);
  });
}

bool read(Reader& r, Picture& p) {
  std::vector<Shape> shapes;
  const bool ok = readList(r, shapes, [&](Shape& s) {
    std::uint8_t kind = 0, colored = 0;
    if (!r.get(kind) || kind > static_cast<std::uint8_t>(Shape::Kind::Value)) return r.fail();
    s.kind = static_cast<Shape::Kind>(kind);
    if (!readList(r, s.points, [&](Point2& q) { return read(r, q); }) || !r.get(s.radius) || !r.get(s.text) || !r.get(s.value) || !r.get(colored)) {
      return false;
    }
    if (colored != 0) s.color.emplace();
    return colored == 0 || r.get(*s.color);
  });
  if (ok) p = Picture(std::move(shapes));
  return ok;
}

void write(Writer& w, const TaskRecord& t) {
  w.put(t.id), w.put(t.parent), w.put(t.depth), w.put(t.name), w.put(t.where), w.put(t.start), w.put(t.end);
  w.put(static_cast<std::uint8_t>(t.how));
  w.put(t.detail);
}

bool read(Reader& r, TaskRecord& t) {
  std::uint8_t how = 0;
  if (!(r.get(t.id) && r.get(t.parent) && r.get(t.depth) && r.get(t.name) && r.get(t.where) && r.get(t.start) && r.get(t.end) && r.get(how) &&
        r.get(t.detail))) {
    return false;
  }
  if (how > static_cast<std::uint8_t>(TaskEnd::Replaced)) return r.fail();
  t.how = static_cast<TaskEnd>(how);
  return true;
}

}  // namespace frob::sandbox
