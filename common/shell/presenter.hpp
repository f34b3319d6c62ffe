/// @file presenter.hpp
/// Presenter mode: a lab's demo.json is an ordered list of steps (a title, a one-sentence caption,
/// the settings it sets, a camera bookmark, optionally a split-screen comparison and measured
/// numbers). Page Down / Page Up (or the arrow keys) step through it in a window, with the caption
/// large in a band below the picture, so that it never hides the subject; --demo-step N renders
/// step N headlessly, so every step is also a slide figure (./workbook slides).
#pragma once
#include "common/platform/label.hpp"
#include "common/shell/command_line.hpp"

#include <glm/vec2.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace wb {

class Settings;
struct MeasureResult;

/// One step of a demo.
struct DemoStep {
  std::string title;              ///< a few words
  std::string caption;            ///< one sentence, shown large
  std::vector<std::string> sets;  ///< "key=value": the demo's common settings, then the step's own
  int bookmark = 0;               ///< camera bookmark, counted from 1 (0: keep the camera)
  CompareChoice compare;          ///< split screen, when on
  bool measure = false;           ///< show measured numbers (against exact visibility)
};

/// Reads `file` (demo.json); throws wb::UsageError naming the file, the step and what is wrong.
std::vector<DemoStep> loadDemo(const std::filesystem::path& file);

/// Applies demo steps to a lab's settings and draws the caption band.
class Presenter {
 public:
  /// Steps from `file`, applied on top of the values `settings` has now.
  Presenter(const std::filesystem::path& file, const Settings& settings);
  /// The number of steps.
  int count() const { return int(steps_.size()); }
  /// Step `k`, counted from 1.
  const DemoStep& step(int k) const { return steps_.at(size_t(k - 1)); }
  /// Puts `settings` back to the starting values, then applies step `k`'s (steps do not accumulate,
  /// so paging back shows what paging forward showed); returns the step.
  const DemoStep& apply(int k, Settings& settings) const;
  /// The caption band's height for a window of `size` pixels, with `pixelsPerPoint` pixels to each
  /// unit of the window's size (2 on a Retina display: the smallest band is that much taller).
  static int bandHeight(glm::ivec2 size, float pixelsPerPoint = 1);
  /// The caption's font size in pixels for a window of `size` (30 at 1080 rows: readable from the
  /// back of a lecture hall; never under 10 points); the title's is 1.13 times it.
  static float captionPixels(glm::ivec2 size, float pixelsPerPoint = 1);
  /// Draws step `k`'s title, caption and `numbers` in the band (the bottom `bandHeight` rows of the
  /// bound framebuffer of `size`).
  void drawBand(int k, const std::string& numbers, glm::ivec2 size, float pixelsPerPoint = 1);
  /// The measured numbers worth saying out loud, on one line.
  static std::string numbersLine(const MeasureResult& r);

 private:
  std::vector<DemoStep> steps_;
  std::vector<std::pair<std::string, std::string>> start_;  // every setting's value at the start
  Label label_;
};

}  // namespace wb
