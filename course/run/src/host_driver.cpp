// Runs driven by controller hosts: each step the robots' frames go out and their replies come back,
// read against the caps of a step and of a run (once every robot of a host is done, only every
// kIdleAsk steps). A run gives each robot a host of its own.
#include "frob/sandbox/wire.hpp"
#include "host_cores.hpp"
#include "host_impl.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace frob::course {

using namespace host_detail;

namespace {

// A host whose robots are all done is asked only every this many steps: whatever it still does (a
// thread, a picture it published) is checked for crashes and limits, but its answer, a stop, is known.
constexpr std::int64_t kIdleAsk = 64;

// Controllers sampled in the host: each step (while any is not done) the frames go out and the
// replies come back. It drives the robots `robots` of the run (their indices in it), robot k of
// them with module modules[k].
class HostDriver final : public worlds::ControllerDriver {
 public:
  HostDriver(std::shared_ptr<ControllerHost> owner, ControllerHost::Impl& host, const worlds::Simulation& sim, std::vector<std::uint32_t> robots,
             const std::vector<std::size_t>& modules, bool pictures)
      : owner_(std::move(owner)),
        host_(host),
        sim_(sim),
        robots_(std::move(robots)),
        pictures_(pictures),
        timelines_(robots_.size()),
        budgets_(robots_.size()),
        stopped_(robots_.size(), false),
        finished_(robots_.size(), false) {
    const auto n = static_cast<std::uint32_t>(robots_.size());
    FROB_ASSERT(!host.driving, "a controller host drives one run");
    FROB_ASSERT(modules.size() == 1 || modules.size() == n, "give one module per robot, or one for all");
    FROB_ASSERT(n <= std::max<std::uint32_t>(host.def.robots, 1), "a controller host drives at most the robots its HostDef names");
    host.driving = true;
    sandbox::BuildRequest request;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::size_t m = modules.size() == 1 ? modules.front() : modules[k];
      FROB_ASSERT(m < host.entries.size(), "no such module in this host");
      request.robots.push_back({static_cast<std::uint32_t>(m), sim.spec(robots_[k])});
    }
    sandbox::Writer w(host.channel.setup());
    sandbox::write(w, request);
    FROB_ASSERT(w.ok(), "a build request larger than the channel's setup area");
    sandbox::Header& h = host.header();
    h.dt = sim.dt();
    h.command = sandbox::Command::Build;
    host.waited = 0.0;  // the run's pace counts from here: loading had its own limit
    sandbox::ring(h.request, host.sequence, -1);
    lost_ = host.await(++host.sequence, host.def.startSeconds, true);
    if (lost_) lost_ = host.refusal();
    if (!lost_) lost_ = Status::failure(lost_.error() + when(0.0, host.header().activity));
  }

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    send(now);
    receive(now, wheels, pictures, failed);
  }

  // Hands the host its robots' frames and asks it for their wheels.
  void send(const Instant& now) {
    asked_ = lost_ && !dead_ && (!idle() || now.step % kIdleAsk == 0);
    if (!asked_) return;
    sandbox::Header& h = host_.header();
    for (std::uint32_t k = 0; k < robots_.size(); ++k) {
      sandbox::Writer w(host_.channel.frameArea(k));
      sandbox::write(w, sim_.frame(robots_[k]));
      FROB_ASSERT(w.ok(), "a sensor frame larger than its area of the channel");
    }
    h.command = sandbox::Command::Step;
    h.step = now.step;
    host_.simulated = now.time;
    sandbox::ring(h.request, host_.sequence, -1);
  }

  // Waits for the host's answer and takes its robots' wheels (and pictures) from it.
  void receive(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures, std::vector<std::pair<std::size_t, std::string>>& failed) {
    if (!lost_) return fail(failed, lost_.error());
    if (dead_) return;
    if (now.step % 64 == 0) host_.drainOutput();  // a student's prints appear as the run goes
    // A robot that is done stands still whatever its host says (its picture is the last one sent).
    for (std::uint32_t k = 0; k < robots_.size(); ++k) {
      if (finished_[k]) wheels[robots_[k]] = Wheels{};
    }
    if (!asked_) return;
    const auto at = [&] {  // formatted only for a failure: a step's budget is a few microseconds
      char text[48];
      std::snprintf(text, sizeof text, " at t = %.2f s", now.time);
      return std::string(text);
    };
    if (Status s = host_.await(++host_.sequence, host_.def.stepSeconds, false); !s) return fail(failed, s.error() + at());
    if (Status s = host_.refusal(); !s) return fail(failed, s.error() + at());
    for (std::uint32_t k = 0; k < robots_.size(); ++k) {
      if (stopped_[k]) continue;
      const std::uint32_t i = robots_[k];
      Wheels said;
      if (Status s = readReply(k, finished_[k] ? said : wheels[i], pictures[i], failed); !s) {
        stopped_[k] = true;
        wheels[i] = Wheels{};
        failed.emplace_back(i, "its controller host sent a reply that cannot be read: " + s.error());
      }
    }
  }

  Timeline& timeline(std::size_t i) override { return timelines_[indexOf(i)]; }
  bool finished(std::size_t i) const override { return finished_[indexOf(i)]; }

 private:
  // Robot `i` of the run as this host numbers it.
  [[nodiscard]] std::size_t indexOf(std::size_t i) const {
    const auto k = std::find(robots_.begin(), robots_.end(), i);
    FROB_ASSERT(k != robots_.end(), "this host does not drive that robot");
    return static_cast<std::size_t>(k - robots_.begin());
  }

  // Every robot is stopped or done: the host has nothing left to think about.
  [[nodiscard]] bool idle() const {
    for (std::size_t k = 0; k < robots_.size(); ++k) {
      if (!stopped_[k] && !finished_[k]) return false;
    }
    return true;
  }

  // The host is gone or lost: the robot it claims it was driving fails, the others stop.
  void fail(std::vector<std::pair<std::size_t, std::string>>& failed, const std::string& why) {
    const std::uint32_t k = host_.header().robot;
    failed.emplace_back(robots_[k < robots_.size() ? k : 0], why);
    stopped_.assign(stopped_.size(), true);
    lost_ = {};
    dead_ = true;
    host_.process.kill();
  }

  // Reads the reply of its robot k (robot robots_[k] of the run), checks it against the caps of a
  // step and of the run, and takes it in.
  Status readReply(std::uint32_t k, Wheels& wheels, Picture& picture, std::vector<std::pair<std::size_t, std::string>>& failed) {
    if (Status s = sandbox::readFramed(host_.channel.replyArea(k), copy_, reply_); !s) return s;
    if (Status s = budgets_[k].take(reply_); !s) return s;
    if (reply_.state == sandbox::StepReply::State::FailedNow) {
      stopped_[k] = true;
      failed.emplace_back(robots_[k], reply_.failure);
    }
    Timeline& timeline = timelines_[k];
    for (TaskRecord& t : reply_.records) {
      if (t.how == TaskEnd::Running) {
        timeline.start(t.parent, std::move(t.name), std::move(t.where), t.start);
      } else {
        timeline.end(t.id, t.end, t.how, std::move(t.detail));
      }
    }
    // Its task returned: the robot stands still from now on, and once all of the host's are done,
    // the host is asked only now and then. Claimed falsely, it only stops its own robot.
    if (reply_.state == sandbox::StepReply::State::Done) finished_[k] = true;
    if (pictures_ && reply_.hasPicture) picture = std::move(reply_.picture);
    // Only the controller's own word stops it.
    wheels = reply_.state == sandbox::StepReply::State::Running && isFinite(reply_.wheels) ? reply_.wheels : Wheels{};
    return {};
  }

  std::shared_ptr<ControllerHost> owner_;
  ControllerHost::Impl& host_;
  const worlds::Simulation& sim_;
  std::vector<std::uint32_t> robots_;
  bool pictures_;
  std::vector<Timeline> timelines_;  // each numbers its tasks as the host's does: the budget checks the order
  std::vector<sandbox::RunBudget> budgets_;
  std::vector<bool> stopped_;
  std::vector<bool> finished_;  // its task returned: it stands still, whatever its host says
  Status lost_;                 // why the host could not build the controllers, reported at the first step
  bool dead_ = false;
  bool asked_ = false;  // this step's frames went to the host
  std::vector<std::byte> copy_;
  sandbox::StepReply reply_;
};

