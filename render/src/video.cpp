#include "frob/render/video.hpp"

#include "frob/render/output_file.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
}

#include <cmath>
#include <condition_variable>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <deque>
#include <mutex>
#include <thread>

namespace frob::render {

namespace {

std::string avError(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

// RGBA (top row first) to planar YUV 4:2:0, BT.601 limited range, in integers. Chroma takes the
// mean of each 2x2 block. Several times faster than swscale's generic path for this one case.
#if defined(__SSE2__)
// Luma of 4 RGBA pixels at `s` as 32-bit lanes: ((66 r + 129 g + 25 b + 128) >> 8) + 16.
inline __m128i luma4(const std::uint8_t* s) {
  const __m128i zero = _mm_setzero_si128(), coef = _mm_set_epi16(0, 25, 129, 66, 0, 25, 129, 66);
  const __m128i px = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s));
  const __m128i a = _mm_madd_epi16(_mm_unpacklo_epi8(px, zero), coef);  // r0*66+g0*129, b0*25, r1.., b1..
  const __m128i b = _mm_madd_epi16(_mm_unpackhi_epi8(px, zero), coef);
  const __m128 af = _mm_castsi128_ps(a), bf = _mm_castsi128_ps(b);
  const __m128i even = _mm_castps_si128(_mm_shuffle_ps(af, bf, _MM_SHUFFLE(2, 0, 2, 0)));
  const __m128i odd = _mm_castps_si128(_mm_shuffle_ps(af, bf, _MM_SHUFFLE(3, 1, 3, 1)));
  const __m128i sum = _mm_add_epi32(_mm_add_epi32(even, odd), _mm_set1_epi32(128));
  return _mm_add_epi32(_mm_srai_epi32(sum, 8), _mm_set1_epi32(16));
}
#endif

void rgbaToYuv420(const Image& img, AVFrame* f) {
  const int w = img.width, h = img.height;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* s = img.rgba.data() + static_cast<std::size_t>(y) * w * 4;
    std::uint8_t* yRow = f->data[0] + static_cast<std::ptrdiff_t>(y) * f->linesize[0];
    int x = 0;
#if defined(__SSE2__)
    // 16 pixels at a time, the same integers as the loop below.
    for (; x + 16 <= w; x += 16) {
      const __m128i p01 = _mm_packs_epi32(luma4(s + 4 * x), luma4(s + 4 * x + 16));
      const __m128i p23 = _mm_packs_epi32(luma4(s + 4 * x + 32), luma4(s + 4 * x + 48));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(yRow + x), _mm_packus_epi16(p01, p23));
    }
#endif
    for (; x < w; ++x) {
      const int r = s[4 * x], g = s[4 * x + 1], b = s[4 * x + 2];
      yRow[x] = static_cast<std::uint8_t>(((66 * r + 129 * g + 25 * b + 128) >> 8) + 16);
    }
  }
  for (int y = 0; y < h / 2; ++y) {
    const std::uint8_t* s0 = img.rgba.data() + static_cast<std::size_t>(2 * y) * w * 4;
    const std::uint8_t* s1 = s0 + static_cast<std::size_t>(w) * 4;
    std::uint8_t* uRow = f->data[1] + static_cast<std::ptrdiff_t>(y) * f->linesize[1];
    std::uint8_t* vRow = f->data[2] + static_cast<std::ptrdiff_t>(y) * f->linesize[2];
    for (int x = 0; x < w / 2; ++x) {
      const int i = 8 * x;
      const int r = (s0[i] + s0[i + 4] + s1[i] + s1[i + 4] + 2) >> 2;
      const int g = (s0[i + 1] + s0[i + 5] + s1[i + 1] + s1[i + 5] + 2) >> 2;
      const int b = (s0[i + 2] + s0[i + 6] + s1[i + 2] + s1[i + 6] + 2) >> 2;
      uRow[x] = static_cast<std::uint8_t>(((-38 * r - 74 * g + 112 * b + 128) >> 8) + 128);
      vRow[x] = static_cast<std::uint8_t>(((112 * r - 94 * g - 18 * b + 128) >> 8) + 128);
    }
  }
}

}  // namespace

