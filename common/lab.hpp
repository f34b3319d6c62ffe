/// @file lab.hpp
/// The lab base class: the hooks a lab overrides (init, update, render, ui), the shared command
/// line, the ImGui shell (info panel, Settings window, debug views), GPU pass timers, screenshots,
/// visibility dumps and the exercise status board. A lab's main() is one line: wb::run<MyLab>().
#pragma once
#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/gl.hpp"
#include "common/prefilter.hpp"
#include "common/scene.hpp"
#include "common/settings.hpp"
#include "common/shader.hpp"
#include "common/shadow_map.hpp"

#include <glm/glm.hpp>

#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace wb {

class Context;

/// Where an exercise stands, as far as the running app can tell.
enum class ExerciseState { Unknown, Implemented, NotImplemented, Failed };

/// One row of the info panel.
struct ExerciseStatus {
  std::string id;                                ///< "01.3"
  std::string title;                             ///< from the lab's exercises.json
  ExerciseState state = ExerciseState::Unknown;  ///< last observed state
  std::string message;                           ///< why it is not implemented or failed
};

/// The shadow-casting light of the current frame, for the debug views and the measurements.
struct LightView {
  Light light;            ///< the light as used this frame (after any lab setting changed it)
  glm::mat4 viewProj{1};  ///< world → light clip space
  GLuint depthMap = 0;    ///< the shadow map's depth texture (0 = none yet)
  int mapSize = 0;        ///< its size in texels
  int kernel = 1;         ///< the prefilter's width (filtered maps): the footprint the PCF reference uses
  bool gaussian = false;  ///< the prefilter's weights: Gaussian, or a box
};

/// Base class of every lab. Override the hooks; use the protected helpers.
class Lab {
 public:
  /// @param defaultScene scene file relative to the repository root. The lab's number, title and
  /// exercise list come from its exercises.json, the one list shared with the tests and grading.
  explicit Lab(std::string defaultScene);
  virtual ~Lab();
  /// Runs the lab with the shared command line; returns the process exit code.
  int main(int argc, char** argv);

 protected:
  /// Creates GL resources; called once after the context and scene exist. Read it as a table of contents.
  virtual void init() = 0;
  /// Advances animation by `dt` seconds (fixed 1/60 s in headless runs, so captures repeat).
  virtual void update(float /*dt*/) {}
  /// Draws one frame into the frame target: color (attachment 0), visibility (1) and world
  /// position (2); shaders/wb/outputs.glsl declares them.
  virtual void render() = 0;
  /// Adds the lab's own widgets to its Settings window.
  virtual void ui() {}

  /// Builds a program that is hot-reloaded with the others; a broken edit keeps the last good one.
  Program& loadProgram(std::vector<ShaderStage> stages, std::string defines = {});
  /// Registers a GLSL exercise and the expression that probes whether it is implemented; the
  /// expression is evaluated in a compute shader with `file` included and compared with WB_TODO.
  void glslExercise(const std::string& id, const std::string& file, const std::string& probe);
  /// Runs a C++ exercise call, recording Implemented / NotImplemented / Failed; true on success.
  template <class F>
  bool attempt(const std::string& id, F&& call) {
    try {
      call();
      setStatus(id, ExerciseState::Implemented, "");
      return true;
    } catch (const NotImplemented& e) {
      setStatus(id, ExerciseState::NotImplemented, e.what());
    } catch (const std::exception& e) {
      setStatus(id, ExerciseState::Failed, e.what());
    }
    return false;
  }
  /// Records an exercise's state (shown in the info panel and printed by headless runs).
  void setStatus(const std::string& id, ExerciseState state, const std::string& message);

