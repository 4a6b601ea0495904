// Four rays of a sonar cone cast together, and a fifth alongside. Rays from one origin a few
// degrees apart cross nearly the same cells, so instead of walking each ray's cells alone (most of
// the cost was the walk, not the tests), the fan is swept in bands of one cell's length: each band
// tests the cells under the bounding box of the rays' pieces in it, against four rays at once in
// SIMD lanes (and a fifth in scalar). A lane is final once its nearest hit lies within the bands
// swept so far. Every lane computes the same
// operations as RayCaster::cast() in the same order, so each ray's distance and incidence are
// bit-identical to casting it alone; only exact ties between two different surfaces could resolve
// differently, as the cells are visited in another order.
#include "ray_caster.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

// The 4-lane vectors pass only between internal functions of this file, so the ABI that AVX would
// change never crosses a boundary.
#pragma clang diagnostic ignored "-Wpsabi"

namespace frob::worlds::detail {
namespace {

using V = double __attribute__((vector_size(32)));        // one ray per lane
using M = std::int64_t __attribute__((vector_size(32)));  // lane masks: all ones or zero

constexpr std::int64_t kSign = INT64_MIN;

[[gnu::always_inline]] inline V splat(double x) { return V{x, x, x, x}; }
[[gnu::always_inline]] inline M bitsOf(V v) { return __builtin_bit_cast(M, v); }
[[gnu::always_inline]] inline V fromBits(M m) { return __builtin_bit_cast(V, m); }
[[gnu::always_inline]] inline V select(M mask, V a, V b) { return fromBits((bitsOf(a) & mask) | (bitsOf(b) & ~mask)); }
[[gnu::always_inline]] inline bool any(M m) { return __builtin_reduce_or(m) != 0; }

// The rays of the fan and each one's nearest hit so far.
struct Fan {
  double ox, oy;
  V ux, uy;
  V best;  // distance, as RayHit::distance
  V cos;   // as RayHit::cosIncidence
};

// A fifth ray swept with the fan but tested in scalar: five lanes cost less than eight.
struct Lone {
  double ux, uy;
  RayHit best;
  bool live;
};

// As hitCircle() in ray_caster.cpp, lane by lane: the scalar parts are shared, the rest per lane.
[[gnu::always_inline]] inline void fanCircle(double cx, double cy, double r, Fan& f) {
  const double px = f.ox - cx, py = f.oy - cy;
  const double c = px * px + py * py - r * r;
  if (c < 0) {  // the origin is inside: every ray reads 0
    f.best = splat(0.0), f.cos = splat(1.0);
    return;
  }
  const V b = px * f.ux + py * f.uy;
  const V disc = b * b - c;
  const M misses = (disc < 0) | (b > 0);
  if (!any(~misses)) return;
  for (int k = 0; k < 4; ++k) {
    if (misses[k]) continue;
    const double t = -b[k] - std::sqrt(disc[k]);
    if (t >= f.best[k]) continue;
    const double nx = (px + t * f.ux[k]) / r, ny = (py + t * f.uy[k]) / r;
    f.best[k] = t, f.cos[k] = std::abs(nx * f.ux[k] + ny * f.uy[k]);
  }
}

}  // namespace

// castFan's body; always inlined, so that each caller below compiles it for its own instruction set.
struct FanCaster {
  using Seg = RayCaster::Seg;
  using Span = RayCaster::Span;
  using Robot = RayCaster::Robot;

  template <bool WithLone>
  [[gnu::always_inline]] static void testCell(const RayCaster& g, int cell, Fan& f, Lone& lone, int self) {
    const M sign = M{kSign, kSign, kSign, kSign};
    for (std::uint32_t k = g.segStart_[cell], end = g.segStart_[cell + 1]; k < end; ++k) {
      // As testCell(): the sign of denom folded in (an exact sign flip), then compared without dividing.
      const Seg& s = g.cellSegs_[k];
      if constexpr (WithLone) RayCaster::hitSegment(s, f.ox, f.oy, lone.ux, lone.uy, lone.best);
      const V denomRaw = f.ux * s.dy - f.uy * s.dx;
      const double wx = s.ax - f.ox, wy = s.ay - f.oy;
      const double tn = wx * s.dy - wy * s.dx;  // the same for every ray of the fan
      const V vnRaw = wx * f.uy - wy * f.ux;
      const M flip = bitsOf(denomRaw) & sign;
      const V denom = fromBits(bitsOf(denomRaw) ^ flip), vn = fromBits(bitsOf(vnRaw) ^ flip);
      const V tns = fromBits(bitsOf(splat(tn)) ^ flip);
      const M hit = (tns >= 0.0) & (vn >= 0.0) & (vn <= denom) & (tns < f.best * denom);
      if (!any(hit)) continue;
      const V cosI = f.ux * s.nx + f.uy * s.ny;
      f.best = select(hit, tns / denom, f.best);
      f.cos = select(hit, fromBits(bitsOf(cosI) & ~sign), f.cos);
    }
    for (std::uint32_t k = g.pillarStart_[cell], end = g.pillarStart_[cell + 1]; k < end; ++k)
      testCircle<WithLone>(g.cellPillars_[k].cx, g.cellPillars_[k].cy, g.cellPillars_[k].r, f, lone);
    const Span robots = g.robotSpan_[cell];
    for (std::uint32_t k = robots.begin; k < robots.end; ++k) {
      const Robot& c = g.cellRobots_[k];
      if (c.index != self) testCircle<WithLone>(c.cx, c.cy, c.r, f, lone);
    }
  }

