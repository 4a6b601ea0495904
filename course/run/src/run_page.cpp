// The run viewer page. Its data is one JSON document, deflated (zlib) and written in base64 inside
// the page, which inflates it with the browser's DecompressionStream. Poses, odometry, wheels and
// sonar are columns of whole thousandths (mm, mrad, mm/s), each the difference from the one before;
// pictures are kept when they change; published values as their changes. Text from the controller
// (task names, picture text, value names) only ever reaches the page inside that data, and the page
// sets it as text, never as markup; its policy runs no script but its own.

#include "run_page.hpp"

#include "frob/render/output_file.hpp"
#include "frob/render/run_view.hpp"

#include <openssl/evp.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace frob::course {

namespace {

// The page, with FROB_SCRIPT_HASH and FROB_RUN_DATA to fill (course/run/viewer/run_viewer.html).
#include "run_viewer_page.inc"

// Pictures kept at every change until they take this much (a rough count of their JSON), then at
// most one per kSparsePictureSamples, and none past twice as much.
constexpr std::uint64_t kPictureBudget = 6'000'000;
constexpr std::int64_t kSparsePictureSamples = 10;
constexpr std::size_t kMaxPublished = 24;         // published values kept per robot
constexpr std::uint64_t kTaskBudget = 6'000'000;  // bytes of task names, places and results kept per robot
constexpr std::size_t kDetailBytes = 256;         // of a task's result or error, what the page keeps

std::int64_t thousandths(double v) { return std::isfinite(v) ? std::llround(std::clamp(v, -1e9, 1e9) * 1000.0) : 0; }
double millis(double v) { return static_cast<double>(thousandths(v)) / 1000.0; }

std::string hexColor(const Color& c) {
  auto byte = [](float v) { return static_cast<unsigned>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  char buf[10];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b), byte(c.a));
  return buf;
}

// A picture's drawn shapes as [kind, colour, radius, text, [x0, y0, x1, y1, ...]], to the millimetre.
nlohmann::json shapesOf(const Picture& p, std::uint64_t& bytes) {
  nlohmann::json out = nlohmann::json::array();
  for (const Shape& s : p.shapes()) {
    if (s.kind == Shape::Kind::Value) continue;
    nlohmann::json points = nlohmann::json::array();
    bool finite = std::isfinite(s.radius);
    for (const Point2& q : s.points) {
      finite = finite && q.allFinite();
      points.push_back(millis(q.x()));
      points.push_back(millis(q.y()));
    }
    if (!finite) continue;  // drawn nowhere
    bytes += 32 + 12 * s.points.size() + s.text.size();
    out.push_back(
        {static_cast<int>(s.kind), s.color ? nlohmann::json(hexColor(*s.color)) : nlohmann::json(), millis(s.radius), s.text, std::move(points)});
  }
  return out;
}

// A picture without its published values: what is drawn.
Picture drawnPart(const Picture& p) {
  std::vector<Shape> drawn;
  for (const Shape& s : p.shapes()) {
    if (s.kind != Shape::Kind::Value) drawn.push_back(s);
  }
  return Picture(std::move(drawn));
}

std::string base64(const unsigned char* bytes, std::size_t n) {
  std::string out(4 * ((n + 2) / 3) + 1, '\0');
  out.resize(static_cast<std::size_t>(EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()), bytes, static_cast<int>(n))));
  return out;
}

// The Content-Security-Policy source that lets exactly `script` run.
std::string scriptHash(std::string_view script) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  EVP_Digest(script.data(), script.size(), digest, &n, EVP_sha256(), nullptr);
  return "'sha256-" + base64(digest, n) + "'";
}

void replaceOnce(std::string& text, std::string_view marker, const std::string& with) {
  const std::size_t at = text.find(marker);
  FROB_ASSERT(at != std::string::npos, "run viewer page: a marker is missing");
  text.replace(at, marker.size(), with);
}

}  // namespace

void RunPage::Column::add(double v) {
  const std::int64_t q = thousandths(v);
  deltas.push_back(q - last);
  last = q;
}

Result<RunPage> RunPage::open(const std::string& path, const worlds::Simulation& sim, double sonarHalfAngle) {
  if (Status s = render::checkWritable(path, "html"); !s) return s;
  return RunPage(path, sim, sonarHalfAngle);
}

