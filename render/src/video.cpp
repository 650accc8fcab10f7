#include "rigid/render/video.h"

#include <dlfcn.h>
#include <sys/types.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
#include <webp/encode.h>
#include <webp/mux.h>
}

#include "backends.h"
#include "rigid/render/atomic_file.h"

namespace rigid::render {

std::optional<VideoFormat> video_format_for(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return std::nullopt;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "webp") return VideoFormat::kWebP;
  if (ext == "mp4") return VideoFormat::kMp4;
  return std::nullopt;
}

namespace {

// One encoding, fed frames in order on the worker thread, writing into the file
// it is given before the first frame.
class Encoder {
 public:
  virtual ~Encoder() = default;
  virtual void begin(std::FILE* file) = 0;
  virtual void encode(const Image& frame, int index) = 0;
  /// Ends the stream and writes what is left of the file.
  virtual void finish(int frames) = 0;
};

// ---- animated WebP ------------------------------------------------------------

// libwebp's entry points, X(library, function): the animation encoder is libwebpmux's.
#define RIGID_WEBP_FUNCTIONS(X)              \
  X(mux, WebPAnimEncoderOptionsInitInternal) \
  X(mux, WebPAnimEncoderNewInternal)         \
  X(mux, WebPAnimEncoderAdd)                 \
  X(mux, WebPAnimEncoderAssemble)            \
  X(mux, WebPAnimEncoderGetError)            \
  X(mux, WebPAnimEncoderDelete)              \
  X(webp, WebPConfigInitInternal)            \
  X(webp, WebPPictureInitInternal)           \
  X(webp, WebPPictureImportRGB)              \
  X(webp, WebPPictureFree)                   \
  X(webp, WebPFree)

struct WebpApi {
  RIGID_WEBP_FUNCTIONS(RIGID_ENTRY_POINT)
};

const WebpApi& webp_api() {
  static const WebpApi table = [] {
    std::string error;
    void* webp = detail::open_library({"libwebp.so.7"}, "libwebp (Debian package libwebp7)", error);
    void* mux = webp ? detail::open_library({"libwebpmux.so.3"},
                                            "libwebpmux (Debian package libwebpmux3)", error)
                     : nullptr;
    if (!mux) throw std::runtime_error(error);
    WebpApi api;
    if (!(true RIGID_WEBP_FUNCTIONS(RIGID_BIND_ENTRY_POINT)))
      throw std::runtime_error("libwebp is too old: an entry point of WebPAnimEncoder is missing");
    return api;
  }();
  return table;
}

class WebpEncoder final : public Encoder {
 public:
  explicit WebpEncoder(const VideoSettings& s) : api_(webp_api()), settings_(s) {
    WebPAnimEncoderOptions options;
    if (!api_.WebPAnimEncoderOptionsInitInternal(&options, WEBP_MUX_ABI_VERSION))
      throw std::runtime_error("libwebpmux: version mismatch");
    options.anim_params.loop_count = 0;  // loop forever, as a README animation should
    options.kmax = 0;                    // no forced key frames: the next frame is coded as a delta
    encoder_ = api_.WebPAnimEncoderNewInternal(s.width, s.height, &options, WEBP_MUX_ABI_VERSION);
    if (!encoder_) throw std::runtime_error("libwebpmux: cannot make an animation encoder");
    if (!api_.WebPConfigInitInternal(&config_, WEBP_PRESET_DRAWING, kQuality,
                                     WEBP_ENCODER_ABI_VERSION))
      throw std::runtime_error("libwebp: version mismatch");
    config_.method = kMethod;
    // A lit surface's smooth shading is where lossy VP8 shows its blocks: spatial noise
    // shaping moves bits from flat areas to busy ones, and a large frame's gradients
    // then break into 16-pixel blotches. Off, with the filter kept, they stay smooth.
    config_.sns_strength = kNoiseShaping;
  }
  ~WebpEncoder() override { api_.WebPAnimEncoderDelete(encoder_); }

