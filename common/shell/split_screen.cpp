#include "common/shell/split_screen.hpp"

#include "common/base/settings.hpp"

#include <algorithm>

namespace wb {

void SplitScreen::render(FrameTarget& target, Settings& settings, const CompareChoice& choice,
                         const std::function<void()>& draw, const std::function<void(int side)>& afterDraw,
                         float labels) {
  const bool split = choice.on && !choice.key.empty();
  if (!split) {
    draw();
    afterDraw(0);
    return;
  }
  const glm::ivec2 size = target.size();
  const int half = size.x / 2;
  if (!saved_[0].id() || savedSize_ != size) {
    saved_[0] = makeTexture2D(GL_RGBA8, half, size.y);
    saved_[1] = makeTexture2D(GL_R32F, half, size.y);
    saved_[2] = makeTexture2D(GL_RGBA32F, half, size.y);
    savedSize_ = size;
  }
  const std::string before = settings.value(choice.key);
  settings.assign(choice.key + "=" + choice.a);
  draw();
  afterDraw(0);
  target.copyColumns(0, half, saved_, false);
  settings.assign(choice.key + "=" + choice.b);
  draw();
  afterDraw(1);
  target.copyColumns(0, half, saved_, true);
  settings.assign(choice.key + "=" + before);
  target.bind();  // a white divider between the halves
  glEnable(GL_SCISSOR_TEST);
  glScissor(half - 1, 0, 2, size.y);
  const float white[4] = {1, 1, 1, 1};
  glClearBufferfv(GL_COLOR, 0, white);
  glDisable(GL_SCISSOR_TEST);
  if (labels > 0) drawLabels(choice, size, labels);
}

void SplitScreen::drawLabels(const CompareChoice& choice, glm::ivec2 size, float pixelsPerPoint) {
  // Each half says what it shows, in the picture itself (a headless screenshot has no panels).
  // (as large as a lecture room needs: 2.25 at 540 rows, 4.5 at 1080, and never wider than the half;
  // rows and sizes in points: a Retina display has pixelsPerPoint pixels to each)
  const int half = size.x / 2, margin = int(8 * pixelsPerPoint);
  const std::string left = choice.key + " = " + choice.a, right = choice.key + " = " + choice.b;
  const float rows = float(size.y) / pixelsPerPoint;
  const float most = (rows >= 400 ? rows / 240.0f : 1.0f) * pixelsPerPoint;
  const float scale =
      std::min(label_.scaleToFit(left, half - 3 * margin, most), label_.scaleToFit(right, half - 3 * margin, most));
  label_.draw(left, {margin, size.y - int(13 * scale)}, size, scale);
  label_.draw(right, {half + margin, size.y - int(13 * scale)}, size, scale);
}

}  // namespace wb
