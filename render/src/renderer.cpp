#include "frob/render/renderer.hpp"

#include "chase_view.hpp"
#include "draw.hpp"
#include "font_atlas.hpp"
#include "frob/base/layout.hpp"
#include "frob/worlds/fnv.hpp"
#include "gl_context.hpp"
#include "model.hpp"
#include "raster.hpp"

#include <GL/gl.h>

#include <cstring>
#include <optional>
#include <type_traits>

namespace frob::render {

namespace {

// The definition with empty asset paths replaced by the ones the build found.
RenderDef withDefaults(RenderDef def) {
  if (def.fontFile.empty()) def.fontFile = FROB_FONT_FILE;
  if (def.monoFontFile.empty()) def.monoFontFile = FROB_MONO_FONT_FILE;
  if (def.robotModelFile.empty()) def.robotModelFile = (layout().models / "robot.obj").string();
  return def;
}

Status checkSizes(const RenderDef& def) {
  if (def.width < 16 || def.height < 16 || def.width > 8192 || def.height > 8192) {
    return Status::failure("render: frame size " + std::to_string(def.width) + "x" + std::to_string(def.height) + " is outside 16..8192 pixels");
  }
  if (def.layout != PanelLayout::WorldOnly && !(def.plotShare >= 0.05 && def.plotShare <= 0.95)) {
    return Status::failure("render: plotShare " + std::to_string(def.plotShare) + " is outside 0.05..0.95");
  }
  return {};
}

// Draws a canvas with the current matrices, one call per run of triangles of the same mode.
void drawBatch(const detail::Canvas& canvas) {
  const std::vector<detail::Vertex>& v = canvas.vertices();
  const std::vector<detail::Run>& runs = canvas.runs();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::size_t first = runs[i].first, end = i + 1 < runs.size() ? runs[i + 1].first : v.size();
    if (end == first) continue;
    if (runs[i].mode == detail::Mode::Opaque)
      glDisable(GL_BLEND);
    else
      glEnable(GL_BLEND);
    // Pointers start at the run so that Mesa uploads only this run's vertices.
    glVertexPointer(3, GL_FLOAT, sizeof(detail::Vertex), &v[first].x);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(detail::Vertex), &v[first].color);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(end - first));
  }
}

}  // namespace

struct Renderer::Impl {
  RenderDef def;
  std::unique_ptr<detail::GlContext> gl;
  std::unique_ptr<detail::FontAtlas> fonts;
  std::optional<detail::Mesh> model;
  detail::Canvas overlay;
  detail::ChaseLayers chase;
  // The top-down view's static world (floor, grid, obstacles, walls, point markers) as drawn
  // pixels, and a hash of the scene parts it was drawn from; each frame starts from a copy.
  std::vector<std::uint8_t> staticPixels;
  std::uint64_t staticKey = 0;

  void begin(const Color& clear, Image& out);
  void draw2d();
  void finish(Image& out);
  // The flat 2D path (top-down view, plots): the canvas is rasterized on the CPU, no GL at all.
  void begin2d(const Color& clear, Image& out);
  void finish2d(Image& out);
  std::size_t overlayFrom = 0;  // vertices before this are already in the frame
};

Status validate(const RenderDef& given) {
  const RenderDef def = withDefaults(given);
  if (Status s = checkSizes(def); !s) return s;
  auto fonts = detail::FontAtlas::create(def.fontFile, def.monoFontFile, def.textPixels);
  if (!fonts) return fonts.status();
  if (def.view == ViewMode::Chase) {
    if (auto model = detail::loadModel(def.robotModelFile); !model) return model.status();
  }
  return {};
}

