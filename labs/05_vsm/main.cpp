// Lab 05: VSM, variance shadow maps and light bleeding
// ---------------------------------------------------------------------------------------------
// Difficulty: 3/5. Handout: README.md beside this file.
// Exercises:  05.1 - 05.3 in shaders/exercise.glsl; 05.4 in exercise.cpp.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// VSM stores the mean and mean square of depth, which filter linearly, and bounds the lit fraction
// with Chebyshev's inequality. The bound is exact for one occluder over one receiver and too
// generous for stacked occluders: light bleeds. The Experiments panel measures both facts.
#include "common/exercise/glsl_harness.hpp"
#include "common/platform/texture_io.hpp"
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <imgui.h>

#include <cstdio>

namespace {

class VsmLab : public wb::Lab {
 public:
  VsmLab() : Lab("scenes/bench_bleeding.json") {
    settings.add("vsm.min_variance", minVariance, 0.0f, 0.001f, "the smallest variance Chebyshev's bound may use");
    settings.add("vsm.bleeding_reduction", bleeding, 0.0f, 0.9f, "light-bleeding reduction: p below this becomes 0");
    prefilter.addTo(settings);
    settings.add("vsm.experiments", printExperiments, "print the three-plane and two-plane experiments at start");
  }

 protected:
  void init() override {
    momentsProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "moments.frag"}});
    planesProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "planes.frag"}});
    blurProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/blur.frag"}});
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    glslExercise("05.1", "exercise.glsl", "vsmMoments(0.5, 0.0, 0.0).x");
    glslExercise("05.2", "exercise.glsl", "chebyshevUpperBound(vec2(0.5, 0.3), 0.6, 0.0)");
    glslExercise("05.3", "exercise.glsl", "reduceLightBleeding(0.5, 0.2)");
    glslExercise("05.H1", "exercise.glsl", "shadowMapCoord(mat4(1.0), vec3(0.0)).x");  // a bug hunt: never a stub
    attempt("05.4", [] { lab05::worstThreePlaneBleeding(1.0); });
    if (printExperiments) runExperiments(true);
  }

  void render() override {
    const wb::Light& light = scene.lights[lightIndex];
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    map.resize(shadowMapSize(), prefilter.options(GL_RG32F));

    // PASS 1: the moments from the light, then the separable prefilter.
    const float far[4] = {1, 1, 0, 0};  // depth 1: (M1, M2) = (1, 1)
    renderFilteredShadowMap(*momentsProgram, map, far, *blurProgram, light, lightViewProj);

    // PASS 2: one filtered lookup per pixel.
    auto timer = timePass("lighting");
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, lightViewProj, map.texture());
    p.set("u_minVariance", minVariance);
    p.set("u_bleeding", bleeding);
    gpuScene->draw(p);
  }

  void ui() override {
    if (!ImGui::CollapsingHeader("experiments")) return;
    if (ImGui::Button("run the experiments")) runExperiments(false);
    if (measured.empty()) return;
    ImGui::Text("three planes: the worst bleeding on c against t = (b-a)/(c-b)");
    ImGui::PlotLines("measured", measured.data(), int(measured.size()), 0, nullptr, 0, 0.5f, ImVec2(0, 60));
    ImGui::PlotLines("your 05.4", formula.data(), int(formula.size()), 0, nullptr, 0, 0.5f, ImVec2(0, 60));
    ImGui::Text("two parallel planes: largest |VSM - box PCF| = %.2e", vsmVsPcf);
  }

 private:
  // Both experiments use a synthetic 64² map: depth a left of column 32, b from it on, through the
  // same moments (05.1) and box prefilter as the scene, then Chebyshev (05.2) in a GLSL kernel.
  void runExperiments(bool print) {
    const int size = 64, split = 32, kernelWidth = 7;
    wb::FilteredShadowMap synthetic;
    synthetic.resize(size, {GL_RG32F, kernelWidth, false, false});
    auto makeMap = [&](float a, float b) {
      const float far[4] = {1, 1, 0, 0};
      synthetic.begin(far);
      glDepthFunc(GL_ALWAYS);
      planesProgram->set("u_a", a);
      planesProgram->set("u_b", b);
      planesProgram->set("u_split", split);
      synthetic.fill(*planesProgram);
      glDepthFunc(GL_LESS);
      synthetic.prefilter(*blurProgram);
    };
    auto texel = [&](int x) {
      glm::vec4 v;
      wb::readTextureRect(synthetic.texture(), x, size / 2, 0, 1, 1, GL_RGBA, GL_FLOAT, &v);
      return glm::vec2(v);
    };
    // Three planes: a = 0.2 left of the edge, b = 0.3 from it on, the receiver c = b + (b - a) / t.
    // After a 7-wide box, texel split - 4 + k mixes 7 - k taps of a with k of b (k = 1..6): the
    // worst measured over them approaches the worst over every mix (05.4) from below.
    const float ts[] = {0.25f, 0.5f, 1, 2, 4, 8};
    std::vector<glm::vec4> inputs;
    makeMap(0.2f, 0.3f);
    for (float t : ts)
      for (int k = 1; k <= 6; ++k) inputs.emplace_back(texel(split - 4 + k), 0.3f + 0.1f / t, 0.0f);
    const size_t planes = inputs.size();
    // Two planes: an occluder at 0.3 over a receiver plane at 0.6; texels 29..35 see 1..7 of the
    // 7 taps on the receiver, so box PCF for a receiver on that plane is exactly (x - 28) / 7.
    makeMap(0.3f, 0.6f);
    for (int x = split - 3; x <= split + 3; ++x) inputs.emplace_back(texel(x), 0.6f, 0.0f);
    std::vector<glm::vec4> out;
    try {
      const auto file = wb::findShaderFile("exercise.glsl", wb::shaderSearchPath());
      out = wb::runGlslKernel(wb::readFile(file), file, "result.x = chebyshevUpperBound(IN(0).xy, IN(0).z, IN(0).w);",
                              int(inputs.size()), 1, inputs);
    } catch (const std::exception& e) {
      warn(std::string("experiments: ") + e.what());
      return;
    }
    measured.clear(), formula.clear();
    if (print)
      std::printf(
          "three planes (a = 0.2, b = 0.3, c = b + (b - a) / t), 7-wide box filter:\n| t | measured worst (mixes k/7) "
          "| 05.4: worst | 05.4: at mix |\n|---|---|---|---|\n");
    for (size_t k = 0; k < std::size(ts); ++k) {
      float worst = 0;
      for (size_t j = 0; j < 6; ++j) worst = std::max(worst, out[k * 6 + j].x);
      glm::dvec2 predicted(-1);
      attempt("05.4", predicted, [&] { return lab05::worstThreePlaneBleeding(ts[k]); });
      measured.push_back(worst), formula.push_back(float(predicted.y));
      if (print) std::printf("| %g | %.5f | %.5f | %.4f |\n", ts[k], worst, predicted.y, predicted.x);
    }
    vsmVsPcf = 0;
    if (print)
      std::printf(
          "two parallel planes (occluder 0.3, receiver 0.6), 7-wide box filter:\n| texel | box PCF | VSM "
          "|\n|---|---|---|\n");
    for (int x = split - 3, k = int(planes); x <= split + 3; ++x, ++k) {
      const float pcf = float(x - (split - 4)) / 7.0f;
      vsmVsPcf = std::max(vsmVsPcf, std::abs(out[size_t(k)].x - pcf));
      if (print) std::printf("| %d | %.5f | %.5f |\n", x, pcf, out[size_t(k)].x);
    }
    if (print) std::printf("largest |VSM - PCF| = %.2e\n", vsmVsPcf);
  }

  wb::Program *momentsProgram = nullptr, *planesProgram = nullptr, *blurProgram = nullptr;  // PASS 1
  wb::Program* sceneProgram = nullptr;                                                      // PASS 2
  wb::FilteredShadowMap map;
  float minVariance = 2e-5f;        // keeps the bound from dividing by a vanishing variance
  float bleeding = 0.0f;            // light-bleeding reduction amount
  wb::PrefilterSettings prefilter;  // prefilter.*: no blur by default, so the lab stays interactive on a CPU
  bool printExperiments = false;
  std::vector<float> measured, formula;  // the three-plane curves for the plot
  float vsmVsPcf = 0;
};

}  // namespace

int main(int argc, char** argv) { return wb::run<VsmLab>(argc, argv); }
