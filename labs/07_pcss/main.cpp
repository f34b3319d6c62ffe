// Lab 07: PCSS, percentage-closer soft shadows
// ---------------------------------------------------------------------------------------------
// Difficulty: 3/5. Handout: README.md beside this file.
// Exercises:  07.1 - 07.4 and the bug hunt 07.H1, all in shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// A light with a size casts shadows that are sharp where the caster touches the receiver and soft
// further away. PCSS estimates that width per pixel from the shadow map: it searches for blockers,
// averages their depth, and filters with a PCF as wide as the penumbra the parallel-planes model
// predicts. --metrics holds it against the area light's true visibility, ray-traced.
#include "common/shell/lab.hpp"

#include <cmath>
#include <string>

namespace {

class PcssLab : public wb::Lab {
 public:
  PcssLab() : Lab("scenes/pcss_plank.json") {
    settings.addChoice("pcss.method", method, {"pcss", "pcf"},
                       "pcss: the filter follows the penumbra; pcf: one fixed width (pcss.pcf_width) everywhere");
    settings.addChoice("pcss.search_samples", searchSamples, {"16", "25", "32", "64"}, "taps of the blocker search");
    settings.addChoice("pcss.filter_samples", filterSamples, {"16", "25", "32", "64"}, "taps of the filter");
    settings.add("pcss.min_filter", minFilterTexels, 0.0f, 8.0f, "the narrowest filter, in texels");
    settings.add("pcss.pcf_width", pcfWidthTexels, 1.0f, 96.0f, "pcf: the fixed filter width, in texels");
    // 512 texels: a CPU renderer's caches hold it, and PCSS's scattered taps then cost a third less
    // than at 1024 (the handout's cost table); the penumbrae are many texels wide anyway.
    settings.assign("shadow.map_size=512");
    useLightSize(0.8f);
    useDepthBias(0.03f);  // here in world units along the light's axis: the tests compare distances
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    for (int m = 0; m < 2; ++m)  // one variant per method: PCSS_METHOD is the pcss.method index
      scenePrograms[m] = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}},
                                      "#define PCSS_METHOD " + std::to_string(m) + "\n");
    glslExercise("07.1", "exercise.glsl", "pcssSearchWidth(0.2, 4.0, 1.0)");
    glslExercise("07.2", "exercise.glsl",
                 "pcssFindBlockers(wb_tex0, vec2(0.5), 4.0, 0.1, 16, mat2(1.0), vec2(1.0, 10.0), 0.0).x");
    glslExercise("07.3", "exercise.glsl", "pcssPenumbraWidth(4.0, 2.0, 0.2)");
    glslExercise("07.4", "exercise.glsl",
                 "pcss(wb_tex0, vec2(0.5), 4.0, PcssSettings(0.2, vec2(1.0, 10.0), 16, 16, 0.0, 0.0), uvec2(0u))");
    glslExercise("07.H1", "exercise.glsl", "0.0");  // a bug hunt: working code, never a stub
  }

  void render() override {
    wb::Light light = spotLight();
    light.size = lightSize();
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    shadowMap.resize(shadowMapSize());

    // PASS 1: depth from the light's centre.
    {
      auto timer = timePass("shadow");
      renderShadowMap(*depthProgram, shadowMap, light, lightViewProj);
    }

    // PASS 2: the camera's view; PCSS per pixel (search, estimate, filter).
    auto timer = timePass("lighting");
    const wb::Program& p = *scenePrograms[method];
    beginCameraPass(p, light, lightViewProj, shadowMap.texture());
    const float nearWidth = 2 * light.nearPlane * std::tan(glm::radians(light.angle));  // the map at the near plane
    const float texel = 1.0f / float(shadowMapSize());
    p.set("u_lightPos", light.position);
    p.set("u_lightDir", glm::normalize(light.direction));
    p.set("u_lightSizeUV", light.size / nearWidth);
    p.set("u_lightSize", light.size);
    p.set("u_nearFar", glm::vec2(light.nearPlane, light.farPlane));
    p.set("u_searchSamples", kCounts[searchSamples]);
    p.set("u_filterSamples", kCounts[filterSamples]);
    p.set("u_minFilterUV", minFilterTexels * texel);
    p.set("u_pcfWidthTexels", pcfWidthTexels);
    p.set("u_bias", depthBias());
    gpuScene->draw(p);
  }

 private:
  // PCSS's formulas need a perspective light: the chosen light if it is a spot, else the first spot.
  wb::Light spotLight() {
    const wb::Light& chosen = scene.lights[size_t(lightIndex)];
    if (chosen.type == wb::LightType::Spot) return chosen;
    for (const auto& l : scene.lights)
      if (l.type == wb::LightType::Spot) {
        warn("lab 07 needs a spot light (PCSS's formulas assume a perspective map); light.index " +
             std::to_string(lightIndex) + " is not one, so the scene's first spot light is used");
        return l;
      }
    throw wb::UsageError(scene.path.string() + " has no spot light; lab 07 needs one (try scenes/pcss_plank.json)");
  }

  static constexpr int kCounts[4] = {16, 25, 32, 64};
  wb::Program* depthProgram = nullptr;  // PASS 1
  wb::Program* scenePrograms[2] = {};   // PASS 2, one per pcss.method
  wb::ShadowMap shadowMap;
  int method = 0;                // pcss.method
  int searchSamples = 0;         // 16 taps
  int filterSamples = 0;         // 16 taps
  float minFilterTexels = 1.5f;  // contact shadows stay anti-aliased
  float pcfWidthTexels = 8.0f;   // pcss.method=pcf
};

}  // namespace

int main(int argc, char** argv) { return wb::run<PcssLab>(argc, argv); }