Result<Renderer> Renderer::create(const RenderDef& given) {
  auto impl = std::make_unique<Impl>();
  impl->def = withDefaults(given);
  const RenderDef& def = impl->def;
  if (Status s = checkSizes(def); !s) return s;
  auto fonts = detail::FontAtlas::create(def.fontFile, def.monoFontFile, def.textPixels);
  if (!fonts) return fonts.status();
  impl->fonts = std::move(fonts.value());
  if (def.view == ViewMode::Chase) {
    auto model = detail::loadModel(def.robotModelFile);
    if (!model) return model.status();
    impl->model = std::move(model.value());
  }
  // Only the chase view needs OpenGL: the top-down view and the plots are rasterized on the CPU.
  if (def.view == ViewMode::Chase) {
    auto gl = detail::GlContext::create(def.width, def.height, true, def.rasterThreads);
    if (!gl) return gl.status();
    impl->gl = std::move(gl.value());

    // Fixed state: client vertex arrays, alpha blending (per run), alpha writes off so frames stay
    // opaque. Text is not drawn by GL at all (see OverlayOp). A scratch buffer makes the context
    // current for this; frames are drawn into the caller's image.
    std::vector<std::uint8_t> scratch(static_cast<std::size_t>(def.width) * def.height * 4);
    impl->gl->makeCurrent(scratch.data());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DITHER);
    glDisable(GL_CULL_FACE);
    glDepthFunc(GL_LEQUAL);
  }
  return Renderer(std::move(impl));
}

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

const RenderDef& Renderer::def() const { return impl_->def; }

void Renderer::Impl::begin(const Color& bg, Image& out) {
  // GL draws straight into the caller's image: no copy afterwards.
  out.width = def.width;
  out.height = def.height;
  out.rgba.resize(static_cast<std::size_t>(def.width) * def.height * 4);
  gl->makeCurrent(out.rgba.data());
  glViewport(0, 0, def.width, def.height);
  glClearColor(bg.r, bg.g, bg.b, 1.0f);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Only the chase view has (and clears) a depth buffer: clearing is a good share of a frame's cost.
  glClear(def.view == ViewMode::Chase ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  overlay.clear();
}

void Renderer::Impl::begin2d(const Color& bg, Image& out) {
  out.width = def.width;
  out.height = def.height;
  out.rgba.resize(static_cast<std::size_t>(def.width) * def.height * 4);
  detail::fillRgba(out.rgba.data(), out.width, out.height, detail::rgba8(bg));
  overlay.clear();
  overlayFrom = 0;
}

void Renderer::Impl::finish2d(Image& out) {
  detail::rasterize(overlay, out.rgba.data(), out.width, out.height, overlayFrom);
  fonts->composite(overlay.overlay(), out.rgba.data(), out.width, out.height);
}

namespace {

// FNV-1a over the bytes of the scene parts the static world is drawn from.
class StaticKey {
 public:
  template <class T>
  void add(const T& v) {
    h_.add(v);
  }
  void add(const Point2& p) { h_.add(p.x()).add(p.y()); }
  [[nodiscard]] std::uint64_t value() const { return h_.value(); }

 private:
  worlds::Fnv1a h_;
};

std::uint64_t staticKeyOf(const FrameScene& s) {
  StaticKey k;
  k.add(s.bounds.min), k.add(s.bounds.max);
  k.add(s.walls.size()), k.add(s.blocks.size()), k.add(s.pillars.size()), k.add(s.points.size());
  for (const Wall& w : s.walls) k.add(w.a), k.add(w.b), k.add(w.thickness);
  for (const Block& b : s.blocks) k.add(b.center), k.add(b.halfExtents.x()), k.add(b.halfExtents.y()), k.add(b.angle);
  for (const Pillar& p : s.pillars) k.add(p.center), k.add(p.radius);
  for (const Marker& p : s.points) {
    k.add(p.at);
    const Color c = p.color.value_or(Color{-1, -1, -1, -1});
    k.add(c.r), k.add(c.g), k.add(c.b), k.add(c.a);
  }
  return k.value();
}

}  // namespace

void Renderer::Impl::draw2d() {
  glViewport(0, 0, def.width, def.height);
  glDisable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, def.width, def.height, 0, -1, 1);  // pixels, y down
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  drawBatch(overlay);
}

