// The top-down world: floor, grid, walls, robots, sensors, paths and the Pictures tasks publish.
#include "draw.hpp"
#include "frob/worlds/world_def.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace frob::render::detail {

namespace {

constexpr Color kRobotColors[] = {blue, orange, green, purple, {0.10f, 0.65f, 0.75f}, {0.55f, 0.35f, 0.20f}};

Color darker(Color c, float f = 0.6f) { return {c.r * f, c.g * f, c.b * f, c.a}; }

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The points of `pts` mapped to the canvas and thinned to within half a pixel, so that a long
// run's path costs a few dozen segments.
std::vector<Vec2> mappedPath(const std::vector<Point2>& pts, const Mapping& m) {
  std::vector<Vec2> mapped;
  mapped.reserve(pts.size());
  for (const Point2& p : pts) mapped.push_back(m.map(p));
  return simplifyPolyline(mapped, 0.5 * m.pixel);
}

// Grid spacing in metres: 1 m unless lines would be closer than 12 pixels.
double gridStep(const Mapping& m) {
  for (double s : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    if (s * m.scale >= 12.0 * m.pixel) return s;
  }
  return 100.0;
}

void drawGrid(Canvas& c, const FontAtlas& fonts, const Bounds& b, const Mapping& m, bool labels, const TextSink& text) {
  const double step = gridStep(m);
  const Rgba8 line = rgba8(palette::grid);
  const double w = m.pixel;
  for (double x = std::ceil(b.min.x() / step) * step; x <= b.max.x() + 1e-9; x += step) {
    c.line(m.map({x, b.min.y()}), m.map({x, b.max.y()}), w, line, false);
  }
  for (double y = std::ceil(b.min.y() / step) * step; y <= b.max.y() + 1e-9; y += step) {
    c.line(m.map({b.min.x(), y}), m.map({b.max.x(), y}), w, line, false);
  }
  if (!labels) return;
  // Labels inside the floor along its bottom and left edges, skipping ones that would overlap.
  const Rgba8 ink = rgba8(palette::gridText);
  double lastRight = -1e9;
  for (double x = std::ceil(b.min.x() / step) * step; x <= b.max.x() + 1e-9; x += step) {
    const std::string s = metres(x);
    const Vec2 p = m.map({x, b.min.y()}) + Vec2(2 * m.pixel, -3 * m.pixel);
    if (p.x() < lastRight + 4) continue;
    lastRight = fonts.draw(c, Font::Sans, p, s, ink);
  }
  double lastTop = 1e9;
  for (double y = std::ceil(b.min.y() / step) * step; y <= b.max.y() + 1e-9; y += step) {
    if (std::abs(y - b.min.y()) < 1e-9) continue;  // the corner is labelled by the x axis
    const Vec2 p = m.map({b.min.x(), y}) + Vec2(2 * m.pixel, -2 * m.pixel);
    if (p.y() > lastTop - fonts.ascent(Font::Sans) - 2) continue;
    fonts.draw(c, Font::Sans, p, metres(y), ink);
    lastTop = p.y() - fonts.ascent(Font::Sans);
  }
  (void)text;
}

// How far a ray from `o` along the unit vector `d` goes before it meets a wall, a block or a pillar
// of `scene`, at most `limit` metres.
double firstHit(const FrameScene& scene, const Point2& o, const Vec2& d, double limit) {
  double best = limit;
  const auto segment = [&](const Point2& a, const Point2& b) { best = std::min(best, worlds::rayToSegment(o, d, a, b)); };
  for (const Wall& w : scene.walls) segment(w.a, w.b);
  for (const Block& b : scene.blocks) {
    const Vec2 u(std::cos(b.angle), std::sin(b.angle)), v(-u.y(), u.x());
    const Vec2 hx = u * b.halfExtents.x(), hy = v * b.halfExtents.y();
    const Point2 corners[] = {b.center - hx - hy, b.center + hx - hy, b.center + hx + hy, b.center - hx + hy};
    for (int k = 0; k < 4; ++k) segment(corners[k], corners[(k + 1) % 4]);
  }
  for (const Pillar& p : scene.pillars) best = std::min(best, worlds::rayToDisc(o, d, p.center, p.radius));
  return best;
}

// Each sonar's cone, from its place on the rim out to its reading and never through a wall: an
// echo ends in a solid arc; a sonar that heard nothing is fainter and ends in a dashed edge.
void drawSonar(Canvas& c, const FrameScene& scene, const RenderDef& def, const RobotView& r, const Mapping& m, Color col) {
  constexpr int kRays = 8;  // rays across a cone, each stopped by the first wall it meets
  const std::size_t n = std::min(r.sonar.size(), r.spec.sonarAngles.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double range = std::clamp(r.sonar[i], 0.0, r.spec.sonarMaxRange);
    const bool echo = r.sonar[i] < r.spec.sonarMaxRange;
    const double a = r.pose.heading + r.spec.sonarAngles[i];
    const Point2 origin = r.pose.position + r.spec.radius * Vec2(std::cos(a), std::sin(a));
    const Vec2 o = m.map(origin);
    std::vector<Vec2> ends, edge;  // every ray's end; the run of ends that reach the reading
    const Rgba8 fill = rgba8(col, echo ? 0.16 : 0.06), rim = echo ? rgba8(darker(col), 0.85) : rgba8(col, 0.6);
    const auto drawEdge = [&] {
      if (echo)
        c.polyline(edge, 2 * m.pixel, rim);
      else
        c.dashed(edge, 1.5 * m.pixel, 4 * m.pixel, 4 * m.pixel, rim);
      edge.clear();
    };
    for (int k = 0; k <= kRays; ++k) {
      const double ak = a - def.sonarHalfAngle + 2.0 * def.sonarHalfAngle * k / kRays;
      const Vec2 dir(std::cos(ak), std::sin(ak));
      const double reach = firstHit(scene, origin, dir, range);
      ends.push_back(m.map(origin + dir * reach));
      if (reach < range)
        drawEdge();
      else
        edge.push_back(ends.back());
      if (k > 0) c.triangle(o, ends[k - 1], ends[k], fill);
    }
    drawEdge();
  }
}

void drawRobot(Canvas& c, const RobotView& r, const Mapping& m, Color col) {
  const double rad = std::max(r.spec.radius * m.scale, 3 * m.pixel);
  if (r.odometry) {
    // Where the robot believes it is: an outline with a heading tick.
    const Vec2 o = m.map(r.odometry->position);
    c.ring(o, rad, 1.5 * m.pixel, rgba8(col, 0.7));
    const Vec2 u(std::cos(r.odometry->heading), -std::sin(r.odometry->heading));
    c.line(o, o + u * rad, 1.5 * m.pixel, rgba8(col, 0.7));
  }
  const Vec2 p = m.map(r.pose.position);
  c.disc(p, rad, rgba8(col));
  c.ring(p, rad, 1.5 * m.pixel, rgba8(darker(col)));
  const Vec2 u(std::cos(r.pose.heading), -std::sin(r.pose.heading));
  c.line(p, p + u * rad, 2.5 * m.pixel, rgba8(white));
  for (const BumperHit& hit : r.bumps) {
    const double a = r.pose.heading + hit.angle;
    const Vec2 q = p + Vec2(std::cos(a), -std::sin(a)) * rad;
    c.disc(q, std::max(0.3 * rad, 3 * m.pixel), rgba8(palette::bump));
    c.ring(q, std::max(0.5 * rad, 5 * m.pixel), 1.5 * m.pixel, rgba8(palette::bump, 0.8));
  }
}

// Whether a robot's picture writes `label` within 30 nominal pixels of `at` (canvas units).
bool pictureWrites(const FrameScene& scene, const std::string& label, const Vec2& at, const Mapping& m) {
  for (const RobotView& r : scene.robots) {
    for (const Shape& s : r.picture.shapes()) {
      if (s.kind == Shape::Kind::Text && s.text == label && !s.points.empty() && (m.map(s.points[0]) - at).norm() < 30 * m.pixel) return true;
    }
  }
  return false;
}

}  // namespace

