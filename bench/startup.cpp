// bench_startup_bare, bench_startup_cairo, bench_startup_ffmpeg: one program that reads
// its command line and exits, built three times: linked with nothing more, with
// libcairo, and with FFmpeg's four libraries (libavcodec, libavformat, libavutil,
// libswscale). figures_bench.py times the three processes from outside, alternating;
// what a linked one takes beyond the bare one is what linking that library would add
// to the start of every process that links the renderer, a lab's run without figures
// included. That cost is why the renderer opens libcairo and FFmpeg with dlopen on
// first use instead (render/src/vector.cpp, render/src/video.cpp).
#include <string>

#include "output.h"

#if defined(RIGID_STARTUP_CAIRO)
#include <cairo.h>
#elif defined(RIGID_STARTUP_FFMPEG)
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libswscale/swscale.h>
}
#endif

int main(int argc, char** argv) {
  bench::Arguments args;
  if (const int status = bench::parse_arguments(
          argc, argv, "bench_startup",
          "starts and exits: its process time is a bare start, or one with the library it "
          "links (--verbose names it)",
          args, /*takes_dir=*/false, /*takes_quick=*/false);
      status >= 0) {
    return status;
  }
  // the linked library's version: a call into it, so that it is linked, not only named
#if defined(RIGID_STARTUP_CAIRO)
  bench::detail("links libcairo %s\n", cairo_version_string());
#elif defined(RIGID_STARTUP_FFMPEG)
  const auto version = [](unsigned v) {
    return std::to_string(AV_VERSION_MAJOR(v)) + "." + std::to_string(AV_VERSION_MINOR(v)) + "." +
           std::to_string(AV_VERSION_MICRO(v));
  };
  bench::detail("links libavcodec %s, libavformat %s, libavutil %s, libswscale %s\n",
                version(avcodec_version()).c_str(), version(avformat_version()).c_str(),
                version(avutil_version()).c_str(), version(swscale_version()).c_str());
#else
  bench::detail("links no library beyond the C++ runtime\n");
#endif
  return 0;
}
