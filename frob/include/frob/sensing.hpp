#pragma once
/// Sensing helpers over the sonar ring and odometry: what students would otherwise rewrite in
/// every controller. Sensing only: how to follow a wall or reach a goal is the student's.

#include "frob/event.hpp"
#include "frob/robot.hpp"

#include <string>

namespace frob {

/// One echo: how far, and in which direction it was heard.
struct Echo {
  double range = 0.0;  ///< metres from the body's surface; the spec's sonarMaxRange means no echo
  double angle = 0.0;  ///< the sonar's direction, radians from the heading, counter-clockwise
  friend bool operator==(const Echo&, const Echo&) = default;
};

/// Readable form of an echo, e.g. "0.840 m at 45.0 deg".
[[nodiscard]] std::string toString(const Echo& e);

/// The nearest echo of the sonars pointing from `from` counter-clockwise to `to` (radians from the
/// heading, from <= to, at most a full turn apart): nearestEcho(r, 45_deg, 135_deg) is the left
/// side. On a tie the sonar nearest to `from` wins. At least one sonar must point in the span.
[[nodiscard]] Behavior<Echo> nearestEcho(const Robot& r, double from, double to);

/// The paper's atPlace: occurs when the robot (by odometry) comes within `within` metres of `p`,
/// or at once if it is already there. (A template, so that a student's own atPlace still wins.)
template <std::convertible_to<Point2> P>
[[nodiscard]] Event<Unit> atPlace(const Robot& r, const P& p, double within = 0.3) {
  return predicate(distance(place(r), Point2(p)) < within);
}

}  // namespace frob