Color palette::robot(const RobotView& r, std::size_t index) { return r.color.value_or(kRobotColors[index % std::size(kRobotColors)]); }

Panels layoutPanels(const RenderDef& def) {
  const double w = def.width, h = def.height, share = std::clamp(def.plotShare, 0.05, 0.95);
  switch (def.layout) {
    case PanelLayout::PlotRight: {
      const double pw = std::round(w * share);
      return {{0, 0, w - pw, h}, {w - pw, 0, pw, h}};
    }
    case PanelLayout::PlotBelow: {
      const double ph = std::round(h * share);
      return {{0, 0, w, h - ph}, {0, h - ph, w, ph}};
    }
    case PanelLayout::WorldOnly:
      break;
  }
  return {{0, 0, w, h}, {}};
}

Mapping fitTopDown(const Bounds& b, double margin, const Viewport& vp) {
  const double ww = std::max(b.max.x() - b.min.x() + 2 * margin, 1e-6);
  const double wh = std::max(b.max.y() - b.min.y() + 2 * margin, 1e-6);
  const double scale = std::min(vp.w / ww, vp.h / wh);
  const Point2 centre = (b.min + b.max) / 2;
  const Vec2 vpCentre(vp.x + vp.w / 2, vp.y + vp.h / 2);
  return {.origin = Vec2(vpCentre.x() - scale * centre.x(), vpCentre.y() + scale * centre.y()), .scale = scale};
}

