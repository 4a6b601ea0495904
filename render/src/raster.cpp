#include "raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace frob::render::detail {

namespace {

// Vertices snap to 1/256 pixel, as llvmpipe's fixed-point setup does.
inline double snap(float v) { return std::nearbyint(static_cast<double>(v) * 256.0) / 256.0; }

// std::ceil for the bounded, finite values met here (|v| < 2^62): inline, without SSE4.1's roundsd
// the library call was a measurable share of the per-row work.
inline double ceilFast(double v) {
  const double t = static_cast<double>(static_cast<long long>(v));
  return t < v ? t + 1.0 : t;
}

struct P {
  double x, y;
};

// One edge of a triangle as a bound on x per row. The crossing is computed from the edge's
// endpoints in a canonical order, so the two triangles sharing an edge get the very same value and
// split the pixels on it (the left bound includes its crossing, the right bound excludes it).
struct Edge {
  P a, b;  // a before b in (y, x) order
  bool horizontal;
  bool leftBound;  // interior lies at larger x (row bound from below)
  bool below;      // horizontal edge: interior lies at larger y
  double slope;    // dx/dy

  Edge(P p, P q, P opposite) {
    if (q.y < p.y || (q.y == p.y && q.x < p.x)) std::swap(p, q);
    a = p, b = q;
    horizontal = a.y == b.y;
    slope = horizontal ? 0.0 : (b.x - a.x) / (b.y - a.y);
    // Which side the third vertex is on decides the bound's direction.
    const double side = (b.x - a.x) * (opposite.y - a.y) - (b.y - a.y) * (opposite.x - a.x);
    leftBound = side < 0;  // the third vertex lies at larger x than the edge at its height
    below = opposite.y > a.y;
  }
};

}  // namespace

void span(std::uint8_t* row, int x0, int x1, Rgba8 c, bool blend) {
  if (x1 <= x0) return;
  std::uint8_t* d = row + static_cast<std::size_t>(x0) * 4;
  const std::size_t n = static_cast<std::size_t>(x1 - x0) * 4;
  std::size_t j = 0;
  if (!blend || c.a == 255) {
    const std::uint8_t px[4] = {c.r, c.g, c.b, 255};
#if defined(__SSE2__)
    std::uint32_t word;
    std::memcpy(&word, px, 4);
    const __m128i four = _mm_set1_epi32(static_cast<int>(word));
    for (; j + 16 <= n; j += 16) _mm_storeu_si128(reinterpret_cast<__m128i*>(d + j), four);
#endif
    for (; j < n; ++j) d[j] = px[j & 3];
    return;
  }
  if (c.a == 0) return;
  // Per byte in 16 bits: v = c * a + d * (255 - a) + 127 <= 65152, and v / 255 = (v + 1 + (v >> 8)) >> 8.
  const unsigned a = c.a;
  const std::uint16_t add[4] = {static_cast<std::uint16_t>(c.r * a + 127), static_cast<std::uint16_t>(c.g * a + 127),
                                static_cast<std::uint16_t>(c.b * a + 127), static_cast<std::uint16_t>(255 * 255 + 127)};
  const std::uint16_t keep[4] = {static_cast<std::uint16_t>(255 - a), static_cast<std::uint16_t>(255 - a), static_cast<std::uint16_t>(255 - a), 0};
#if defined(__SSE2__)
  const __m128i vadd = _mm_set_epi16(static_cast<short>(add[3]), static_cast<short>(add[2]), static_cast<short>(add[1]), static_cast<short>(add[0]),
                                     static_cast<short>(add[3]), static_cast<short>(add[2]), static_cast<short>(add[1]), static_cast<short>(add[0]));
  const __m128i vkeep = _mm_set_epi16(0, static_cast<short>(keep[0]), static_cast<short>(keep[0]), static_cast<short>(keep[0]), 0,
                                      static_cast<short>(keep[0]), static_cast<short>(keep[0]), static_cast<short>(keep[0]));
  const __m128i zero = _mm_setzero_si128(), one = _mm_set1_epi16(1);
  auto div255 = [&](__m128i v) { return _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(v, one), _mm_srli_epi16(v, 8)), 8); };
  for (; j + 16 <= n; j += 16) {
    const __m128i px = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + j));
    const __m128i lo = _mm_add_epi16(_mm_mullo_epi16(_mm_unpacklo_epi8(px, zero), vkeep), vadd);
    const __m128i hi = _mm_add_epi16(_mm_mullo_epi16(_mm_unpackhi_epi8(px, zero), vkeep), vadd);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(d + j), _mm_packus_epi16(div255(lo), div255(hi)));
  }
#endif
  for (; j < n; ++j) {
    const unsigned v = add[j & 3] + d[j] * keep[j & 3];
    d[j] = static_cast<std::uint8_t>((v + 1 + (v >> 8)) >> 8);
  }
}

