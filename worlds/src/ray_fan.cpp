// The rays of a sonar cone cast together: eight at once with AVX-512, else four, and a fifth
// alongside. Rays from one origin a few degrees apart cross nearly the same cells, so instead of
// walking each ray's cells alone (most of the cost was the walk, not the tests), the fan is swept in
// bands of one cell's length: each band tests the cells under the bounding box of the rays' pieces
// in it, against all rays at once in SIMD lanes (with four lanes, a fifth in scalar), and then the
// ring of nearby robots that no ray can meet before the band, eight (or four) at a time culled
// against the fan's wedge, only those left tested against the rays. A lane is final once its
// nearest hit lies within the bands swept so far. Every lane computes the same operations as
// RayCaster::cast() in the same order, so each ray's distance and incidence are bit-identical to
// casting it alone; only exact ties between two different surfaces could resolve differently, as
// they are met in another order.
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

// One ray per lane: four lanes (AVX2 or plain x86-64, with a fifth ray alone) or eight (AVX-512).
using V4 = double __attribute__((vector_size(32)));
using V8 = double __attribute__((vector_size(64)));
template <class V>
using MaskOf = std::int64_t __attribute__((vector_size(sizeof(V))));  // lane masks: all ones or zero
template <class V>
constexpr int kLanes = sizeof(V) / sizeof(double);

constexpr std::int64_t kSign = INT64_MIN;

template <class V>
[[gnu::always_inline]] inline V splat(double x) {
  return V{} + x;
}
template <class V>
[[gnu::always_inline]] inline MaskOf<V> bitsOf(V v) {
  return __builtin_bit_cast(MaskOf<V>, v);
}
template <class V>
[[gnu::always_inline]] inline V fromBits(MaskOf<V> m) {
  return __builtin_bit_cast(V, m);
}
template <class V>
[[gnu::always_inline]] inline V select(MaskOf<V> mask, V a, V b) {
  return fromBits<V>((bitsOf(a) & mask) | (bitsOf(b) & ~mask));
}
template <class M>
[[gnu::always_inline]] inline bool any(M m) {
  return __builtin_reduce_or(m) != 0;
}
// Bit k set when lane k of `m` is.
template <class M>
[[gnu::always_inline]] inline unsigned maskBits(const M& m) {
  using Bits = bool __attribute__((ext_vector_type(8)));
  if constexpr (sizeof(M) == 64) {
    return __builtin_bit_cast(std::uint8_t, __builtin_convertvector(m, Bits));
  } else {
    return __builtin_bit_cast(std::uint8_t, __builtin_convertvector(__builtin_shufflevector(m, m, 0, 1, 2, 3, 0, 1, 2, 3), Bits)) & 15u;
  }
}
template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
// Lane-wise square root, correctly rounded, so each lane equals std::sqrt: one vsqrtpd of the
// caller's width, as this file is built without errno for math (worlds/CMakeLists.txt).
template <class V>
[[gnu::always_inline]] inline V sqrtLanes(V v) {
  V r;
  for (int k = 0; k < kLanes<V>; ++k) r[k] = std::sqrt(v[k]);
  return r;
}

// More robots near than this, and they set the best of most fans, so that which segments a fan
// meets nearer is too irregular to branch on (10 robots in the hall: 4% faster at 8 than at 0).
constexpr std::size_t kCrowd = 8;

// RayCaster::castCones()'s arguments.
struct Cones {
  std::span<const Point2> origins;
  std::span<const double> dirX, dirY;
  const Spread& spread;
  double range, cosCutoff;
  const Neighbours& near;
  std::span<double> readings;
};

// The rays of the fan and each one's nearest hit so far.
template <class V>
struct Fan {
  double ox, oy;
  V ux, uy;
  V best;  // distance, as RayHit::distance
  V cos;   // as RayHit::cosIncidence
};

// A fifth ray swept with a four-lane fan but tested in scalar: five lanes cost less than eight.
struct Lone {
  double ux, uy;
  RayHit best;
  bool live;
};

// As hitCircle() in ray_caster.hpp, in every lane: the scalar parts are shared, the rest per lane.
template <class V>
[[gnu::always_inline]] inline void fanCircle(double cx, double cy, double r, Fan<V>& f) {
  const double px = f.ox - cx, py = f.oy - cy;
  const double c = px * px + py * py - r * r;
  if (c < 0) {  // the origin is inside: every ray reads 0
    f.best = splat<V>(0.0), f.cos = splat<V>(1.0);
    return;
  }
  const V b = px * f.ux + py * f.uy;
  const V disc = b * b - c;
  const MaskOf<V> misses = (disc < 0) | (b > 0);
  const V t = -b - sqrtLanes(disc < 0 ? splat<V>(0.0) : disc);  // a missing lane's t is never taken
  const MaskOf<V> nearer = ~misses & ~(t >= f.best);
  const V nx = (px + t * f.ux) / r, ny = (py + t * f.uy) / r;
  const V cosI = nx * f.ux + ny * f.uy;
  f.best = select(nearer, t, f.best);
  f.cos = select(nearer, fromBits<V>(bitsOf(cosI) & ~splat<MaskOf<V>>(kSign)), f.cos);
}

}  // namespace

