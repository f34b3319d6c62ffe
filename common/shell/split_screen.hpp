/// @file split_screen.hpp
/// Split-screen comparison of one setting: the frame is drawn twice, with value A kept in the left
/// half and value B in the right, a white divider between them, and each half's value written in it.
#pragma once
#include "common/platform/frame_target.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/label.hpp"
#include "common/shell/command_line.hpp"

#include <functional>

namespace wb {

class Settings;

/// Draws one frame whole or split.
class SplitScreen {
 public:
  /// Calls `draw` once, or with `choice.on` twice (setting `choice.key` to A, then B, then back);
  /// `afterDraw(side)` runs after each (side 0 = left or whole frame, 1 = right).
  /// The halves' labels are drawn with `labels` pixels per point (drawLabels()); with 0 they are left
  /// out of the frame (a window that stretches the frame, render.scale, draws them sharp itself).
  void render(FrameTarget& target, Settings& settings, const CompareChoice& choice, const std::function<void()>& draw,
              const std::function<void(int side)>& afterDraw, float labels = 1);
  /// Writes each half's setting at its bottom left, into the bound framebuffer's viewport of `size`.
  void drawLabels(const CompareChoice& choice, glm::ivec2 size, float pixelsPerPoint = 1);

 private:
  Texture saved_[3];  // the left half's attachments while the right half is drawn
  glm::ivec2 savedSize_{0};
  Label label_;  // each half's value, in the frame
};

}  // namespace wb