RunPage::RunPage(std::string path, const worlds::Simulation& sim, double sonarHalfAngle) : path_(std::move(path)), dt_(sim.dt()) {
  const render::FrameScene scene = render::staticScene(sim);
  nlohmann::json walls = nlohmann::json::array(), blocks = nlohmann::json::array(), pillars = nlohmann::json::array(),
                 points = nlohmann::json::array();
  for (const render::Wall& w : scene.walls) walls.push_back({w.a.x(), w.a.y(), w.b.x(), w.b.y(), w.thickness});
  for (const render::Block& b : scene.blocks) blocks.push_back({b.center.x(), b.center.y(), b.halfExtents.x(), b.halfExtents.y(), b.angle});
  for (const render::Pillar& p : scene.pillars) pillars.push_back({p.center.x(), p.center.y(), p.radius});
  for (const render::Marker& m : scene.points) points.push_back({m.name, m.at.x(), m.at.y()});
  world_ = {{"bounds", {scene.bounds.min.x(), scene.bounds.min.y(), scene.bounds.max.x(), scene.bounds.max.y()}},
            {"walls", std::move(walls)},
            {"blocks", std::move(blocks)},
            {"pillars", std::move(pillars)},
            {"points", std::move(points)},
            {"sonarHalfAngle", sonarHalfAngle},
            {"robots", nlohmann::json::array()}};
  const std::optional<Point2> goal = worlds::findPoint(sim.world(), "goal");
  for (std::size_t i = 0; i < sim.robotCount(); ++i) {
    const RobotSpec& spec = sim.spec(i);
    world_["robots"].push_back({{"name", sim.robotName(i)},
                                {"radius", spec.radius},
                                {"sonarAngles", spec.sonarAngles},
                                {"sonarMax", spec.sonarMaxRange},
                                {"front", render::frontSonarIndex(spec)},
                                {"goal", goal ? nlohmann::json{goal->x(), goal->y()} : nlohmann::json()},
                                {"goalName", "goal"}});
    robots_.emplace_back().sonar.resize(spec.sonarAngles.size());
  }
}

void RunPage::keepPicture(Track& t, const Picture& picture) {
  // Published values: each one's changes.
  for (const Shape& s : picture.shapes()) {
    if (s.kind != Shape::Kind::Value) continue;
    auto [at, added] = t.publishedIndex.try_emplace(s.text, t.published.size());
    if (added) {
      if (t.published.size() == kMaxPublished) {
        t.publishedIndex.erase(at);
        continue;
      }
      t.published.push_back({s.text, s.color, {}});
    }
    std::vector<std::pair<std::int64_t, double>>& changes = t.published[at->second].changes;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", s.value);  // six figures: what a reader of the table or chart can use
    const double v = std::strtod(buf, nullptr);
    const bool same = !changes.empty() && (changes.back().second == v || (std::isnan(v) && std::isnan(changes.back().second)));
    if (!same) changes.emplace_back(samples_, v);
  }
  // The drawn shapes, when they changed (and, past the budget, not too often).
  Picture drawn = drawnPart(picture);
  if (drawn == t.shown && !t.pictures.empty()) return;
  if (pictureBytes_ > 2 * kPictureBudget) {
    picturesStopped_ = true;
    return;
  }
  if (pictureBytes_ > kPictureBudget && !t.pictures.empty() && samples_ - t.pictures.back().first < kSparsePictureSamples) return;
  t.pictures.emplace_back(samples_, shapesOf(drawn, pictureBytes_));
  t.shown = std::move(drawn);
}

void RunPage::step(const worlds::StepRecord& rec) {
  if (!t0_) t0_ = rec.time;
  for (std::size_t i = 0; i < rec.robots.size() && i < robots_.size(); ++i) {
    const worlds::RobotRecord& r = rec.robots[i];
    Track& t = robots_[i];
    t.x.add(r.truePose.position.x());
    t.y.add(r.truePose.position.y());
    t.h.add(r.truePose.heading);
    t.ox.add(r.odometry.position.x());
    t.oy.add(r.odometry.position.y());
    t.oh.add(r.odometry.heading);
    t.forward.add(r.wheels.forward);
    t.turn.add(r.wheels.turn);
    t.wheels.push_back(r.wheels);
    for (std::size_t k = 0; k < t.sonar.size(); ++k) t.sonar[k].add(k < r.sonar.size() ? r.sonar[k] : 0.0);
    for (const BumperHit& b : r.bumps) t.bumps.emplace_back(samples_, thousandths(b.angle));
    for (char key : r.keys) t.keys.emplace_back(samples_, std::string(1, key));
    keepPicture(t, r.picture);
  }
  ++samples_;
}

