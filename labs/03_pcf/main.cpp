// Lab 03: PCF, percentage-closer filtering
// ---------------------------------------------------------------------------------------------
// Difficulty: 2/5. Handout: README.md beside this file.
// Exercises:  03.1 - 03.5 and hunts 03.H1 - 03.H2, all in shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// A shadow map answers "lit or not" per texel, so its edges are as blocky as its texels. PCF
// averages the answers of several nearby texels: the edge becomes a ramp whose width is the filter
// footprint. The kernels here trade banding, noise and fetches; --sweep times them.
#include "common/shell/lab.hpp"

#include <string>

namespace {

class PcfLab : public wb::Lab {
 public:
  PcfLab() : Lab("scenes/depth_map.json") {
    settings.addChoice("pcf.method", method, {"grid", "hardware", "gaussian", "poisson", "gather"},
                       "which filter: N x N grid, hardware 2x2, Gaussian grid, rotated Poisson disk, textureGather");
    settings.addChoice("pcf.kernel", kernel, {"1", "3", "5", "7"}, "grid, gaussian, gather: width in taps");
    settings.add("pcf.spacing", spacing, 0.5f, 4.0f, "grid, gaussian: texels between taps (the softness)");
    settings.add("pcf.sigma", sigma, 0.25f, 4.0f, "gaussian: standard deviation in texels");
    settings.addChoice("pcf.poisson_count", poissonCount, {"16", "32", "64"}, "poisson: taps");
    settings.add("pcf.poisson_radius", poissonRadius, 0.5f, 8.0f, "poisson: disk radius in texels");
    // A single tap's bias; each filter scales it by how far its taps reach (03.H2), since wider
    // kernels compare further along sloped receivers.
    useDepthBias(0.003f, 0.05f, "depth bias of a single tap, subtracted from the receiver depth; filters scale it");
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    for (int m = 0; m < kMethods; ++m)  // one variant per filter: PCF_METHOD is the pcf.method index
      scenePrograms[m] = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}},
                                      "#define PCF_METHOD " + std::to_string(m) + "\n");
    glslExercise("03.1", "exercise.glsl", "pcfGrid(wb_tex0, vec3(0.5), 1, 1.0, 0.0)");
    glslExercise("03.2", "exercise.glsl", "pcfHardware(wb_shadow0, vec3(0.5), 0.0)");
    glslExercise("03.3", "exercise.glsl",
                 "gaussianWeight(vec2(1.0), 1.0) + pcfGaussian(wb_tex0, vec3(0.5), 1, 1.0, 1.0, 0.0)");
    glslExercise("03.4", "exercise.glsl", "pcfPoisson(wb_tex0, vec3(0.5), 16, 1.0, uvec2(0u), 0.0)");
    glslExercise("03.5", "exercise.glsl", "pcfGather(wb_tex0, vec3(0.5), 1, 0.0)");
    glslExercise("03.H1", "exercise.glsl", "insideShadowMap(vec3(0.5)) ? 1.0 : 0.0");  // a bug hunt: never a stub
    glslExercise("03.H2", "exercise.glsl", "filterBias(1.0, 1.0)");                    // a bug hunt too
    // The hardware filter reads the same depth texture through a sampler that compares.
    compareSampler = wb::makeComparisonSampler();
  }

  void render() override {
    const wb::Light& light = scene.lights[lightIndex];
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    shadowMap.resize(shadowMapSize());

    // PASS 1: depth from the light.
    {
      auto timer = timePass("shadow");
      renderShadowMap(*depthProgram, shadowMap, light, lightViewProj);
    }

    // PASS 2: the camera's view, filtering the comparisons.
    auto timer = timePass("lighting");
    const wb::Program& p = *scenePrograms[method];
    beginCameraPass(p, light, lightViewProj, shadowMap.texture());
    wb::bindTexture(1, shadowMap.texture());
    p.set("u_shadowCompare", 1);
    glBindSampler(1, compareSampler.id());
    p.set("u_bias", depthBias());
    p.set("u_radius", kernel);
    p.set("u_spacing", spacing);
    p.set("u_sigma", sigma);
    p.set("u_poissonCount", 16 << poissonCount);
    p.set("u_poissonRadius", poissonRadius);
    gpuScene->draw(p);
    glBindSampler(1, 0);
  }

 private:
  wb::Program* depthProgram = nullptr;  // PASS 1
  static constexpr int kMethods = 5;
  wb::Program* scenePrograms[kMethods] = {};  // PASS 2, one per pcf.method
  wb::ShadowMap shadowMap;
  wb::Sampler compareSampler;  // the hardware filter's comparing sampler
  int method = 1;              // pcf.method: hardware, the cheapest: interactive on a CPU renderer
  int kernel = 1;              // radius index: width 1, 3, 5, 7
  float spacing = 1.0f;        // texels between grid taps
  float sigma = 1.0f;          // Gaussian standard deviation, texels
  int poissonCount = 1;        // 16 << index taps
  float poissonRadius = 2.5f;  // texels
};

}  // namespace

int main(int argc, char** argv) { return wb::run<PcfLab>(argc, argv); }
