#pragma once
// The drawing passes shared by the renderer's views: each appends triangles to a Canvas.

#include "canvas.hpp"
#include "font_atlas.hpp"
#include "frob/render/plot.hpp"
#include "frob/render/renderer.hpp"
#include "frob/render/scene.hpp"

#include <functional>
#include <string>
#include <utility>

namespace frob::render::detail {

// A rectangle of the frame in pixels, y down from the top.
struct Viewport {
  double x = 0, y = 0, w = 0, h = 0;
};

// World metres to canvas units: x right, y flipped (canvas y grows downwards).
struct Mapping {
  Vec2 origin = Vec2(0, 0);  // canvas position of the world origin
  double scale = 1.0;        // canvas units per metre
  double pixel = 1.0;        // canvas units per nominal pixel (line widths, marker sizes)
  [[nodiscard]] Vec2 map(const Point2& p) const { return {origin.x() + scale * p.x(), origin.y() - scale * p.y()}; }
};

// Where the world view and the plot panel go.
struct Panels {
  Viewport world;
  Viewport plots;  // w == 0 when there is no plot panel
};
[[nodiscard]] Panels layoutPanels(const RenderDef& def);

// The top-down camera: world bounds plus margin fitted into `vp`, centred, y up.
[[nodiscard]] Mapping fitTopDown(const Bounds& bounds, double margin, const Viewport& vp);

// Fixed colours of the scene.
namespace palette {
inline constexpr Color background{0.80f, 0.82f, 0.85f};
inline constexpr Color floor{0.97f, 0.96f, 0.93f};
inline constexpr Color grid{0.84f, 0.83f, 0.80f};
inline constexpr Color gridText{0.45f, 0.45f, 0.45f};
inline constexpr Color wall{0.23f, 0.25f, 0.28f};
inline constexpr Color obstacle{0.42f, 0.45f, 0.50f};
inline constexpr Color point{0.10f, 0.55f, 0.35f};
inline constexpr Color picture{0.85f, 0.10f, 0.60f};  // Picture shapes with no colour of their own
inline constexpr Color bump{0.95f, 0.10f, 0.10f};
inline constexpr Color chart{0.98f, 0.98f, 0.98f};  // a plot's background
[[nodiscard]] Color robot(const RobotView& r, std::size_t index);
[[nodiscard]] Color series(const Series& s, std::size_t index);
}  // namespace palette

// Receives text anchored at a world point; the chase view projects it, the top-down view draws it.
using TextSink = std::function<void(const Point2& at, const std::string& text, Color color)>;

// The ground layer: floor, grid, obstacles seen from above, named points, paths, sonar, pictures.
// In the top-down view the robots are drawn too (`bodies`). With `clearedFloor` the frame was
// cleared to the floor colour and only the part of that viewport outside the floor is painted.
// With `staticEnd`, it receives the canvas's vertex count once the static world (floor, grid,
// obstacles, walls, point markers) is drawn: those triangles depend on nothing that moves.
void drawGround(Canvas& canvas, const FontAtlas& fonts, const RenderDef& def, const FrameScene& scene, const Mapping& m, bool bodies,
                const TextSink& text, const Viewport* clearedFloor = nullptr, std::size_t* staticEnd = nullptr);
// One Picture in world coordinates.
void drawPicture(Canvas& canvas, const Picture& picture, const Mapping& m, const TextSink& text);
// Time, and per robot its task, wheel command and front sonar reading, in the top-left of `vp`.
void drawHud(Canvas& canvas, const FontAtlas& fonts, const FrameScene& scene, const Viewport& vp);
// The plot panel: charts stacked in `vp`, samples up to `now`, task switches, a cursor at `now`.
void drawPlots(Canvas& canvas, const FontAtlas& fonts, const PlotSet& plots, double now, const Viewport& vp);
// A short number for an axis label: three significant digits, and 0 for what rounds to it.
[[nodiscard]] std::string tick(double v);
// A plot's value range widened to numbers of two significant digits (0.915 -> 0.92, 16.3 -> 17),
// with rounding noise near 0 taken as 0, so that its axis labels read as numbers.
[[nodiscard]] std::pair<double, double> niceRange(double lo, double hi);

}  // namespace frob::render::detail
