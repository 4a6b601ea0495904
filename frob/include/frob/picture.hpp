#pragma once
/// Pictures: values in world coordinates that tasks draw for debugging (withPicture).

#include "frob/behavior.hpp"
#include "frob/geometry.hpp"

#include <optional>
#include <string>
#include <vector>

namespace frob {

/// An RGBA colour, each channel in [0, 1].
struct Color {
  float r = 0, g = 0, b = 0, a = 1;
  friend bool operator==(const Color&, const Color&) = default;
};

inline constexpr Color black{0, 0, 0};
inline constexpr Color white{1, 1, 1};
inline constexpr Color red{0.90f, 0.16f, 0.16f};
inline constexpr Color green{0.16f, 0.70f, 0.25f};
inline constexpr Color blue{0.15f, 0.40f, 0.90f};
inline constexpr Color yellow{0.95f, 0.80f, 0.10f};
inline constexpr Color orange{0.95f, 0.55f, 0.10f};
inline constexpr Color purple{0.60f, 0.25f, 0.80f};
inline constexpr Color gray{0.5f, 0.5f, 0.5f};

/// One drawable element of a picture, in world coordinates (metres).
struct Shape {
  enum class Kind { Circle, Disc, Polyline, Polygon, Arrow, Text, Value };
  Kind kind = Kind::Polyline;
  std::vector<Point2> points;  ///< centre (Circle, Disc, Text), vertices (Polyline, Polygon), tail and tip (Arrow)
  double radius = 0.0;         ///< Circle and Disc radius, metres
  std::string text;            ///< Text content; a Value's name
  double value = 0.0;          ///< a Value: a number to plot, not drawn (plotValue, withPlot)
  std::optional<Color> color;  ///< unset until a withColor reaches it; renderers pick a default
  friend bool operator==(const Shape&, const Shape&) = default;
};

/// A picture: an overlay of shapes. Cheap to build, combined with `+`.
class Picture {
 public:
  Picture() = default;
  explicit Picture(std::vector<Shape> shapes) : shapes_(std::move(shapes)) {}
  /// The shapes, back to front.
  [[nodiscard]] const std::vector<Shape>& shapes() const { return shapes_; }
  [[nodiscard]] bool empty() const { return shapes_.empty(); }
  /// Overlay: `b` is drawn over `a`.
  friend Picture operator+(Picture a, const Picture& b);
  Picture& operator+=(const Picture& b);
  friend bool operator==(const Picture&, const Picture&) = default;

 private:
  std::vector<Shape> shapes_;
};

/// The empty picture.
[[nodiscard]] inline Picture emptyPicture() { return {}; }
/// A circle outline of radius `r` metres centred on the origin.
[[nodiscard]] Picture circle(double r);
/// A filled disc of radius `r` metres centred on the origin.
[[nodiscard]] Picture disc(double r);
/// A line segment from `a` to `b`.
[[nodiscard]] Picture line(const Point2& a, const Point2& b);
/// An open polyline through `points`.
[[nodiscard]] Picture polyline(std::vector<Point2> points);
/// A filled polygon with vertices `points`.
[[nodiscard]] Picture polygon(std::vector<Point2> points);
/// An arrow from `tail` to `tip`.
[[nodiscard]] Picture arrow(const Point2& tail, const Point2& tip);
/// Text anchored at the origin.
[[nodiscard]] Picture text(std::string s);
/// A named number for the plots (`frob run --plot`), not drawn: `name` is the chart's title.
[[nodiscard]] Picture plotValue(std::string name, double v);
/// `p` with colour `c` given to every shape that has none yet (inner colours win).
[[nodiscard]] Picture withColor(const Color& c, Picture p);
/// `p` moved so that its origin lies at `at`.
[[nodiscard]] Picture paintAt(const Point2& at, Picture p);
/// `p` moved, at every instant, so that its origin lies at `at`'s value: paintAt(place(r), circle(0.3)).
template <BehaviorType P>
  requires std::convertible_to<ValueOf<P>, Point2>
[[nodiscard]] Behavior<Picture> paintAt(const P& at, Picture p) {
  return lift([p = std::move(p)](const Point2& x) { return paintAt(x, p); }, at);
}

}  // namespace frob
