// Lab 04: ESM, exponential shadow maps
// ---------------------------------------------------------------------------------------------
// Difficulty: 3/5. Handout: README.md beside this file.
// Exercises:  04.1, 04.2, 04.3, 04.5 in shaders/exercise.glsl; 04.4 in exercise.cpp.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// PCF filters comparisons per pixel, every frame. ESM makes the comparison itself filterable: it
// stores exp(c z), which a blur, mipmaps and the hardware's bilinear filter may average, and one
// lookup then gives a soft answer. The price: leaks near contacts, and an exponent bounded by the
// float format.
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <algorithm>

namespace {

class EsmLab : public wb::Lab {
 public:
  EsmLab() : Lab("scenes/depth_map.json") {
    settings.add("esm.c", c, 1.0f, 200.0f, "the exponent c (clamped to the format's bound, 04.4)");
    settings.addChoice("esm.format", format, {"fp32", "fp16"}, "the map's float format");
    settings.add("esm.log_space", logSpace, "store c z and filter in log space (04.2): no bound on c");
    settings.add("esm.fallback", fallback, "fall back to 3x3 PCF where ESM's assumption fails (04.5)");
    settings.add("esm.epsilon", epsilon, 0.0f, 1.0f, "fallback threshold: ESM value above 1 + epsilon");
    prefilter.addTo(settings);
    useDepthBias();  // only the PCF fallback (04.5) compares depths
  }

 protected:
  void init() override {
    warpProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "warp.frag"}});
    blurProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/blur.frag"}});
    logBlurProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "blur_log.frag"}});
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    glslExercise("04.1", "exercise.glsl", "esmWarp(0.5, 1.0)");
    glslExercise("04.2", "exercise.glsl", "logAdd(0.0, 0.0)");
    glslExercise("04.3", "exercise.glsl", "esmVisibility(0.0, 0.5, 1.0)");
    glslExercise("04.5", "exercise.glsl", "esmNeedsFallback(0.0, 0.5, 1.0, 0.1)");
    glslExercise("04.H1", "exercise.glsl", "0.0");  // a bug hunt: working code, never a stub
  }

  void render() override {
    const wb::Light& light = scene.lights[lightIndex];
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    const GLenum glFormat = format == 0 ? GL_R32F : GL_R16F;
    map.resize(shadowMapSize(), prefilter.options(glFormat));

    // The exponent's bound (04.4): exp(c) must fit the format, unless the map is in log space.
    float cUsed = c;
    double bound = 0;
    if (!logSpace && attempt("04.4", bound, [&] { return lab04::esmMaxExponent(wb::formatMax(glFormat)); }) &&
        c > bound) {
      cUsed = float(bound) * 0.999f;
      warn("esm.c = " + std::to_string(c) + " overflows " + (format == 0 ? "fp32" : "fp16") + "; clamped to " +
           std::to_string(cUsed) + " (or turn on esm.log_space)");
    }

    // PASS 1: the warped depth from the light, then the separable prefilter.
    const float far[4] = {logSpace ? cUsed : std::exp(std::min(cUsed, 88.0f)), 0, 0, 0};  // depth 1
    warpProgram->set("u_c", cUsed);
    warpProgram->set("u_logSpace", logSpace ? 1 : 0);
    renderFilteredShadowMap(*warpProgram, map, far, logSpace ? *logBlurProgram : *blurProgram, light, lightViewProj);

    // PASS 2: one filtered lookup per pixel.
    auto timer = timePass("lighting");
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, lightViewProj, map.texture());
    wb::bindTexture(1, map.depthTexture());
    p.set("u_depthMap", 1);
    p.set("u_c", cUsed);
    p.set("u_logSpace", logSpace ? 1 : 0);
    p.set("u_fallback", fallback ? 1 : 0);
    p.set("u_epsilon", epsilon);
    p.set("u_bias", depthBias());
    gpuScene->draw(p);
  }

 private:
  wb::Program *warpProgram = nullptr, *blurProgram = nullptr, *logBlurProgram = nullptr;  // PASS 1
  wb::Program* sceneProgram = nullptr;                                                    // PASS 2
  wb::FilteredShadowMap map;
  float c = 80.0f;        // the paper suggests 80 for fp32
  int format = 0;         // fp32, fp16
  bool logSpace = false;  // filter c z in log space
  bool fallback = false;  // PCF where the ESM value exceeds 1 + epsilon
  float epsilon = 0.05f;
  wb::PrefilterSettings prefilter;  // prefilter.*: no blur by default, so the lab stays interactive on a CPU
};

}  // namespace

int main(int argc, char** argv) { return wb::run<EsmLab>(argc, argv); }
