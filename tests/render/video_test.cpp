// Animations (video.h) read back by the libraries' own readers: FFmpeg's demuxer
// and decoder for the MP4, libwebp's animation decoder for the WebP. Frames,
// size, rate and duration as asked; the first frame's pixels as drawn (within
// the lossy codecs' error); a failed or unfinished animation leaves no file; a
// lab's first frame is its still figure's scene.
#include "rigid/render/video.h"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "rigid/render/png.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
#include <webp/demux.h>
}

using namespace rigid::render;
namespace fs = std::filesystem;

namespace {

// Frame k: a white background with a dark square moving right, k pixels a frame,
// and a colour ramp, so both codecs have edges and gradients to keep.
Image test_frame(int width, int height, int k) {
  Image img{width, height, std::vector<std::uint8_t>(3 * width * height, 255)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = img.at(x, y);
      if (y < height / 4) {
        p[0] = static_cast<std::uint8_t>(255 * x / width);
        p[1] = 128;
        p[2] = static_cast<std::uint8_t>(255 - 255 * x / width);
      }
      if (x >= 20 + 4 * k && x < 80 + 4 * k && y >= height / 2 && y < height / 2 + 60) {
        p[0] = 20, p[1] = 40, p[2] = 90;
      }
    }
  return img;
}

struct ReadBack {
  int frames = 0, width = 0, height = 0;
  double fps = 0, duration = 0;
  Image first;
  std::vector<Image> kept;  ///< the first `keep` frames (read_mp4)
};

ReadBack read_mp4(const std::string& path, int keep = 1) {
  ReadBack r;
  AVFormatContext* fmt = nullptr;
  REQUIRE(avformat_open_input(&fmt, path.c_str(), nullptr, nullptr) == 0);
  REQUIRE(avformat_find_stream_info(fmt, nullptr) >= 0);
  const AVStream* st = fmt->streams[0];
  r.width = st->codecpar->width;
  r.height = st->codecpar->height;
  r.fps = av_q2d(st->avg_frame_rate);
  r.duration = st->duration * av_q2d(st->time_base);
  const AVCodec* codec = avcodec_find_decoder(st->codecpar->codec_id);
  AVCodecContext* dec = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(dec, st->codecpar);
  REQUIRE(avcodec_open2(dec, codec, nullptr) == 0);
  AVPacket* pkt = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  const auto take = [&] {
    while (avcodec_receive_frame(dec, frame) == 0) {
      if (r.frames++ < keep) {
        Image rgb{frame->width, frame->height,
                  std::vector<std::uint8_t>(3 * frame->width * frame->height)};
        SwsContext* sws = sws_getContext(
            frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
            frame->height, AV_PIX_FMT_RGB24, SWS_BILINEAR, nullptr, nullptr, nullptr);
        std::uint8_t* dst[] = {rgb.rgb.data()};
        const int stride[] = {3 * frame->width};
        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
        sws_freeContext(sws);
        r.kept.push_back(std::move(rgb));
      }
    }
  };
  while (av_read_frame(fmt, pkt) >= 0) {
    avcodec_send_packet(dec, pkt);
    av_packet_unref(pkt);
    take();
  }
  avcodec_send_packet(dec, nullptr);
  take();
  av_frame_free(&frame);
  av_packet_free(&pkt);
  avcodec_free_context(&dec);
  avformat_close_input(&fmt);
  if (!r.kept.empty()) r.first = r.kept.front();
  return r;
}

ReadBack read_webp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  WebPData data{bytes.data(), bytes.size()};
  WebPAnimDecoderOptions options;
  WebPAnimDecoderOptionsInit(&options);
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* dec = WebPAnimDecoderNew(&data, &options);
  REQUIRE(dec != nullptr);
  WebPAnimInfo info;
  WebPAnimDecoderGetInfo(dec, &info);
  ReadBack r;
  r.width = static_cast<int>(info.canvas_width);
  r.height = static_cast<int>(info.canvas_height);
  int last_ms = 0;
  while (WebPAnimDecoderHasMoreFrames(dec)) {
    std::uint8_t* rgba = nullptr;
    int timestamp = 0;  // the frame's end time, ms
    REQUIRE(WebPAnimDecoderGetNext(dec, &rgba, &timestamp));
    if (r.frames++ == 0) {
      r.first = {r.width, r.height, std::vector<std::uint8_t>(3 * r.width * r.height)};
      for (int i = 0; i < r.width * r.height; ++i)
        for (int c = 0; c < 3; ++c) r.first.rgb[3 * i + c] = rgba[4 * i + c];
    }
    last_ms = timestamp;
  }
  WebPAnimDecoderDelete(dec);
  r.duration = last_ms / 1000.0;
  r.fps = r.frames / r.duration;
  return r;
}

// The mean absolute difference per channel between two images of one size.
double mean_difference(const Image& a, const Image& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  double sum = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::abs(a.rgb[i] - b.rgb[i]);
  return sum / a.rgb.size();
}

}  // namespace

TEST_CASE("video: the format comes from the extension") {
  CHECK(video_format_for("a/b.mp4") == VideoFormat::kMp4);
  CHECK(video_format_for("B.WEBP") == VideoFormat::kWebP);
  CHECK_FALSE(video_format_for("a.gif").has_value());
  CHECK_FALSE(video_format_for("a.mp4/b").has_value());
  CHECK_FALSE(video_format_for("mp4").has_value());
}

