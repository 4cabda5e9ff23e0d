#include "formats/video_file.h"

#include <gif_lib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace oflab {

namespace fs = std::filesystem;

// One format's encoder: opened with the stored size on the writer's temporary file (which
// the writer renames into place), fed frames of at least that size (the top-left width x
// height pixels are stored), then finished. The destructor releases everything, also after a
// failed open. Errors throw VideoFileError with a message that does not name the path (the
// writer adds it), or the file's FileWriteError.
class VideoWriter::Encoder {
 public:
  virtual ~Encoder() = default;
  virtual void open(AtomicFile& file, VideoSize size, int fps) = 0;
  virtual void add(const Image& frame) = 0;
  virtual void finish() = 0;
};

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// ---- MP4 and Ogg Theora: libavformat's muxers and libavcodec's encoders ----

std::string av_message(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

void av_check(int code, const char* what) {
  if (code < 0) throw VideoFileError(std::string(what) + ": " + av_message(code));
}

const AVCodec* mp4_encoder() {
  if (const AVCodec* c = avcodec_find_encoder_by_name("libx264")) return c;
  if (const AVCodec* c = avcodec_find_encoder(AV_CODEC_ID_H264)) return c;
  return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}

// The encoder's options: H.264 at constant quality, Theora at quality 7 of 10, MPEG-4
// part 2 at a fixed rate.
void set_quality(AVCodecContext* context, const AVCodec* codec, AVDictionary** options) {
  const std::string name = codec->name;
  if (name == "libx264") {
    av_dict_set(options, "preset", "medium", 0);
    av_dict_set(options, "crf", "20", 0);  // visually lossless for flat synthetic images
  } else if (name == "libtheora") {
    context->flags |= AV_CODEC_FLAG_QSCALE;
    context->global_quality = 7 * FF_QP2LAMBDA;
  } else {
    context->bit_rate = 4000000;
  }
}

// One libavformat container with one libavcodec video stream in YUV 4:2:0.
class LibavEncoder final : public VideoWriter::Encoder {
 public:
  // `muxer`: libavformat's name ("mp4", "ogg"); `codec`: the encoder (may be null).
  LibavEncoder(const char* muxer, const AVCodec* codec) : muxer_(muxer), codec_(codec) {}

  void open(AtomicFile& file, VideoSize size, int fps) override {
    size_ = size;
    const std::string& path = file.temp_path();
    const AVCodec* codec = codec_;
    if (!codec) throw VideoFileError(std::string("this libavcodec has no encoder for ") + muxer_);
    // The encoders' banners and complaints are not for the terminal: a failure becomes one
    // line, the writer's.
    av_log_set_level(AV_LOG_QUIET);
    av_check(avformat_alloc_output_context2(&format_, nullptr, muxer_, path.c_str()),
             "cannot set up the container");
    stream_ = avformat_new_stream(format_, nullptr);
    context_ = avcodec_alloc_context3(codec);
    frame_ = av_frame_alloc();
    rgba_ = av_frame_alloc();
    packet_ = av_packet_alloc();
    if (!stream_ || !context_ || !frame_ || !rgba_ || !packet_) {
      throw VideoFileError("out of memory");
    }
    open_codec(codec, fps);
    av_check(avio_open(&format_->pb, path.c_str(), AVIO_FLAG_WRITE), "cannot create the file");
    AVDictionary* muxer = nullptr;
    if (std::string(muxer_) == "mp4") {
      av_dict_set(&muxer, "movflags", "faststart", 0);  // index first: slides start at once
    }
    const int written = avformat_write_header(format_, &muxer);
    av_dict_free(&muxer);
    av_check(written, "cannot write the header");
    frame_->format = context_->pix_fmt;
    frame_->width = size.width;
    frame_->height = size.height;
    av_check(av_frame_get_buffer(frame_, 0), "out of memory");
    rgba_->format = AV_PIX_FMT_RGBA;  // padded rows: swscale's vector code reads past a row
    rgba_->width = size.width;
    rgba_->height = size.height;
    av_check(av_frame_get_buffer(rgba_, 0), "out of memory");
    scaler_ = sws_getContext(size.width, size.height, AV_PIX_FMT_RGBA, size.width, size.height,
                             context_->pix_fmt, SWS_BICUBIC, nullptr, nullptr, nullptr);
    if (!scaler_) throw VideoFileError("no RGBA to YUV conversion");
  }

  ~LibavEncoder() override {
    sws_freeContext(scaler_);
    av_packet_free(&packet_);
    av_frame_free(&frame_);
    av_frame_free(&rgba_);
    avcodec_free_context(&context_);
    if (format_ && format_->pb) avio_closep(&format_->pb);
    avformat_free_context(format_);
  }

  void add(const Image& image) override {
    av_check(av_frame_make_writable(frame_), "out of memory");
    for (int y = 0; y < size_.height; ++y) {  // premultiplied RGBA: the pixel over black
      std::memcpy(rgba_->data[0] + static_cast<std::size_t>(y) * rgba_->linesize[0], image.row(y),
                  static_cast<std::size_t>(size_.width) * sizeof(Pixel));
    }
    sws_scale(scaler_, rgba_->data, rgba_->linesize, 0, size_.height, frame_->data,
              frame_->linesize);
    frame_->pts = next_pts_++;
    encode(frame_);
  }

  void finish() override {
    encode(nullptr);
    av_check(av_write_trailer(format_), "cannot complete the file");
    av_check(avio_closep(&format_->pb), "cannot close the file");
  }

 private:
  // YUV 4:2:0 in limited range with BT.601 colours: what presentation programs play.
  void open_codec(const AVCodec* codec, int fps) {
    context_->width = size_.width;
    context_->height = size_.height;
    context_->time_base = AVRational{1, fps};
    context_->framerate = AVRational{fps, 1};
    context_->pix_fmt = AV_PIX_FMT_YUV420P;
    context_->gop_size = fps;
    context_->color_range = AVCOL_RANGE_MPEG;
    context_->colorspace = AVCOL_SPC_SMPTE170M;
    if (format_->oformat->flags & AVFMT_GLOBALHEADER) {
      context_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    }
    AVDictionary* options = nullptr;
    set_quality(context_, codec, &options);
    const int opened = avcodec_open2(context_, codec, &options);
    av_dict_free(&options);
    av_check(opened, "cannot open the video encoder");
    av_check(avcodec_parameters_from_context(stream_->codecpar, context_), "encoder parameters");
    stream_->time_base = context_->time_base;
  }

  // Sends one frame (nullptr: flush) and writes every packet the encoder returns.
  void encode(const AVFrame* frame) {
    av_check(avcodec_send_frame(context_, frame), "the video encoder failed");
    for (;;) {
      const int got = avcodec_receive_packet(context_, packet_);
      if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
      av_check(got, "the video encoder failed");
      // Every frame lasts one tick of 1/fps; without it the MP4 edit list ends at the last
      // frame's start and players drop that frame.
      if (packet_->duration == 0) packet_->duration = 1;
      av_packet_rescale_ts(packet_, context_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      av_check(av_interleaved_write_frame(format_, packet_), "cannot write a video packet");
    }
  }

  const char* muxer_;
  const AVCodec* codec_;
  VideoSize size_;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  AVCodecContext* context_ = nullptr;
  AVFrame* frame_ = nullptr;  // YUV, to the encoder
  AVFrame* rgba_ = nullptr;   // the image's pixels, padded
  AVPacket* packet_ = nullptr;
  SwsContext* scaler_ = nullptr;
  std::int64_t next_pts_ = 0;
};

// ---- GIF: one local palette per frame (giflib's median-cut quantiser), looping ----

class GifEncoder final : public VideoWriter::Encoder {
 public:
  void open(AtomicFile& file, VideoSize size, int fps) override {
    size_ = size;
    file_ = &file;
    int error = 0;
    gif_ = EGifOpen(this, write_to_file, &error);
    if (!gif_)
      throw VideoFileError(std::string("cannot create the file: ") + GifErrorString(error));
    EGifSetGifVersion(gif_, true);
    // Hundredths of a second per frame; at least 2, the smallest delay browsers honour.
    delay_cs_ = std::max(2, static_cast<int>(std::lround(100.0 / fps)));
    check(EGifPutScreenDesc(gif_, size.width, size.height, 8, 0, nullptr));
    static const GifByteType kNetscape[] = "NETSCAPE2.0";
    const GifByteType loop_forever[3] = {1, 0, 0};
    check(EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE));
    check(EGifPutExtensionBlock(gif_, 11, kNetscape));
    check(EGifPutExtensionBlock(gif_, 3, loop_forever));
    check(EGifPutExtensionTrailer(gif_));
  }

  ~GifEncoder() override {
    int error = 0;
    if (gif_) EGifCloseFile(gif_, &error);
  }

  void add(const Image& image) override {
    const std::size_t n = static_cast<std::size_t>(size_.width) * size_.height;
    std::vector<GifByteType> r(n), g(n), b(n), indices(n);
    for (int y = 0; y < size_.height; ++y) {
      const Pixel* row = image.row(y);
      for (int x = 0; x < size_.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * size_.width + x;
        r[i] = row[x].r;  // premultiplied: the pixel over black
        g[i] = row[x].g;
        b[i] = row[x].b;
      }
    }
    std::unique_ptr<ColorMapObject, void (*)(ColorMapObject*)> palette(
        GifMakeMapObject(256, nullptr), GifFreeMapObject);
    int colours = 256;
    if (!palette ||
        GifQuantizeBuffer(static_cast<unsigned>(size_.width), static_cast<unsigned>(size_.height),
                          &colours, r.data(), g.data(), b.data(), indices.data(),
                          palette->Colors) == GIF_ERROR) {
      throw VideoFileError("cannot reduce a frame to 256 colours");
    }
    GraphicsControlBlock control{DISPOSE_DO_NOT, false, delay_cs_, NO_TRANSPARENT_COLOR};
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&control, extension);
    check(EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension));
    check(EGifPutImageDesc(gif_, 0, 0, size_.width, size_.height, false, palette.get()));
    for (int y = 0; y < size_.height; ++y) {
      check(EGifPutLine(gif_, indices.data() + static_cast<std::size_t>(y) * size_.width,
                        size_.width));
    }
  }

  void finish() override {
    int error = 0;
    const int closed = EGifCloseFile(gif_, &error);
    gif_ = nullptr;
    if (!write_error_.empty()) throw FileWriteError(write_error_);
    if (closed == GIF_ERROR)
      throw VideoFileError(std::string("cannot complete the GIF: ") + GifErrorString(error));
  }

 private:
  // giflib's output function: the bytes go to the temporary file, every write checked. A
  // failure is kept for check() to throw (no exception may cross giflib's C code).
  static int write_to_file(GifFileType* gif, const GifByteType* data, int length) {
    auto* self = static_cast<GifEncoder*>(gif->UserData);
    try {
      self->file_->write(data, static_cast<std::size_t>(length));
      return length;
    } catch (const FileWriteError& e) {
      self->write_error_ = e.what();
      return 0;
    }
  }

  void check(int status) const {
    if (!write_error_.empty()) throw FileWriteError(write_error_);
    if (status == GIF_ERROR) {
      throw VideoFileError(std::string("cannot write the GIF: ") + GifErrorString(gif_->Error));
    }
  }

  VideoSize size_;
  GifFileType* gif_ = nullptr;
  AtomicFile* file_ = nullptr;
  std::string write_error_;  // the FileWriteError of a failed write
  int delay_cs_ = 3;
};