// castFan's body; always inlined, so that each caller below compiles it for its own instruction set.
struct FanCaster {
  using Seg = RayCaster::Seg;
  using Wedge = RayCaster::Wedge;

  // The walls of cells [begin, end) of one row: their segments, then their pillars.
  template <class V, bool WithLone, bool Crowd>
  [[gnu::always_inline]] static void testCells(const RayCaster& g, int begin, int end, Fan<V>& f, Lone& lone) {
    using M = MaskOf<V>;
    const M sign = splat<M>(kSign);
    for (std::uint32_t k = g.segStart_[begin], last = g.segStart_[end]; k < last; ++k) {
      // As testCell(): the sign of denom folded in (an exact sign flip), then compared without dividing.
      const Seg& s = g.cellSegs_[k];
      if constexpr (WithLone) RayCaster::hitSegment(s, f.ox, f.oy, lone.ux, lone.uy, lone.best);
      const V denomRaw = f.ux * s.dy - f.uy * s.dx;
      const double wx = s.ax - f.ox, wy = s.ay - f.oy;
      const double tn = wx * s.dy - wy * s.dx;  // the same for every ray of the fan
      const V vnRaw = wx * f.uy - wy * f.ux;
      const M flip = bitsOf(denomRaw) & sign;
      const V denom = fromBits<V>(bitsOf(denomRaw) ^ flip), vn = fromBits<V>(bitsOf(vnRaw) ^ flip);
      const V tns = fromBits<V>(bitsOf(splat<V>(tn)) ^ flip);
      const M hit = (tns >= 0.0) & (vn >= 0.0) & (vn <= denom) & (tns < f.best * denom);
      // Among robots, which segments are met nearer than the best so far is too irregular to
      // predict, and a missed prediction costs more than the division; alone, it is mostly none.
      if (!Crowd && !any(hit)) continue;
      const V cosI = f.ux * s.nx + f.uy * s.ny;
      f.best = select(hit, tns / denom, f.best);
      f.cos = select(hit, fromBits<V>(bitsOf(cosI) & ~sign), f.cos);
    }
    for (std::uint32_t k = g.pillarStart_[begin], last = g.pillarStart_[end]; k < last; ++k)
      testCircle<V, WithLone>(g.cellPillars_[k].cx, g.cellPillars_[k].cy, g.cellPillars_[k].r, f, lone);
  }

  // Of the robots near.x/y/r[begin, end), those within the wedge that may be met nearer than
  // `cap`, tested against the fan, eight (or four) culled at once.
  template <class V, bool WithLone>
  [[gnu::always_inline]] static void testRobots(const Neighbours& near, std::size_t begin, std::size_t end, const Wedge& w, double cap, Fan<V>& f,
                                                Lone& lone) {
    using M = MaskOf<V>;
    constexpr int lanes = kLanes<V>;
    for (std::size_t b = begin; b < end; b += lanes) {
      const V qx = load<V>(&near.x[b]) - f.ox, qy = load<V>(&near.y[b]) - f.oy, r = load<V>(&near.r[b]);
      const V along = qx * w.ax + qy * w.ay;
      const V across = fromBits<V>(bitsOf(qx * w.ay - qy * w.ax) & ~splat<M>(kSign));
      const V ahead = select(along > 0.0, along, splat<V>(0.0));
      const M maybe = (across * w.cosH - ahead * w.sinH <= r + w.margin) & (along >= -r - w.behind) & (along < cap + r + w.margin);  // false for NaN
      unsigned bits = maskBits(maybe);
      if (end - b < lanes) bits &= (1u << (end - b)) - 1;  // lanes past the end belong to the next ring
      for (; bits != 0; bits &= bits - 1) {
        const std::size_t k = b + static_cast<std::size_t>(__builtin_ctz(bits));
        testCircle<V, WithLone>(near.x[k], near.y[k], near.r[k], f, lone);
      }
    }
  }

  template <class V, bool WithLone>
  [[gnu::always_inline]] static void testCircle(double cx, double cy, double r, Fan<V>& f, Lone& lone) {
    if constexpr (WithLone) RayCaster::hitCircle(cx, cy, r, f.ox, f.oy, lone.ux, lone.uy, lone.best);
    fanCircle(cx, cy, r, f);
  }

