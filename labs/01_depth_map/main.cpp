// Lab 01: Depth map, the shadow-mapping principle
// ---------------------------------------------------------------------------------------------
// Difficulty: 1/5. Handout: README.md beside this file.
// Exercises:  01.1, 01.2 and the bug hunt 01.H1 in exercise.cpp; 01.3, 01.4, 01.5 in
//             shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// Two passes: the light renders the scene's depth into a texture (the shadow map); the camera then
// renders the scene and asks, per pixel, whether the light saw something nearer than this point.
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <array>

#include <cmath>

namespace {

class DepthMapLab : public wb::Lab {
 public:
  DepthMapLab() : Lab("scenes/depth_map.json") {
    useDepthBias();
    settings.add("light.spin", spin, -90.0f, 90.0f,
                 "degrees per second the light turns about the vertical axis while the lab runs (headless: 1/60 s a "
                 "frame; the bug hunt 01.H1)");
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "depth.vert"}, {GL_FRAGMENT_SHADER, "depth.frag"}});
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    // The info panel asks each GLSL exercise once with a sample input whether it is implemented.
    glslExercise("01.3", "exercise.glsl", "worldToShadowCoord(mat4(1.0), vec3(0.0)).x");
    glslExercise("01.4", "exercise.glsl", "hardShadow(wb_tex0, vec3(0.5), 0.0)");
    glslExercise("01.5", "exercise.glsl", "casterCoverage(wb_tex0, vec2(0.5), 0.5)");
    // Both C++ exercises are tried once, so the panel shows them whichever light is in use.
    attempt("01.1", [] { lab01::directionalLightViewProj({0, -1, 0}, glm::vec3(-1), glm::vec3(1)); });
    attempt("01.2", [] { lab01::spotLightViewProj({0, 5, 0}, {0, -1, 0}, 30, 0.5f, 20); });
  }

  void update(float dt) override { spun += spin * dt; }

  void render() override {
    const wb::Light light = wb::turnedAboutY(scene.lights[lightIndex], spun);
    if (light.type == wb::LightType::Point) {
      warn("lab 01 casts shadows from directional and spot lights; light " + std::to_string(lightIndex) +
           " is a point light (lab 08 covers those)");
    }
    // The light's camera: an orthographic box around the scene, or the spot's perspective cone.
    const bool spot = light.type == wb::LightType::Spot;
    const bool ready =
        spot ? attempt("01.2", lightViewProj,
                       [&] {
                         return lab01::spotLightViewProj(light.position, light.direction, light.angle, light.nearPlane,
                                                         light.farPlane);
                       })
             : light.type == wb::LightType::Directional && attempt("01.1", lightViewProj, [&] {
                 return lab01::directionalLightViewProj(light.direction, scene.boundsMin, scene.boundsMax);
               });
    shadowMap.resize(shadowMapSize());
    // A turning light: each pass's matrix from this frame's and last frame's (01.H1), the light's
    // matrix from the framework's fit (01.1 and 01.2 are graded on still lights, where this is unused).
    const glm::mat4 moving = wb::lightViewProj(light, scene);
    if (!started) passes = {{moving, moving}}, started = true;  // (the first frame has no earlier one)
    attempt("01.H1", passes, [&] {
      const lab01::PassMatrices now = lab01::updatePassMatrices({passes[0], passes[1]}, moving);
      return std::array<glm::mat4, 2>{now.shadowPass, now.cameraPass};
    });
    const bool turning = spun != 0;
    const glm::mat4 shadowPass = turning ? passes[0] : lightViewProj, cameraPass = turning ? passes[1] : lightViewProj;

    // PASS 1: depth from the light. No colour target; only the depth buffer is kept.
    // Every face is drawn (no culling): the leaves are open quads, and any face may cast a shadow.
    if (ready) {
      auto timer = timePass("shadow");
      renderShadowMap(*depthProgram, shadowMap, light, shadowPass);
    }

    // PASS 2: the camera's view, with the shadow test per pixel.
    auto timer = timePass("lighting");
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, cameraPass, shadowMap.texture());
    p.set("u_shadowsReady", ready ? 1 : 0);
    p.set("u_bias", depthBias());
    gpuScene->draw(p);
  }

 private:
  wb::Program* depthProgram = nullptr;  // PASS 1
  wb::Program* sceneProgram = nullptr;  // PASS 2
  wb::ShadowMap shadowMap;
  glm::mat4 lightViewProj{1};
  float spin = 0;                     // light.spin: degrees per second
  float spun = 0;                     // degrees turned so far
  bool started = false;               // passes holds a frame's matrices
  std::array<glm::mat4, 2> passes{};  // the shadow pass's and the camera pass's light matrix (01.H1)
};

}  // namespace

int main(int argc, char** argv) { return wb::run<DepthMapLab>(argc, argv); }
