#include "frob/run/fork.hpp"

#include "frob/run/format.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace frob::course {

namespace {

// The cells of one CSV line; a quoted cell (a task's name) only at the end, which is not needed.
std::vector<std::string_view> cells(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t at = 0; at <= line.size();) {
    if (at < line.size() && line[at] == '"') break;
    const std::size_t end = std::min(line.find(',', at), line.size());
    out.push_back(line.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

bool number(std::string_view text, double& out) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size();
}

class ForkDriver final : public worlds::ControllerDriver {
 public:
  ForkDriver(const ForkPoint& fork, const worlds::Simulation& sim, std::unique_ptr<worlds::ControllerDriver> controllers)
      : fork_(fork), sim_(sim), controllers_(std::move(controllers)) {}

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    const auto k = static_cast<std::size_t>(now.step);
    if (k < fork_.poses.size()) {  // the earlier run's instant: the same world to the last bit, or not this run at all
      for (std::size_t i = 0; i < wheels.size() && !strayed_; ++i) {
        const Pose2 was = fork_.poses[k][i], is = sim_.truePose(i);
        if (was.position.x() == is.position.x() && was.position.y() == is.position.y() && was.heading == is.heading) continue;
        strayed_ = true;
        failed.emplace_back(i, format("the run strays from %s at %.2f s: it is not a run of this world and seed (give frob run that run's --world, "
                                      "--seed and --dt)",
                                      fork_.source.c_str(), now.time));
      }
    }
    if (k < fork_.wheels.size()) {
      for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = fork_.wheels[k][i];
      return;
    }
    controllers_->decide(now, wheels, pictures, failed);
  }
  Timeline& timeline(std::size_t i) override { return controllers_->timeline(i); }

 private:
  const ForkPoint& fork_;
  const worlds::Simulation& sim_;
  std::unique_ptr<worlds::ControllerDriver> controllers_;
  bool strayed_ = false;
};

}  // namespace

Result<ForkPoint> readForkPoint(const std::string& spec, double dt) {
  const std::size_t hash = spec.rfind("#t=");
  ForkPoint f{.source = spec.substr(0, hash)};
  if (hash == std::string::npos || !number(std::string_view(spec).substr(hash + 3), f.at) || !(f.at >= 0)) {
    return Status::failure("--from " + spec + ": give an earlier run's trace and an instant of it, e.g. run.csv#t=12.5");
  }
  if (f.source.ends_with(".html")) {
    return Status::failure("--from " + f.source +
                           ": a run viewer page keeps the run to the millimetre, not to the last bit: fork from that run's "
                           "--trace (frob run ... --trace run.csv, then --from run.csv#t=" +
                           spec.substr(hash + 3) + ")");
  }
  std::ifstream in(f.source);
  if (!in) return Status::failure("--from: cannot read the trace '" + f.source + "' (write one with frob run --trace)");
  const auto bad = [&](std::size_t line, const std::string& why) {
    return Status::failure(format("--from: %s:%zu: %s", f.source.c_str(), line, why.c_str()));
  };
  std::string line;
  if (!std::getline(in, line) || !line.starts_with("time,robot,true_x,true_y,true_heading,odom_x,odom_y,odom_heading,forward,turn,")) {
    return bad(1, "not a trace of frob run (its first line names time, robot, true_x, ...)");
  }
  const auto steps = static_cast<std::size_t>(std::llround(f.at / dt));
  for (std::size_t n = 2; std::getline(in, line); ++n) {
    const std::vector<std::string_view> c = cells(line);
    double v[10];
    for (std::size_t j = 0; j < 10; ++j) {
      if (j >= c.size() || !number(c[j], v[j])) return bad(n, "not a row of numbers where a trace has them");
    }
    const auto k = static_cast<std::size_t>(std::llround(v[0] / dt)), robot = static_cast<std::size_t>(v[1]);
    if (std::abs(static_cast<double>(k) * dt - v[0]) > 1e-6 || v[1] != static_cast<double>(robot))
      return bad(n, "a time or robot that is not a step's");
    if (k > steps) break;
    if (k >= f.poses.size()) f.poses.resize(k + 1), f.wheels.resize(k + 1);
    if (robot != f.poses[k].size()) return bad(n, "rows out of order (each step's robots in turn)");
    f.poses[k].push_back(Pose2{Point2(v[2], v[3]), v[4]});
    f.wheels[k].push_back(Wheels{v[8], v[9]});
  }
  if (f.poses.size() != steps + 1) {
    return Status::failure(format("--from: %s has its run up to %.2f s, not to %.2f s", f.source.c_str(),
                                  f.poses.empty() ? 0.0 : static_cast<double>(f.poses.size() - 1) * dt, f.at));
  }
  f.wheels.pop_back();  // the controllers decide at the instant itself
  return f;
}

worlds::DriverFactory forkedAt(const ForkPoint& fork, worlds::DriverFactory controllers) {
  return [&fork, controllers = std::move(controllers)](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    return std::make_unique<ForkDriver>(fork, sim, controllers(sim));
  };
}

}  // namespace frob::course