  // The fan of the rays in lanes ux/uy, and (loneX, loneY) as a lone extra ray when WithLone;
  // Crowd when more than kCrowd robots are near.
  template <class V, bool WithLone, bool Crowd>
  [[gnu::always_inline]] static double cast(const RayCaster& g, double ox, double oy, const V& ux, const V& uy, double loneX, double loneY,
                                            double cap, double cosCutoff, const Neighbours& near, const Wedge& wedge) {
    using M = MaskOf<V>;
    Fan<V> f{ox, oy, ux, uy, splat<V>(cap), splat<V>(1.0)};
    Lone lone{loneX, loneY, RayHit{cap, 1.0}, WithLone};
    const std::size_t rings = near.ringStart.size() - 1;
    double nearest = cap;  // the nearest echo of the lanes found final so far
    M live = splat<M>(-1);
    RayCaster::CellBox before;  // the cells of the previous band, already tested
    const V far = splat<V>(INFINITY);
    // The extreme directions of the live rays, found again only when a ray finishes.
    double uxLo, uxHi, uyLo, uyHi;
    auto bound = [&] {
      uxLo = __builtin_reduce_min(select(live, f.ux, far)), uxHi = __builtin_reduce_max(select(live, f.ux, -far));
      uyLo = __builtin_reduce_min(select(live, f.uy, far)), uyHi = __builtin_reduce_max(select(live, f.uy, -far));
      if (lone.live) uxLo = std::min(uxLo, lone.ux), uxHi = std::max(uxHi, lone.ux), uyLo = std::min(uyLo, lone.uy), uyHi = std::max(uyHi, lone.uy);
    };
    bool stale = true;     // the extremes need finding again
    std::size_t band = 0;  // band k starts k cell lengths out
    for (double d0 = 0.0; (any(live) || lone.live) && d0 < nearest; ++band) {
      if (stale) bound(), stale = false;
      const double d1 = std::min(d0 + g.cell_, nearest);
      const RayCaster::CellBox now = g.bandBox(ox, oy, uxLo, uxHi, uyLo, uyHi, d0, d1);
      g.forEachNewRun(now, before, [&](int begin, int end) { testCells<V, WithLone, Crowd>(g, begin, end, f, lone); });
      before = now;
      // The robots no sensor meets nearer than this band's start: none further can be met within it.
      if (band < rings) testRobots<V, WithLone>(near, near.ringStart[band], near.ringStart[band + 1], wedge, nearest, f, lone);
      // A hit within [0, d1] is final: every cell the ray crosses up to d1 has been tested.
      const M done = live & (f.best <= d1);
      const M echoes = done & (f.best < nearest) & (f.cos >= cosCutoff);  // false for NaN
      if (any(echoes)) nearest = __builtin_reduce_min(select(echoes, f.best, far));
      live &= ~done;
      const bool loneDone = lone.live && lone.best.distance <= d1;
      if (loneDone) {
        lone.live = false;
        if (lone.best.distance < nearest && lone.best.cosIncidence >= cosCutoff) nearest = lone.best.distance;
      }
      stale = any(done) || loneDone;
      d0 = d1;
    }
    return nearest;
  }

  // castFan: `rays` rays of one cone at once, 3 to 8 with eight lanes (padded with copies of the
  // first: a repeat leaves the minimum as it is), else 4 or 5 (the fifth alone; the caller pads 3
  // to 4): the nearest echo below `cap`, else `cap`.
  template <class V, bool Crowd>
  [[gnu::always_inline]] static double castFan(const RayCaster& g, int rays, double ox, double oy, const double* ux, const double* uy, double cap,
                                               double cosCutoff, const Neighbours& near, const Wedge& wedge) {
    if constexpr (kLanes<V> == 8) {
      V x, y;
      for (int k = 0; k < 8; ++k) x[k] = ux[k < rays ? k : 0], y[k] = uy[k < rays ? k : 0];
      return cast<V, false, Crowd>(g, ox, oy, x, y, 0.0, 0.0, cap, cosCutoff, near, wedge);
    } else {
      const V x = load<V>(ux), y = load<V>(uy);
      return rays == 5 ? cast<V, true, Crowd>(g, ox, oy, x, y, ux[4], uy[4], cap, cosCutoff, near, wedge)
                       : cast<V, false, Crowd>(g, ox, oy, x, y, 0.0, 0.0, cap, cosCutoff, near, wedge);
    }
  }