// Frames are converted to YUV on the caller's thread (which also avoids copying the RGBA frame) and
// encoded on a worker thread, so that rendering the next frame overlaps with encoding this one; the
// two sides are then about as busy. At most kQueued frames wait; their buffers are recycled.
struct VideoWriter::Impl {
  static constexpr std::size_t kQueued = 2;
  VideoDef def;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVPacket* packet = nullptr;
  std::int64_t frames = 0;   // accepted by write()
  std::int64_t encoded = 0;  // sent to the encoder (worker thread)
  bool finished = false;     // closed (successfully or not): nothing left to clean up but memory

  std::thread worker;
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<AVFrame*> queue;   // guarded by mutex: converted frames waiting for the encoder
  std::vector<AVFrame*> spare;  // guarded by mutex: encoded frames to reuse
  Status workerStatus;          // guarded by mutex: the first encoding error
  bool stopping = false;        // guarded by mutex
  bool dropQueued = false;      // guarded by mutex: stop without encoding what waits

  ~Impl() {
    stopWorker(true);
    release();
    if (!finished) discardPartial(def.path);
  }
  void release() {
    if (format != nullptr) {
      if (format->pb != nullptr) avio_closep(&format->pb);
      avformat_free_context(format);
      format = nullptr;
    }
    avcodec_free_context(&codec);
    av_packet_free(&packet);
    for (AVFrame*& f : queue) av_frame_free(&f);
    for (AVFrame*& f : spare) av_frame_free(&f);
    queue.clear();
    spare.clear();
  }
  [[nodiscard]] Status error(const std::string& what, int code) const {
    return Status::failure("video: " + what + " for '" + def.path + "': " + avError(code));
  }
  // Gives up on the file: frees everything and removes the temporary. Main thread only.
  Status abandon(Status why) {
    stopWorker(true);
    release();
    discardPartial(def.path);
    finished = true;
    return why;
  }
  void stopWorker(bool drop) {
    if (!worker.joinable()) return;
    {
      const std::lock_guard lock(mutex);
      stopping = true;
      dropQueued = drop;
    }
    changed.notify_all();
    worker.join();
  }
  void run() {
    for (;;) {
      AVFrame* f = nullptr;
      {
        std::unique_lock lock(mutex);
        changed.wait(lock, [&] { return !queue.empty() || stopping; });
        if (queue.empty() || dropQueued) return;
        f = queue.front();
        queue.pop_front();
      }
      f->pts = encoded++;
      Status s = encode(f);
      {
        const std::lock_guard lock(mutex);
        if (!s && workerStatus.ok()) workerStatus = std::move(s);
        spare.push_back(f);
      }
      changed.notify_all();
    }
  }
  // Sends `f` (nullptr: flush) to the encoder and writes every packet it gives back.
  Status encode(const AVFrame* f) {
    if (int err = avcodec_send_frame(codec, f); err < 0) return error("encoding failed", err);
    for (;;) {
      const int err = avcodec_receive_packet(codec, packet);
      if (err == AVERROR(EAGAIN) || err == AVERROR_EOF) return {};
      if (err < 0) return error("encoding failed", err);
      // Every frame lasts 1/fps; without a duration the MP4's last frame would have none.
      if (packet->duration == 0) packet->duration = 1;
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if (int w = av_interleaved_write_frame(format, packet); w < 0) return error("writing failed", w);
    }
  }
};