  void encode(const Image& frame, int index) override {
    WebPPicture picture;
    api_.WebPPictureInitInternal(&picture, WEBP_ENCODER_ABI_VERSION);
    picture.width = frame.width;
    picture.height = frame.height;
    picture.use_argb = 0;
    const bool imported =
        api_.WebPPictureImportRGB(&picture, frame.rgb.data(), 3 * frame.width) != 0;
    const bool added =
        imported && api_.WebPAnimEncoderAdd(encoder_, &picture, timestamp_ms(index), &config_);
    api_.WebPPictureFree(&picture);
    if (!added)
      throw std::runtime_error(std::string("libwebp: ") + api_.WebPAnimEncoderGetError(encoder_));
  }

  void begin(std::FILE* file) override { file_ = file; }

  // WebPAnimEncoder keeps every encoded frame until the file is assembled (the
  // animation's bytes, not its pixels): the file is written here in one piece.
  void finish(int frames) override {
    WebPData data{nullptr, 0};
    if (!api_.WebPAnimEncoderAdd(encoder_, nullptr, timestamp_ms(frames), nullptr) ||
        !api_.WebPAnimEncoderAssemble(encoder_, &data))
      throw std::runtime_error(std::string("libwebp: ") + api_.WebPAnimEncoderGetError(encoder_));
    const bool written = std::fwrite(data.bytes, 1, data.size, file_) == data.size;
    // WebPData holds the buffer it hands over as const and WebPFree takes it as not
    // (libwebp's own WebPDataClear casts the same way; inline, it would call a WebPFree
    // linked, not this one)
    api_.WebPFree(const_cast<std::uint8_t*>(data.bytes));
    if (!written) throw std::runtime_error("short write");
  }

 private:
  // Quality 90 of WebP's drawing preset, without noise shaping, keeps thin lines, text
  // and lit gradients clean (at 80 with it, a 1920x1080 frame's shaded ellipsoid broke
  // into 16-pixel blotches; this costs 1.2 times the bytes there, 95 cost 1.6, lossless
  // 9); method 0, the fastest, was within a few per cent of method 4's size on these
  // scenes.
  static constexpr float kQuality = 90.0f;
  static constexpr int kMethod = 0;
  static constexpr int kNoiseShaping = 0;

  int timestamp_ms(int index) const {
    return static_cast<int>(std::lround(1000.0 * index / settings_.fps));
  }

  const WebpApi& api_;
  VideoSettings settings_;
  WebPAnimEncoder* encoder_ = nullptr;
  WebPConfig config_{};
  std::FILE* file_ = nullptr;
};

// ---- H.264 in MP4 ---------------------------------------------------------------

// Why FFmpeg is opened here and not linked: linked, its four libraries bring about 130
// shared objects (every codec Debian builds in), which would load at the start of every
// process that links the renderer, animating or not: 24 to 26 ms more, where the fastest
// lab's whole run without figures takes 2 to 3 ms (bench/results.md, "Start-up:
// what a linked library costs"). Opened on the first MP4, only an animation pays. The
// libraries opened are those of the headers built against (the major version is the
// soname's), and each entry point is typed by its header's declaration.

// FFmpeg's library lib<name> of the given major version (the number its soname
// carries), or nullptr with `error` set, naming the Debian package that has it.
void* open_ffmpeg(const std::string& name, int major, std::string& error) {
  const std::string soname = "lib" + name + ".so." + std::to_string(major);
  const std::string what =
      "lib" + name + " (Debian package lib" + name + std::to_string(major) + ")";
  return detail::open_library({soname.c_str()}, what.c_str(), error);
}

// FFmpeg's entry points, X(library, function).
#define RIGID_FFMPEG_FUNCTIONS(X)           \
  X(codec, avcodec_find_encoder_by_name)    \
  X(codec, avcodec_alloc_context3)          \
  X(codec, avcodec_open2)                   \
  X(codec, avcodec_send_frame)              \
  X(codec, avcodec_receive_packet)          \
  X(codec, avcodec_free_context)            \
  X(codec, avcodec_parameters_from_context) \
  X(codec, av_packet_alloc)                 \
  X(codec, av_packet_free)                  \
  X(codec, av_packet_rescale_ts)            \
  X(format, avformat_alloc_output_context2) \
  X(format, avformat_new_stream)            \
  X(format, avformat_write_header)          \
  X(format, av_interleaved_write_frame)     \
  X(format, av_write_trailer)               \
  X(format, avformat_free_context)          \
  X(format, avio_alloc_context)             \
  X(format, avio_context_free)              \
  X(format, avio_flush)                     \
  X(util, av_frame_alloc)                   \
  X(util, av_frame_get_buffer)              \
  X(util, av_frame_make_writable)           \
  X(util, av_frame_free)                    \
  X(util, av_malloc)                        \
  X(util, av_freep)                         \
  X(util, av_opt_set)                       \
  X(util, av_strerror)                      \
  X(util, av_log_set_level)                 \
  X(scale, sws_getContext)                  \
  X(scale, sws_scale)                       \
  X(scale, sws_freeContext)

struct AvApi {
  RIGID_FFMPEG_FUNCTIONS(RIGID_ENTRY_POINT)
};

const AvApi& av_api() {
  static const AvApi table = [] {
    std::string error;
    void* util = open_ffmpeg("avutil", LIBAVUTIL_VERSION_MAJOR, error);
    void* codec = util ? open_ffmpeg("avcodec", LIBAVCODEC_VERSION_MAJOR, error) : nullptr;
    void* format = codec ? open_ffmpeg("avformat", LIBAVFORMAT_VERSION_MAJOR, error) : nullptr;
    void* scale = format ? open_ffmpeg("swscale", LIBSWSCALE_VERSION_MAJOR, error) : nullptr;
    if (!scale) throw std::runtime_error(error);
    AvApi api;
    if (!(true RIGID_FFMPEG_FUNCTIONS(RIGID_BIND_ENTRY_POINT)))
      throw std::runtime_error("FFmpeg's libraries lack an entry point of the version built for");
    // libx264's statistics and FFmpeg's notices would spill over the lab's output;
    // failures come back as return codes, said here in one line
    api.av_log_set_level(AV_LOG_QUIET);
    return api;
  }();
  return table;
}

// The MP4 streams into the file as it is encoded: libavformat writes through these
// callbacks and seeks back at the end to patch its headers. A failed write keeps
// its errno, the cause to report (libavformat's own message would only echo it).
struct StreamFile {
  std::FILE* file = nullptr;
  std::int64_t size = 0;  // the largest offset written: the file's length
  int error = 0;

