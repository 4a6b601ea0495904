#pragma once
/// Geometry and units for Frob: points and vectors on Eigen, angles, SI unit literals.

#include <Eigen/Core>

#include <numbers>

namespace frob {

/// A 2D vector in metres (or metres per second), on Eigen.
using Vec2 = Eigen::Vector2d;
/// A position in the world plane, metres.
using Point2 = Eigen::Vector2d;

/// Pi as a double.
inline constexpr double pi = std::numbers::pi;

/// Wraps an angle to (-pi, pi], radians.
[[nodiscard]] double wrapAngle(double radians);
/// The signed smallest rotation from angle `from` to angle `to`, in (-pi, pi] radians: positive
/// is counter-clockwise, a turn to the left, as a positive turn rate is. angleDiff(0, pi / 2) is
/// pi / 2, angleDiff(pi / 2, 0) is -pi / 2, angleDiff(3, -3) is 2 pi - 6 (about 0.28, across pi).
/// So wheels(0, 0.8 * angleDiff(heading, target)) turns towards `target` the short way round.
[[nodiscard]] double angleDiff(double from, double to);
/// Euclidean distance between two points, metres.
[[nodiscard]] inline double distance(const Point2& a, const Point2& b) { return (a - b).norm(); }
/// Unit vector at `radians` from the x axis.
[[nodiscard]] inline Vec2 unitVector(double radians) { return {std::cos(radians), std::sin(radians)}; }
/// Direction of `v` from the x axis, radians in (-pi, pi].
[[nodiscard]] inline double heading(const Vec2& v) { return std::atan2(v.y(), v.x()); }

/// Unit literals: every quantity in Frob is SI (metres, seconds, radians).
namespace literals {
constexpr double operator""_m(long double v) { return static_cast<double>(v); }
constexpr double operator""_m(unsigned long long v) { return static_cast<double>(v); }
constexpr double operator""_cm(long double v) { return static_cast<double>(v) / 100.0; }
constexpr double operator""_cm(unsigned long long v) { return static_cast<double>(v) / 100.0; }
constexpr double operator""_mm(long double v) { return static_cast<double>(v) / 1000.0; }
constexpr double operator""_mm(unsigned long long v) { return static_cast<double>(v) / 1000.0; }
constexpr double operator""_s(long double v) { return static_cast<double>(v); }
constexpr double operator""_s(unsigned long long v) { return static_cast<double>(v); }
constexpr double operator""_ms(long double v) { return static_cast<double>(v) / 1000.0; }
constexpr double operator""_ms(unsigned long long v) { return static_cast<double>(v) / 1000.0; }
constexpr double operator""_deg(long double v) { return static_cast<double>(v) * pi / 180.0; }
constexpr double operator""_deg(unsigned long long v) { return static_cast<double>(v) * pi / 180.0; }
constexpr double operator""_rad(long double v) { return static_cast<double>(v); }
constexpr double operator""_rad(unsigned long long v) { return static_cast<double>(v); }
}  // namespace literals

}  // namespace frob
