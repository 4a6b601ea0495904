#pragma once
// Test helper: decodes a video file with libavformat and libavcodec, to check what was written.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "frob/render/image.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace frob::render::testing {

struct Decoded {
  int frames = 0, width = 0, height = 0;
  std::string codec;
  std::vector<Image> images;  // every frame as RGBA, when asked for
};

// Decodes every frame of `path` with libavformat and libavcodec; with `keepImages`, converts each to
// RGBA with libswscale (BT.601, limited range, as the writer tags its frames), independent of the
// writer's own conversion.
inline Decoded decode(const std::string& path, bool keepImages = false) {
  Decoded out;
  AVFormatContext* fmt = nullptr;
  if (avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) < 0) return out;
  avformat_find_stream_info(fmt, nullptr);
  const AVCodec* dec = nullptr;
  const int stream = av_find_best_stream(fmt, AVMEDIA_TYPE_VIDEO, -1, -1, &dec, 0);
  AVCodecContext* ctx = avcodec_alloc_context3(dec);
  avcodec_parameters_to_context(ctx, fmt->streams[stream]->codecpar);
  avcodec_open2(ctx, dec, nullptr);
  out.codec = dec->name;
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  auto drain = [&] {
    while (avcodec_receive_frame(ctx, frame) == 0) {
      ++out.frames;
      out.width = frame->width;
      out.height = frame->height;
      if (!keepImages) continue;
      sws = sws_getCachedContext(sws, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width, frame->height,
                                 AV_PIX_FMT_RGBA, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr);
      Image img{.width = frame->width,
                .height = frame->height,
                .rgba = std::vector<std::uint8_t>(static_cast<std::size_t>(frame->width) * frame->height * 4)};
      std::uint8_t* dst[1] = {img.rgba.data()};
      const int dstStride[1] = {4 * frame->width};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, dstStride);
      out.images.push_back(std::move(img));
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    if (pkt->stream_index == stream) {
      avcodec_send_packet(ctx, pkt);
      drain();
    }
    av_packet_unref(pkt);
  }
  avcodec_send_packet(ctx, nullptr);
  drain();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&pkt);
  avcodec_free_context(&ctx);
  avformat_close_input(&fmt);
  return out;
}

// How many pixels' luma (BT.601 weights) differs between two same-sized images by more than 40
// levels. H.264 at the writer's defaults (crf 23, ultrafast) keeps luma at full resolution and
// within a few levels on flat areas, though a sharp edge may ring; a moved robot, path or text
// changes hundreds of pixels by far more than 40.
inline long lumaOutliers(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return static_cast<long>(a.width) * a.height;
  auto luma = [](const std::uint8_t* p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; };
  long n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) n += std::abs(luma(&a.rgba[i]) - luma(&b.rgba[i])) > 40.0;
  return n;
}

// The most luma outliers a decoded frame may have against the image it was encoded from: measured
// 0 on the test frames (320 x 240 and 320 x 160 renders); 20 leaves room for another x264 build
// ringing at a few edges. Frames a step or more apart in the test runs differ in 700 or more.
inline constexpr long kCodecLumaOutliers = 20;

}  // namespace frob::render::testing