  /// PASS 1 of most labs: draws the scene's depth into `map` as seen through `lightViewProj` with
  /// `depthProgram` (setting u_lightViewProj and u_alphaCutoff), and shows `light` in the debug views.
  void renderShadowMap(const Program& depthProgram, const ShadowMap& map, const Light& light,
                       const glm::mat4& lightViewProj);
  /// PASS 1 of the filterable techniques (ESM, VSM, EVSM): clears `map` to `far` (the stored value
  /// of depth 1), draws the scene with `writer` (u_lightViewProj and u_alphaCutoff set; set the
  /// rest first), prefilters it with `blur`, and shows `light` in the debug views. Times "shadow"
  /// and "prefilter".
  void renderFilteredShadowMap(const Program& writer, FilteredShadowMap& map, const float far[4], const Program& blur,
                               const Light& light, const glm::mat4& lightViewProj);
  /// PASS 2 of most labs: binds the frame target and sets what every camera pass reads: u_viewProj,
  /// u_lightViewProj, u_alphaCutoff, and `shadowMap` on texture unit 0 as u_shadowMap.
  void beginCameraPass(const Program& program, const glm::mat4& lightViewProj, GLuint shadowMap);
  /// Binds the offscreen frame target (color + visibility + depth) and sets the viewport.
  void bindFrameTarget() const;
  /// The frame target's size in pixels.
  glm::ivec2 frameSize() const { return frameSize_; }
  /// The view-projection the scene is seen through: the camera, or the light in "view from light".
  glm::mat4 viewProj() const;
  /// The eye position matching viewProj().
  glm::vec3 viewPosition() const;
  /// Tells the debug views about the light; call once per frame after building its matrix.
  void showLight(const LightView& light) { light_ = light; }
  /// The shadow map size chosen in the UI or by --set, clamped to GL_MAX_TEXTURE_SIZE.
  int shadowMapSize();
  /// The constant depth bias of the shared debug controls.
  float depthBias() const { return bias_; }
  /// Texels of alpha-tested materials below this alpha are holes (setting alpha.cutoff); the exact
  /// visibility uses the same value.
  float alphaCutoff() const { return alphaCutoff_; }
  /// A warning shown in the info panel (and printed once on stderr).
  void warn(const std::string& message);

  /// Times the GPU work of one pass until the returned object is destroyed (GL_TIME_ELAPSED).
  class PassTimer {
   public:
    /// Begins a GL_TIME_ELAPSED query for the pass `name`.
    PassTimer(Lab& lab, const char* name);
    /// Ends the query; the result is collected when the GPU has it.
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

   private:
    Lab& lab_;
  };
  /// Starts timing a pass: `auto t = timePass("shadow");`.
  PassTimer timePass(const char* name) { return PassTimer(*this, name); }

  Settings settings;                   ///< this lab's tunables (register them in the constructor)
  Scene scene;                         ///< the loaded scene file
  std::unique_ptr<GpuScene> gpuScene;  ///< the scene on the GPU
  OrbitCamera camera;                  ///< the viewer's camera
  int lightIndex = 0;                  ///< which scene light casts shadows (setting light.index)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  void frame(float dt);
  void drawShell();
  void drawScene(bool programsOk);
  void probeGlslExercises();
  void writeOutputs();
  void measure(bool report = true);
  int sweep();

  std::string number_, title_, defaultScene_;
  glm::ivec2 frameSize_{960, 540};
  LightView light_;
  int mapSizeChoice_ = 1;  // index into 512..8192
  float bias_ = 0.004f;
  float alphaCutoff_ = 0.5f;
  int debugView_ = 0;  // 0 = camera, 1 = light
  bool showMap_ = false, showFrustum_ = false;
  int bookmark_ = 0;
  std::list<Program> programs_;
  std::vector<ExerciseStatus> exercises_;
  std::vector<std::string> warnings_;
};

/// Constructs lab T and runs it: `int main(int c, char** v) { return wb::run<DepthMapLab>(c, v); }`.
template <class T>
int run(int argc, char** argv) {
  T lab;
  return lab.main(argc, argv);
}

}  // namespace wb
