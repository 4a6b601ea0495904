#pragma once
// A batch of coloured triangles built on the CPU and drawn in a few calls, plus text and fills
// composited on the CPU afterwards.
// 2D drawing is in pixels, x right and y down from the top-left corner of the frame.

#include "frob/geometry.hpp"
#include "frob/picture.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace frob::render::detail {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

// `c` in 8 bits per channel, its alpha multiplied by `alpha`.
[[nodiscard]] Rgba8 rgba8(const Color& c, double alpha = 1.0);

struct Vertex {
  float x, y, z;
  Rgba8 color;
};

// How a run of triangles is drawn. Opaque runs skip blending, which llvmpipe does faster; the
// result is the same.
enum class Mode { Opaque, Blend };

// Text and flat fills composited on the CPU over the finished GL frame, in order. Small textured
// glyph quads cost llvmpipe microseconds each; copying glyph bitmaps costs nanoseconds.
struct OverlayOp {
  enum class Kind { Text, Fill } kind = Kind::Text;
  int font = 0;                        // Text: which face
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // Text: pen at (x0, y0) on the baseline; Fill: the rectangle
  std::string text;
  Rgba8 color;
  int clip[4] = {0, 0, 0, 0};  // x0, y0, x1, y1 of the region it may touch
};

struct Run {
  Mode mode;
  std::size_t first;  // index of the first vertex
};

// `pts` thinned (Reumann-Witkam): a point is kept only where the line leaves a corridor of
// half-width `tol` around the line from the last kept point, or turns back. Ends are kept.
[[nodiscard]] std::vector<Vec2> simplifyPolyline(std::span<const Vec2> pts, double tol);

class Canvas {
 public:
  // Corners tested by polygon()'s ear clipping in a frame: some milliseconds' work.
  static constexpr std::size_t kEarTestsPerFrame = std::size_t{1} << 22;

  void clear() {
    earTests_ = 0;
    vertices_.clear();
    runs_.clear();
    overlay_.clear();
    setClip(-1 << 20, -1 << 20, 1 << 20, 1 << 20);
  }
  // Limits later overlay ops to this pixel rectangle.
  void setClip(int x0, int y0, int x1, int y1) { clip_[0] = x0, clip_[1] = y0, clip_[2] = x1, clip_[3] = y1; }
  // Text with its baseline starting at pixel (x, y), composited after the GL pass.
  void text(int font, int x, int y, std::string_view s, Rgba8 col);
  // A flat rectangle composited after the GL pass (under later text).
  void fill(double x0, double y0, double x1, double y1, Rgba8 col);
  [[nodiscard]] const std::vector<OverlayOp>& overlay() const { return overlay_; }
  [[nodiscard]] const std::vector<Vertex>& vertices() const { return vertices_; }
  // Consecutive vertices drawn in the same mode, in order.
  [[nodiscard]] const std::vector<Run>& runs() const { return runs_; }

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
  // A filled simple polygon, convex or not (ear clipping); false when it was filled as a fan instead:
  // a self-intersecting one, or one past the frame's budget of ear tests.
  bool polygon(std::span<const Vec2> pts, Rgba8 col);
  void arrow(const Vec2& tail, const Vec2& tip, double width, double head, Rgba8 col);
  // A 3D triangle (chase view).
  void triangle3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, Rgba8 col);

  // Segments used for a circle of radius `r` pixels: enough that it looks round.
  [[nodiscard]] static int segmentsFor(double r);

 private:
  void begin(Mode mode) {
    if (runs_.empty() || runs_.back().mode != mode) runs_.push_back({mode, vertices_.size()});
  }
  void vertex(double x, double y, Rgba8 col) { vertices_.push_back({static_cast<float>(x), static_cast<float>(y), 0.0f, col}); }
  std::vector<Vertex> vertices_;
  std::vector<Run> runs_;
  std::vector<OverlayOp> overlay_;
  int clip_[4] = {-1 << 20, -1 << 20, 1 << 20, 1 << 20};
  std::size_t earTests_ = 0;
};

}  // namespace frob::render::detail