void drawPicture(Canvas& c, const Picture& picture, const Mapping& m, const TextSink& text) {
  std::vector<Vec2> pts;
  for (const Shape& s : picture.shapes()) {
    const Color col = s.color.value_or(palette::picture);
    const Rgba8 ink = rgba8(col);
    pts.clear();
    for (const Point2& p : s.points) pts.push_back(m.map(p));
    if (pts.empty()) continue;
    switch (s.kind) {
      case Shape::Kind::Circle:
        c.ring(pts[0], s.radius * m.scale, 2 * m.pixel, ink);
        break;
      case Shape::Kind::Disc:
        c.disc(pts[0], s.radius * m.scale, ink);
        break;
      case Shape::Kind::Polyline:
        c.polyline(pts, 2 * m.pixel, ink);
        break;
      case Shape::Kind::Polygon:
        c.polygon(pts, ink);
        break;
      case Shape::Kind::Arrow:
        if (pts.size() >= 2) c.arrow(pts[0], pts[1], 2 * m.pixel, 10 * m.pixel, ink);
        break;
      case Shape::Kind::Text:
        text(s.points[0], s.text, col);
        break;
      case Shape::Kind::Value:
        break;  // plotted, not drawn
    }
  }
}

void drawGround(Canvas& c, const FontAtlas& fonts, const RenderDef& def, const FrameScene& scene, const Mapping& m, bool bodies, const TextSink& text,
                const Viewport* clearedFloor, std::size_t* staticEnd) {
  const Bounds& b = scene.bounds;
  const Vec2 lo = m.map(b.min), hi = m.map(b.max);
  if (clearedFloor == nullptr) {
    c.rect(lo.x(), hi.y(), hi.x(), lo.y(), rgba8(palette::floor));
  } else {
    // The frame was cleared to the floor colour (cheaper than a full-frame quad): paint the margins.
    const Viewport& v = *clearedFloor;
    const Rgba8 bg = rgba8(palette::background);
    const double x0 = std::max(v.x, lo.x()), x1 = std::min(v.x + v.w, hi.x());
    c.rect(v.x, v.y, v.x + v.w, std::max(v.y, hi.y()), bg);
    c.rect(v.x, std::min(v.y + v.h, lo.y()), v.x + v.w, v.y + v.h, bg);
    c.rect(v.x, hi.y(), x0, lo.y(), bg);
    c.rect(x1, hi.y(), v.x + v.w, lo.y(), bg);
  }
  if (def.grid) drawGrid(c, fonts, b, m, bodies, text);

  // Obstacles seen from above (the chase view also extrudes them).
  const Rgba8 solid = rgba8(palette::obstacle);
  for (const Block& k : scene.blocks) {
    const Vec2 u(std::cos(k.angle), std::sin(k.angle)), v(-u.y(), u.x());
    const Vec2 ex = u * k.halfExtents.x(), ey = v * k.halfExtents.y();
    c.quad(m.map(k.center - ex - ey), m.map(k.center + ex - ey), m.map(k.center + ex + ey), m.map(k.center - ex + ey), solid);
  }
  for (const Pillar& p : scene.pillars) c.disc(m.map(p.center), p.radius * m.scale, solid);
  const Rgba8 wallInk = rgba8(palette::wall);
  for (const Wall& w : scene.walls) c.line(m.map(w.a), m.map(w.b), std::max(w.thickness * m.scale, 2 * m.pixel), wallInk);

  // Named points: a diamond and a label, unless a task's picture writes that label there itself.
  for (const Marker& p : scene.points) {
    const Color col = p.color.value_or(palette::point);
    const Vec2 q = m.map(p.at);
    const double s = 5 * m.pixel;
    c.quad(q + Vec2(0, -s), q + Vec2(s, 0), q + Vec2(0, s), q + Vec2(-s, 0), rgba8(col));
    if (!p.name.empty() && !pictureWrites(scene, p.name, q, m)) {
      text(p.at + Vec2(7 * m.pixel / m.scale, -4 * m.pixel / m.scale), p.name, darker(col));
    }
  }

  if (staticEnd != nullptr) *staticEnd = c.vertices().size();

  // Paths: the odometry path dashed beneath the true path.
  if (def.paths) {
    for (std::size_t i = 0; i < scene.robots.size(); ++i) {
      const RobotView& r = scene.robots[i];
      const Color col = palette::robot(r, i);
      c.dashed(mappedPath(r.odometryPath, m), 1.5 * m.pixel, 12 * m.pixel, 7 * m.pixel, rgba8(col, 0.75));
      c.polyline(mappedPath(r.path, m), 2 * m.pixel, rgba8(darker(col, 0.8)));
    }
  }
  if (def.sonar) {
    for (std::size_t i = 0; i < scene.robots.size(); ++i) drawSonar(c, scene, def, scene.robots[i], m, palette::robot(scene.robots[i], i));
  }
  if (bodies) {
    for (std::size_t i = 0; i < scene.robots.size(); ++i) drawRobot(c, scene.robots[i], m, palette::robot(scene.robots[i], i));
  }
  // Pictures last, so a task's debugging overlay is never hidden.
  for (const RobotView& r : scene.robots) drawPicture(c, r.picture, m, text);
}

}  // namespace frob::render::detail
