#include "canvas.hpp"

#include <algorithm>
#include <cmath>

namespace frob::render::detail {

namespace {
std::uint8_t channel(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }
double cross(const Vec2& o, const Vec2& a, const Vec2& b) { return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x()); }
}  // namespace

std::vector<Vec2> simplifyPolyline(std::span<const Vec2> pts, double tol) {
  std::vector<Vec2> out;
  if (pts.empty()) return out;
  Vec2 anchor = pts[0], prev = anchor, dir(0, 0);
  double reach = 0.0;  // how far along dir the kept stretch goes
  out.push_back(anchor);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Vec2& p = pts[i];
    const Vec2 d = p - anchor;
    if (dir.isZero()) {
      if (d.norm() >= tol) dir = d.normalized();
      prev = p;
      continue;
    }
    const double along = d.dot(dir);
    const double across = std::abs(dir.x() * d.y() - dir.y() * d.x());
    if (across > tol || along < reach - tol) {
      out.push_back(prev);
      anchor = prev;
      const Vec2 e = p - anchor;
      dir = e.norm() >= 1e-12 ? Vec2(e.normalized()) : Vec2(0, 0);
      reach = dir.isZero() ? 0.0 : e.dot(dir);
    } else {
      reach = std::max(reach, along);
    }
    prev = p;
  }
  if ((prev - out.back()).squaredNorm() > 0) out.push_back(prev);
  return out;
}

Rgba8 rgba8(const Color& c, double alpha) { return {channel(c.r), channel(c.g), channel(c.b), channel(c.a * alpha)}; }

// A chord of a circle with n segments strays r (1 - cos(pi / n)) ~ r pi^2 / (2 n^2) from it; keep
// that under a quarter pixel. Fewer, fatter triangles matter: llvmpipe pays per triangle.
int Canvas::segmentsFor(double r) {
  if (!std::isfinite(r)) return 8;
  return static_cast<int>(std::clamp(std::ceil(4.5 * std::sqrt(std::max(r, 0.0))), 8.0, 128.0));
}

void Canvas::triangle(const Vec2& a, const Vec2& b, const Vec2& c, Rgba8 col) {
  begin(col.a == 255 ? Mode::Opaque : Mode::Blend);
  vertex(a.x(), a.y(), col);
  vertex(b.x(), b.y(), col);
  vertex(c.x(), c.y(), col);
}

void Canvas::quad(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Rgba8 col) {
  triangle(a, b, c, col);
  triangle(a, c, d, col);
}

void Canvas::rect(double x0, double y0, double x1, double y1, Rgba8 col) { quad({x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, col); }

void Canvas::line(const Vec2& a, const Vec2& b, double width, Rgba8 col, bool cap) {
  Vec2 d = b - a;
  const double len = d.norm();
  if (len < 1e-9) {
    if (cap) rect(a.x() - width / 2, a.y() - width / 2, a.x() + width / 2, a.y() + width / 2, col);
    return;
  }
  d /= len;
  const Vec2 n(-d.y() * width / 2, d.x() * width / 2);
  const Vec2 e = cap ? Vec2(d * width / 2) : Vec2(0, 0);
  quad(a - e + n, b + e + n, b + e - n, a - e - n, col);
}

void Canvas::polyline(std::span<const Vec2> pts, double width, Rgba8 col, bool closed) {
  if (pts.empty()) return;
  if (pts.size() == 1) line(pts[0], pts[0], width, col);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) line(pts[i], pts[i + 1], width, col);
  if (closed && pts.size() > 2) line(pts.back(), pts.front(), width, col);
}

void Canvas::dashed(std::span<const Vec2> pts, double width, double dash, double gap, Rgba8 col) {
  // Walk the polyline carrying the dash phase across vertices so the pattern is continuous.
  double phase = 0.0;  // distance into the current dash+gap period
  const double period = dash + gap;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 a = pts[i];
    const Vec2 d = pts[i + 1] - a;
    const double len = d.norm();
    if (!(len >= 1e-9)) continue;  // also NaN
    if (!(len / period < 1e5)) {   // absurdly long (or infinite): solid, rather than a million dashes
      line(a, pts[i + 1], width, col, false);
      continue;
    }
    const Vec2 u = d / len;
    double s = 0.0;
    while (s < len) {
      const double left = (phase < dash ? dash : period) - phase;
      const double step = std::min(left, len - s);
      if (phase < dash) line(a + u * s, a + u * (s + step), width, col, false);
      s += step;
      phase += step;
      if (phase >= period - 1e-9) phase = 0.0;
    }
  }
}

void Canvas::disc(const Vec2& c, double r, Rgba8 col) { sector(c, r, 0.0, 2 * pi, col); }

void Canvas::ring(const Vec2& c, double r, double width, Rgba8 col) { arc(c, r, 0.0, 2 * pi, width, col); }

void Canvas::sector(const Vec2& c, double r, double a0, double a1, Rgba8 col) {
  const int n = std::max(2, static_cast<int>(std::ceil(segmentsFor(r) * (a1 - a0) / (2 * pi))));
  Vec2 prev = c + r * Vec2(std::cos(a0), -std::sin(a0));
  for (int i = 1; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    const Vec2 p = c + r * Vec2(std::cos(a), -std::sin(a));
    triangle(c, prev, p, col);
    prev = p;
  }
}

