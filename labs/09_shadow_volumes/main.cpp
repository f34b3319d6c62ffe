// Lab 09: stencil shadow volumes
// ---------------------------------------------------------------------------------------------
// Difficulty: 4/5. Handout: README.md beside this file.
// Exercises:  09.1, 09.4, 09.5 and 09.6 in exercise.cpp; 09.2 and 09.3 in shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// No map at all: every caster's silhouette, as the light sees it, is pushed to infinity, and the
// stencil buffer counts, per pixel, how many of those volumes the pixel lies in. Zero means lit.
// The shadows are exact to the pixel; the price is fill rate and a pass over the geometry.
#include "common/shell/lab.hpp"
#include "common/truth/ground_truth.hpp"
#include "exercise.hpp"

#include <array>
#include <memory>
#include <string>

namespace {

class VolumeLab : public wb::Lab {
 public:
  VolumeLab() : Lab("scenes/volumes_casters.json", wb::ShadowKind::Geometry) {
    settings.addChoice("volume.method", method, {"auto", "zpass", "zfail"},
                       "auto: z-fail for the casters whose volume may hold the camera's near plane (09.6), "
                       "z-pass for the rest; zpass or zfail: one method for every caster");
    settings.addChoice("shadow.technique", technique, {"volumes", "shadow_map", "ray_traced"},
                       "volumes: this lab; shadow_map: a 2048² map, slope-scaled bias and 2x2 PCF, to compare; "
                       "ray_traced: a ray per pixel to the first surface and one to the light, on the CPU");
    settings.add("ray_traced.threads", threads, 0, 64, "ray_traced: CPU threads (0: every core)");
    settings.add("debug.volumes", showVolumes, "draw the volumes translucent over the frame");
    settings.add("debug.silhouettes", showSilhouettes, "draw the silhouette edges as lines");
    settings.add("debug.stencil", showCounts, "colour each pixel by its stencil count (0 black, then 1, 2, 3, ...)");
  }