namespace {

void triangle(const Vertex& v0, const Vertex& v1, const Vertex& v2, bool blend, std::uint8_t* rgba, int width, int height) {
  const P p0{snap(v0.x), snap(v0.y)}, p1{snap(v1.x), snap(v1.y)}, p2{snap(v2.x), snap(v2.y)};
  for (const P& p : {p0, p1, p2})
    if (!(std::abs(p.x) < 1e7 && std::abs(p.y) < 1e7)) return;  // non-finite or absurd: nothing sensible to draw
  const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
  if (area == 0.0) return;
  const Edge edges[3] = {Edge(p0, p1, p2), Edge(p1, p2, p0), Edge(p2, p0, p1)};
  const double ymin = std::min({p0.y, p1.y, p2.y}), ymax = std::max({p0.y, p1.y, p2.y});
  const double xmin = std::min({p0.x, p1.x, p2.x}), xmax = std::max({p0.x, p1.x, p2.x});
  // Rows whose centres (r + 0.5) lie in [ymin, ymax].
  const int r0 = std::max(0, static_cast<int>(std::ceil(ymin - 0.5)));
  const int r1 = std::min(height - 1, static_cast<int>(std::floor(ymax - 0.5)));
  const int cx0 = std::max(0, static_cast<int>(std::ceil(xmin - 0.5)));
  const int cx1 = std::min(width - 1, static_cast<int>(std::floor(xmax - 0.5)));
  if (cx1 < cx0) return;
  const Rgba8 col = v0.color;
  for (int r = r0; r <= r1; ++r) {
    const double yc = r + 0.5;
    int lo = cx0, hi = cx1 + 1;  // columns [lo, hi)
    for (const Edge& e : edges) {
      if (e.horizontal) {
        // The row is on the interior side, or on the edge itself and the interior is above it
        // (OpenGL's top edge: the window's y axis points up, the canvas's down).
        const bool in = e.below ? yc > e.a.y : yc <= e.a.y;
        if (!in) hi = lo;
        continue;
      }
      const double xc = e.a.x + (yc - e.a.y) * e.slope;  // where the edge's line crosses the row
      const double c = ceilFast(xc - 0.5);               // first column whose centre is at or right of it
      if (e.leftBound) {
        if (c > lo) lo = c > hi ? hi : static_cast<int>(c);
      } else {
        if (c < hi) hi = c < lo ? lo : static_cast<int>(c);
      }
    }
    if (hi > lo) span(rgba + static_cast<std::size_t>(r) * width * 4, lo, hi, col, blend);
  }
}

// Triangles (a, b, c) and (a, c, d), as Canvas::quad makes them, when they form an axis-aligned
// rectangle of one colour: filled straight, with the coverage the two triangles would give
// (columns with centres in [x0, x1), rows with centres in (y0, y1]). Most of a frame's
// triangles are such: dashes, fills, grid and axis lines, walls along the axes.
bool axisRect(const Vertex* v, bool blend, std::uint8_t* rgba, int width, int height) {
  const Vertex &a = v[0], &b = v[1], &c = v[2];
  if (!(v[3].x == a.x && v[3].y == a.y && v[4].x == c.x && v[4].y == c.y)) return false;
  const Vertex& d = v[5];
  const Rgba8 col = a.color;
  for (const Vertex* w : {&b, &c, &v[3], &v[4], &d}) {
    if (w->color.r != col.r || w->color.g != col.g || w->color.b != col.b || w->color.a != col.a) return false;
  }
  const bool rowsFirst = a.y == b.y && b.x == c.x && c.y == d.y && d.x == a.x;
  const bool colsFirst = a.x == b.x && b.y == c.y && c.x == d.x && d.y == a.y;
  if (!rowsFirst && !colsFirst) return false;
  const double x0 = snap(std::min(a.x, c.x)), x1 = snap(std::max(a.x, c.x));
  const double y0 = snap(std::min(a.y, c.y)), y1 = snap(std::max(a.y, c.y));
  if (!(x0 > -1e7 && x1 < 1e7 && y0 > -1e7 && y1 < 1e7)) return true;  // non-finite or absurd: nothing
  const int c0 = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
  const int c1 = std::min(width, static_cast<int>(std::ceil(x1 - 0.5)));
  const int r0 = std::max(0, static_cast<int>(std::floor(y0 - 0.5)) + 1);
  const int r1 = std::min(height - 1, static_cast<int>(std::floor(y1 - 0.5)));
  for (int r = r0; r <= r1 && c1 > c0; ++r) span(rgba + static_cast<std::size_t>(r) * width * 4, c0, c1, col, blend);
  return true;
}

}  // namespace

void fillRgba(std::uint8_t* rgba, int width, int height, Rgba8 clear) {
  const std::uint8_t px[4] = {clear.r, clear.g, clear.b, 255};
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (n == 0) return;
  std::memcpy(rgba, px, 4);
  // Doubling copies: a handful of memcpy calls for the whole frame.
  std::size_t done = 1;
  while (done < n) {
    const std::size_t k = std::min(done, n - done);
    std::memcpy(rgba + done * 4, rgba, k * 4);
    done += k;
  }
}

void rasterize(const Canvas& canvas, std::uint8_t* rgba, int width, int height, std::size_t firstVertex, std::size_t endVertex) {
  const std::vector<Vertex>& v = canvas.vertices();
  const std::vector<Run>& runs = canvas.runs();
  endVertex = std::min(endVertex, v.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::size_t first = std::max(runs[i].first, firstVertex);
    const std::size_t end = std::min(i + 1 < runs.size() ? runs[i + 1].first : v.size(), endVertex);
    const bool blend = runs[i].mode == Mode::Blend;
    for (std::size_t k = first; k + 3 <= end;) {
      if (k + 6 <= end && axisRect(&v[k], blend, rgba, width, height)) {
        k += 6;
        continue;
      }
      triangle(v[k], v[k + 1], v[k + 2], blend, rgba, width, height);
      k += 3;
    }
  }
}

}  // namespace frob::render::detail
