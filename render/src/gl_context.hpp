#pragma once
// An OSMesa (llvmpipe) offscreen OpenGL context of fixed size, owning its colour buffer.

#include "frob/render/result.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace frob::render::detail {

class GlContext {
 public:
  // Creates a compatibility-profile RGBA context with a 24-bit depth buffer. `rasterThreads` sets
  // LP_NUM_THREADS before the first context of the process is made (-1: leave it).
  [[nodiscard]] static Result<std::unique_ptr<GlContext>> create(int width, int height, int rasterThreads);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes this context current on the calling thread.
  void makeCurrent();
  // Waits for drawing to finish; afterwards pixels() holds the frame, top row first.
  void finish();
  [[nodiscard]] const std::uint8_t* pixels() const { return buffer_.data(); }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }

 private:
  GlContext(void* ctx, int width, int height);
  void* ctx_;  // OSMesaContext
  int width_, height_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace frob::render::detail