 protected:
  void init() override {
    sceneProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/scene.vert"}, {GL_FRAGMENT_SHADER, "scene.frag"}});
    volumeProgram = &loadProgram(
        {{GL_VERTEX_SHADER, "volume.vert"}, {GL_GEOMETRY_SHADER, "volume.geom"}, {GL_FRAGMENT_SHADER, "flat.frag"}});
    edgeProgram = &loadProgram({{GL_VERTEX_SHADER, "volume.vert"},
                                {GL_GEOMETRY_SHADER, "silhouette.geom"},
                                {GL_FRAGMENT_SHADER, "flat.frag"}});
    flatProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "flat.frag"}});
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    glslExercise("09.2", "exercise.glsl",
                 "facesLight(vec3(0.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec4(0.0, 0.0, 1.0, 0.0)) + "
                 "silhouetteEdge(vec3(0.0), vec3(1.0, 0.0, 0.0), vec3(0.0, -1.0, 0.0), vec4(0.0, 0.0, 1.0, 0.0))");
    glslExercise("09.3", "exercise.glsl", "extrudeToInfinity(vec3(1.0), vec4(0.0, 2.0, 0.0, 1.0)).x");
    glslExercise("09.H1", "exercise.glsl", "nearCapVertex(mat4(1.0), vec3(0.0)).x");  // a bug hunt: never a stub
    int leafy = 0;  // alpha-tested objects: their triangles' outline is not their leaves'
    for (const auto& o : scene.objects) leafy += !o.castsVolume && !o.material.texture.empty();
    if (leafy)
      warn(std::to_string(leafy) +
           " alpha-tested object(s) cast no shadow volume: a volume follows triangles, and "
           "their leaves are holes in the texture, not in the triangles");
    for (const auto& o : scene.objects) bounds.push_back(wb::worldBounds(o));  // the scene does not move
    for (size_t k = 0; k < scene.objects.size(); ++k) {
      const wb::SceneObject& o = scene.objects[k];
      if (!o.castsVolume) continue;
      std::vector<uint32_t> adjacency;
      adjacent_ = attempt("09.1", adjacency, [&] { return lab09::buildAdjacency(o.mesh.weldedIndices); }) && adjacent_;
      if (!adjacent_) continue;
      try {
        gpuScene->setIndices(k, adjacency, GL_TRIANGLES_ADJACENCY);
      } catch (const std::exception& e) {
        setStatus("09.1", wb::ExerciseState::Failed, std::string("its indices cannot be drawn: ") + e.what());
        adjacent_ = false;
      }
    }
  }

  void render() override {
    const wb::Light& light = scene.lights[size_t(lightIndex)];
    const glm::vec4 l =
        light.type == wb::LightType::Directional ? glm::vec4(-light.direction, 0) : glm::vec4(light.position, 1);
    wb::LightView shown;
    shown.light = light;
    showLight(shown);  // no map: the measurement casts its rays to this light
    // 09.4, 09.5 and (with auto) 09.6 are called every frame, whatever the others do, and 09.1 once in
    // init(): the grader records each one from the lab's own run.
    std::vector<uint32_t> zpass, zfail;
    const bool zpassOk = attempt("09.4", zpass, [] { return packed(lab09::zPassSetup()); });
    const bool zfailOk = attempt("09.5", zfail, [] { return packed(lab09::zFailSetup()); });
    const std::vector<bool> useZFail = countingPerCaster(l);
    const bool ready = adjacent_ && zpassOk && zfailOk && board().stateOf("09.2") == wb::ExerciseState::Implemented &&
                       board().stateOf("09.3") == wb::ExerciseState::Implemented;
    if (technique == 1) return renderShadowMapped(light);

    // PASS 1: the scene's depth, lit by the ambient term only (visibility 0).
    {
      auto timer = timePass("depth");
      drawScene(light, false, !ready && technique == 0);
    }
    if (technique == 2) return renderRayTraced(light);
    if (!ready) return;  // a stub: the frame shows the not-implemented pattern

    // PASS 2: the volumes into the stencil buffer only: no colour, no depth writes, depth clamp on
    // so the caps at infinity are not clipped away.
    {
      auto timer = timePass("volumes");
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      glDepthMask(GL_FALSE);
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_ALWAYS, 0, 0xFF);
      glDisable(GL_CULL_FACE);
      drawVolumes(l, zpass, zfail, useZFail);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    // PASS 3: the light, where the count is 0.
    {
      auto timer = timePass("lighting");
      glStencilFunc(GL_EQUAL, 0, 0xFF);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      glDepthFunc(GL_LEQUAL);
      drawScene(light, true, false);
      glDepthFunc(GL_LESS);
    }
    drawDebugViews(l, zpass, zfail);
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
  }

 private:
  // A StencilSetup as the numbers the exercise tape records: front ops, back ops, caps.
  static std::vector<uint32_t> packed(const lab09::StencilSetup& s) {
    return {s.front.stencilFail, s.front.depthFail, s.front.depthPass, s.back.stencilFail,
            s.back.depthFail,    s.back.depthPass,  s.caps ? 1u : 0u};
  }

  void drawScene(const wb::Light& light, bool lit, bool todo, const glm::mat4& lightViewProj = glm::mat4(1),
                 GLuint shadowMap = 0) {
    const wb::Program& p = *sceneProgram;
    beginCameraPass(p, light, lightViewProj, shadowMap);
    p.set("u_lit", lit ? 1 : 0);
    p.set("u_todo", todo ? 1 : 0);
    p.set("u_technique", technique);
    p.set("u_rayTraced", 1);  // (the shadow map is on unit 0)
    gpuScene->draw(p);
  }

  // The comparison: a 2048² shadow map with slope-scaled bias, looked up with hardware 2x2 PCF.
  void renderShadowMapped(const wb::Light& light) {
    const glm::mat4 lightViewProj = wb::lightViewProj(light, scene);
    map.resize(2048);
    {
      auto timer = timePass("shadow_map");
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.5f, 2.0f);
      renderShadowMap(*depthProgram, map, light, lightViewProj);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    auto timer = timePass("lighting");
    if (!compare.id()) compare = wb::makeComparisonSampler();
    glBindSampler(0, compare.id());
    drawScene(light, true, false, lightViewProj, map.texture());
    glBindSampler(0, 0);
  }

  // The ground truth as a render mode: the CPU casts a ray through every pixel and one to the light
  // (on ray_traced.threads threads); the lighting pass reads the result.
  void renderRayTraced(const wb::Light& light) {
    const glm::ivec2 size = frameSize();
    {
      auto timer = timePass("ray_tracing_cpu");
      if (!rays) rays = std::make_unique<wb::RayScene>(scene, alphaCutoff());
      const wb::FloatImage v = wb::rayTracedVisibility(*rays, light, glm::inverse(viewProj()), size.x, size.y, threads);
      if (traced.id() == 0 || tracedSize != size)
        traced = wb::makeTexture2D(GL_R32F, size.x, size.y), tracedSize = size;
      wb::uploadTexture2D(traced.id(), 0, 0, size.x, size.y, GL_RED, GL_FLOAT, v.pixels.data());
    }
    auto timer = timePass("lighting");
    wb::bindTexture(1, traced.id());
    glDepthFunc(GL_LEQUAL);
    drawScene(light, true, false);
    glDepthFunc(GL_LESS);
  }

  // Per object, whether its volume is counted by z-fail: the setting, or with `auto` 09.6's answer
  // for its bounding box.
  std::vector<bool> countingPerCaster(const glm::vec4& l) {
    const std::array<glm::vec3, 4> quad = nearQuad();
    std::vector<bool> zfail(scene.objects.size(), method == 2);
    for (size_t k = 0; k < scene.objects.size() && method == 0; ++k) {
      if (!scene.objects[k].castsVolume) continue;
      const auto& box = bounds[k];
      bool inside = true;  // (a failed call leaves the safe answer)
      attempt("09.6", inside, [&] { return lab09::nearPlaneMayBeShadowed(quad, l, box.first, box.second); });
      zfail[k] = inside;
    }
    return zfail;
  }

  // Every caster's volume, counted by z-pass or z-fail as `useZFail` says.
  void drawVolumes(const glm::vec4& l, const std::vector<uint32_t>& zpass, const std::vector<uint32_t>& zfail,
                   const std::vector<bool>& useZFail) {
    const wb::Program& p = *volumeProgram;
    p.use();
    p.set("u_viewProj", viewProj());
    p.set("u_light", l);
    for (size_t k = 0; k < scene.objects.size(); ++k) {
      if (!scene.objects[k].castsVolume) continue;
      const std::vector<uint32_t>& s = useZFail[k] ? zfail : zpass;
      glStencilOpSeparate(GL_FRONT, s[0], s[1], s[2]);
      glStencilOpSeparate(GL_BACK, s[3], s[4], s[5]);
      p.set("u_caps", int(s[6]));
      gpuScene->drawObjectWelded(k, p, true);
    }
  }

  // The near plane's rectangle in world space, from the inverse of the view-projection.
  std::array<glm::vec3, 4> nearQuad() const {
    const glm::mat4 inv = glm::inverse(viewProj());
    std::array<glm::vec3, 4> q;
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (size_t c = 0; c < 4; ++c) {
      const glm::vec4 w = inv * glm::vec4(corners[c], -1, 1);
      q[c] = glm::vec3(w) / w.w;
    }
    return q;
  }

  // Debug views, over the lit frame: the stencil count as colours, the volumes translucent, the
  // silhouette edges as lines.
  void drawDebugViews(const glm::vec4& l, const std::vector<uint32_t>& zpass, const std::vector<uint32_t>& zfail) {
    if (showCounts) {
      const glm::vec4 colours[4] = {
          {0.9f, 0.8f, 0.1f, 1}, {0.9f, 0.4f, 0.1f, 1}, {0.8f, 0.1f, 0.2f, 1}, {0.5f, 0.1f, 0.6f, 1}};
      wb::VertexArray empty = wb::makeEmptyVertexArray();
      glBindVertexArray(empty.id());
      glDisable(GL_DEPTH_TEST);
      flatProgram->use();
      for (int n = 0; n < 5; ++n) {  // 0, 1, 2, 3, and 4 or more
        glStencilFunc(n < 4 ? GL_EQUAL : GL_LEQUAL, n, 0xFF);
        flatProgram->set("u_rgba", n == 0 ? glm::vec4(0, 0, 0, 1) : colours[n - 1]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
      }
      glEnable(GL_DEPTH_TEST);
    }
    glDisable(GL_STENCIL_TEST);
    if (showVolumes) {
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      volumeProgram->set("u_rgba", glm::vec4(0.2f, 0.5f, 1.0f, 0.15f));
      const std::vector<uint32_t>& s = method == 1 ? zpass : zfail;
      volumeProgram->set("u_caps", int(s[6]));
      for (size_t k = 0; k < scene.objects.size(); ++k)
        if (scene.objects[k].castsVolume) gpuScene->drawObjectWelded(k, *volumeProgram, true);
      glDisable(GL_BLEND);
    }
    if (showSilhouettes) {
      edgeProgram->use();
      edgeProgram->set("u_viewProj", viewProj());
      edgeProgram->set("u_light", l);
      edgeProgram->set("u_rgba", glm::vec4(1, 0.9f, 0.2f, 1));
      glDisable(GL_DEPTH_TEST);
      for (size_t k = 0; k < scene.objects.size(); ++k)
        if (scene.objects[k].castsVolume) gpuScene->drawObjectWelded(k, *edgeProgram, false);
      glEnable(GL_DEPTH_TEST);
    }
  }

  wb::Program* sceneProgram = nullptr;   // PASSES 1 and 3
  wb::Program* volumeProgram = nullptr;  // PASS 2 (and debug.volumes)
  wb::Program* edgeProgram = nullptr;    // debug.silhouettes
  wb::Program* flatProgram = nullptr;    // debug.stencil
  wb::Program* depthProgram = nullptr;   // shadow_map: the map
  wb::ShadowMap map;                     // shadow_map
  wb::Sampler compare;                   // shadow_map: 2x2 PCF
  std::unique_ptr<wb::RayScene> rays;    // ray_traced
  wb::Texture traced;                    // ray_traced: the CPU's visibility
  glm::ivec2 tracedSize{0};
  int technique = 0;                                    // volumes
  int threads = 0;                                      // every core
  std::vector<std::pair<glm::vec3, glm::vec3>> bounds;  // each object's world-space box, for 09.6
  bool adjacent_ = true;                                // 09.1 gave every caster its adjacency
  int method = 0;                                       // auto
  bool showVolumes = false, showSilhouettes = false, showCounts = false;
};

}  // namespace

int main(int argc, char** argv) { return wb::run<VolumeLab>(argc, argv); }
