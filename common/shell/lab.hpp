/// @file lab.hpp
/// What a lab sees: the hooks it overrides (init, update, render, ui) and a handful of helpers
/// (loadProgram, attempt / glslExercise, timePass, warn, the shadow and camera-pass helpers). The
/// machinery behind them (the app, command line, frame target, debug views, measurement, bench)
/// lives in files a lab author can leave closed. A lab's main() is one line: wb::run<MyLab>().
#pragma once
#include "common/base/error.hpp"
#include "common/base/settings.hpp"
#include "common/base/value_codec.hpp"
#include "common/exercise/exercise_board.hpp"
#include "common/exercise/exercise_tape.hpp"
#include "common/platform/frame_target.hpp"
#include "common/platform/gl.hpp"
#include "common/platform/gpu_timers.hpp"
#include "common/platform/shader.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/light_view.hpp"
#include "common/scene/scene.hpp"
#include "common/shadows/prefilter.hpp"
#include "common/shadows/shadow_map.hpp"
#include "common/shell/command_line.hpp"
#include "common/shell/debug_views.hpp"

#include <glm/glm.hpp>

#include <functional>
#include <list>
#include <memory>
#include <string>
#include <vector>

namespace wb {

struct LabStage;

/// How a lab makes its shadows, so that it gets only the shared settings that mean something there.
enum class ShadowKind {
  Map,      ///< from a shadow map: shadow.map_size and the map's debug views (debug.*)
  Geometry  ///< from geometry (stencil shadow volumes): no map, so neither of those
};

/// What a lab's last frame showed, for its host's debug views and measurements.
struct FrameShown {
  LightView light;           ///< the light and map the lab showed (showLight()); no map where it showed none
  Light litBy;               ///< the light to measure with: that light, else the scene's light.index
  DebugOptions debug;        ///< debug.*
  glm::mat4 viewProj{1};     ///< what the scene was seen through (viewProj())
  float alphaCutoff = 0.5f;  ///< alpha.cutoff
  int lightRays = 16;        ///< rays per pixel of the area-light reference (truth.light_samples)
  /// Set when the frame's visibility output holds a measure of the lab's own (lab 10's debug.density,
  /// lab 11's warp.view): it gives that measure's numbers on one line, and the host then measures
  /// nothing against exact visibility (the shadow numbers of such a frame would mean nothing).
  std::function<std::string()> ownMeasure;
};

/// Base class of every lab. Override the hooks; use the protected helpers.
class Lab {
 public:
  /// @param defaultScene scene file relative to the repository root. The lab's number, title and
  /// exercise list come from its exercises.json, the one list shared with the tests and grading.
  /// @param kind how the lab makes its shadows (which shared settings it gets).
  explicit Lab(std::string defaultScene, ShadowKind kind = ShadowKind::Map);
  virtual ~Lab();
  Lab(const Lab&) = delete;
  Lab& operator=(const Lab&) = delete;

  // The hooks: a lab overrides them, its host calls them.

  /// Creates GL resources; called once after the context and scene exist. Read it as a table of contents.
  virtual void init() = 0;
  /// Advances animation by `dt` seconds (fixed 1/60 s in headless runs, so captures repeat).
  virtual void update(float /*dt*/) {}
  /// Draws one frame into the frame target: color (attachment 0), visibility (1) and world
  /// position (2); shaders/wb/outputs.glsl declares them.
  virtual void render() = 0;
  /// Adds the lab's own widgets to its Settings window.
  virtual void ui() {}
  /// Called after the frame was measured against exact visibility (the Measure button, --metrics,
  /// a presenter step), with the measured numbers on one line; `split` when the frame was split.
  virtual void measured(const std::string& /*numbers*/, bool /*split*/) {}
  /// What the last frame showed, for the host's debug views and measurements. A lab that draws
  /// another lab's frame (the showcase) returns that lab's.
  virtual FrameShown shown() const;

  // What a host calls (LabHost; EmbeddedLab for a lab inside another). A lab author can skip these.

