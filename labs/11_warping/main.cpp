// Lab 11: perspective aliasing: warped shadow maps (LiSPSM) and splits fitted to the frame (SDSM)
// ---------------------------------------------------------------------------------------------
// Difficulty: 5/5. Handout: README.md beside this file.
// Exercises:  11.1, 11.2 and 11.5 in shaders/exercise.glsl; 11.3, 11.4 and 11.6 in exercise.cpp.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// A map's texel covers the same width of ground everywhere, but a pixel near the eye covers far less
// ground than one on the horizon: near the eye a texel shows as a block. This lab measures that, as
// texels per pixel, and spends the map where the pixels are: by warping it with a perspective along
// the view (LiSPSM), by cascades, and by fitting the cascades to the depths the frame really holds (SDSM).
#include "common/shadows/depth_bounds.hpp"
#include "common/shell/lab.hpp"
#include "common/shell/lab_stage.hpp"
#include "exercise.hpp"

#include <imgui.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>

namespace {

enum Scheme { kUniform, kLispsm, kCsm, kCsmLispsm };

class WarpLab : public wb::Lab {
 public:
  WarpLab() : Lab("scenes/csm_field.json") {
    settings.addChoice("warp.scheme", scheme, {"uniform", "lispsm", "csm", "csm_lispsm"},
                       "one map, uniform or warped by LiSPSM (11.3, 11.4); or cascades, each uniform or warped");
    settings.addChoice("warp.sdsm", sdsm, {"off", "on"},
                       "on: the maps cover the view distances the frame holds (SDSM: 11.5, 11.6), not near to far");
    settings.add("warp.strength", strength, 0.0f, 1.0f, "LiSPSM: 0 the uniform map, 1 the optimal n (11.3)");
    settings.add("warp.fade", fadeSin, 0.0f, 1.0f,
                 "LiSPSM: the sine of the angle between view and light below which the warp fades, to none at "
                 "0.02 (the dueling frusta)");
    settings.add("csm.cascades", count, 1, 4, "how many cascades (csm schemes)");
    settings.add("csm.lambda", lambda, 0.0f, 1.0f, "the practical splits' logarithmic share (11.6)");
    settings.add("warp.shadow_distance", shadowFar, 10.0f, 400.0f, "the view distance the maps cover");
    settings.addChoice("warp.view", view, {"shade", "density", "perspective", "projective"},
                       "shade; or the aliasing measure over the view: texels per pixel (11.1), its perspective or "
                       "its projective part (11.2), written where --dump-visibility writes visibility (the ground "
                       "alone; 0 elsewhere)");
    settings.add("warp.bias", biasWorld, 0.0f, 0.5f, "constant bias, metres towards the light (before any warp)");
    settings.addChoice("warp.bias_space", biasSpace, {"world", "depth"},
                       "world: warp.bias moves the point towards the light before any matrix; depth: warp.depth_bias "
                       "is taken off the map's depth after the warp (the acne a warp brings back)");
    settings.add("warp.depth_bias", biasDepth, 0.0f, 0.02f,
                 "warp.bias_space=depth: the bias in the map's depth (0..1)");
    settings.assign("shadow.map_size=1024");
    useLightFaces();
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    prepass = &loadProgram({{GL_VERTEX_SHADER, "prepass.vert"}, {GL_FRAGMENT_SHADER, "prepass.frag"}});
    reduction = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "reduce.frag"}});
    compare = wb::makeComparisonSampler();
    sceneVariant();
    glslExercise("11.1", "exercise.glsl", "texelsPerPixel(vec2(1.0), vec2(1.0), vec2(1.0)).x");
    glslExercise("11.2", "exercise.glsl", "aliasingParts(vec3(1.0), vec3(0.0, 1.0, 0.0), vec3(1.0), 1.0, 1.0).x");
    glslExercise("11.5", "exercise.glsl", "minMaxDepth(vec2(1.0), vec2(1.0), vec2(1.0), vec2(1.0)).x");
  }

  void render() override {
    const wb::Light& light = scene.lights[size_t(lightIndex)];
    // SDSM: the frame's depth bounds, reduced on the GPU (11.5), before the maps are placed.
    glm::vec2 bounds(0);
    bool ready = true;
    if (sdsm) ready = frameDepthBounds(bounds);
    const Maps m = buildMaps(light, bounds);
    ready = ready && m.ready;

    // PASS 1: one depth layer per map (the warped ones through a perspective matrix).
    maps.resize(shadowMapSize(), int(m.matrices.size()));
    {
      auto timer = timePass("shadow");
      renderShadowMap(*depthProgram, maps, light, m.matrices);
    }
    wb::LightView shown = maps.describe(light, m.matrices);
    shown.outlines = m.bodies;
    showLight(shown);

    // PASS 2: the camera's view; each pixel looks up its map, or writes the aliasing measure.
    auto timer = timePass("lighting");
    const wb::Program& p = sceneVariant();
    beginCameraPass(p, light, m.matrices[0], 0);
    wb::bindTexture(1, maps.texture());
    glBindSampler(1, compare.id());
    p.set("u_compare", 1);
    glm::vec4 far(1e9f);  // where each cascade ends for the camera pass (11.H1)
    for (int i = 0; i < 4; ++i) {
      const size_t k = std::min(size_t(i), m.matrices.size() - 1);
      p.set(("u_cascades[" + std::to_string(i) + "]").c_str(), m.matrices[k]);
      if (size_t(i) < m.switchAt.size()) far[i] = m.switchAt[size_t(i)];
    }
    p.set("u_splits", far);
    p.set("u_count", int(m.matrices.size()));
    p.set("u_ready", ready ? 1 : 0);
    p.set("u_view", camera.view());
    p.set("u_mapTexels", glm::vec2(float(shadowMapSize())));
    p.set("u_eye", glm::vec3(glm::inverse(camera.view())[3]));
    p.set("u_pixelAngle", 2 * std::tan(glm::radians(camera.pose.fov) / 2) / float(std::max(1, frameSize().y)));
    p.set("u_biasWorld", biasSpace ? 0.0f : biasWorld);
    p.set("u_biasDepth", biasSpace ? biasDepth : 0.0f);
    gpuScene->draw(p);
    glBindSampler(1, 0);
  }

  // In a measuring view, --metrics, the Measure button and a presenter step give the measure's numbers
  // over the ground instead of shadow numbers (the visibility output holds the measure).
  wb::FrameShown shown() const override {
    wb::FrameShown f = Lab::shown();
    if (view != 0) f.ownMeasure = [this] { return groundStats(); };
    return f;
  }

  // The Settings window (a window only: headless runs read nothing back) shows the measure's numbers,
  // read back every 20 frames.
  void ui() override {
    if (view == 0) return;
    if (++framesSinceStats >= 20 || stats.empty()) framesSinceStats = 0, stats = groundStats();
    ImGui::TextWrapped("%s", stats.c_str());
  }

 private:
  struct Maps {
    bool ready = true;                             // 11.4 and 11.H1 returned values (11.3, 11.6: see buildMaps)
    std::vector<float> splits;                     // C_0 .. C_N (11.6)
    std::vector<float> switchAt;                   // where the camera pass moves to the next cascade (11.H1)
    std::vector<glm::mat4> matrices;               // one light matrix per map (11.4, with 11.3's n)
    std::vector<std::array<glm::vec3, 8>> bodies;  // each map's slice of the view, for debug.frustum
  };

  // The splits (11.6) and each map's matrix (11.3, 11.4). Every exercise is called every frame,
  // whatever the others returned: the grader records each one from the lab's own run. Without 11.6's
  // splits (not done, or not N + 1 rising numbers) the cascades take even ones, and without 11.3's n the
  // maps are not warped (n = infinity): both still draw, and the info panel says which is missing, so
  // 11.4 can be judged on its own (the grader replays the missing one in both of its renders).
  Maps buildMaps(const wb::Light& light, glm::vec2 bounds) {
    const bool cascades = scheme >= kCsm, warped = scheme == kLispsm || scheme == kCsmLispsm;
    const int n = cascades ? count : 1;
    Maps m;
    const bool split =
        attempt("11.6", m.splits, [&] { return lab11::fittedSplits(bounds, camera.nearPlane, shadowFar, n, lambda); });
    if (!split || m.splits.size() != size_t(n) + 1 || !std::is_sorted(m.splits.begin(), m.splits.end())) {
      m.splits.clear();
      for (int i = 0; i <= n; ++i)
        m.splits.push_back(camera.nearPlane + (shadowFar - camera.nearPlane) * float(i) / float(n));
    }
    const bool switched =
        attempt("11.H1", m.switchAt, [&] { return lab11::switchDistances(m.splits, camera.nearPlane, shadowFar); });
    m.ready = m.ready && switched && m.switchAt.size() == size_t(n) - 1;
    const glm::vec3 forward = -glm::vec3(glm::inverse(camera.view())[2]);
    const float sinGamma = glm::length(glm::cross(forward, glm::normalize(light.direction)));
    const glm::vec3 up = sinGamma > 1e-3f                      ? forward
                         : std::abs(light.direction.y) > 0.99f ? glm::vec3(1, 0, 0)
                                                               : glm::vec3(0, 1, 0);
    const glm::mat4 lightView = glm::lookAt(glm::vec3(0), light.direction, up);  // +y: the warp axis
    const float reach = 0.5f * glm::length(scene.boundsMax - scene.boundsMin);
    for (int i = 0; i < n; ++i) {
      const std::vector<glm::vec3> body = sliceOf(m.splits[size_t(i)], m.splits[size_t(i) + 1]);
      float lo = 1e30f, hi = -1e30f;  // the body's extent along the warp axis
      for (const glm::vec3& b : body) {
        const float y = (lightView * glm::vec4(b, 1)).y;
        lo = std::min(lo, y), hi = std::max(hi, y);
      }
      float near = std::numeric_limits<float>::infinity();
      attempt("11.3", near, [&] { return lab11::warpNear(m.splits[size_t(i)], hi - lo, sinGamma, strength, fadeSin); });
      if (!warped || !(near < 64 * (hi - lo))) near = std::numeric_limits<float>::infinity();  // (float: see README)
      glm::mat4 matrix(1);
      const bool haveMatrix = attempt("11.4", matrix, [&] { return lab11::warpMatrix(lightView, body, near, reach); });
      m.ready = m.ready && haveMatrix;
      m.matrices.push_back(matrix);
      std::array<glm::vec3, 8> corners{};
      std::copy(body.begin(), body.end(), corners.begin());
      m.bodies.push_back(corners);
    }
    return m;
  }

  // The camera's frustum between view distances d0 and d1: its eight corners in the world.
  std::vector<glm::vec3> sliceOf(float d0, float d1) const {
    const float aspect = float(frameSize().x) / float(std::max(1, frameSize().y));
    const glm::mat4 toWorld =
        glm::inverse(glm::perspective(glm::radians(camera.pose.fov), aspect, d0, d1) * camera.view());
    std::vector<glm::vec3> out;
    for (int k = 0; k < 8; ++k) {
      const glm::vec4 p = toWorld * glm::vec4(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1, 1);
      out.push_back(glm::vec3(p) / p.w);
    }
    return out;
  }

  // SDSM's pre-pass and reduction (11.5): false while 11.5 is a stub.
  bool frameDepthBounds(glm::vec2& bounds) {
    auto timer = timePass("depth bounds");
    depthBounds.begin(frameSize());
    prepass->set("u_viewProj",
                 camera.projection(float(frameSize().x) / float(std::max(1, frameSize().y))) * camera.view());
    prepass->set("u_view", camera.view());
    prepass->set("u_alphaCutoff", alphaCutoff());
    gpuScene->draw(*prepass);
    bounds = depthBounds.reduce(*reduction);
    bindFrameTarget();
    return !(bounds.x <= -1e29f || bounds.y <= -1e29f);
  }

  // The measure over the ground: the worst (fewest texels per pixel), the median and the spread.
  std::string groundStats() const {
    glFinish();
    const wb::LabStage& host = stage();  // the frame target the lab drew into
    const wb::FloatImage v = host.target.readVisibility();
    const std::vector<glm::vec4> at = host.target.readPositions();
    std::vector<float> ground;
    bool todo = false;
    for (size_t k = 0; k < v.pixels.size() && k < at.size(); ++k) {
      todo = todo || v.pixels[k] <= -1e29f;
      if (at[k].w != 0 && v.pixels[k] > 0) ground.push_back(v.pixels[k]);
    }
    const char* what[] = {"", "texels per pixel", "perspective part", "projective part"};
    if (todo) return std::string(what[view]) + ": not measured, an exercise the frame needs is not implemented yet";
    if (ground.empty()) return std::string(what[view]) + " over the ground: no ground in view";
    std::sort(ground.begin(), ground.end());
    char line[200];
    std::snprintf(line, sizeof line, "%s over the ground: worst %.3g, median %.3g, spread (max/min) %.3g, %zu pixels",
                  what[view], ground.front(), ground[ground.size() / 2], ground.back() / ground.front(), ground.size());
    return line;
  }

  // PASS 2's program for the view and the number of maps (one per combination: llvmpipe runs both
  // sides of a branch, and every turn of a loop, even on a uniform).
  const wb::Program& sceneVariant() {
    const char* views[] = {"", "#define WB_VIEW_DENSITY\n", "#define WB_VIEW_PERSPECTIVE\n",
                           "#define WB_VIEW_PROJECTIVE\n"};
    const bool cascades = scheme >= kCsm;
    wb::Program*& p = scenePrograms[2 * view + (cascades ? 1 : 0)];
    if (!p)
      p = &loadProgram({{GL_VERTEX_SHADER, "warp.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}},
                       std::string(views[view]) + (cascades ? "#define WB_CASCADES\n" : ""));
    return *p;
  }

  wb::Program* depthProgram = nullptr;  // PASS 1
  wb::Program* prepass = nullptr;       // SDSM's depth pre-pass
  wb::Program* reduction = nullptr;     // SDSM's reduction (11.5)
  std::map<int, wb::Program*> scenePrograms;
  wb::ShadowMapArray maps;
  wb::DepthBounds depthBounds;
  wb::Sampler compare;
  int scheme = kLispsm;
  int sdsm = 0;
  float strength = 1, fadeSin = 0.5f;
  int count = 3;
  float lambda = 0.75f;
  float shadowFar = 120;
  int view = 0;
  float biasWorld = 0.1f;
  int biasSpace = 0;  // world
  float biasDepth = 0.002f;
  int framesSinceStats = 0;
  std::string stats;
};

}  // namespace

int main(int argc, char** argv) { return wb::run<WarpLab>(argc, argv); }
