#include "common/platform/video.hpp"

#include "common/base/error.hpp"
#include "common/base/strf.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#if defined(_WIN32)  // (untested there: the command line below quotes for a POSIX shell)
#define popen _popen
#define pclose _pclose
#endif

namespace wb {

Animation parseAnimation(const std::string& text) {
  const size_t eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  Animation a;
  try {
    if (eq == std::string::npos || colon == std::string::npos) throw std::invalid_argument("form");
    a.key = text.substr(0, eq);
    size_t used = 0;
    a.from = std::stod(text.substr(eq + 1, colon - eq - 1), &used);
    a.to = std::stod(text.substr(colon + 1));
  } catch (const std::exception&) {
    throw UsageError("--animate expects key=from:to (e.g. path.step=1:90), got '" + text + "'");
  }
  return a;
}

std::string Animation::valueAt(int k, int frames) const {
  const double t = frames > 1 ? double(k) / double(frames - 1) : 0.0, v = from + (to - from) * t;
  const bool whole = std::floor(from) == from && std::floor(to) == to;
  return whole ? std::to_string(long(std::lround(v))) : strf("%g", v);
}

VideoEncoder::VideoEncoder(const std::string& path, int width, int height, int fps)
    : path_(path), frameBytes_(size_t(width) * size_t(height) * 4) {
  const std::string ext = std::filesystem::path(path).extension().string();
  std::string codec;
  if (ext == ".mp4")
    codec = "-c:v libx264 -pix_fmt yuv420p -crf 26 -movflags +faststart";
  else if (ext == ".webm")
    codec = "-c:v libvpx-vp9 -pix_fmt yuv420p -crf 36 -b:v 0 -row-mt 1";
  else if (ext == ".gif")
    codec = "-filter_complex \"[0:v]vflip,split[a][b];[a]palettegen[p];[b][p]paletteuse\"";
  else
    throw UsageError("--record-video " + path + ": the file must end in .mp4, .webm or .gif");
  // Rows arrive bottom to top: ffmpeg flips them (inside the GIF's filter graph, or with -vf).
  const std::string flip = ext == ".gif" ? "" : " -vf vflip";
  log_ = path + ".ffmpeg.log";
  const std::string cmd =
      strf("ffmpeg -y -loglevel error -f rawvideo -pix_fmt rgba -s %dx%d -r %d -i - %s%s '%s' 2>'%s'", width, height,
           fps, codec.c_str(), flip.c_str(), path.c_str(), log_.c_str());
  pipe_ = popen(cmd.c_str(), "w");
  if (!pipe_) throw Error("cannot start ffmpeg for --record-video (sudo apt-get install ffmpeg)");
}

VideoEncoder::~VideoEncoder() {
  if (pipe_) pclose(pipe_);
}

void VideoEncoder::add(const std::vector<unsigned char>& rgba) {
  if (rgba.size() != frameBytes_) throw Error("--record-video: a frame of another size");
  if (std::fwrite(rgba.data(), 1, rgba.size(), pipe_) != rgba.size())
    throw Error("--record-video: ffmpeg stopped taking frames (is it installed? sudo apt-get install ffmpeg)");
}

void VideoEncoder::finish() {
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  std::ostringstream said;
  said << std::ifstream(log_).rdbuf();
  std::error_code ec;
  std::filesystem::remove(log_, ec);
  if (status != 0)
    throw Error(
        "--record-video: ffmpeg failed making " + path_ +
        (said.str().empty() ? std::string(" (is it installed? sudo apt-get install ffmpeg)") : ": " + said.str()));
}

double flippedShare(const std::vector<float>& before, const std::vector<float>& after, int width, int x0, int x1) {
  if (before.size() != after.size() || width <= 0 || x1 <= x0) return 0;
  size_t flipped = 0, counted = 0;
  for (size_t k = 0; k < after.size(); ++k) {
    const int x = int(k % size_t(width));
    if (x < x0 || x >= x1) continue;
    ++counted;
    flipped += (before[k] > 0.5f) != (after[k] > 0.5f);
  }
  return counted ? double(flipped) / double(counted) : 0;
}

}  // namespace wb
