/// @file panels.hpp
/// The ImGui panels around every lab: the info panel (renderer, fps, exercise states, GPU time per
/// pass, the measurement, shader errors, warnings) and the Settings window (every setting, the
/// split-screen choice, then the lab's own widgets).
#pragma once
#include "common/exercise/exercise_board.hpp"
#include "common/exercise/live_checks.hpp"
#include "common/platform/gpu_timers.hpp"
#include "common/platform/shader.hpp"
#include "common/shell/command_line.hpp"

#include <glm/vec2.hpp>

#include <functional>
#include <list>
#include <string>
#include <vector>

namespace wb {

class Settings;

/// What the shell shows and what its widgets change, kept by the app between frames.
struct PanelState {
  bool hidePanels = false;        ///< H: the scene alone, for a lecture
  bool showHeatmap = false;       ///< the measurement's heatmap over the frame
  bool showTimes = false;         ///< GPU time per pass in the info panel
  bool measureRequested = false;  ///< set when the Measure button was pressed
  std::string measured;           ///< the last measurement, as text
  std::string lastScreenshot;     ///< the last screenshot's path
  CompareChoice compare;          ///< the split-screen choice
};

/// What the shell reads from the hosted lab this frame.
struct PanelInput {
  const ExerciseBoard& board;                ///< exercise states
  const LiveChecks* checks;                  ///< their fast checks' verdicts (nullptr headless)
  const GpuTimers& timers;                   ///< GPU time per pass
  const std::list<Program>& programs;        ///< for their compile errors
  const std::vector<std::string>& warnings;  ///< the lab's warnings
  Settings& settings;                        ///< the lab's settings (edited here)
  glm::ivec2 frameSize;                      ///< where the windows go
  GLuint picture = 0;                        ///< the handout's picture of the finished lab (0: none)
  glm::ivec2 pictureSize{0};                 ///< its size in pixels
  std::function<void()> labUi;               ///< the lab's own widgets
  const std::string* symptom = nullptr;      ///< the hunts' live symptom (SymptomWatch::line()), if any
};

/// Draws the info panel and the Settings window (inside an ImGui frame).
void drawPanels(const PanelInput& in, PanelState& state);

}  // namespace wb
