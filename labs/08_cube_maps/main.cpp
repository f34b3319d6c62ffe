// Lab 08: point lights and cube shadow maps
// ---------------------------------------------------------------------------------------------
// Difficulty: 3/5. Handout: README.md beside this file.
// Exercises:  08.1 and the bug hunt 08.H1 in exercise.cpp; 08.2, 08.4 and 08.5 in
//             shaders/exercise.glsl; 08.3 in shaders/exercise_layered.geom.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// A point light shines every way, so one perspective map cannot hold its shadows: six can, one per
// face of a cube around the light. Each face is a 90° square frustum with its own up vector; the
// map stores the distance to the light, and the lookup needs no matrix at all, only the direction.
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace {

class CubeLab : public wb::Lab {
 public:
  CubeLab() : Lab("scenes/cube_lantern.json") {
    settings.addChoice("cube.filter", filter, {"hard", "pcf"}, "hard: one lookup (08.4); pcf: 3D offsets (08.5)");
    settings.addChoice("cube.pcf_samples", samples, {"16", "32", "64"}, "pcf: offsets per pixel");
    settings.add("cube.pcf_radius", radius, 0.005f, 0.2f, "pcf: the offsets' length in world units");
    settings.addChoice("cube.method", method, {"six_passes", "geometry", "instanced"},
                       "six_passes: the scene drawn once per face; geometry: once, a geometry shader (08.3) "
                       "sends each triangle to all six faces; instanced: six instances, the vertex shader "
                       "picks the face (needs GL_ARB_shader_viewport_layer_array)");
    settings.addChoice("cube.cache", cache, {"off", "on"},
                       "on: draw the six faces only when the light, the map or its shader changes (the lantern "
                       "is static); off: every frame, to time the fill");
    settings.addChoice("cube.slope_bias", slopeBias, {"off", "on"},
                       "on: the hard test adds half a texel's change of distance on sloped faces (tan of the "
                       "angle to the light) to the bias; off: the constant bias alone");
    settings.assign("shadow.map_size=512");  // per face: six of them
    useDepthBias(0.03f, 0.5f, "subtracted from the distance to the light, in world units (the map stores distances)");
    useLightFaces();
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "depth_cube.vert"}, {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
    layeredProgram = &loadProgram({{GL_VERTEX_SHADER, "depth_layered.vert"},
                                   {GL_GEOMETRY_SHADER, "exercise_layered.geom"},
                                   {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
    glslExercise("08.3", "exercise_layered.geom", "");  // (a geometry shader: its text is read)
    if (wb::hasGlExtension("GL_ARB_shader_viewport_layer_array"))
      instancedProgram =
          &loadProgram({{GL_VERTEX_SHADER, "depth_instanced.vert"}, {GL_FRAGMENT_SHADER, "depth_cube.frag"}});
    for (int f = 0; f < 2; ++f)  // one variant per filter: CUBE_FILTER is the cube.filter index
      scenePrograms[f] = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}},
                                      "#define CUBE_FILTER " + std::to_string(f) + "\n");
    glslExercise("08.2", "exercise.glsl", "cubeDepth(vec3(1.0), vec3(0.0), 10.0)");
    glslExercise("08.4", "exercise.glsl", "cubeShadow(wb_tex1, vec3(1.0), vec3(0.0), 10.0, 0.0)");
    glslExercise("08.5", "exercise.glsl", "cubePcf(wb_tex1, vec3(1.0), vec3(0.0), 10.0, 0.0, 0.05, 16)");
    attempt("08.1", [] { lab08::cubeFaceViewProj(0, glm::vec3(0), 0.1f, 10); });
  }

  void render() override {
    const wb::Light light = pointLight();
    glm::vec2 nearFar{0.01f, 1.0f};
    bool ready = attempt("08.H1", nearFar, [&] { return lab08::cubeNearFar(scene.objects, light.position); });
    for (int k = 0; k < 6; ++k)
      ready = attempt("08.1", faces[size_t(k)],
                      [&] { return lab08::cubeFaceViewProj(k, light.position, nearFar.x, nearFar.y); }) &&
              ready;
    cube.resize(shadowMapSize());

    // PASS 1: six faces, each through its own matrix, storing |p - light| / far; kept while nothing
    // it depends on changes.
    const Drawn now{light.position, nearFar, cube.size(), depthProgram->id(), alphaCutoff(), faces};
    if (ready && (!cache || !(now == drawn))) {
      auto timer = timePass("shadow");
      fillCube(light, nearFar.y);
      drawn = now;
    }
    if (ready) showLight(described(light));

    // PASS 2: the camera's view; the lookup needs only the direction from the light.
    auto timer = timePass("lighting");
    const wb::Program& p = *scenePrograms[filter];
    beginCameraPass(p, light, faces[0], 0);
    wb::bindTexture(1, cube.texture());
    p.set("u_cube", 1);
    p.set("u_lightPos", light.position);
    p.set("u_far", nearFar.y);
    p.set("u_bias", depthBias());
    p.set("u_slopeScale", slopeBias ? 0.5f : 0.0f);  // half a texel: a sample is that far from its centre
    p.set("u_radius", radius);
    p.set("u_samples", 16 << samples);
    gpuScene->draw(p);
  }

 private:
  // The six faces in six passes, in one through the geometry shader of 08.3, or in one instanced
  // pass; six passes, with a note, when the chosen way cannot run here.
  void fillCube(const wb::Light& light, float far) {
    wb::Program* p = method == 1 ? layeredProgram : method == 2 ? instancedProgram : depthProgram;
    if (method == 1 && (board().stateOf("08.3") != wb::ExerciseState::Implemented || !p->ok())) {
      warn("cube.method=geometry needs 08.3 (exercise_layered.geom): six passes for now");
      p = depthProgram;
    }
    if (method == 2 && !p) {
      warn("cube.method=instanced needs GL_ARB_shader_viewport_layer_array, which this driver lacks: six passes");
      p = depthProgram;
    }
    p->set("u_lightPos", light.position);
    p->set("u_far", far);
    if (p == depthProgram) return renderShadowMap(*p, cube, light, faces, true);
    cube.beginLayered();
    p->set("u_alphaCutoff", alphaCutoff());
    for (int k = 0; k < 6; ++k) p->set(("u_faceViewProj[" + std::to_string(k) + "]").c_str(), faces[size_t(k)]);
    gpuScene->draw(*p, wb::GpuScene::kAlbedoUnit, p == instancedProgram ? 6 : 1);
  }

  // The cube as the debug views and measurements see it, with the lookups PASS 2 makes (the same
  // Fibonacci directions as cubeOffsetDir in cube_common.glsl), so they can be repeated with rays.
  wb::LightView described(const wb::Light& light) const {
    wb::LightView v = cube.describe(light, faces, true);
    v.cubeBias = depthBias();
    const int n = 16 << samples;
    for (int k = 0; filter == 1 && k < n; ++k) {
      const float y = 1 - 2 * (float(k) + 0.5f) / float(n), r = std::sqrt(std::max(0.0f, 1 - y * y)),
                  phi = 2.39996323f * float(k);
      v.cubeOffsets.push_back(radius * glm::vec3(r * std::cos(phi), y, r * std::sin(phi)));
    }
    return v;
  }

  // The light: the chosen one if it is a point light, else the scene's first point light.
  wb::Light pointLight() {
    const wb::Light& chosen = scene.lights[size_t(lightIndex)];
    if (chosen.type == wb::LightType::Point) return chosen;
    for (const auto& l : scene.lights)
      if (l.type == wb::LightType::Point) {
        warn("lab 08 needs a point light; light.index " + std::to_string(lightIndex) +
             " is not one, so the scene's first point light is used");
        return l;
      }
    throw wb::UsageError(scene.path.string() + " has no point light; lab 08 needs one (try scenes/cube_lantern.json)");
  }

  // What the cube was last drawn with.
  struct Drawn {
    glm::vec3 light{0};
    glm::vec2 nearFar{0};
    int size = 0;
    GLuint program = 0;
    float alphaCutoff = 0;
    std::vector<glm::mat4> faces;
    bool operator==(const Drawn& o) const {
      return light == o.light && nearFar == o.nearFar && size == o.size && program == o.program &&
             alphaCutoff == o.alphaCutoff && faces == o.faces;
    }
  };
  Drawn drawn;
  wb::Program* depthProgram = nullptr;      // PASS 1, one face at a time
  wb::Program* layeredProgram = nullptr;    // PASS 1, all six faces at once (08.3)
  wb::Program* instancedProgram = nullptr;  // PASS 1, six instances (null without the extension)
  wb::Program* scenePrograms[2] = {};       // PASS 2, one per cube.filter
  wb::CubeShadowMap cube;
  std::vector<glm::mat4> faces = std::vector<glm::mat4>(6, glm::mat4(1));
  int cache = 1;         // on: a static lantern's cube is drawn once
  int method = 0;        // six passes
  int filter = 0;        // hard: 16 cube lookups a pixel (pcf) cost a CPU renderer 35 ms more
  int slopeBias = 1;     // on: no acne on faces nearly edge-on to the light (the truth suite's finding)
  int samples = 0;       // 16 offsets
  float radius = 0.04f;  // world units
};

}  // namespace

int main(int argc, char** argv) { return wb::run<CubeLab>(argc, argv); }
