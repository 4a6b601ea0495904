#pragma once
// A CPU rasterizer for the 2D canvas: the top-down view and the plots are flat-coloured triangles
// in pixel coordinates, which llvmpipe draws at a few microseconds each plus a fixed cost per
// frame; filling their spans here costs about what their pixels cost.

#include "canvas.hpp"

#include <cstdint>

namespace frob::render::detail {

// Fills a `width` x `height` RGBA buffer (top row first) with `clear`, alpha 255.
void fillRgba(std::uint8_t* rgba, int width, int height, Rgba8 clear);

// Pixels x0 .. x1-1 of an RGBA row painted with `c`: stored (opaque, or !blend), else mixed as
// (c * a + d * (255 - a)) / 255 rounded. Alpha bytes become 255: frames are opaque.
void span(std::uint8_t* row, int x0, int x1, Rgba8 c, bool blend);

// Draws the canvas's triangles (flat, the first vertex's colour; z ignored) into the buffer in
// order, as OpenGL would without multisampling: a pixel is covered when its centre is inside, a
// centre on an edge shared by two triangles belongs to exactly one of them. Blend runs mix with
// the colour's alpha; the buffer's alpha stays as it is.
// Only vertices from `firstVertex` on are drawn.
void rasterize(const Canvas& canvas, std::uint8_t* rgba, int width, int height, std::size_t firstVertex = 0,
               std::size_t endVertex = static_cast<std::size_t>(-1));

}  // namespace frob::render::detail
