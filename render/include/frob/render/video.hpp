#pragma once
/// MP4 video (H.264, yuv420p) from RGBA frames, and the choice of which simulation steps become frames.

#include "frob/base/result.hpp"
#include "frob/render/image.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace frob::render {

/// What video to write. Fill with designated initializers.
struct VideoDef {
  std::string path;                  ///< output .mp4; written as path + ".partial" until close() succeeds
  int width = 640;                   ///< pixels, even
  int height = 480;                  ///< pixels, even
  int fps = 30;                      ///< frames per second of the video
  int crf = 23;                      ///< x264 constant rate factor: lower is better and larger
  std::string preset = "ultrafast";  ///< x264 preset: ultrafast (fastest, larger files) ... veryslow
  int threads = 2;                   ///< x264 encoding threads (frames are converted to YUV on the writer's thread); 0: x264 picks
  int maxKilobitsPerSecond = 0;      ///< 0: the crf alone sets the size; else the bitrate stays under this (x264's VBV, 1 s buffer)
};

/// Checks a VideoDef without writing anything: sizes, frame rate, encoder, output directory.
[[nodiscard]] Status validate(const VideoDef& def);

/// Encodes frames into an MP4 on a worker thread (write() converts the frame to YUV and returns). The file
/// appears under its name only when close() succeeds; on failure or destruction without close()
/// the temporary is removed.
class VideoWriter {
 public:
  /// Validates `def` and opens the encoder and the temporary file.
  [[nodiscard]] static Result<VideoWriter> open(const VideoDef& def);
  VideoWriter(VideoWriter&&) noexcept;             ///< movable, not copyable
  VideoWriter& operator=(VideoWriter&&) noexcept;  ///< movable, not copyable
  ~VideoWriter();                                  ///< without a successful close(): removes the temporary

  /// Queues one frame (copied); its size must be the video's. Reports an earlier encoding error.
  [[nodiscard]] Status write(const Image& frame);
  /// Flushes the encoder, finishes the file and renames it into place.
  [[nodiscard]] Status close();
  /// Frames written so far.
  [[nodiscard]] std::int64_t frameCount() const;

 private:
  struct Impl;
  explicit VideoWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Maps simulation steps to video frames: frame k shows the last step whose time is at most k / fps.
class FramePicker {
 public:
  /// `stepSeconds` is the simulation's dt; `fps` the video's frame rate. Both positive.
  FramePicker(double stepSeconds, double fps);
  /// How many video frames show the state after step `step` (step 0 is time 0); usually 0 or 1.
  [[nodiscard]] int framesAt(std::int64_t step) const;
  /// The step shown by each frame of a run of `stepCount` steps, in order (one entry per frame).
  [[nodiscard]] std::vector<std::int64_t> steps(std::int64_t stepCount) const;

 private:
  [[nodiscard]] std::int64_t framesBefore(std::int64_t step) const;
  double framesPerStep_;
};

}  // namespace frob::render
