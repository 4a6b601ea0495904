#pragma once
/// The offscreen renderer: FrameScenes (plus plots) to RGBA images. The top-down view and plots are
/// rasterized on the CPU; the chase view goes through OSMesa (llvmpipe).

#include "frob/base/result.hpp"
#include "frob/geometry.hpp"
#include "frob/render/image.hpp"
#include "frob/render/plot.hpp"
#include "frob/render/scene.hpp"

#include <memory>
#include <string>

namespace frob::render {

/// How the world is looked at.
enum class ViewMode {
  TopDown,  ///< orthographic from above, fitted to the world bounds, y up
  Chase,    ///< perspective from behind and above one robot, walls extruded
};

/// Where the world view and the plot panel go in the frame.
enum class PanelLayout {
  WorldOnly,  ///< the world fills the frame
  PlotRight,  ///< world on the left, plots on the right
  PlotBelow,  ///< world on top, plots below
};

/// Everything fixed for the life of a renderer. Fill with designated initializers.
struct RenderDef {
  int width = 640;                              ///< frame width, pixels
  int height = 480;                             ///< frame height, pixels
  ViewMode view = ViewMode::TopDown;            ///< top-down or chase view
  int chaseRobot = 0;                           ///< index of the robot the chase camera follows
  PanelLayout layout = PanelLayout::WorldOnly;  ///< where plots go
  double plotShare = 0.4;                       ///< share of the width (PlotRight) or height (PlotBelow) for plots
  bool hud = true;                              ///< draw time, tasks, wheels and front sonar over the world
  bool grid = true;                             ///< 1 m grid with labels
  bool sonar = true;                            ///< sonar cones with their readings
  bool paths = true;                            ///< true path (solid) and odometry path (dashed)
  double sonarHalfAngle = 0.13;                 ///< half width of a drawn sonar cone, radians
  double margin = 0.3;                          ///< space around the world bounds in the top-down view, metres
  double wallHeight = 0.5;                      ///< height of extruded walls in the chase view, metres
  int textPixels = 13;                          ///< text size, pixels
  std::string fontFile;                         ///< proportional font; empty: DejaVuSans from the build
  std::string monoFontFile;                     ///< fixed-width font for the HUD; empty: DejaVuSansMono
  std::string robotModelFile;                   ///< chase-view robot mesh (assimp); empty: robot.obj of frob::layout().models
  int rasterThreads = 0;                        ///< chase view: llvmpipe threads (LP_NUM_THREADS, read at the process's first context); -1: leave it
};

/// Checks a RenderDef without building anything heavy: sizes, fonts and (for Chase) the model.
[[nodiscard]] Status validate(const RenderDef& def);

/// Draws frames of fixed size: the top-down view and plots on the CPU, the chase view in an offscreen
/// OpenGL context. Output is a pure function of the inputs: the same scene and plots give the same pixels. Not thread-safe; one per thread.
/// Typical use (see tests/render/pipeline_test.cpp): validate() the RenderDef and VideoDef before
/// the run, create() and VideoWriter::open(), then per step renderInto() as often as
/// FramePicker::framesAt() says and VideoWriter::write(), and finally VideoWriter::close().
class Renderer {
 public:
  /// Validates `def`, loads fonts (and the model), creates the context. Fails with a readable message.
  [[nodiscard]] static Result<Renderer> create(const RenderDef& def);
  Renderer(Renderer&&) noexcept;             ///< movable, not copyable (it owns a GL context)
  Renderer& operator=(Renderer&&) noexcept;  ///< movable, not copyable
  ~Renderer();                               ///< frees the GL context

  /// Draws `scene`, and `plots` up to the scene's time into the plot panel if the layout has one.
  [[nodiscard]] Image render(const FrameScene& scene, const PlotSet& plots = {});
  /// As render(), reusing `out`'s storage.
  void renderInto(const FrameScene& scene, const PlotSet& plots, Image& out);
  /// Draws only `plots`, filling the whole frame, with samples up to time `now` (kWholeRun: all).
  [[nodiscard]] Image renderPlots(const PlotSet& plots, double now = kWholeRun);
  /// Where world point `p` lands in the top-down view of `scene`: pixel x right, y down from the top.
  [[nodiscard]] Vec2 worldToPixel(const FrameScene& scene, const Point2& p) const;
  /// The definition this renderer was created with (defaults filled in).
  [[nodiscard]] const RenderDef& def() const;

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace frob::render