  /// The scene file used when none is named.
  const std::string& defaultScene() const { return defaultScene_; }
  /// Takes `scene` as the lab's: light.index must name one of its lights (else wb::UsageError), and
  /// that light's size becomes light.size unless `keepLightSize` (the command line names it).
  void adoptScene(Scene scene, bool keepLightSize);
  /// Starts the lab on a host's `stage`, which outlives it: puts the scene on the GPU, calls init()
  /// and probes the GLSL exercises. Once, after adoptScene().
  void start(LabStage& stage);
  /// The stage the lab was started on; throws wb::Error before start().
  LabStage& stage() const;

  Settings settings;                   ///< this lab's tunables (register them in the constructor)
  Scene scene;                         ///< the loaded scene file
  std::unique_ptr<GpuScene> gpuScene;  ///< the scene on the GPU
  OrbitCamera camera;                  ///< the viewer's camera (the host moves it: mouse, bookmarks)
  int lightIndex = 0;                  ///< which scene light casts shadows (setting light.index)

 protected:
  /// The split screen of this frame (on, the setting compared and its two values).
  const CompareChoice& comparison() const;
  /// The lab's exercises and their states (as the info panel shows them).
  const ExerciseBoard& board() const;

  /// Builds a program that is hot-reloaded with the others; a broken edit keeps the last good one.
  Program& loadProgram(std::vector<ShaderStage> stages, std::string defines = {});
  /// Registers a GLSL exercise and the expression that probes whether it is implemented; the
  /// expression is evaluated in a vertex shader with `file` included and compared with WB_TODO; it
  /// may read wb_tex0 (a 2D texture) and wb_tex1 (a cube map).
  void glslExercise(const std::string& id, const std::string& file, const std::string& probe);
  /// Runs a C++ exercise call, recording Implemented / NotImplemented / Failed; true on success.
  template <class F>
  bool attempt(const std::string& id, F&& call) {
    return runExercise(
        id, [&] { return call(), nlohmann::json(); }, [](const nlohmann::json&) {});
  }
  /// Runs a C++ exercise that produces a value: `out = call()`. When the grader replays a
  /// student's run (ExerciseTape), `out` is the student's recorded value instead.
  template <class T, class F>
  bool attempt(const std::string& id, T& out, F&& call) {
    return runExercise(
        id, [&] { return out = call(), encode(out); }, [&](const nlohmann::json& v) { out = decode<T>(v); });
  }
  /// Runs a C++ exercise that sets the depth pass's rasterizer state (polygon offset, culling);
  /// a replay sets the state the student's call left.
  template <class F>
  bool attemptRasterState(const std::string& id, F&& call) {
    return runExercise(
        id, [&] { return call(), captureRasterState(); }, applyRasterState);
  }
  /// Records an exercise's state (shown in the info panel, printed and recorded by headless runs).
  void setStatus(const std::string& id, ExerciseState state, const std::string& message);

