#include "frob/worlds/run.hpp"

#include "frob/errors.hpp"

namespace frob::worlds {

namespace {

// Controllers sampled here, each robot reading the frame its simulation refreshes in place.
class InProcessDriver final : public ControllerDriver {
 public:
  InProcessDriver(const Simulation& sim, const std::vector<Controller>& controllers) {
    const std::size_t n = sim.robotCount();
    FROB_ASSERT(controllers.size() == n || controllers.size() == 1, "Run: give one controller per robot, or one for all robots");
    for (std::size_t i = 0; i < n; ++i) {
      // The simulation outlives its robots, so the frame is borrowed, not owned.
      const Robot robot(sim.spec(i), std::shared_ptr<const SensorFrame>(std::shared_ptr<void>(), &sim.frame(i)));
      controllers_.emplace_back(controllers.size() == 1 ? controllers.front() : controllers[i], robot);
    }
  }

  void decide(const Instant& now, std::span<Wheels> wheels, std::span<Picture> pictures,
              std::vector<std::pair<std::size_t, std::string>>& failed) override {
    if (!started_) {  // controllers that failed while being built, reported at the first instant
      started_ = true;
      for (std::size_t i = 0; i < controllers_.size(); ++i) {
        if (controllers_[i].failed()) failed.emplace_back(i, controllers_[i].failure());
      }
    }
    for (std::size_t i = 0; i < controllers_.size(); ++i) {
      RunningController& c = controllers_[i];
      if (c.failed()) continue;
      wheels[i] = c.step(now, &pictures[i]);
      if (c.failed()) failed.emplace_back(i, c.failure());
    }
  }

  Timeline& timeline(std::size_t i) override { return controllers_.at(i).robot().debugChannel()->timeline(); }
  bool finished(std::size_t i) const override { return controllers_.at(i).finished(); }

 private:
  std::vector<RunningController> controllers_;
  bool started_ = false;
};

}  // namespace

DriverFactory inProcess(std::vector<Controller> controllers) {
  return [controllers = std::move(controllers)](const Simulation& sim) -> std::unique_ptr<ControllerDriver> {
    return std::make_unique<InProcessDriver>(sim, controllers);
  };
}

Run::Run(const WorldDef& world, const SimOptions& options, const std::vector<Controller>& controllers, RecorderOptions recording)
    : Run(world, options, inProcess(controllers), recording) {}

Run::Run(const WorldDef& world, const SimOptions& options, const DriverFactory& driver, RecorderOptions recording)
    : sim_(std::make_unique<Simulation>(world, options)), clock_(sim_->dt()), recorder_(recording) {
  driver_ = driver(*sim_);
  wheels_.resize(sim_->robotCount());
  pictures_.resize(sim_->robotCount());
}

void Run::step() {
  const Instant& now = started_ ? clock_.advance() : clock_.now();
  started_ = true;
  sim_->sense();
  failed_.clear();
  driver_->decide(now, wheels_, pictures_, failed_);
  for (auto& [robot, why] : failed_) {
    wheels_[robot] = Wheels{};
    pictures_[robot] = Picture{};
    failures_.push_back({robot, now.time, sim_->robotName(robot) + ": " + why});
  }
  recorder_.record(*sim_, wheels_, pictures_);
  sim_->step(wheels_);
}

void Run::runUntil(double seconds) {
  // Half a step of tolerance so that rounding in step × dt never adds or drops a step.
  while (sim_->time() + 0.5 * sim_->dt() < seconds) step();
}

}  // namespace frob::worlds
