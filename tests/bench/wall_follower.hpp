#pragma once
// The paper's wall follower as a benchmark controller, in Frob and hand-written, shared by the
// core and task benchmarks.

#include "frob/frob.hpp"

#include <algorithm>
#include <cmath>

namespace bench {

using namespace frob;
using namespace frob::literals;

constexpr double kSetpoint = 0.6;
constexpr double kThetaMax = 30_deg;
constexpr double kStop = 0.5;
constexpr double kVmax = 0.4;

// Synthetic sensor readings that change every step, identical for both versions.
inline void fillFrame(SensorFrame& f, std::int64_t step) {
  double t = static_cast<double>(step) * 0.01;
  f.sonar.assign(16, 2.0);
  f.sonar[4] = 0.6 + 0.2 * std::sin(t);  // left
  f.sonar[0] = 1.5 + std::cos(0.3 * t);  // front
  f.velocity = 0.3 + 0.05 * std::sin(2 * t);
}

// The paper's wall follower: rerror limited by velocity, PID on it for the turn, speed from the front.
inline Behavior<Wheels> wallFollower(const Robot& r) {
  auto limit = [](const Behavior<double>& m, const Behavior<double>& v) { return min(max(-m, v), m); };
  Behavior<double> m = velocity(r) * std::sin(kThetaMax);
  Behavior<double> rerror = limit(m, kSetpoint - leftSonar(r));
  Behavior<double> turn = 1.5 * rerror + 0.2 * derivative(rerror) + 0.05 * integral(rerror);
  Behavior<double> forward = clamp((frontSonar(r) - kStop) * 0.8, 0.0, kVmax);
  Behavior<double> slowed = forward * (1.0 - 0.5 * abs(rerror) / (m + 1e-3));
  return wheels(slowed, turn);
}

// The same algorithm, hand-written.
struct HandWritten {
  double previous = 0, previousTime = 0, sum = 0, lastErr = 0;
  bool started = false;
  Wheels step(const SensorFrame& f, double t) {
    double m = f.velocity * std::sin(kThetaMax);
    double err = std::min(std::max(-m, kSetpoint - f.sonar[4]), m);
    double d = 0;
    if (started) {
      d = (err - previous) / (t - previousTime);
      sum += (err + previous) * (0.5 * (t - previousTime));
    }
    started = true;
    previous = err;
    previousTime = t;
    double forward = std::clamp((f.sonar[0] - kStop) * 0.8, 0.0, kVmax);
    double slowed = forward * (1.0 - 0.5 * std::abs(err) / (m + 1e-3));
    return {slowed, 1.5 * err + 0.2 * d + 0.05 * sum};
  }
};

}  // namespace bench
