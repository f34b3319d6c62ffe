/// @file embedded_lab.hpp
/// A lab hosted inside another lab. The showcase links every lab's solution into one program (each
/// lab's main.cpp compiled with main renamed, see wb::g_hostedLab) and draws the chosen technique
/// into its own frame target, through its own camera, on its own scene. Nothing of a lab is copied:
/// an EmbeddedLab calls the lab's own init(), render() and ui(), and is its host: it keeps the lab's
/// stage (its programs, exercises and warnings) and lends it the frame target of the lab it is
/// drawn in.
#pragma once
#include "common/shell/lab.hpp"
#include "common/shell/lab_stage.hpp"

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
  /// (the first call copies the scene and starts the lab). The lab's shown() then describes what was
  /// drawn, for a host that passes it on to the app's debug views and measurements. Throws what
  /// init() or render() throw, and wb::Error for a shader that does not compile.
  void render(const Lab& host, float dt);
  /// The lab's own widgets.
  void ui();
  /// The lab's warnings not taken yet, each named with the lab ("03_pcf: ..."), for the host to show.
  std::vector<std::string> takeWarnings();
  /// Gives the host this lab's warnings again at the next takeWarnings() (a host that cleared its own).
  void resendWarnings() { warningsSeen_ = 0; }

 private:
  class Use;  // points wb::variant at this lab while it lives
  std::string labName_, shaderPath_, labDir_, solutionDir_;
  std::unique_ptr<LabStage> stage_;  // from the first render() (the lab's stage: it outlives the lab)
  std::unique_ptr<Lab> lab_;
  int frames_ = 0;
  size_t warningsSeen_ = 0;
};

}  // namespace wb