// A host per robot: every host is handed its frame before any answer is awaited, so that they
// think at once, each on whatever core is free.
class PerRobotDriver final : public worlds::ControllerDriver {
 public:
  explicit PerRobotDriver(std::vector<std::unique_ptr<HostDriver>> drivers) : drivers_(std::move(drivers)) {}

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    for (const auto& d : drivers_) d->send(now);
    for (const auto& d : drivers_) d->receive(now, wheels, pictures, failed);
  }

  Timeline& timeline(std::size_t i) override { return drivers_.at(i)->timeline(i); }
  bool finished(std::size_t i) const override { return drivers_.at(i)->finished(i); }

 private:
  std::vector<std::unique_ptr<HostDriver>> drivers_;
};
}  // namespace

worlds::DriverFactory ControllerHost::driver(std::vector<std::size_t> modulePerRobot, bool pictures) {
  return [self = shared_from_this(), modulePerRobot = std::move(modulePerRobot),
          pictures](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    std::vector<std::uint32_t> all(sim.robotCount());
    std::iota(all.begin(), all.end(), 0u);
    return std::make_unique<HostDriver>(self, *self->impl_, sim, std::move(all), modulePerRobot, pictures);
  };
}

Result<RobotHosts> RobotHosts::start(const std::vector<fs::path>& modules, const std::vector<std::string>& sources,
                                     const std::vector<std::size_t>& modulePerRobot, std::size_t robots, HostDef def) {
  FROB_ASSERT(modulePerRobot.size() == 1 || modulePerRobot.size() == robots, "give one module per robot, or one for all");
  def.robots = 1;
  RobotHosts all;
  for (std::size_t i = 0; i < robots; ++i) {
    const std::size_t m = modulePerRobot.size() == 1 ? modulePerRobot.front() : modulePerRobot[i];
    Result<std::shared_ptr<ControllerHost>> host = ControllerHost::start({modules.at(m)}, {sources.at(m)}, def);
    if (!host) return host.status();
    all.hosts_.push_back(std::move(host.value()));
  }
  return all;
}

