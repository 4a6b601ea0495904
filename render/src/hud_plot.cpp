// The heads-up display and the plot panel, both in frame pixels.
#include "draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace frob::render::detail {

namespace {

constexpr Color kSeriesColors[] = {blue, red, green, orange, purple, {0.10f, 0.65f, 0.75f}, black};

template <class... A>
std::string format(const char* fmt, A... args) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

std::string tick(double v) { return format("%.3g", std::abs(v) < 1e-12 ? 0.0 : v); }

std::pair<double, double> niceRange(double lo, double hi) {
  const double span = hi - lo;
  if (!(span > 0.0) || !std::isfinite(span)) return {lo, hi};
  const auto nearZero = [&](double v) { return std::abs(v) < 1e-3 * span ? 0.0 : v; };  // rounding noise round 0
  const double step = std::pow(10.0, std::floor(std::log10(span)) - 1.0);               // two significant digits of the span
  return {std::floor(nearZero(lo) / step) * step, std::ceil(nearZero(hi) / step) * step};
}

Color palette::series(const Series& s, std::size_t index) { return s.color.value_or(kSeriesColors[index % std::size(kSeriesColors)]); }

void drawHud(Canvas& c, const FontAtlas& fonts, const FrameScene& scene, const Viewport& vp) {
  std::vector<std::pair<std::string, Color>> lines;
  lines.emplace_back(format("t = %.2f s", scene.time), white);
  if (!scene.note.empty()) lines.emplace_back(scene.note, white);
  for (std::size_t i = 0; i < scene.robots.size(); ++i) {
    const RobotView& r = scene.robots[i];
    const std::string name = r.name.empty() ? format("robot %zu", i) : r.name;
    lines.emplace_back(name + ": " + (r.task.empty() ? std::string("-") : r.task), palette::robot(r, i));
    const int f = frontSonarIndex(r.spec);
    const std::string front =
        (f >= 0 && static_cast<std::size_t>(f) < r.sonar.size()) ? format("%.2f m", r.sonar[static_cast<std::size_t>(f)]) : std::string("-");
    lines.emplace_back(format("  fwd %+.2f m/s turn %+.2f rad/s front ", r.wheels.forward, r.wheels.turn) + front, white);
  }
  const double lh = fonts.lineHeight(Font::Mono);
  double w = 0;
  for (const auto& l : lines) w = std::max(w, fonts.width(Font::Mono, l.first));
  const double x0 = vp.x + 6, y0 = vp.y + 6;
  c.fill(x0, y0, x0 + w + 22, y0 + lh * static_cast<double>(lines.size()) + 8, rgba8(black, 0.62));
  double y = y0 + 4 + fonts.ascent(Font::Mono);
  for (const auto& [text, col] : lines) {
    // Robot lines start with a swatch of the robot's colour; the text itself stays white for contrast.
    if (!(col == white)) c.fill(x0 + 5, y - fonts.ascent(Font::Mono) + 2, x0 + 13, y, rgba8(col));
    fonts.draw(c, Font::Mono, {x0 + 16, y}, text, rgba8(white));
    y += lh;
  }
}

void drawPlots(Canvas& c, const FontAtlas& fonts, const PlotSet& plots, double now, const Viewport& vp) {
  c.rect(vp.x, vp.y, vp.x + vp.w, vp.y + vp.h, rgba8(white));
  c.rect(vp.x, vp.y, vp.x + 1, vp.y + vp.h, rgba8(palette::grid));  // separator from the world view
  if (plots.plots.empty()) return;
  // The time axis: tEnd, or the last sample of any series.
  double t0 = plots.tStart, t1 = plots.tEnd;
  if (!(t1 > t0)) {
    for (const Plot& p : plots.plots)
      for (const Series& s : p.series)
        if (!s.samples.empty()) t1 = std::max(t1, s.samples.back().t);
    if (!(t1 > t0)) t1 = t0 + 1.0;
  }
  const int asc = fonts.ascent(Font::Sans), lh = fonts.lineHeight(Font::Sans);
  const double left = vp.x + 44, right = vp.x + vp.w - 10;
  const double top = vp.y + 8 + lh, bottom = vp.y + vp.h - lh - 6;  // room for task names and time labels
  const double gap = 8;
  const std::size_t n = plots.plots.size();
  const double ph = (bottom - top - gap * static_cast<double>(n - 1)) / static_cast<double>(n);
  if (ph < 10 || right - left < 10) return;
  auto xOf = [&](double t) { return left + (t - t0) / (t1 - t0) * (right - left); };
  const Rgba8 axis = rgba8(gray), ink = rgba8(black), faint = rgba8(palette::grid);
  auto chartTop = [&](std::size_t pi) { return top + static_cast<double>(pi) * (ph + gap); };

  // Chart backgrounds first: the task-switch lines go over them, and the series over both.
  for (std::size_t pi = 0; pi < n; ++pi) c.rect(left, chartTop(pi), right, chartTop(pi) + ph, rgba8(palette::chart));

  // Task switches: dashed vertical lines through all charts, names staggered on two rows above.
  double lastRight = -1e9;
  for (const TaskMark& mk : plots.taskMarks) {
    if (mk.t > now || mk.t < t0 || mk.t > t1) continue;
    const double x = std::round(xOf(mk.t)) + 0.5;
    const Vec2 seg[2] = {{x, top}, {x, bottom}};
    c.dashed(seg, 1, 4, 3, rgba8(purple, 0.8));
    const double tx = std::min(x + 2, right - fonts.width(Font::Sans, mk.name));
    if (tx < lastRight + 4) continue;  // names of switches close together would overlap
    lastRight = fonts.draw(c, Font::Sans, {tx, vp.y + 4 + asc}, mk.name, rgba8(purple));
  }

  for (std::size_t pi = 0; pi < n; ++pi) {
    const Plot& plot = plots.plots[pi];
    const double y0 = chartTop(pi), y1 = y0 + ph;
    // Title and legend at the chart's top, wrapping onto more lines when the chart is narrow; the
    // values are drawn below them, so that no series runs through the legend.
    double lx = fonts.draw(c, Font::Sans, {left + 4, y0 + asc + 1}, plot.title, ink) + 8, ly = y0 + asc + 1;
    for (std::size_t si = 0; si < plot.series.size(); ++si) {
      const std::string& name = plot.series[si].name;
      if (lx + fonts.width(Font::Sans, name) > right && lx > left + 4) lx = left + 4, ly += lh;
      lx = fonts.draw(c, Font::Sans, {lx, ly}, name, rgba8(palette::series(plot.series[si], si))) + 8;
    }
    const double valuesTop = std::min(ly + (lh - asc) + 2, y1 - 4);
    // Value range from the whole data (not just up to now) so axes stay still during a video.
    double lo = 1e300, hi = -1e300;
    for (const Series& s : plot.series)
      for (const Sample& v : s.samples)
        if (std::isfinite(v.value)) lo = std::min(lo, v.value), hi = std::max(hi, v.value);
    for (const double level : plot.levels) lo = std::min(lo, level), hi = std::max(hi, level);
    if (plot.yMin) lo = *plot.yMin;
    if (plot.yMax) hi = *plot.yMax;
    if (!(hi > lo)) lo = (lo > 1e299 ? 0.0 : lo) - 1.0, hi = lo + 2.0;
    if (!plot.yMin && !plot.yMax) std::tie(lo, hi) = niceRange(lo, hi);
    auto yOf = [&](double v) { return y1 - (std::clamp(v, lo, hi) - lo) / (hi - lo) * (y1 - valuesTop); };
    if (lo < 0 && hi > 0) c.line({left, yOf(0)}, {right, yOf(0)}, 1, faint, false);
    for (const double level : plot.levels) {
      const Vec2 across[2] = {{left, yOf(level)}, {right, yOf(level)}};
      c.dashed(across, 1, 5, 3, rgba8(green));
    }
    c.polyline(std::vector<Vec2>{{left, y0}, {left, y1}, {right, y1}}, 1, axis);
    fonts.draw(c, Font::Sans, {vp.x + 4, valuesTop + asc}, tick(hi), ink);
    fonts.draw(c, Font::Sans, {vp.x + 4, y1}, tick(lo), ink);
    // Each series, reduced to first/min/max/last per pixel column so long runs stay cheap.
    for (std::size_t si = 0; si < plot.series.size(); ++si) {
      const Series& s = plot.series[si];
      std::vector<Vec2> pts;
      long column = -1;
      double cmin = 0, cmax = 0, clast = 0, cx = 0;
      auto flush = [&] {
        if (column < 0) return;
        if (cmin < clast || cmax > clast) {
          pts.emplace_back(cx, cmin);
          pts.emplace_back(cx, cmax);
        }
        pts.emplace_back(cx, clast);
      };
      for (const Sample& v : s.samples) {
        if (v.t > now) break;
        if (v.t < t0 || v.t > t1) continue;
        if (!std::isfinite(v.value)) {  // a gap: the line so far is drawn, the next starts afresh
          flush();
          c.polyline(simplifyPolyline(pts, 0.4), 1.5, rgba8(palette::series(s, si)));
          pts.clear(), column = -1;
          continue;
        }
        const double x = xOf(v.t), y = yOf(v.value);
        const long col = std::lround(std::floor(x));
        if (col != column) {
          flush();
          column = col, cx = x, cmin = cmax = y;
          pts.emplace_back(x, y);
        }
        cmin = std::min(cmin, y), cmax = std::max(cmax, y), clast = y;
      }
      flush();
      c.polyline(simplifyPolyline(pts, 0.4), 1.5, rgba8(palette::series(s, si)));
    }
  }
  // Time labels and the cursor.
  fonts.draw(c, Font::Sans, {left, bottom + asc + 3}, tick(t0) + " s", ink);
  const std::string end = tick(t1) + " s";
  fonts.draw(c, Font::Sans, {right - fonts.width(Font::Sans, end), bottom + asc + 3}, end, ink);
  if (std::isfinite(now) && now >= t0 && now <= t1) c.line({xOf(now), top}, {xOf(now), bottom}, 1, rgba8(red, 0.7), false);
}

}  // namespace frob::render::detail
