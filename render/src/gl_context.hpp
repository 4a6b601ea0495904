#pragma once
// An OSMesa (llvmpipe) offscreen OpenGL context of fixed size, drawing into a caller's buffer.

#include "frob/base/result.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace frob::render::detail {

class GlContext {
 public:
  // Creates a compatibility-profile RGBA context, with a 24-bit depth buffer if `depth`.
  // `rasterThreads` sets LP_NUM_THREADS before the first context of the process is made (-1: leave it).
  [[nodiscard]] static Result<std::unique_ptr<GlContext>> create(int width, int height, bool depth, int rasterThreads);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread, drawing into `rgba` (width * height * 4
  // bytes, top row first).
  void makeCurrent(std::uint8_t* rgba);
  // Waits for drawing to finish; afterwards the buffer holds the frame.
  void finish();
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }

 private:
  GlContext(void* ctx, int width, int height);
  void* ctx_;  // OSMesaContext
  int width_, height_;
};

}  // namespace frob::render::detail