worlds::DriverFactory RobotHosts::driver(bool pictures) const {
  return [hosts = hosts_, pictures](const worlds::Simulation& sim) -> std::unique_ptr<worlds::ControllerDriver> {
    FROB_ASSERT(hosts.size() == sim.robotCount(), "these hosts were started for another number of robots");
    std::vector<int> pids;
    for (const auto& h : hosts) pids.push_back(h->processId());
    keepGraderCore(pids);  // this thread simulates the run
    std::vector<std::unique_ptr<HostDriver>> drivers;
    for (std::uint32_t i = 0; i < hosts.size(); ++i) {
      drivers.push_back(std::make_unique<HostDriver>(hosts[i], *hosts[i]->impl_, sim, std::vector{i}, std::vector<std::size_t>{0}, pictures));
    }
    return std::make_unique<PerRobotDriver>(std::move(drivers));
  };
}

const std::vector<sandbox::Layer>& RobotHosts::layers() const {
  static const std::vector<sandbox::Layer> none;
  return hosts_.empty() ? none : hosts_.front()->layers();
}

std::vector<std::string> RobotHosts::notes() const {
  std::vector<std::string> all;
  for (const auto& h : hosts_) {
    for (std::string& n : h->notes()) {
      if (std::find(all.begin(), all.end(), n) == all.end()) all.push_back(std::move(n));
    }
  }
  return all;
}

}  // namespace frob::course