Status validate(const VideoDef& def) {
  if (def.width <= 0 || def.height <= 0 || def.width > 8192 || def.height > 8192) {
    return Status::failure("video: frame size " + std::to_string(def.width) + "x" + std::to_string(def.height) + " is outside 1..8192 pixels");
  }
  if (def.width % 2 != 0 || def.height % 2 != 0) {
    return Status::failure("video: H.264 in yuv420p needs an even width and height; got " + std::to_string(def.width) + "x" +
                           std::to_string(def.height));
  }
  if (def.fps < 1 || def.fps > 240) return Status::failure("video: fps " + std::to_string(def.fps) + " is outside 1..240");
  if (def.threads < 0 || def.threads > 64) return Status::failure("video: threads " + std::to_string(def.threads) + " is outside 0..64");
  if (def.crf < 0 || def.crf > 51) return Status::failure("video: crf " + std::to_string(def.crf) + " is outside 0..51");
  if (def.maxKilobitsPerSecond < 0 || def.maxKilobitsPerSecond > 1'000'000)
    return Status::failure("video: maxKilobitsPerSecond " + std::to_string(def.maxKilobitsPerSecond) + " is outside 0..1000000");
  if (avcodec_find_encoder_by_name("libx264") == nullptr) {
    return Status::failure("video: this libavcodec has no libx264 encoder (install libavcodec59 with x264)");
  }
  return checkWritable(def.path, "video");
}

Result<VideoWriter> VideoWriter::open(const VideoDef& def) {
  if (Status s = validate(def); !s) return s;
  av_log_set_level(AV_LOG_ERROR);  // libx264 prints its settings at the info level
  auto m = std::make_unique<Impl>();
  m->def = def;
  const std::string tmp = partialPath(def.path);
  // The muxer is named explicitly: the temporary's extension says nothing about the format.
  if (int err = avformat_alloc_output_context2(&m->format, nullptr, "mp4", tmp.c_str()); err < 0)
    return m->abandon(m->error("cannot set up MP4", err));
  const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
  m->stream = avformat_new_stream(m->format, nullptr);
  m->codec = avcodec_alloc_context3(x264);
  m->packet = av_packet_alloc();
  if (!m->stream || !m->codec || !m->packet) return m->abandon(m->error("out of memory", AVERROR(ENOMEM)));
  m->codec->width = def.width;
  m->codec->height = def.height;
  m->codec->pix_fmt = AV_PIX_FMT_YUV420P;
  m->codec->time_base = AVRational{1, def.fps};
  m->codec->framerate = AVRational{def.fps, 1};
  m->codec->gop_size = def.fps * 2;
  m->codec->thread_count = def.threads;
  // What rgbaToYuv420 produces, stated so that players convert back the same way.
  m->codec->color_range = AVCOL_RANGE_MPEG;
  m->codec->colorspace = AVCOL_SPC_SMPTE170M;
  m->codec->color_primaries = AVCOL_PRI_SMPTE170M;
  m->codec->color_trc = AVCOL_TRC_SMPTE170M;
  if (m->format->oformat->flags & AVFMT_GLOBALHEADER) m->codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  av_opt_set(m->codec->priv_data, "preset", def.preset.c_str(), 0);
  av_opt_set(m->codec->priv_data, "crf", std::to_string(def.crf).c_str(), 0);
  if (def.maxKilobitsPerSecond > 0) {  // capped CRF: the crf's quality where the cap allows it
    m->codec->rc_max_rate = std::int64_t{def.maxKilobitsPerSecond} * 1000;
    m->codec->rc_buffer_size = def.maxKilobitsPerSecond * 1000;
  }
  if (int err = avcodec_open2(m->codec, x264, nullptr); err < 0) return m->abandon(m->error("cannot open the H.264 encoder", err));
  if (int err = avcodec_parameters_from_context(m->stream->codecpar, m->codec); err < 0) return m->abandon(m->error("cannot set up the stream", err));
  m->stream->time_base = m->codec->time_base;
  if (int err = avio_open(&m->format->pb, tmp.c_str(), AVIO_FLAG_WRITE); err < 0) return m->abandon(m->error("cannot open the file", err));
  if (int err = avformat_write_header(m->format, nullptr); err < 0) return m->abandon(m->error("cannot write the header", err));
  Impl* raw = m.get();
  m->worker = std::thread([raw] { raw->run(); });
  return VideoWriter(std::move(m));
}

