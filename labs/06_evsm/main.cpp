// Lab 06: EVSM, exponential variance shadow maps
// ---------------------------------------------------------------------------------------------
// Difficulty: 3/5. Handout: README.md beside this file.
// Exercises:  06.1, 06.3 in shaders/exercise.glsl; 06.2 and the bug hunt 06.H1 in exercise.cpp.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// VSM bleeds where occluders are far apart compared with their distance to the receiver. Warping
// depth exponentially before taking moments squeezes that ratio, and a second, negative warp
// catches what the first misses; the smaller of the two bounds is kept. The extension (06.x) stores
// four powers of depth instead and reconstructs the shadow from them (moment shadow maps).
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <algorithm>

namespace {

class EvsmLab : public wb::Lab {
 public:
  EvsmLab() : Lab("scenes/bench_bleeding.json") {
    settings.addChoice("evsm.technique", technique, {"evsm", "msm"}, "EVSM, or moment shadow maps (06.x)");
    settings.add("evsm.c_positive", cPos, 1.0f, 100.0f, "exponent of the positive warp (clamped by 06.2)");
    settings.add("evsm.c_negative", cNeg, 1.0f, 100.0f, "exponent of the negative warp (clamped by 06.2)");
    settings.addChoice("evsm.channels", channels, {"2", "4"}, "2: positive warp only; 4: both warps");
    settings.addChoice("evsm.format", format, {"fp32", "fp16"}, "the map's float format");
    settings.add("evsm.min_variance", minVariance, 0.0f, 0.001f, "the smallest variance, before the warp's slope");
    settings.add("evsm.bleeding_reduction", bleeding, 0.0f, 0.9f, "light-bleeding reduction amount");
    settings.add("msm.moment_bias", momentBias, 0.0f, 0.001f, "MSM: how far the moments are pulled towards 0.5");
    prefilter.addTo(settings);
  }

 protected:
  void init() override {
    momentsProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "moments.frag"}});
    blurProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/blur.frag"}});
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    glslExercise("06.1", "exercise.glsl", "evsmMoments(0.5, 1.0, 1.0).x");
    glslExercise("06.3", "exercise.glsl", "evsmVisibility(vec4(1.0), 0.5, 1.0, 1.0, 0.0, 0.0, 4)");
    glslExercise("06.x", "exercise.glsl", "msmVisibility(vec4(0.5), 0.5, 0.0) + msmMoments(0.5).x");
  }

  void render() override {
    const wb::Light& light = scene.lights[lightIndex];
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    const GLenum glFormat = format == 0 ? GL_RGBA32F : GL_RGBA16F;
    map.resize(shadowMapSize(), prefilter.options(glFormat));

    // The exponents' bound (06.2): exp(c)^2 must fit the format; the exponents used under it (06.H1).
    double bound = 0;
    if (!attempt("06.2", bound, [&] { return lab06::evsmMaxExponent(wb::formatMax(glFormat)); })) bound = 1e30;
    glm::vec2 used(cPos, cNeg);
    attempt("06.H1", used, [&] { return lab06::usableExponents(cPos, cNeg, bound, format == 1); });
    const float pos = used.x, neg = used.y;
    if (used != glm::vec2(cPos, cNeg))
      warn("an EVSM exponent above " + std::to_string(bound) + " overflows " + (format == 0 ? "fp32" : "fp16") +
           "; clamped");

    // PASS 1: the warped moments from the light, then the separable prefilter.
    const bool msm = technique == 1;
    if (msm && format == 1) warn("MSM needs fp32 moments here (fp16 would need the optimized quantization)");
    const float evsmFar[4] = {std::exp(pos), std::exp(2 * pos), -std::exp(-neg), std::exp(-2 * neg)};  // depth 1
    const float msmFar[4] = {1, 1, 1, 1};
    const float* far = msm ? msmFar : evsmFar;
    momentsProgram->set("u_msm", int(msm));
    momentsProgram->set("u_cPos", pos);
    momentsProgram->set("u_cNeg", neg);
    renderFilteredShadowMap(*momentsProgram, map, far, *blurProgram, light, lightViewProj);

    // PASS 2: one filtered lookup per pixel.
    auto timer = timePass("lighting");
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, lightViewProj, map.texture());
    p.set("u_cPos", pos);
    p.set("u_cNeg", neg);
    p.set("u_minVariance", minVariance);
    p.set("u_bleeding", bleeding);
    p.set("u_channels", channels == 0 ? 2 : 4);
    p.set("u_msm", int(msm));
    p.set("u_momentBias", momentBias);
    gpuScene->draw(p);
  }

 private:
  wb::Program *momentsProgram = nullptr, *blurProgram = nullptr;  // PASS 1
  wb::Program* sceneProgram = nullptr;                            // PASS 2
  wb::FilteredShadowMap map;
  float cPos = 40.0f, cNeg = 5.0f;  // a well-known sample clamps to 42 (fp32)
  int technique = 0;                // EVSM
  int channels = 1;                 // 4 channels
  int format = 0;                   // fp32
  float minVariance = 1e-6f;        // before scaling by (c w)^2; larger values bleed (see the handout)
  float bleeding = 0.0f;
  float momentBias = 3e-5f;         // Peters and Klein's value for 32-bit moments
  wb::PrefilterSettings prefilter;  // prefilter.*: no blur by default, so the lab stays interactive on a CPU
};

}  // namespace

int main(int argc, char** argv) { return wb::run<EvsmLab>(argc, argv); }
