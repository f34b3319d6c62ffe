/// @file symptom_watch.hpp
/// A bug hunt's symptom, live in the window: a lab with hunts (exercises NN.Hk) measures its frame
/// against exact visibility whenever what the frame shows has settled after a change (the view,
/// the light, a setting, a shader the student edited), so the info panel's hunt rows show the acne
/// and the leak of the code as it is now. Measuring costs one frame's ray casting (about 90 ms at
/// 960x540 on two llvmpipe cores), so it runs once per change, never while the view moves.
#pragma once
#include "common/base/settings.hpp"

#include <glm/glm.hpp>

#include <string>

namespace wb {

struct MeasureResult;

/// Decides when to measure again, from a signature of what each frame shows.
class SymptomWatch {
 public:
  /// The frames a changed view must stay still before it is measured.
  static constexpr int kSettleFrames = 20;
  /// Called once per frame with what it shows; true on the frame the measurement is due.
  bool due(const Settings& settings, const glm::mat4& viewProj, glm::ivec2 frameSize, int reloads);
  /// Records a measurement for the panel.
  void record(const MeasureResult& r);
  /// The hunt rows' line: "now: acne 0.04%, leak 69.12% (this view)", "measuring..." before the first.
  const std::string& line() const { return line_; }

 private:
  std::string shown_;    // the signature of the frame last measured
  std::string pending_;  // the signature of the frames seen since the last change
  int still_ = 0;        // frames pending_ has been seen
  std::string line_ = "measuring when the view is still...";
};

}  // namespace wb
