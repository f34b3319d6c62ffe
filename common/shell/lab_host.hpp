/// @file lab_host.hpp
/// LabHost, the app that hosts a lab: the GL context (a window, or EGL surfaceless when headless), the
/// ImGui panels, the frame loop with input and hot reload, and the run's outputs (screenshot, visibility,
/// bench, measurement, the JSON record). A lab is an object the app hosts, so another program (a
/// showcase of every technique) can host one lab after another in the same window.
#pragma once
#include "common/exercise/live_checks.hpp"
#include "common/exercise/run_record.hpp"
#include "common/platform/frame_target.hpp"
#include "common/platform/gpu_timers.hpp"
#include "common/platform/label.hpp"
#include "common/shell/bench.hpp"
#include "common/shell/command_line.hpp"
#include "common/shell/debug_views.hpp"
#include "common/shell/host_settings.hpp"
#include "common/shell/lab_stage.hpp"
#include "common/shell/panels.hpp"
#include "common/shell/presenter.hpp"
#include "common/shell/split_screen.hpp"
#include "common/shell/symptom_watch.hpp"
#include "common/truth/measurement.hpp"

#include <glm/glm.hpp>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wb {

class Context;
class Lab;
class ImGuiLayer;

/// Hosts labs in one context; see the file comment. The host's settings (host_settings.hpp) and
/// what it lends and keeps for the lab it hosts (lab_stage.hpp) are its own; it reaches the lab
/// through the lab's public side only.
class LabHost {
 public:
  /// Runs `lab` with the shared command line: parses it, configures the lab, opens the context,
  /// hosts the lab and renders (or sweeps), then writes the outputs and the record. Returns the
  /// exit code: 0 done, 1 failed, 2 bad input, 3 no OpenGL 4.1 context.
  static int runLab(int argc, char** argv, std::unique_ptr<Lab> lab);

  /// Takes the run's options; nothing opens before open().
  explicit LabHost(const Options& options);
  ~LabHost();
  LabHost(const LabHost&) = delete;
  LabHost& operator=(const LabHost&) = delete;

  /// Adds the host's settings to the lab's (after its own), applies the command line's --set, and
  /// checks its --compare and --sweep values (CPU only, so bad input fails before any window
  /// opens); throws wb::UsageError. Once per lab, before loadScene().
  void configure(Lab& lab);
  /// Loads the lab's scene (options.scene, or its default) and goes to camera.bookmark; throws
  /// wb::UsageError.
  void loadScene(Lab& lab);
  /// Creates the context and the ImGui shell (in a window); throws wb::ContextError.
  void open(const std::string& title);
  /// Hosts a lab with its scene loaded (loadScene()): the previous lab (if any) is destroyed first,
  /// while the context still lives; then the lab starts on a new stage (its scene on the GPU, init()).
  void host(std::unique_ptr<Lab> lab);
  /// Renders frames until the window closes or options.frames have been drawn.
  void loop();
  /// Loads the handout's picture of the finished lab (for the "Next" panel), in a window.
  void loadPicture();
  /// Draws one frame of the hosted lab (`dt` seconds after the last one).
  void frame(float dt);
  /// Runs --sweep; returns the exit code.
  int sweep();
  /// --record-video: renders the frames one by one (the --animate setting moving) into a video.
  void recordVideo();
  /// Measures after the loop if asked, writes the requested files, and fills `record`.
  void finish(RunRecord& record);
  /// Shows presenter step `k` of the lab's demo.json (from 1; 0 leaves presenter mode); throws
  /// wb::UsageError for a step that does not exist or sets what the lab does not have.
  void showStep(int k);
  /// The frame target the hosted lab draws into (what the last frame showed).
  const FrameTarget& target() const { return target_; }

 private:
  void beginUiFrame();
  void applyUiScale();           // the panels' text size: ui.scale, or the monitor's
  float pixelsPerPoint() const;  // framebuffer pixels per unit of the window's size (2 on a Retina display)
  void handleKeys();
  void upscale(int band, glm::ivec2 shown);  // the frame over the window's scene area (render.scale)
  bool stretched() const { return imgui_ && frameSize_ != viewSize_; }  // render.scale below 1, in a window
  void hotReload();
  void drawLab();
  void presentWindow();
  void saveWindowScreenshot(const std::string& path);
  void startPresenter();
  void stepKeys(const std::function<bool(int)>& pressed);
  void applyPresentation();
  MeasureResult measureFrame();  // this frame against exact visibility (the hunts' symptom line too)
  MeasureResult measureNow(bool report);
  void say(const std::string& text) const;

  Options options_;
  HostSettings shared_;           // camera.bookmark, light.orbit, camera.dolly, render.scale, ui.*, present.*
  SceneMotion motion_;            // light.orbit and camera.dolly, applied to the hosted lab's scene
  std::unique_ptr<Context> ctx_;  // declared first: destroyed last, after every GL object below
  std::unique_ptr<ImGuiLayer> imgui_;
  FrameTarget target_;
  GpuTimers timers_;
  std::unique_ptr<DebugViews> debug_;
  SplitScreen split_;
  Measurement measurement_;
  Texture heatmap_;
  Label label_;      // text burnt into the frame (a shader error at start-up)
  Texture picture_;  // the handout's picture of the finished lab (a window only)
  glm::ivec2 pictureSize_{0};
  std::unique_ptr<LiveChecks> checks_;      // the exercises' fast checks, in a window
  std::unique_ptr<Presenter> presenter_;    // the lab's demo.json, if it has one
  std::unique_ptr<SymptomWatch> symptoms_;  // a window of a lab with bug hunts: their symptom, live
  int reloads_ = 0;                         // shader programs rebuilt so far (a hunt's edit)
  std::unique_ptr<LabStage> stage_;         // what the hosted lab draws on and reports to
  std::unique_ptr<Lab> lab_;                // declared last: destroyed first

  PanelState panels_;
  int step_ = 0;               // the presenter step shown (0: not presenting)
  bool fullscreen_ = false;    // the window fills the monitor (--fullscreen, F11)
  glm::ivec2 viewSize_{0, 0};  // the window's scene area; frameSize_ is it times render.scale
  Program upscale_;            // render.scale below 1: the frame stretched over viewSize_
  VertexArray emptyVao_;
  Sampler linear_;            // the stretch's filtering
  bool measureStep_ = false;  // the step asks for numbers: measure after its first frame
  std::string stepNumbers_;   // and show them in the caption band
  LightView sides_[2];
  std::optional<MeasureResult> lastMeasure_;
  std::vector<std::pair<std::string, std::string>> written_;  // (kind, path) of files written
  glm::ivec2 frameSize_{960, 540};
  int frameIndex_ = 0;
  WallClock wall_;
  bool strictGl_ = false, screenshotRequested_ = false;
  glm::dvec2 lastMouse_{0};
  std::map<int, bool> keyDown_;
};

}  // namespace wb
