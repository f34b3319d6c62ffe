// LabHost::recordVideo (lab_host.hpp): --record-video, frame by frame into ffmpeg.
#include "common/base/strf.hpp"
#include "common/platform/video.hpp"
#include "common/shell/lab.hpp"
#include "common/shell/lab_host.hpp"

#include <filesystem>
#include <optional>

namespace wb {

void LabHost::recordVideo() {
  const int frames = std::max(2, options_.frames);
  std::optional<Animation> moving;
  if (!options_.animate.empty()) {
    moving = parseAnimation(options_.animate);
    lab_->settings.assign(moving->key + "=" + moving->valueAt(0, frames));  // (a bad key or value says so now)
  }
  std::optional<VideoEncoder> video;
  std::vector<float> before;
  for (int k = 0; k < frames; ++k) {
    if (moving) lab_->settings.assign(moving->key + "=" + moving->valueAt(k, frames));
    frame(1.0f / 60);
    const glm::ivec2 size = target_.size();
    if (!video) video.emplace(options_.video, size.x, size.y, options_.fps);
    if (options_.showFlips) {  // the share of each half whose shadow changed since the frame before
      std::vector<float> now = target_.readVisibility().pixels;
      const int halves = panels_.compare.on ? 2 : 1, width = size.x / halves;
      target_.bind();
      for (int h = 0; h < halves; ++h) {
        const std::string said = before.empty()
                                     ? "shadow changed since the frame before: -"
                                     : strf("shadow changed since the frame before: %.2f %% of the pixels",
                                            100 * flippedShare(before, now, size.x, h * width, (h + 1) * width));
        label_.draw(said, {h * width + 8, 8}, size, label_.scaleToFit(said, width - 24, float(size.y) / 540 * 1.6f));
      }
      before = std::move(now);
    }
    glFinish();
    video->add(target_.readColor());
    ++frameIndex_;
  }
  video->finish();
  written_.emplace_back("video", options_.video);
  say("wrote " + std::filesystem::absolute(options_.video).string() + strf(" (%d frames)", frames));
}

}  // namespace wb