std::unique_ptr<VideoWriter::Encoder> make_encoder(VideoFormat format) {
  switch (format) {
    case VideoFormat::kMp4:
      return std::make_unique<LibavEncoder>("mp4", mp4_encoder());
    case VideoFormat::kGif:
      return std::make_unique<GifEncoder>();
    case VideoFormat::kOgv:
      return std::make_unique<LibavEncoder>("ogg", avcodec_find_encoder_by_name("libtheora"));
  }
  throw VideoFileError("unknown video format");
}

}  // namespace

VideoFormat video_format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".mp4") return VideoFormat::kMp4;
  if (ext == ".gif") return VideoFormat::kGif;
  if (ext == ".ogv") return VideoFormat::kOgv;
  throw VideoFileError("'" + path + "': the video format is chosen by the extension, one of " +
                       video_format_list());
}

const char* video_format_name(VideoFormat format) {
  switch (format) {
    case VideoFormat::kMp4:
      return "mp4";
    case VideoFormat::kGif:
      return "gif";
    case VideoFormat::kOgv:
      return "ogv";
  }
  return "?";
}

std::string video_format_list() { return "mp4, gif, ogv"; }

VideoSize stored_video_size(VideoFormat format, int width, int height) {
  if (format == VideoFormat::kGif) return {width, height};
  return {width & ~1, height & ~1};
}