  static int write(void* opaque, std::uint8_t* buf, int size) {
    auto& f = *static_cast<StreamFile*>(opaque);
    const std::size_t n = static_cast<std::size_t>(size);
    if (std::fwrite(buf, 1, n, f.file) != n) {
      f.error = errno != 0 ? errno : EIO;
      return AVERROR(f.error);
    }
    f.size = std::max<std::int64_t>(f.size, ::ftello(f.file));
    return size;
  }
  static std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
    auto& f = *static_cast<StreamFile*>(opaque);
    if (whence & AVSEEK_SIZE) return f.size;
    const int from = (whence & 3) == SEEK_CUR   ? SEEK_CUR
                     : (whence & 3) == SEEK_END ? SEEK_END
                                                : SEEK_SET;
    if (::fseeko(f.file, static_cast<off_t>(offset), from) != 0) return -1;
    return ::ftello(f.file);
  }
};

class Mp4Encoder final : public Encoder {
 public:
  explicit Mp4Encoder(const VideoSettings& s) : api_(av_api()), settings_(s) {
    if (s.width % 2 != 0 || s.height % 2 != 0)
      throw std::invalid_argument("an MP4 (H.264, 4:2:0) needs an even width and height");
    const AVCodec* codec = api_.avcodec_find_encoder_by_name("libx264");
    if (!codec) throw std::runtime_error("libavcodec has no libx264 encoder");
    codec_ = api_.avcodec_alloc_context3(codec);
    // the rate as a fraction: 30 fps is 1/30 s a frame, 29.97 is 1001/30000
    const int rate = static_cast<int>(std::lround(s.fps * 1000.0));
    codec_->time_base = AVRational{1000, rate};
    codec_->framerate = AVRational{rate, 1000};
    codec_->width = s.width;
    codec_->height = s.height;
    codec_->pix_fmt = AV_PIX_FMT_YUV420P;
    codec_->gop_size = static_cast<int>(std::lround(2 * s.fps));  // a key frame every 2 s
    // swscale converts with BT.601 coefficients in limited range: say so in the stream
    codec_->colorspace = AVCOL_SPC_SMPTE170M;
    codec_->color_primaries = AVCOL_PRI_BT709;
    codec_->color_trc = AVCOL_TRC_IEC61966_2_1;
    codec_->color_range = AVCOL_RANGE_MPEG;
    codec_->thread_count = 1;  // the renderer uses the other core
    api_.av_opt_set(codec_->priv_data, "preset", kPreset, 0);
    api_.av_opt_set(codec_->priv_data, "crf", kCrf, 0);
    api_.av_opt_set(codec_->priv_data, "tune", "animation", 0);

    if (api_.avformat_alloc_output_context2(&format_, nullptr, "mp4", nullptr) < 0 || !format_)
      throw std::runtime_error("libavformat cannot make an MP4");
    if (format_->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    check(api_.avcodec_open2(codec_, codec, nullptr), "cannot open libx264");
    stream_ = api_.avformat_new_stream(format_, nullptr);
    if (!stream_) throw std::runtime_error("libavformat cannot add a stream");
    stream_->time_base = codec_->time_base;
    check(api_.avcodec_parameters_from_context(stream_->codecpar, codec_), "stream parameters");

    frame_ = api_.av_frame_alloc();
    frame_->format = AV_PIX_FMT_YUV420P;
    frame_->width = s.width;
    frame_->height = s.height;
    check(api_.av_frame_get_buffer(frame_, 0), "frame buffer");
    sws_ = api_.sws_getContext(s.width, s.height, AV_PIX_FMT_RGB24, s.width, s.height,
                               AV_PIX_FMT_YUV420P, SWS_BILINEAR, nullptr, nullptr, nullptr);
    packet_ = api_.av_packet_alloc();
    if (!sws_ || !packet_) throw std::runtime_error("libswscale or libavcodec: out of memory");
  }

  ~Mp4Encoder() override {
    api_.sws_freeContext(sws_);
    api_.av_frame_free(&frame_);
    api_.av_packet_free(&packet_);
    api_.avcodec_free_context(&codec_);
    if (io_) {
      api_.av_freep(&io_->buffer);  // the buffer is the caller's (libavformat may have replaced it)
      api_.avio_context_free(&io_);
    }
    if (format_) api_.avformat_free_context(format_);
  }

  void begin(std::FILE* file) override {
    file_.file = file;
    constexpr int kBuffer = 1 << 16;
    auto* buffer = static_cast<unsigned char*>(api_.av_malloc(kBuffer));
    io_ = api_.avio_alloc_context(buffer, kBuffer, 1, &file_, nullptr, &StreamFile::write,
                                  &StreamFile::seek);
    if (!io_) throw std::runtime_error("libavformat: out of memory");
    format_->pb = io_;
    format_->flags |= AVFMT_FLAG_CUSTOM_IO;
    check(api_.avformat_write_header(format_, nullptr), "cannot write the MP4 header");
  }

  void encode(const Image& image, int index) override {
    check(api_.av_frame_make_writable(frame_), "frame buffer");
    const std::uint8_t* src[] = {image.rgb.data()};
    const int stride[] = {3 * image.width};
    api_.sws_scale(sws_, src, stride, 0, image.height, frame_->data, frame_->linesize);
    frame_->pts = index;
    check(api_.avcodec_send_frame(codec_, frame_), "libx264 refused a frame");
    drain();
  }

  void finish(int /*frames*/) override {
    check(api_.avcodec_send_frame(codec_, nullptr), "libx264 could not flush");
    drain();
    check(api_.av_write_trailer(format_), "cannot finish the MP4");
    api_.avio_flush(io_);
    if (file_.error != 0) throw std::runtime_error(std::strerror(file_.error));
  }

 private:
  // veryfast at CRF 20: sharp lines and text at a few MB a minute; the faster
  // presets blur thin lines on these scenes (tune animation favours flat areas)
  static constexpr const char* kPreset = "veryfast";
  static constexpr const char* kCrf = "20";

  void drain() {
    for (;;) {
      const int r = api_.avcodec_receive_packet(codec_, packet_);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check(r, "libx264 failed");
      // each frame lasts one frame time: the MP4's duration then counts the last one too
      if (packet_->duration == 0) packet_->duration = 1;
      api_.av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      check(api_.av_interleaved_write_frame(format_, packet_), "cannot write a frame to the MP4");
    }
  }

  void check(int r, const char* what) const {
    if (r >= 0) return;
    if (file_.error != 0) throw std::runtime_error(std::strerror(file_.error));
    char text[128] = {};
    api_.av_strerror(r, text, sizeof text);
    throw std::runtime_error(std::string(what) + ": " + text);
  }

  const AvApi& api_;
  VideoSettings settings_;
  AVCodecContext* codec_ = nullptr;
  AVFormatContext* format_ = nullptr;
  AVStream* stream_ = nullptr;
  AVIOContext* io_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  SwsContext* sws_ = nullptr;
  StreamFile file_;
};

std::unique_ptr<Encoder> make_encoder(VideoFormat format, const VideoSettings& s) {
  if (format == VideoFormat::kWebP) return std::make_unique<WebpEncoder>(s);
  return std::make_unique<Mp4Encoder>(s);
}

}  // namespace

