#pragma once
/// Forward declarations of Frob's main types, for headers that only name them.

namespace frob {
struct Instant;
class Clock;
template <class T>
class Behavior;
template <class R, class F, class... Args>
class Pointwise;
template <class T>
class Event;
struct Unit;
class Robot;
struct RobotSpec;
struct SensorFrame;
struct Wheels;
struct Pose2;
struct BumperHit;
class Picture;
class TaskState;
class RoboErr;
template <class A, class B>
class Task;
class DebugChannel;
class Timeline;
}  // namespace frob