std::string mp4_encoder_name() {
  const AVCodec* codec = mp4_encoder();
  return codec ? codec->name : "";
}

VideoWriter::VideoWriter(const std::string& path, int fps, bool overwrite)
    : path_(path), format_(video_format_of(path)), fps_(fps), overwrite_(overwrite) {
  if (fps < kMinVideoFps || fps > kMaxVideoFps) {
    throw VideoFileError("'" + path + "': frame rate " + std::to_string(fps) + " is outside " +
                         std::to_string(kMinVideoFps) + ".." + std::to_string(kMaxVideoFps));
  }
  std::error_code ec;
  if (!overwrite && fs::exists(path, ec)) {
    throw VideoFileError("'" + path + "' exists; not overwritten");
  }
}

VideoWriter::~VideoWriter() {
  encoder_.reset();  // closes the temporary file, which file_ then removes unless committed
  file_.reset();
}

void VideoWriter::add_frame(const Image& frame) {
  if (finished_) throw VideoFileError("'" + path_ + "': a frame after the video was finished");
  try {
    if (!encoder_) {
      const VideoSize size = stored_video_size(format_, frame.width(), frame.height());
      if (size.width < 2 || size.height < 2) {
        throw VideoFileError("a frame of " + std::to_string(frame.width()) + " x " +
                             std::to_string(frame.height()) + " pixels is too small");
      }
      const Limit& limit = limits::kVideoFramePixels;
      if (!limit.allows(double(size.width) * size.height)) {  // before the encoder allocates
        throw VideoFileError("a frame of " + std::to_string(frame.width()) + " x " +
                             std::to_string(frame.height()) + " pixels is larger than " +
                             std::to_string(long(limit.maximum)) + " pixels (the " + limit.what +
                             " limit)");
      }
      width_ = frame.width();
      height_ = frame.height();
      std::unique_ptr<Encoder> encoder = make_encoder(format_);
      file_ = std::make_unique<AtomicFile>(path_,
                                           overwrite_ ? Overwrite::kReplace : Overwrite::kRefuse);
      encoder->open(*file_, size, fps_);
      encoder_ = std::move(encoder);
    }
    if (frame.width() != width_ || frame.height() != height_) {
      throw VideoFileError("frame " + std::to_string(frames_) + " is " +
                           std::to_string(frame.width()) + " x " + std::to_string(frame.height()) +
                           " pixels, the first was " + std::to_string(width_) + " x " +
                           std::to_string(height_));
    }
    encoder_->add(frame);
    ++frames_;
  } catch (const VideoFileError& e) {
    throw VideoFileError("'" + path_ + "': " + e.what());
  }
}

void VideoWriter::finish() {
  if (finished_) return;
  if (!encoder_) throw VideoFileError("'" + path_ + "': no frames to write");
  try {
    encoder_->finish();
  } catch (const VideoFileError& e) {
    throw VideoFileError("'" + path_ + "': " + e.what());
  }
  file_->commit();
  finished_ = true;
}

}  // namespace oflab