// ---- the writer: a queue in front of the encoder on its own thread ------------------

// The encoder thread owns the file: it opens the temporary (write_file_atomically),
// encodes each frame into it as it arrives and, at finish(), ends the stream and
// renames it in. A writer abandoned without finish() makes the thread give up
// inside the write, which removes the temporary.
struct VideoWriter::Impl {
  std::string path;
  VideoSettings settings;
  std::unique_ptr<Encoder> encoder;
  std::thread worker;
  std::mutex mutex;
  std::condition_variable changed;
  std::deque<Image> queue;
  bool closing = false;
  bool abandoned = false;
  std::exception_ptr failure;
  int added = 0, encoded = 0;
  std::size_t bytes = 0;

  static constexpr std::size_t kMaxQueued = 2;

  struct Abandoned {};

  // The next frame, or none once the queue is closed and empty.
  std::optional<Image> next() {
    std::unique_lock<std::mutex> lock(mutex);
    changed.wait(lock, [&] { return !queue.empty() || closing; });
    if (abandoned) throw Abandoned{};
    if (queue.empty()) return std::nullopt;
    Image frame = std::move(queue.front());
    queue.pop_front();
    lock.unlock();
    changed.notify_all();
    return frame;
  }

  void run() {
    std::exception_ptr error;
    try {
      write_file_atomically(path, [&](std::FILE* f) {
        encoder->begin(f);
        while (std::optional<Image> frame = next()) {
          encoder->encode(*frame, encoded);
          ++encoded;
        }
        encoder->finish(encoded);
        std::fflush(f);
        bytes = static_cast<std::size_t>(std::max<off_t>(0, ::ftello(f)));
      });
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    if (error && !abandoned) failure = error;
    queue.clear();
    closing = true;
    changed.notify_all();
  }

  void stop(bool abandon) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      closing = true;
      abandoned = abandon;
    }
    changed.notify_all();
    if (worker.joinable()) worker.join();
  }
};

