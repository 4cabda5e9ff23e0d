#include "video_decode.h"

#include <algorithm>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace oflab::testing {
namespace {

// A decoded frame as RGB24 rows, top to bottom, without padding. Converts into a padded
// AVFrame first: swscale's vector code may write past the end of an unpadded row.
std::vector<std::uint8_t> rgb_of(const AVFrame* frame) {
  const int w = frame->width, h = frame->height;
  AVFrame* rgb = av_frame_alloc();
  rgb->format = AV_PIX_FMT_RGB24;
  rgb->width = w;
  rgb->height = h;
  av_frame_get_buffer(rgb, 0);
  SwsContext* sws = sws_getContext(w, h, AVPixelFormat(frame->format), w, h, AV_PIX_FMT_RGB24,
                                   SWS_BICUBIC, nullptr, nullptr, nullptr);
  sws_scale(sws, frame->data, frame->linesize, 0, h, rgb->data, rgb->linesize);
  sws_freeContext(sws);
  std::vector<std::uint8_t> out(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y) {
    std::copy_n(rgb->data[0] + static_cast<size_t>(y) * rgb->linesize[0], 3 * w,
                out.data() + static_cast<size_t>(y) * 3 * w);
  }
  av_frame_free(&rgb);
  return out;
}

}  // namespace

Decoded decode_with_libav(const std::string& path) {
  Decoded d;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return d;
  avformat_find_stream_info(format, nullptr);
  const AVCodec* codec = nullptr;
  const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
  if (stream < 0) {
    avformat_close_input(&format);
    return d;
  }
  AVCodecContext* context = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(context, format->streams[stream]->codecpar);
  avcodec_open2(context, codec, nullptr);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  const auto drain = [&] {
    while (avcodec_receive_frame(context, frame) == 0) {
      if (d.frames++ > 0) continue;
      d.width = frame->width;
      d.height = frame->height;
      d.first_rgb = rgb_of(frame);
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == stream) {
      // A full decoder refuses the packet (EAGAIN) until its frames are taken.
      while (avcodec_send_packet(context, packet) == AVERROR(EAGAIN)) drain();
      drain();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(context, nullptr);
  drain();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&context);
  avformat_close_input(&format);
  return d;
}

void GifCloser::operator()(GifFileType* gif) const {
  int error = 0;
  DGifCloseFile(gif, &error);
}

SlurpedGif read_gif(const std::string& path) {
  int error = 0;
  SlurpedGif gif(DGifOpenFileName(path.c_str(), &error));
  if (!gif || DGifSlurp(gif.get()) != GIF_OK) return nullptr;
  return gif;
}

}  // namespace oflab::testing
