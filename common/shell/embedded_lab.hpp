/// @file embedded_lab.hpp
/// A lab hosted inside another lab. The showcase links every lab's solution into one program (each
/// lab's main.cpp compiled with main renamed, see wb::g_hostedLab) and draws the chosen technique
/// into its own frame target, through its own camera, on its own scene. Nothing of a lab is copied:
/// a EmbeddedLab calls the lab's own init(), render() and ui().
#pragma once
#include "common/shell/lab.hpp"

#include <memory>
#include <string>
#include <vector>

namespace wb {

/// One hosted lab and the folders it reads its files from.
class EmbeddedLab {
 public:
  /// A lab's main() compiled for hosting: with wb::g_hostedLab set, it makes the lab and returns.
  using MainFunction = int (*)(int, char**);
  /// Makes the lab of folder `lab` (e.g. "03_pcf") by calling `mainOf`, with wb::variant pointed at
  /// that lab's solution, and applies `sets` ("key=value"); throws what the lab or assign() throws.
  EmbeddedLab(const std::string& lab, MainFunction mainOf, const std::vector<std::string>& sets);
  ~EmbeddedLab();
  EmbeddedLab(const EmbeddedLab&) = delete;
  EmbeddedLab& operator=(const EmbeddedLab&) = delete;

  /// The hosted lab (its settings, its board).
  Lab& lab() { return *lab_; }
  /// Draws one frame of the lab into `host`'s frame target, as `host`'s camera sees `host`'s scene
  /// (the first call copies the scene and runs init()). Afterwards the host carries the lab's light,
  /// debug options, alpha cutoff and light samples, so the app's debug views and measurements
  /// describe what was drawn. Throws what init() or render() throw, and wb::Error for a shader that
  /// does not compile.
  void render(Lab& host, float dt);
  /// The lab's own widgets.
  void ui();
  /// Gives the host this lab's warnings again at the next render (a host that cleared its own).
  void resendWarnings() { warningsSeen_ = 0; }
  /// The settings a host shows for this lab: all but camera.bookmark (the host's camera is shared).
  static bool shown(const Setting& s) { return s.name != "camera.bookmark"; }

 private:
  class Use;  // points wb::variant at this lab while it lives
  std::string labName_, shaderPath_, labDir_, solutionDir_;
  std::unique_ptr<Lab> lab_;
  bool initialised_ = false;
  int frames_ = 0;
  size_t warningsSeen_ = 0;
};

}  // namespace wb
