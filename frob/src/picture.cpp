#include "frob/picture.hpp"

namespace frob {

namespace {
Picture single(Shape s) { return Picture({std::move(s)}); }
}  // namespace

Picture operator+(Picture a, const Picture& b) { return a += b; }

Picture& Picture::operator+=(const Picture& b) {
  shapes_.insert(shapes_.end(), b.shapes_.begin(), b.shapes_.end());
  return *this;
}

Picture circle(double r) { return single({.kind = Shape::Kind::Circle, .points = {Point2::Zero()}, .radius = r}); }
Picture disc(double r) { return single({.kind = Shape::Kind::Disc, .points = {Point2::Zero()}, .radius = r}); }
Picture line(const Point2& a, const Point2& b) { return single({.kind = Shape::Kind::Polyline, .points = {a, b}}); }
Picture polyline(std::vector<Point2> points) { return single({.kind = Shape::Kind::Polyline, .points = std::move(points)}); }
Picture polygon(std::vector<Point2> points) { return single({.kind = Shape::Kind::Polygon, .points = std::move(points)}); }
Picture arrow(const Point2& tail, const Point2& tip) { return single({.kind = Shape::Kind::Arrow, .points = {tail, tip}}); }
Picture text(std::string s) { return single({.kind = Shape::Kind::Text, .points = {Point2::Zero()}, .text = std::move(s)}); }

Picture plotValue(std::string name, double v) { return single({.kind = Shape::Kind::Value, .text = std::move(name), .value = v}); }

Picture withColor(const Color& c, Picture p) {
  std::vector<Shape> shapes = p.shapes();
  for (Shape& s : shapes) {
    if (!s.color) s.color = c;
  }
  return Picture(std::move(shapes));
}

Picture paintAt(const Point2& at, Picture p) {
  std::vector<Shape> shapes = p.shapes();
  for (Shape& s : shapes) {
    for (Point2& q : s.points) q += at;
  }
  return Picture(std::move(shapes));
}

}  // namespace frob