VideoWriter::VideoWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VideoWriter::VideoWriter(VideoWriter&&) noexcept = default;
VideoWriter& VideoWriter::operator=(VideoWriter&&) noexcept = default;
VideoWriter::~VideoWriter() = default;

std::int64_t VideoWriter::frameCount() const { return impl_->frames; }

Status VideoWriter::write(const Image& image) {
  Impl& m = *impl_;
  if (m.finished) return Status::failure("video: '" + m.def.path + "' is already closed");
  if (image.width != m.def.width || image.height != m.def.height || image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    return Status::failure("video: frame of " + std::to_string(image.width) + "x" + std::to_string(image.height) + " does not match the video's " +
                           std::to_string(m.def.width) + "x" + std::to_string(m.def.height));
  }
  AVFrame* slot = nullptr;
  {
    std::unique_lock lock(m.mutex);
    m.changed.wait(lock, [&] { return m.queue.size() < Impl::kQueued || !m.workerStatus.ok(); });
    if (!m.workerStatus.ok()) {
      Status why = m.workerStatus;
      lock.unlock();
      return m.abandon(std::move(why));
    }
    if (!m.spare.empty()) {
      slot = m.spare.back();
      m.spare.pop_back();
    }
  }
  // Converted outside the lock, into a recycled (or new) frame that the encoder no longer holds.
  if (slot == nullptr) {
    slot = av_frame_alloc();
    if (slot == nullptr) return m.abandon(m.error("out of memory", AVERROR(ENOMEM)));
    slot->format = AV_PIX_FMT_YUV420P;
    slot->width = m.def.width;
    slot->height = m.def.height;
    if (int err = av_frame_get_buffer(slot, 0); err < 0) {
      av_frame_free(&slot);
      return m.abandon(m.error("out of memory", err));
    }
  }
  if (int err = av_frame_make_writable(slot); err < 0) {
    av_frame_free(&slot);
    return m.abandon(m.error("out of memory", err));
  }
  rgbaToYuv420(image, slot);
  {
    const std::lock_guard lock(m.mutex);
    m.queue.push_back(slot);
  }
  m.changed.notify_all();
  ++m.frames;
  return {};
}

Status VideoWriter::close() {
  Impl& m = *impl_;
  if (m.finished) return Status::failure("video: '" + m.def.path + "' is already closed");
  m.stopWorker(false);  // encodes what is queued, then stops
  if (!m.workerStatus.ok()) return m.abandon(m.workerStatus);
  if (Status s = m.encode(nullptr); !s) return m.abandon(s);
  if (int err = av_write_trailer(m.format); err < 0) return m.abandon(m.error("cannot finish the file", err));
  if (int err = avio_closep(&m.format->pb); err < 0) return m.abandon(m.error("cannot close the file", err));
  m.release();
  m.finished = true;
  return commitPartial(m.def.path, "video");
}

FramePicker::FramePicker(double stepSeconds, double fps) : framesPerStep_(stepSeconds * fps) {}

std::int64_t FramePicker::framesBefore(std::int64_t step) const {
  // Frames k with k / fps < step * dt; the tolerance absorbs rounding in dt * fps.
  return static_cast<std::int64_t>(std::ceil(static_cast<double>(step) * framesPerStep_ - 1e-6));
}

int FramePicker::framesAt(std::int64_t step) const { return static_cast<int>(framesBefore(step + 1) - framesBefore(step)); }

std::vector<std::int64_t> FramePicker::steps(std::int64_t stepCount) const {
  std::vector<std::int64_t> out;
  for (std::int64_t i = 0; i < stepCount; ++i)
    for (int k = framesAt(i); k > 0; --k) out.push_back(i);
  return out;
}

}  // namespace frob::render
