#pragma once
// The machinery behind robot.hpp: how a sensor reading reads the robot's frame.

#include "frob/detail/node.hpp"
#include "frob/fwd.hpp"
#include "frob/robot_values.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace frob {
namespace detail {

// The paper's pairB on behaviors of numbers, compiled once in libfrob (see numbers.hpp).
namespace numbers {
Behavior<Wheels> wheels(const Behavior<double>& forward, const Behavior<double>& turn);
}

// Throws std::out_of_range for a sonar the frame lacks.
[[noreturn]] void sonarOutOfRange(std::size_t index, std::size_t size);

// Which value of the frame a reading takes.
enum class FrameSlot : std::uint8_t { sonar, heading, velocity };

// Reads one value of the robot's frame. Inline, not through a function pointer: sensor reads are
// among the most frequent operations of a controller.
template <class T>
struct FrameField;
template <>
struct FrameField<double> {
  FrameSlot slot = FrameSlot::sonar;
  std::size_t index = 0;  // the sonar, for FrameSlot::sonar
  double operator()(const SensorFrame* frame) const {
    if (slot == FrameSlot::sonar) [[likely]] {
      // A source may give fewer sonars than its spec says: a clear error, not a stray read.
      const std::vector<double>& ranges = frame->sonar;
      if (index >= ranges.size()) [[unlikely]]
        sonarOutOfRange(index, ranges.size());
      return ranges[index];
    }
    return slot == FrameSlot::heading ? frame->odometry.heading : frame->velocity;
  }
};
template <>
struct FrameField<Point2> {
  Point2 operator()(const SensorFrame* frame) const { return frame->odometry.position; }
};

// The robot's frame at an instant, for readings: a frame its owner refreshes in place is read
// directly (no node, no per-instant check); a FrameSource is fetched once per instant by `node`.
struct FrameArg {
  const SensorFrame* const* slot = nullptr;        // node->value(): the frame in place, or this instant's fetch
  bool fetched = false;                            // whether `node` must fetch it at each instant
  NodeRef<BehaviorNode<const SensorFrame*>> node;  // holds the frame in `slot`
  const SensorFrame* get(const Instant& now) const {
    if (!fetched) [[likely]]
      return *slot;
    return fetch(now);
  }
  // Out of line, so that a node reading a fixed frame needs no registers saved for the call.
  [[gnu::noinline]] const SensorFrame* fetch(const Instant& now) const { return node->at(now); }
  // As for any lifted argument (see Arg): the frame once a plan has fetched it; the node to fetch.
  const SensorFrame* fresh(const Instant&) const { return *slot; }
  void inputs(std::vector<Input>& out) const {
    if (fetched) out.push_back(inputOf(node));
  }
};

}  // namespace detail
}  // namespace frob