TEST_CASE("video: MP4 and WebP hold the frames, size, rate and duration asked for") {
  const fs::path dir =
      fs::temp_directory_path() / ("rigid_video_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const VideoSettings settings{320, 240, 12.5};
  constexpr int kFrames = 25;  // 2 s at 12.5 fps
  for (const auto& [name, format] :
       {std::pair{"a.mp4", VideoFormat::kMp4}, std::pair{"a.webp", VideoFormat::kWebP}}) {
    const std::string path = (dir / name).string();
    {
      VideoWriter w(path, format, settings);
      for (int k = 0; k < kFrames; ++k) w.add(test_frame(320, 240, k));
      CHECK(w.frames() == kFrames);
      const std::size_t bytes = w.finish();
      CHECK(bytes == fs::file_size(path));
    }
    const ReadBack r = format == VideoFormat::kMp4 ? read_mp4(path) : read_webp(path);
    INFO(name << ": " << r.frames << " frames, " << r.width << "x" << r.height << ", " << r.fps
              << " fps, " << r.duration << " s");
    CHECK(r.frames == kFrames);
    CHECK(r.width == 320);
    CHECK(r.height == 240);
    // the rate and duration to a millisecond (WebP keeps frame times in whole ms)
    CHECK(std::abs(r.fps - 12.5) < 1e-3 * 12.5);
    CHECK(std::abs(r.duration - 2.0) < 1e-3);
    // lossy codecs: the first frame within a few levels on average of what was drawn
    // (measured: about 1 for both at their quality settings)
    CHECK(mean_difference(r.first, test_frame(320, 240, 0)) < 4.0);
  }
  fs::remove_all(dir);
}

TEST_CASE("video: a writer that is not finished, or is given a wrong frame, leaves no file") {
  const fs::path dir =
      fs::temp_directory_path() / ("rigid_video_test2_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "b.mp4").string();
  {
    VideoWriter w(path, VideoFormat::kMp4, {320, 240, 30});
    w.add(test_frame(320, 240, 0));
    CHECK_THROWS_AS(w.add(test_frame(322, 240, 0)), std::invalid_argument);
  }
  CHECK(fs::is_empty(dir));
  CHECK_THROWS_AS(VideoWriter(path, VideoFormat::kMp4, {321, 240, 30}), std::invalid_argument);
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("video: an MP4 streams into its temporary file as it is encoded, not into memory") {
  const fs::path dir =
      fs::temp_directory_path() / ("rigid_video_test3_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "c.mp4").string();
  // the size on disk before finish(): the temporary beside the target
  const auto on_disk = [&] {
    std::uintmax_t bytes = 0;
    for (const auto& e : fs::directory_iterator(dir)) bytes += fs::file_size(e.path());
    return bytes;
  };
  // Noise does not compress: each 320x240 frame costs tens of kB at CRF 20, so
  // 120 frames are megabytes, far past libx264's lookahead and the 64 kB I/O buffer.
  std::uint32_t seed = 12345;
  const auto noise = [&] {
    Image img{320, 240, std::vector<std::uint8_t>(3 * 320 * 240)};
    for (auto& b : img.rgb) {
      seed = seed * 1664525u + 1013904223u;  // Numerical Recipes' LCG
      b = static_cast<std::uint8_t>(seed >> 24);
    }
    return img;
  };
  {
    VideoWriter w(path, VideoFormat::kMp4, {320, 240, 30});
    for (int k = 0; k < 120; ++k) w.add(noise());
    const std::uintmax_t before = on_disk();
    CHECK_FALSE(fs::exists(path));  // not in place before finish()
    const std::size_t bytes = w.finish();
    INFO("on disk before finish: " << before << " of " << bytes << " bytes");
    CHECK(before > bytes / 2);
    CHECK(fs::file_size(path) == bytes);
  }
  // abandoned part-way: its temporary goes too
  {
    VideoWriter w((dir / "d.mp4").string(), VideoFormat::kMp4, {320, 240, 30});
    for (int k = 0; k < 60; ++k) w.add(noise());
  }
  CHECK_FALSE(fs::exists(dir / "d.mp4"));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  fs::remove_all(dir);
}

TEST_CASE("video: the gallery's animations are what the figures target makes") {
  // figures/<lab>_motion.webp: 640x360, 12 fps, 8 s (scripts/figures.cmake)
  int found = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(RIGID_SOURCE_DIR) / "figures")) {
    if (entry.path().extension() != ".webp") continue;
    ++found;
    const ReadBack r = read_webp(entry.path().string());
    INFO(entry.path().filename().string() << ": " << r.frames << " frames, " << r.width << "x"
                                          << r.height << ", " << r.duration << " s");
    // 96 frames, or fewer where libwebp stored a run of identical frames (a hold, as
    // euler_angles' last second) as one frame shown as long: the 8 s are what count
    CHECK(r.frames <= 96);
    CHECK(r.frames >= 48);
    CHECK(r.width == 640);
    CHECK(r.height == 360);
    CHECK(std::abs(r.duration - 8.0) < 1e-3);
  }
  CHECK(found == 5);  // poinsot, tennis_racquet, football, euler_angles, top_nutation
}
