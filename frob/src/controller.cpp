#include "frob/controller.hpp"

#include "frob/errors.hpp"

#include <cstdio>
#include <exception>
#include <new>

namespace frob {

namespace {

// The message of the exception in flight.
std::string currentMessage() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return "ran out of memory (std::bad_alloc): it allocated more than a controller may";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception of unknown type";
  }
}

}  // namespace

RunningController::RunningController(const Controller& make, const Robot& robot) : robot_(robot) {
  try {
    behavior_.emplace(make(robot_));
  } catch (...) {
    failure_ = "building its controller failed: " + currentMessage();
  }
}

Wheels RunningController::step(const Instant& now, Picture* picture) {
  if (!behavior_) return Wheels{};
  try {
    const Wheels w = behavior_->at(now);
    if (isFinite(w)) {
      if (picture != nullptr) *picture = robot_.debugChannel()->picture(now);
      return w;
    }
    char at[48];
    std::snprintf(at, sizeof at, " at t = %.3f s", now.time);
    failure_ = "the controller commanded non-finite wheels " + toString(w) + at;
  } catch (...) {
    failure_ = currentMessage();
  }
  behavior_.reset();
  if (picture != nullptr) *picture = Picture{};
  return Wheels{};
}

}  // namespace frob
