#include "gl_context.hpp"

#include <GL/osmesa.h>

#include <cstdlib>
#include <string>

namespace frob::render::detail {

Result<std::unique_ptr<GlContext>> GlContext::create(int width, int height, bool depth, int rasterThreads) {
  if (width <= 0 || height <= 0 || width > 8192 || height > 8192) {
    return Status::failure("render: frame size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1..8192 pixels");
  }
  // llvmpipe reads LP_NUM_THREADS once, when the first context is created. With 0 it rasterizes
  // on the calling thread, which measured fastest for our small frames on a shared 2-core machine.
  if (rasterThreads >= 0) setenv("LP_NUM_THREADS", std::to_string(rasterThreads).c_str(), 1);
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth ? 24 : 0, 0, 0, nullptr);
  if (ctx == nullptr) return Status::failure("render: OSMesa could not create an offscreen OpenGL context");
  return std::unique_ptr<GlContext>(new GlContext(ctx, width, height));
}

GlContext::GlContext(void* ctx, int width, int height) : ctx_(ctx), width_(width), height_(height) {}

GlContext::~GlContext() { OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_)); }

void GlContext::makeCurrent(std::uint8_t* rgba) {
  OSMesaMakeCurrent(static_cast<OSMesaContext>(ctx_), rgba, GL_UNSIGNED_BYTE, width_, height_);
  // Row 0 of the buffer is the top of the image, as PNG and video want it.
  OSMesaPixelStore(OSMESA_Y_UP, 0);
}

void GlContext::finish() { glFinish(); }

}  // namespace frob::render::detail