  // RayCaster::castCone()'s body, in fans of V's lanes.
  template <class V, bool Crowd>
  [[gnu::always_inline]] static double castCone(const RayCaster& g, const Point2& origin, const double* dirX, const double* dirY, std::size_t n,
                                                const Spread& spread, double range, double cosCutoff, const Neighbours& near) {
    const double ox = origin.x(), oy = origin.y();
    // A millionth, in the cosine and sine and in metres, outweighs any rounding, of turning the rays too.
    constexpr double margin = 1e-6;
    const bool narrow = spread.cos > 2 * margin;  // under 90 degrees: else every robot in range is tested
    const Wedge wedge = narrow ? Wedge{dirX[0], dirY[0], spread.cos - margin, spread.sin + margin, margin, margin}
                               : Wedge{dirX[0], dirY[0], 0.0, 1.0, margin, INFINITY};
    double nearest = range;
    // From inside the grid, in fans of at least three rays: up to eight with eight lanes, else four
    // (five when five are left, three as four with the first repeated); the rest one by one. Each
    // is cast only as far as the nearest echo so far: the reading is the minimum over the rays, so
    // neither the order nor a repeat changes it.
    constexpr bool eight = kLanes<V> == 8;
    std::size_t fanned = 0;
    if (g.inside(ox, oy)) [[likely]] {
      while (n - fanned >= 3) {
        const std::size_t left = n - fanned;
        const int rays = eight ? static_cast<int>(std::min<std::size_t>(left, 8)) : left == 5 ? 5 : 4;
        const double* ux = &dirX[fanned];
        const double* uy = &dirY[fanned];
        double padX[4], padY[4];
        if (left == 3 && !eight) {
          padX[0] = padX[3] = ux[0], padX[1] = ux[1], padX[2] = ux[2];
          padY[0] = padY[3] = uy[0], padY[1] = uy[1], padY[2] = uy[2];
          ux = padX, uy = padY;
        }
        nearest = castFan<V, Crowd>(g, rays, ox, oy, ux, uy, nearest, cosCutoff, near, wedge);
        fanned += std::min<std::size_t>(left, static_cast<std::size_t>(rays));
      }
    }
    for (; fanned < n; ++fanned) {
      const RayHit hit = g.cast(origin, Vec2(dirX[fanned], dirY[fanned]), nearest, near);
      if (hit.cosIncidence >= cosCutoff) nearest = std::min(nearest, hit.distance);
    }
    return nearest;
  }

  template <class V>
  [[gnu::always_inline]] static void castCones(const RayCaster& g, const Cones& c) {
    const std::size_t n = c.dirX.size() / c.origins.size();
    for (std::size_t j = 0; j < c.origins.size(); ++j) {
      const Point2& o = c.origins[j];
      const double *x = &c.dirX[j * n], *y = &c.dirY[j * n];
      c.readings[j] = c.near.count > kCrowd ? castCone<V, true>(g, o, x, y, n, c.spread, c.range, c.cosCutoff, c.near)
                                            : castCone<V, false>(g, o, x, y, n, c.spread, c.range, c.cosCutoff, c.near);
    }
  }
};

namespace {

// Every build gives bit-identical results: the same IEEE operations, no fused multiply-adds.
[[gnu::target("avx512f,avx512dq,avx512vl")]] void castAvx512(const RayCaster& g, const Cones& c) { FanCaster::castCones<V8>(g, c); }
[[gnu::target("avx2")]] void castAvx2(const RayCaster& g, const Cones& c) { FanCaster::castCones<V4>(g, c); }
void castBaseline(const RayCaster& g, const Cones& c) { FanCaster::castCones<V4>(g, c); }

bool supported(Isa isa) {
  __builtin_cpu_init();  // may run before the runtime's own initialisation
  switch (isa) {
    case Isa::Avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
    case Isa::Avx2:
      return __builtin_cpu_supports("avx2");
    case Isa::Baseline:
      return true;
  }
  return false;
}
// The widest instruction set the CPU has, or a narrower one a test asked for.
Isa widestUpTo(Isa wanted) {
  return wanted == Isa::Avx512 && !supported(Isa::Avx512) ? widestUpTo(Isa::Avx2) : supported(wanted) ? wanted : Isa::Baseline;
}
std::atomic<Isa> isa = widestUpTo(Isa::Avx512);

}  // namespace

void RayCaster::castCones(std::span<const Point2> origins, std::span<const double> dirX, std::span<const double> dirY, const Spread& spread,
                          double range, double cosCutoff, const Neighbours& near, std::span<double> readings) const {
  const Isa now = isa.load(std::memory_order_relaxed);
  (now == Isa::Avx512 ? castAvx512
   : now == Isa::Avx2 ? castAvx2
                      : castBaseline)(*this, {origins, dirX, dirY, spread, range, cosCutoff, near, readings});
}

Isa useIsa(Isa widest) {
  const Isa now = widestUpTo(widest);
  isa.store(now);
  return now;
}

}  // namespace frob::worlds::detail
