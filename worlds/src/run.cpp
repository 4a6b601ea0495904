#include "frob/worlds/run.hpp"

#include "frob/errors.hpp"

#include <cstdio>
#include <exception>

namespace frob::worlds {

namespace {

// The message of the exception in flight.
std::string currentMessage() {
  try {
    throw;
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception of unknown type";
  }
}

}  // namespace

Run::Run(const WorldDef& world, const SimOptions& options, const std::vector<Controller>& controllers,
         RecorderOptions recording)
    : sim_(std::make_unique<Simulation>(world, options)), clock_(sim_->dt()), recorder_(recording) {
  std::size_t n = sim_->robotCount();
  FROB_ASSERT(controllers.size() == n || controllers.size() == 1,
              "Run: give one controller per robot, or one for all robots");
  wheels_.resize(n);
  pictures_.resize(n);
  // Each robot reads its frame where the simulation refreshes it (the simulation outlives the robots).
  for (std::size_t i = 0; i < n; ++i) {
    robots_.emplace_back(sim_->spec(i), std::shared_ptr<const SensorFrame>(std::shared_ptr<void>(), &sim_->frame(i)));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Controller& make = controllers.size() == 1 ? controllers.front() : controllers[i];
    try {
      controllers_.emplace_back(make(robots_[i]));
    } catch (...) {
      controllers_.emplace_back(std::nullopt);
      fail(i, 0.0, "building its controller failed: " + currentMessage());
    }
  }
}

void Run::fail(std::size_t i, double time, const std::string& why) {
  controllers_[i].reset();
  wheels_[i] = Wheels{};
  pictures_[i] = Picture{};
  failures_.push_back({i, time, sim_->robotName(i) + ": " + why});
}

void Run::step() {
  const Instant& now = started_ ? clock_.advance() : clock_.now();
  started_ = true;
  sim_->sense();
  for (std::size_t i = 0; i < controllers_.size(); ++i) {
    if (!controllers_[i]) continue;
    try {
      Wheels w = controllers_[i]->at(now);
      if (!isFinite(w)) {
        char at[48];
        std::snprintf(at, sizeof at, " at t = %.3f s", now.time);
        fail(i, now.time, "the controller commanded non-finite wheels " + toString(w) + at);
        continue;
      }
      wheels_[i] = w;
      pictures_[i] = robots_[i].debugChannel()->picture(now);
    } catch (...) {
      fail(i, now.time, currentMessage());
    }
  }
  recorder_.record(*sim_, wheels_, pictures_);
  sim_->step(wheels_);
}

void Run::runUntil(double seconds) {
  // Half a step of tolerance so that rounding in step × dt never adds or drops a step.
  while (sim_->time() + 0.5 * sim_->dt() < seconds) step();
}

}  // namespace frob::worlds
