// Lab 02: Bias, acne and peter-panning
// ---------------------------------------------------------------------------------------------
// Difficulty: 2/5. Handout: README.md beside this file.
// Exercises:  02.3, 02.4 and the bug hunt 02.H1 in exercise.cpp; 02.1, 02.2, 02.5, 02.6 and the bug
//             hunt 02.H2 in shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot; "Measure" in the
//             info panel compares the frame with exact (ray-cast) visibility.
// Every remedy for shadow acne trades it for something else. This lab puts six of them on one scene
// and measures both sides of the trade: acne (lit surfaces drawn shadowed) and the contact gap
// (shadows detached from their casters, "peter-panning").
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <cmath>

namespace {

class BiasLab : public wb::Lab {
 public:
  enum Method { None, Constant, Slope, PolygonOffset, FrontFaces, NormalOffset, ReceiverPlane };

  BiasLab() : Lab("scenes/bias_grazing.json") {
    useDepthBias();
    settings.addChoice(
        "bias.method", method,
        {"none", "constant", "slope", "polygon_offset", "front_faces", "normal_offset", "receiver_plane"},
        "how the depth comparison is kept from shadowing surfaces by themselves");
    settings.add("bias.slope_scale", slopeScale, 0.0f, 0.02f,
                 "slope: bias per unit of tan(angle between normal and light)");
    settings.add("bias.max", maxBias, 0.0f, 0.05f, "slope: the clamp on the slope-scaled bias");
    settings.add("bias.offset_factor", offsetFactor, 0.0f, 8.0f, "polygon_offset: glPolygonOffset factor (slope)");
    settings.add("bias.offset_units", offsetUnits, 0.0f, 256.0f, "polygon_offset: glPolygonOffset units (constant)");
    settings.add("bias.normal_offset", normalOffset, 0.0f, 4.0f, "normal_offset: how far to move, in texels");
    settings.addChoice("pcf.kernel", kernel, {"1", "3", "5", "7"}, "filter width in texels (explicit taps)");
    settings.add("light.elevation", elevation, 0.0f, 89.0f, "sun elevation in degrees (0: as in the scene file)");
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    glslExercise("02.1", "exercise.glsl", "biasedCompare(0.5, 0.5, 0.0)");
    glslExercise("02.2", "exercise.glsl", "slopeScaledBias(0.5, 0.0, 0.0, 1.0)");
    glslExercise("02.5", "exercise.glsl",
                 "normalOffsetPosition(vec3(0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), 1.0, 1.0).x");
    glslExercise("02.6", "exercise.glsl",
                 "receiverPlaneDepthBias(vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0)).x + "
                 "receiverPlaneTapDepth(0.5, vec2(0.0), vec2(0.0), vec2(0.0))");
    glslExercise("02.H2", "exercise.glsl", "0.0");  // a bug hunt: working code, never a stub
    attempt("02.3", [] { lab02::d3dDepthBias(0, 0, 0, 0, 0.5f); });
    attempt("02.4", [] { lab02::cullForDepthPass(false); });
  }

  void render() override {
    wb::Light light = scene.lights[lightIndex];
    if (elevation > 0 && light.type == wb::LightType::Directional) {  // keep the azimuth, set the height
      const glm::vec2 azimuth = glm::normalize(glm::vec2(light.direction.x, light.direction.z) + 1e-6f);
      const float e = glm::radians(elevation);
      light.direction = glm::vec3(azimuth.x * std::cos(e), -std::sin(e), azimuth.y * std::cos(e));
    }
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    shadowMap.resize(shadowMapSize());

    // PASS 1: depth from the light, with the depth-pass remedies (02.3, 02.4) when chosen, culled as 02.H1 says.
    bool ready = true;
    {
      auto timer = timePass("shadow");
      if (method == PolygonOffset)
        ready = attemptRasterState("02.3", [&] { lab02::applyRasterizerBias(offsetFactor, offsetUnits); });
      if (method == FrontFaces)
        ready = attemptRasterState("02.4", [&] { lab02::cullForDepthPass(true); });
      else
        ready = attemptRasterState("02.H1", [] { lab02::depthPassCulling(); }) && ready;
      renderShadowMap(*depthProgram, shadowMap, light, lightViewProj);
      glDisable(GL_POLYGON_OFFSET_FILL);  // back to the state every other pass expects
      glDisable(GL_CULL_FACE);
    }

    // PASS 2: the camera's view; the shader applies the comparison-side remedies (02.1, 02.2, 02.5, 02.6).
    auto timer = timePass("lighting");
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, lightViewProj, shadowMap.texture());
    p.set("u_lightDir", light.direction);
    p.set("u_lightPos", light.position);
    p.set("u_spot", light.type == wb::LightType::Spot ? 1 : 0);
    p.set("u_method", method);
    p.set("u_ready", ready ? 1 : 0);
    p.set("u_bias", method == None ? 0.0f : depthBias());
    p.set("u_slopeScale", slopeScale);
    p.set("u_maxBias", maxBias);
    p.set("u_normalOffset", normalOffset);
    // A directional map's texel is one size everywhere; a spot map's grows with the depth along its
    // axis, so the shader scales this one (the size at depth 1) by the fragment's depth.
    p.set("u_texelWorld", wb::texelWorldSize(lightViewProj, shadowMap.size()));
    p.set("u_radius", kernel);
    gpuScene->draw(p);
  }

 private:
  wb::Program* depthProgram = nullptr;  // PASS 1
  wb::Program* sceneProgram = nullptr;  // PASS 2
  wb::ShadowMap shadowMap;
  int method = Constant;      // which remedy (see the bias.method setting)
  float slopeScale = 0.002f;  // slope: bias per unit tan(theta)
  float maxBias = 0.01f;      // slope: clamp
  float offsetFactor = 1.5f;  // polygon_offset: slope factor
  float offsetUnits = 4.0f;   // polygon_offset: units of the smallest depth step
  float normalOffset = 3.0f;  // normal_offset: texels
  int kernel = 0;             // PCF radius index: width 1, 3, 5, 7
  float elevation = 0;        // degrees; 0 keeps the scene's light
};

}  // namespace

int main(int argc, char** argv) { return wb::run<BiasLab>(argc, argv); }