Result<std::uint64_t> RunPage::write(const RunPageEnd& end) const {
  if (samples_ == 0) return Status::failure("html: the run took no step, so there is nothing to show");
  nlohmann::json doc = world_;
  std::string subtitle = end.subtitle;
  if (pictureBytes_ > kPictureBudget)
    subtitle += " Pictures were kept at most every " + std::to_string(kSparsePictureSamples) + " steps once they grew large" +
                (picturesStopped_ ? ", and then no more." : ".");
  doc["title"] = end.title;
  doc["dt"] = dt_;
  doc["t0"] = t0_.value_or(0.0);
  doc["samples"] = samples_;
  for (std::size_t i = 0; i < robots_.size(); ++i) {
    const Track& t = robots_[i];
    nlohmann::json& r = doc["robots"][i];
    nlohmann::json sonar = nlohmann::json::array();
    for (const Column& c : t.sonar) sonar.push_back(c.deltas);
    r["q"] = {{"x", t.x.deltas},   {"y", t.y.deltas},        {"h", t.h.deltas},     {"ox", t.ox.deltas},    {"oy", t.oy.deltas},
              {"oh", t.oh.deltas}, {"fw", t.forward.deltas}, {"tu", t.turn.deltas}, {"s", std::move(sonar)}};
    nlohmann::json wheels = nlohmann::json::array();  // [forward, turn] per sample, to the last bit
    for (const Wheels& w : t.wheels) wheels.push_back({w.forward, w.turn});
    r["wheels"] = std::move(wheels);
    r["bumps"] = t.bumps;
    r["keys"] = t.keys;
    nlohmann::json pictures = nlohmann::json::array();
    for (const auto& [at, shapes] : t.pictures) pictures.push_back({at, shapes});
    r["pictures"] = std::move(pictures);
    nlohmann::json values = nlohmann::json::array();
    for (const Published& p : t.published) values.push_back({p.name, p.color ? nlohmann::json(hexColor(*p.color)) : nlohmann::json(), p.changes});
    r["values"] = std::move(values);
    r["controller"] = i < end.controllers.size() ? end.controllers[i] : "";
    r["finishedAt"] = i < end.finishedAt.size() && end.finishedAt[i] ? nlohmann::json(*end.finishedAt[i]) : nlohmann::json();
    nlohmann::json tasks = nlohmann::json::array();
    std::uint64_t taskBytes = 0;
    if (i < end.tasks.size()) {
      for (const TaskRecord& task : end.tasks[i]) {
        taskBytes += 64 + task.name.size() + task.where.size() + std::min(task.detail.size(), kDetailBytes);
        if (taskBytes > kTaskBudget) {
          subtitle += " Only the first " + std::to_string(tasks.size()) + " of " + std::to_string(end.tasks[i].size()) + " tasks of " +
                      doc["robots"][i]["name"].get<std::string>() + " are shown.";
          break;
        }
        const bool running = task.how == TaskEnd::Running;
        tasks.push_back({{"name", task.name},
                         {"where", task.where},
                         {"depth", task.depth},
                         {"start", task.start},
                         {"end", running ? nlohmann::json() : nlohmann::json(task.end)},
                         {"how", toString(task.how)},
                         {"detail", task.detail.substr(0, kDetailBytes)}});
      }
    }
    r["tasks"] = std::move(tasks);
    // An assignment's measures, at the page's instants: name, unit, band and values as the columns are kept.
    nlohmann::json judged = nlohmann::json::array();
    for (const Measured& m : end.measured) {
      if (m.robot != i || m.values.empty()) continue;
      Column c;
      for (std::int64_t k = 0; k < samples_; ++k) {
        const double at = std::round((t0_.value_or(0.0) + static_cast<double>(k) * dt_) / m.dt);
        c.add(m.values[static_cast<std::size_t>(std::clamp(at, 0.0, static_cast<double>(m.values.size() - 1)))]);
      }
      const auto bound = [](const std::optional<double>& b) { return b ? nlohmann::json(*b) : nlohmann::json(); };
      judged.push_back({{"name", m.name},
                        {"unit", m.unit},
                        {"low", bound(m.low)},
                        {"high", bound(m.high)},
                        {"each", m.everyInstant},
                        {"from", m.from},
                        {"v", c.deltas}});
    }
    r["judged"] = std::move(judged);
  }
  doc["subtitle"] = subtitle;
  // The controller's strings may hold any bytes: what is not UTF-8 becomes U+FFFD.
  const std::string json = doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  uLongf packedSize = compressBound(json.size());
  std::vector<unsigned char> packed(packedSize);
  if (compress2(packed.data(), &packedSize, reinterpret_cast<const Bytef*>(json.data()), json.size(), Z_BEST_COMPRESSION) != Z_OK) {
    return Status::failure("html: compressing the run failed");
  }

  std::string page(kRunViewerPage);
  // The policy names the hash of the page's own script: all between <script> and </script>.
  const std::size_t scriptAt = page.find("<script>\n") + 8, scriptEnd = page.find("</script>", scriptAt);
  replaceOnce(page, "FROB_SCRIPT_HASH", scriptHash(std::string_view(page).substr(scriptAt, scriptEnd - scriptAt)));
  replaceOnce(page, "FROB_RUN_DATA", base64(packed.data(), packedSize));
  {
    std::ofstream out(render::partialPath(path_), std::ios::binary);
    out << page;
    if (!out.flush()) {
      render::discardPartial(path_);
      return Status::failure("html: writing '" + path_ + "' failed (disk full?)");
    }
  }
  if (Status s = render::commitPartial(path_, "html"); !s) return s;
  return static_cast<std::uint64_t>(page.size());
}

}  // namespace frob::course