void Canvas::arc(const Vec2& c, double r, double a0, double a1, double width, Rgba8 col) {
  const int n = std::max(2, static_cast<int>(std::ceil(segmentsFor(r) * (a1 - a0) / (2 * pi))));
  const double ri = std::max(0.0, r - width / 2), ro = r + width / 2;
  for (int i = 0; i < n; ++i) {
    const double b0 = a0 + (a1 - a0) * i / n, b1 = a0 + (a1 - a0) * (i + 1) / n;
    const Vec2 u0(std::cos(b0), -std::sin(b0)), u1(std::cos(b1), -std::sin(b1));
    quad(c + ri * u0, c + ro * u0, c + ro * u1, c + ri * u1, col);
  }
}

bool Canvas::polygon(std::span<const Vec2> pts, Rgba8 col) {
  const std::size_t n = pts.size();
  if (n < 3) return true;
  // Ear clipping on indices; orientation decides which side is inside. Each ear's test looks at
  // every corner left, so a frame's tests are counted against a budget: a picture made to be the
  // worst case (O(n^3)) would otherwise take minutes a frame.
  double area = 0.0;
  for (std::size_t i = 0; i < n; ++i) area += cross(Vec2(0, 0), pts[i], pts[(i + 1) % n]);
  const double sign = area >= 0 ? 1.0 : -1.0;
  std::vector<std::size_t> idx(n);
  for (std::size_t i = 0; i < n; ++i) idx[i] = i;
  bool exact = true;
  std::size_t k = 0;  // where the search for the next ear starts: next to the last one clipped
  while (idx.size() > 3 && exact) {
    bool clipped = false;
    for (std::size_t tried = 0; tried < idx.size() && !clipped; ++tried, k = (k + 1) % idx.size()) {
      if (earTests_ >= kEarTestsPerFrame) {
        exact = false;
        break;
      }
      const Vec2& a = pts[idx[(k + idx.size() - 1) % idx.size()]];
      const Vec2& b = pts[idx[k]];
      const Vec2& c = pts[idx[(k + 1) % idx.size()]];
      if (sign * cross(a, b, c) <= 0) continue;  // reflex corner
      earTests_ += idx.size();
      bool inside = false;
      for (std::size_t m : idx) {
        const Vec2& p = pts[m];
        if (&p == &a || &p == &b || &p == &c) continue;
        if (sign * cross(a, b, p) > 0 && sign * cross(b, c, p) > 0 && sign * cross(c, a, p) > 0) {
          inside = true;
          break;
        }
      }
      if (inside) continue;
      triangle(a, b, c, col);
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(k));
      k = k % idx.size();
      clipped = true;
    }
    if (!clipped) exact = false;  // degenerate (self-intersecting), or past the budget: the rest as a fan below
  }
  for (std::size_t j = 1; j + 1 < idx.size(); ++j) triangle(pts[idx[0]], pts[idx[j]], pts[idx[j + 1]], col);
  return exact;
}

void Canvas::arrow(const Vec2& tail, const Vec2& tip, double width, double head, Rgba8 col) {
  Vec2 d = tip - tail;
  const double len = d.norm();
  if (len < 1e-9) return;
  d /= len;
  head = std::min(head, len);
  const Vec2 n(-d.y(), d.x());
  const Vec2 base = tip - d * head;
  line(tail, base, width, col, false);
  triangle(tip, base + n * head * 0.5, base - n * head * 0.5, col);
}

void Canvas::text(int font, int x, int y, std::string_view s, Rgba8 col) {
  OverlayOp op{.kind = OverlayOp::Kind::Text, .font = font, .x0 = x, .y0 = y, .text = std::string(s), .color = col};
  std::copy(std::begin(clip_), std::end(clip_), std::begin(op.clip));
  overlay_.push_back(std::move(op));
}

void Canvas::fill(double x0, double y0, double x1, double y1, Rgba8 col) {
  for (double v : {x0, y0, x1, y1})
    if (!(std::abs(v) < 1e6)) return;  // off-frame or non-finite
  OverlayOp op{.kind = OverlayOp::Kind::Fill,
               .x0 = static_cast<int>(std::lround(x0)),
               .y0 = static_cast<int>(std::lround(y0)),
               .x1 = static_cast<int>(std::lround(x1)),
               .y1 = static_cast<int>(std::lround(y1)),
               .color = col};
  std::copy(std::begin(clip_), std::end(clip_), std::begin(op.clip));
  overlay_.push_back(std::move(op));
}

void Canvas::triangle3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, Rgba8 col) {
  begin(col.a == 255 ? Mode::Opaque : Mode::Blend);
  for (const Eigen::Vector3d* p : {&a, &b, &c}) {
    vertices_.push_back({static_cast<float>(p->x()), static_cast<float>(p->y()), static_cast<float>(p->z()), col});
  }
}

}  // namespace frob::render::detail
