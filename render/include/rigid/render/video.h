// Animations as files: animated WebP through libwebp's animation encoder
// (WebPAnimEncoder, libwebpmux), or H.264 in MP4 through libavcodec and
// libavformat (libx264), picked by the file's extension. Both libraries are
// opened with dlopen when the first animation is made, like the GL backends,
// so a run without an animation loads nothing new.
//
// Frames are handed over as Images and encoded on a second thread while the
// caller draws the next one (at most two frames wait). The MP4 streams into its
// temporary file as it is encoded, so memory does not grow with its length; the
// WebP encoder keeps the encoded frames (the file's bytes) until finish(). The
// file appears atomically (atomic_file.h) when finish() returns.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "rigid/render/image.h"

namespace rigid::render {

/// The encodings an animation can be written in.
enum class VideoFormat {
  kWebP,  ///< animated WebP (lossy): plays in browsers and in a README
  kMp4,   ///< H.264 in MP4 (yuv420p): plays in video players, slides and browsers
};

/// The format of a path by its extension (".webp" or ".mp4", any case); none otherwise.
std::optional<VideoFormat> video_format_for(const std::string& path);

/// What to write: frame size in pixels (even, for H.264's 4:2:0 chroma) and rate.
struct VideoSettings {
  int width = 1280;
  int height = 720;
  double fps = 30.0;
};

/// Writes one animation. Construction loads the encoder's library and throws
/// std::runtime_error (one line, naming the library and the Debian package) if it
/// is missing; add() and finish() throw std::runtime_error if encoding fails. A
/// writer destroyed without finish() leaves no file.
class VideoWriter {
 public:
  VideoWriter(const std::string& path, VideoFormat format, const VideoSettings& settings);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Queues one frame (its size must be the settings' size, else std::invalid_argument).
  void add(Image frame);
  /// Encodes what is queued, ends the stream and writes the file; returns its size in bytes.
  std::size_t finish();
  /// Frames added so far.
  int frames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rigid::render