void Renderer::Impl::finish(Image& out) {
  gl->finish();
  fonts->composite(overlay.overlay(), out.rgba.data(), out.width, out.height);
}

Image Renderer::render(const FrameScene& scene, const PlotSet& plots) {
  Image out;
  renderInto(scene, plots, out);
  return out;
}

void Renderer::renderInto(const FrameScene& scene, const PlotSet& plots, Image& out) {
  Impl& m = *impl_;
  const bool topDown = m.def.view == ViewMode::TopDown;
  if (topDown)
    m.begin2d(detail::palette::floor, out);
  else
    m.begin(detail::palette::background, out);
  const detail::Panels panels = detail::layoutPanels(m.def);
  const auto& w = panels.world;
  m.overlay.setClip(static_cast<int>(w.x), static_cast<int>(w.y), static_cast<int>(w.x + w.w), static_cast<int>(w.y + w.h));
  if (m.def.view == ViewMode::TopDown) {
    const detail::Mapping map = detail::fitTopDown(scene.bounds, m.def.margin, panels.world);
    const detail::TextSink text = [&](const Point2& at, const std::string& s, Color col) {
      m.fonts->draw(m.overlay, detail::Font::Sans, map.map(at), s, detail::rgba8(col));
    };
    std::size_t staticEnd = 0;
    detail::drawGround(m.overlay, *m.fonts, m.def, scene, map, true, text, &panels.world, &staticEnd);
    // The static world is drawn once per change of the walls (usually once per renderer) and copied
    // into each frame: re-rasterizing its long thin triangles was a good share of a frame.
    const std::uint64_t key = staticKeyOf(scene);
    if (m.staticPixels.size() != out.rgba.size() || key != m.staticKey) {
      detail::rasterize(m.overlay, out.rgba.data(), out.width, out.height, 0, staticEnd);
      m.staticPixels = out.rgba;
      m.staticKey = key;
    } else {
      std::memcpy(out.rgba.data(), m.staticPixels.data(), out.rgba.size());
    }
    m.overlayFrom = staticEnd;
  } else {
    detail::buildChase(m.chase, m.overlay, *m.fonts, m.def, scene, *m.model, panels.world);
    const auto& vp = panels.world;
    glViewport(static_cast<GLint>(vp.x), static_cast<GLint>(m.def.height - vp.y - vp.h), static_cast<GLsizei>(vp.w), static_cast<GLsizei>(vp.h));
    glMatrixMode(GL_PROJECTION);
    const Eigen::Matrix4f proj = m.chase.viewProj.cast<float>();
    glLoadMatrixf(proj.data());
    glMatrixMode(GL_MODELVIEW);
    // The ground canvas has y pointing down the screen (y = -world y): flip it back.
    const float flip[16] = {1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    glLoadMatrixf(flip);
    glDisable(GL_DEPTH_TEST);
    drawBatch(m.chase.ground);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    drawBatch(m.chase.solid);
  }
  if (m.def.hud) detail::drawHud(m.overlay, *m.fonts, scene, panels.world);
  if (panels.plots.w > 0) {
    const auto& p = panels.plots;
    m.overlay.setClip(static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.x + p.w), static_cast<int>(p.y + p.h));
    detail::drawPlots(m.overlay, *m.fonts, plots, scene.time, panels.plots);
  }
  if (topDown) {
    m.finish2d(out);
    return;
  }
  m.draw2d();
  m.finish(out);
}

Image Renderer::renderPlots(const PlotSet& plots, double now) {
  Impl& m = *impl_;
  Image out;
  m.begin2d(white, out);
  detail::drawPlots(m.overlay, *m.fonts, plots, now, {0, 0, static_cast<double>(m.def.width), static_cast<double>(m.def.height)});
  m.finish2d(out);
  return out;
}

Vec2 Renderer::worldToPixel(const FrameScene& scene, const Point2& p) const {
  const detail::Panels panels = detail::layoutPanels(impl_->def);
  return detail::fitTopDown(scene.bounds, impl_->def.margin, panels.world).map(p);
}

}  // namespace frob::render
