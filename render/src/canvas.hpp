#pragma once
// A batch of coloured, optionally textured triangles, built on the CPU and drawn in one call.
// 2D drawing is in pixels, x right and y down from the top-left corner of the frame.

#include "frob/geometry.hpp"
#include "frob/picture.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace frob::render::detail {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

// `c` in 8 bits per channel, its alpha multiplied by `alpha`.
[[nodiscard]] Rgba8 rgba8(const Color& c, double alpha = 1.0);

struct Vertex {
  float x, y, z;
  float u, v;
  Rgba8 color;
};

class Canvas {
 public:
  // Texture coordinates of an opaque white texel, used for untextured geometry.
  void setWhiteTexel(float u, float v) { whiteU_ = u, whiteV_ = v; }
  void clear() { vertices_.clear(); }
  [[nodiscard]] const std::vector<Vertex>& vertices() const { return vertices_; }

  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, Rgba8 col);
  void quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Rgba8 col);
  void rect(double x0, double y0, double x1, double y1, Rgba8 col);
  // A segment `width` wide; `cap` extends it by half the width at both ends (square caps).
  void line(const Vec2& a, const Vec2& b, double width, Rgba8 col, bool cap = true);
  void polyline(std::span<const Vec2> pts, double width, Rgba8 col, bool closed = false);
  // A polyline drawn as dashes of `dash` pixels separated by `gap` pixels.
  void dashed(std::span<const Vec2> pts, double width, double dash, double gap, Rgba8 col);
  void disc(const Vec2& c, double r, Rgba8 col);
  void ring(const Vec2& c, double r, double width, Rgba8 col);
  // A filled circular sector from angle a0 to a1 (radians, counter-clockwise on screen).
  void sector(const Vec2& c, double r, double a0, double a1, Rgba8 col);
  void arc(const Vec2& c, double r, double a0, double a1, double width, Rgba8 col);
  // A filled simple polygon, convex or not (ear clipping).
  void polygon(std::span<const Vec2> pts, Rgba8 col);
  void arrow(const Vec2& tail, const Vec2& tip, double width, double head, Rgba8 col);
  // A textured rectangle (glyphs): pixel corners and texture corners.
  void textured(double x0, double y0, double x1, double y1, float u0, float v0, float u1, float v1, Rgba8 col);
  // A 3D triangle (chase view).
  void triangle3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, Rgba8 col);

  // Segments used for a circle of radius `r` pixels: enough that it looks round.
  [[nodiscard]] static int segmentsFor(double r);

 private:
  void vertex(double x, double y, Rgba8 col) {
    vertices_.push_back({static_cast<float>(x), static_cast<float>(y), 0.0f, whiteU_, whiteV_, col});
  }
  std::vector<Vertex> vertices_;
  float whiteU_ = 0, whiteV_ = 0;
};

}  // namespace frob::render::detail
