/// @file video.hpp
/// Motion for lectures: shimmer, swimming and the pop at a cascade split only show in motion. A
/// run with --record-video renders its frames one by one (a setting animated across them with
/// --animate, e.g. a camera path step) and encodes them with ffmpeg (Debian's ffmpeg package).
#pragma once
#include <cstdio>
#include <string>
#include <vector>

namespace wb {

/// --animate key=a:b: the setting's value in each of `frames` frames, from a to b, evenly.
struct Animation {
  std::string key;  ///< the setting
  double from = 0;  ///< its value in the first frame
  double to = 0;    ///< its value in the last frame
  /// The value at frame `k` of `frames`, as the setting's text ("12" for whole numbers).
  std::string valueAt(int k, int frames) const;
};
/// Parses "key=a:b"; throws wb::UsageError naming the expected form.
Animation parseAnimation(const std::string& text);

/// Frames piped into ffmpeg: MP4 (H.264), WebM (VP9, what browsers play everywhere) or GIF, by the
/// file's extension. Frames are RGBA rows bottom to top, as OpenGL reads them.
class VideoEncoder {
 public:
  /// Starts ffmpeg; throws wb::UsageError for an unknown extension, wb::Error when ffmpeg is missing.
  VideoEncoder(const std::string& path, int width, int height, int fps);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;
  /// Adds one frame (width * height * 4 bytes).
  void add(const std::vector<unsigned char>& rgba);
  /// Waits for ffmpeg; throws wb::Error with its last lines when it failed.
  void finish();

 private:
  std::string path_, log_;
  FILE* pipe_ = nullptr;
  size_t frameBytes_;
};

/// The share of pixels in columns [x0, x1) whose visibility crossed 0.5 between two frames of the
/// same size (1 lit, 0 shadowed): the shadows that changed.
double flippedShare(const std::vector<float>& before, const std::vector<float>& after, int width, int x0, int x1);

}  // namespace wb