VideoWriter::VideoWriter(const std::string& path, VideoFormat format, const VideoSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  if (settings.width <= 0 || settings.height <= 0 || !(settings.fps > 0.0) ||
      !std::isfinite(settings.fps))
    throw std::invalid_argument("an animation needs a positive size and frame rate");
  impl_->path = path;
  impl_->settings = settings;
  impl_->encoder = make_encoder(format, settings);
  impl_->worker = std::thread([this] { impl_->run(); });
}

VideoWriter::~VideoWriter() {
  if (impl_) impl_->stop(/*abandon=*/true);
}

void VideoWriter::add(Image frame) {
  if (frame.width != impl_->settings.width || frame.height != impl_->settings.height)
    throw std::invalid_argument("an animation frame must be the animation's size");
  std::unique_lock<std::mutex> lock(impl_->mutex);
  impl_->changed.wait(lock, [&] {
    return impl_->queue.size() < Impl::kMaxQueued || impl_->failure || impl_->closing;
  });
  if (impl_->failure) std::rethrow_exception(impl_->failure);
  if (impl_->closing) throw std::logic_error("VideoWriter: a frame added after finish()");
  impl_->queue.push_back(std::move(frame));
  ++impl_->added;
  lock.unlock();
  impl_->changed.notify_all();
}

std::size_t VideoWriter::finish() {
  impl_->stop(/*abandon=*/false);
  if (impl_->failure) std::rethrow_exception(impl_->failure);
  return impl_->bytes;
}

int VideoWriter::frames() const {
  return impl_->added;
}

}  // namespace rigid::render