  /// PASS 1 of most labs: draws the scene's depth into `map` as seen through `lightViewProj` with
  /// `depthProgram` (setting u_lightViewProj and u_alphaCutoff), and shows `light` in the debug views.
  void renderShadowMap(const Program& depthProgram, const ShadowMap& map, const Light& light,
                       const glm::mat4& lightViewProj);
  /// PASS 1 for a point light: the six faces of `map`, face k through `faceViewProj[k]` (set as
  /// u_lightViewProj; set the rest first). Shows the cube in the debug views.
  void renderShadowMap(const Program& depthProgram, const CubeShadowMap& map, const Light& light,
                       const std::vector<glm::mat4>& faceViewProj, bool linearDistance);
  /// PASS 1 for cascades: layer k of `map` through `layerViewProj[k]`. Shows every layer. With
  /// `layerCasters`, layer k draws only the casters object i of which `(*layerCasters)[k][i]` is true.
  void renderShadowMap(const Program& depthProgram, const ShadowMapArray& map, const Light& light,
                       const std::vector<glm::mat4>& layerViewProj,
                       const std::vector<std::vector<bool>>* layerCasters = nullptr);
  /// PASS 1 of the filterable techniques (ESM, VSM, EVSM): clears `map` to `far` (the stored value
  /// of depth 1), draws the scene with `writer` (u_lightViewProj and u_alphaCutoff set; set the
  /// rest first), prefilters it with `blur`, and shows `light` in the debug views. Times "shadow"
  /// and "prefilter".
  void renderFilteredShadowMap(const Program& writer, FilteredShadowMap& map, const float far[4], const Program& blur,
                               const Light& light, const glm::mat4& lightViewProj);
  /// PASS 2 of most labs: binds the frame target and sets what every camera pass reads: u_viewProj,
  /// u_lightViewProj, u_alphaCutoff, `shadowMap` on texture unit 0 as u_shadowMap, and `light` for
  /// wbToLight() and wbLightReach() (shaders/wb/lighting.glsl), so every technique is lit alike.
  void beginCameraPass(const Program& program, const Light& light, const glm::mat4& lightViewProj, GLuint shadowMap);
  /// Binds the offscreen frame target (colour, visibility, position, depth + stencil) and its viewport.
  void bindFrameTarget() const;
  /// The frame target's size in pixels.
  glm::ivec2 frameSize() const;
  /// The view-projection the scene is seen through: the camera, or the light in "view from light".
  glm::mat4 viewProj() const;
  /// The eye position matching viewProj().
  glm::vec3 viewPosition() const;
  /// Tells the debug views and measurements about the light and its map; the render helpers call it.
  void showLight(const LightView& light) { light_ = light, lightShown_ = true; }
  /// The shadow map size chosen in the UI or by --set, clamped to GL_MAX_TEXTURE_SIZE.
  int shadowMapSize();
  /// Registers the shadow.bias setting (a constant depth bias, from 0 to `max`), for labs whose
  /// shaders use it; `help` says what unit it is in.
  void useDepthBias(float initial = 0.004f, float max = 0.05f,
                    const char* help = "constant depth bias subtracted from the receiver depth");
  /// Registers debug.light_face (which face or cascade the view from the light shows), for labs
  /// whose light has several matrices.
  void useLightFaces() { debug_.addLightFace(settings); }
  /// Registers light.size (the spot light's disk diameter, world units: the scene light's "size"
  /// when it has one and the command line does not set it, else `initial`) and truth.light_samples
  /// (rays per pixel of the area-light reference), for labs with soft shadows.
  void useLightSize(float initial);
  /// The light's size (useLightSize() registers its setting; 0 without it).
  float lightSize() const { return lightSize_; }
  /// The constant depth bias (useDepthBias() registers its setting).
  float depthBias() const { return bias_; }
  /// Texels of alpha-tested materials below this alpha are holes (setting alpha.cutoff); the exact
  /// visibility uses the same value.
  float alphaCutoff() const { return alphaCutoff_; }
  /// A warning shown in the info panel (and printed once on stderr).
  void warn(const std::string& message);
  /// Forgets the warnings shown (a host that switches the lab it shows: the showcase).
  void clearWarnings();

  /// Times a pass's GPU work until it is destroyed.
  using PassTimer = GpuTimers::Scope;
  /// Starts timing a pass: `auto t = timePass("shadow");`.
  PassTimer timePass(const char* name);

 private:
  bool runExercise(const std::string& id, const std::function<nlohmann::json()>& call,
                   const std::function<void(const nlohmann::json&)>& replay);
  std::string defaultScene_;
  LabStage* stage_ = nullptr;  // the host's, from start()
  LightView light_;            // what showLight() was given
  bool lightShown_ = false;
  DebugOptions debug_;
  int mapSizeChoice_ = 1;  // index into 512..8192
  float bias_ = 0.004f;
  bool biasRegistered_ = false;
  float lightSize_ = 0;
  bool lightSizeUsed_ = false;  // useLightSize() was called: a scene's light size sets light.size
  int lightSamples_ = 1;        // index into 16, 64, 256
  float alphaCutoff_ = 0.5f;
};

/// Runs `lab` with the shared command line in a LabHost (lab_host.hpp) and returns the exit code.
int runLab(int argc, char** argv, std::unique_ptr<Lab> lab);

/// Set by a program that hosts labs (the showcase, which compiles each lab's main.cpp with main
/// renamed): while it is set, run<T>() puts a new T here instead of running it.
extern std::unique_ptr<Lab>* g_hostedLab;

/// Constructs lab T and runs it with the shared command line in a LabHost: `int main(int c, char** v)
/// { return wb::run<DepthMapLab>(c, v); }`.
template <class T>
int run(int argc, char** argv) {
  if (g_hostedLab) return *g_hostedLab = std::make_unique<T>(), 0;
  return runLab(argc, argv, std::make_unique<T>());
}

}  // namespace wb