  template <bool WithLone>
  [[gnu::always_inline]] static void testCircle(double cx, double cy, double r, Fan& f, Lone& lone) {
    if constexpr (WithLone) RayCaster::hitCircle(cx, cy, r, f.ox, f.oy, lone.ux, lone.uy, lone.best);
    fanCircle(cx, cy, r, f);
  }

  // The fan of ux/uy[0..3], and ux/uy[4] as a lone fifth ray when WithLone.
  template <bool WithLone>
  [[gnu::always_inline]] static double cast(const RayCaster& g, double ox, double oy, const double* ux, const double* uy, double cap, int self,
                                            double cosCutoff) {
    Fan f{ox, oy, V{ux[0], ux[1], ux[2], ux[3]}, V{uy[0], uy[1], uy[2], uy[3]}, splat(cap), splat(1.0)};
    Lone lone{WithLone ? ux[4] : 0.0, WithLone ? uy[4] : 0.0, RayHit{cap, 1.0}, WithLone};
    for (int k : g.outside_)
      if (k != self) testCircle<WithLone>(g.robots_[k].cx, g.robots_[k].cy, g.robots_[k].r, f, lone);
    double nearest = cap;  // the nearest echo of the lanes found final so far
    M live = M{-1, -1, -1, -1};
    int pi0 = 1, pj0 = 1, pi1 = 0, pj1 = 0;  // the cells of the previous band, already tested
    for (double d0 = 0.0; (any(live) || lone.live) && d0 < nearest;) {
      const double d1 = std::min(d0 + g.cell_, nearest);
      // The live rays' pieces over [d0, d1] lie in the box of their end points.
      const V xa = ox + d0 * f.ux, xb = ox + d1 * f.ux, ya = oy + d0 * f.uy, yb = oy + d1 * f.uy;
      const V far = splat(INFINITY);
      const V lxs = select(live, xa < xb ? xa : xb, far), hxs = select(live, xa < xb ? xb : xa, -far);
      const V lys = select(live, ya < yb ? ya : yb, far), hys = select(live, ya < yb ? yb : ya, -far);
      double lx = __builtin_reduce_min(lxs), hx = __builtin_reduce_max(hxs);
      double ly = __builtin_reduce_min(lys), hy = __builtin_reduce_max(hys);
      if (lone.live) {
        const double xa1 = ox + d0 * lone.ux, xb1 = ox + d1 * lone.ux, ya1 = oy + d0 * lone.uy, yb1 = oy + d1 * lone.uy;
        lx = std::min(lx, std::min(xa1, xb1)), hx = std::max(hx, std::max(xa1, xb1));
        ly = std::min(ly, std::min(ya1, yb1)), hy = std::max(hy, std::max(ya1, yb1));
      }
      int i0, j0, i1, j1;
      RayCaster::cellSpan(lx, hx, g.x0_, g.inv_, g.nx_, i0, i1);
      RayCaster::cellSpan(ly, hy, g.y0_, g.inv_, g.ny_, j0, j1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
          if (i < pi0 || i > pi1 || j < pj0 || j > pj1) testCell<WithLone>(g, j * g.nx_ + i, f, lone, self);
      pi0 = i0, pj0 = j0, pi1 = i1, pj1 = j1;
      // A hit within [0, d1] is final: every cell the ray crosses up to d1 has been tested.
      const M done = live & (f.best <= d1);
      const M echoes = done & (f.best < nearest) & (f.cos >= cosCutoff);  // false for NaN
      if (any(echoes)) nearest = __builtin_reduce_min(select(echoes, f.best, far));
      live &= ~done;
      if (lone.live && lone.best.distance <= d1) {
        lone.live = false;
        if (lone.best.distance < nearest && lone.best.cosIncidence >= cosCutoff) nearest = lone.best.distance;
      }
      d0 = d1;
    }
    return nearest;
  }
};

namespace {

// Both builds give bit-identical results: the same IEEE operations, no fused multiply-adds.
[[gnu::target("avx2")]] double castAvx2(const RayCaster& g, int rays, double ox, double oy, const double* ux, const double* uy, double cap, int self,
                                        double cosCutoff) {
  return rays == 5 ? FanCaster::cast<true>(g, ox, oy, ux, uy, cap, self, cosCutoff) : FanCaster::cast<false>(g, ox, oy, ux, uy, cap, self, cosCutoff);
}
double castBaseline(const RayCaster& g, int rays, double ox, double oy, const double* ux, const double* uy, double cap, int self, double cosCutoff) {
  return rays == 5 ? FanCaster::cast<true>(g, ox, oy, ux, uy, cap, self, cosCutoff) : FanCaster::cast<false>(g, ox, oy, ux, uy, cap, self, cosCutoff);
}
std::atomic<bool> avx2 = [] {
  __builtin_cpu_init();  // may run before the runtime's own initialisation
  return __builtin_cpu_supports("avx2") != 0;
}();

}  // namespace

double RayCaster::castFan(int rays, double ox, double oy, const double* ux, const double* uy, double cap, int self, double cosCutoff) const {
  return (avx2.load(std::memory_order_relaxed) ? castAvx2 : castBaseline)(*this, rays, ox, oy, ux, uy, cap, self, cosCutoff);
}

bool useAvx2(bool on) { return avx2.exchange(on && __builtin_cpu_supports("avx2")); }

}  // namespace frob::worlds::detail
