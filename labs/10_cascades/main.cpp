// Lab 10: cascaded shadow maps
// ---------------------------------------------------------------------------------------------
// Difficulty: 4/5. Handout: README.md beside this file.
// Exercises:  10.1 - 10.4 and the bug hunt 10.H2 in exercise.cpp; 10.5, 10.6 and the bug hunt 10.H1 in
//             shaders/exercise.glsl.
// Controls:   drag to orbit, wheel to zoom, 1-9 camera bookmarks, F12 screenshot.
// One map over a 200 m field spends its texels evenly, so the bench at your feet gets as few as the
// trees on the horizon. Cascades cut the view into slices, near ones short and far ones long, and give
// each slice a map of its own: resolution where the camera needs it.
#include "common/shadows/prefilter.hpp"
#include "common/shell/lab.hpp"
#include "exercise.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace {

class CascadeLab : public wb::Lab {
 public:
  CascadeLab() : Lab("scenes/csm_field.json") {
    settings.add("csm.cascades", count, 1, 4, "how many cascades (map layers)");
    settings.addChoice("csm.split", scheme, {"uniform", "logarithmic", "practical"}, "how the view is cut (10.1)");
    settings.add("csm.lambda", lambda, 0.0f, 1.0f, "practical: the logarithmic share");
    settings.addChoice("csm.stable", stable, {"off", "on"}, "on: sphere fit and whole texels (10.4); off: crop (10.3)");
    settings.addChoice("csm.select", select, {"interval", "map"}, "choose the cascade by view depth or by map (10.5)");
    settings.add("csm.blend", band, 0.0f, 0.5f, "the blend band before each split, a share of the cascade (10.6)");
    settings.addChoice("csm.blend_mode", smooth, {"dither", "smooth"},
                       "in the band: one lookup, the next cascade where the weight beats a per-pixel threshold; "
                       "or both cascades' lookups, mixed (a second lookup on every pixel on llvmpipe)");
    settings.add("csm.shadow_distance", shadowFar, 10.0f, 400.0f, "the view distance the cascades cover");
    settings.addChoice("csm.kernel", kernel, {"1", "3", "5", "7"},
                       "PCF taps per side (each a 2x2 comparison), spaced by cascade 0's texel in world units in "
                       "every cascade, so softness stays the same across the splits");
    settings.addChoice("csm.filter", filter, {"pcf", "esm", "vsm", "evsm"},
                       "pcf: a comparing lookup per tap; esm, vsm, evsm: your functions of lab 04, 05 or 06 on a "
                       "map prefiltered per cascade (blur width csm.kernel, in cascade 0's texels, kept in world "
                       "units)");
    settings.add("esm.c", esmC, 1.0f, 88.0f, "csm.filter=esm: the exponent (lab 04)");
    settings.add("evsm.c_positive", cPos, 1.0f, 42.0f, "csm.filter=evsm: the positive warp's exponent (lab 06)");
    settings.add("evsm.c_negative", cNeg, 1.0f, 42.0f, "csm.filter=evsm: the negative warp's exponent (lab 06)");
    settings.add("vsm.min_variance", minVariance, 0.0f, 0.001f, "csm.filter=vsm or evsm: the smallest variance");
    settings.add("vsm.bleeding_reduction", bleeding, 0.0f, 0.9f, "csm.filter=vsm or evsm: light-bleeding reduction");
    settings.addChoice("csm.cull", cull, {"off", "on"},
                       "on: each cascade's map draws only the objects that concern it (10.H2), not every object "
                       "(csm.filter=pcf; a filtered map needs the receivers too)");
    settings.add("csm.freeze", freeze, "keep the cascades (and their slices) where they are while the camera moves");
    settings.addChoice("measure.region", region, {"all", "c0", "c1", "c2", "c3", "splits", "rest"},
                       "the pixels --metrics counts: all, one cascade, those within 10% of a cascade's range of an "
                       "inner split, or the rest (the others are dimmed)");
    settings.add("debug.cascades", showCascades, "tint each cascade: red, green, blue, yellow");
    settings.add("debug.density", showDensity,
                 "aliasing: colour by shadow-map texels per screen pixel (red many, dark few), and write that "
                 "number where --dump-visibility writes visibility");
    settings.add("path.step", pathStep, 0, 10000,
                 "0: the camera as you move it; k: step k of the fixed path from bookmark 1 (a slow dolly, a "
                 "sub-texel strafe, a small turn)");
    settings.add("path.matrices_step", matricesStep, -1, 10000,
                 "-1: the cascades follow the camera; k: they are built for path step k (shimmer: render step k "
                 "with step k - 1's cascades and compare)");
    settings.assign("shadow.map_size=1024");
    useDepthBias(0.002f);
    useLightFaces();
  }

 protected:
  void init() override {
    depthProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, "wb/depth.frag"}});
    compare = wb::makeComparisonSampler();
    for (const auto& o : scene.objects) boxes.push_back(wb::worldBounds(o));  // the scene does not move
    sceneVariant();  // the defaults' variant now, so a shader error shows at once
    glslExercise("10.5", "exercise.glsl",
                 "cascadeByInterval(1.0, vec4(2.0), 4) < 0 || cascadeByMap(vec3(0.0), mat4[4](mat4(1.0), mat4(1.0), "
                 "mat4(1.0), mat4(1.0)), 4) < 0 ? WB_TODO : 0.0");
    glslExercise("10.6", "exercise.glsl", "blendWeight(1.0, 0.0, 2.0, 0.1)");
    glslExercise("10.H1", "exercise.glsl", "0.0");  // a bug hunt: working code, never a stub
    attempt("10.1", [] { lab10::splitDistances(1, 10, 2, lab10::SplitScheme::Uniform, 0); });
  }

  // debug.density writes texels per pixel where the visibility goes: no shadow numbers for it (lab 11
  // measures it over the ground).
  wb::FrameShown shown() const override {
    wb::FrameShown f = Lab::shown();
    if (showDensity)
      f.ownMeasure = [] { return std::string("debug.density: texels per pixel (lab 11 gives its numbers)"); };
    return f;
  }

  void render() override {
    if (pathStep > 0) camera.pose = poseAt(pathStep);
    const wb::Light& light = scene.lights[size_t(lightIndex)];
    Cascades c = buildCascades(light);
    if (freeze && frozen.ready && frozen.matrices.size() == size_t(count))
      c = frozen;
    else
      frozen = c;

    // PASS 1: one depth layer per cascade (or a filtered map per cascade, csm.filter=esm, vsm, evsm).
    maps.resize(shadowMapSize(), count);  // (a filtered run shows this array's slot in the debug views)
    if (c.ready) {
      if (filter)
        renderFiltered(light, c.matrices);
      else {
        auto timer = timePass("shadow");
        renderShadowMap(*depthProgram, maps, light, c.matrices, cull ? &c.casters : nullptr);
      }
      wb::LightView shown = maps.describe(light, c.matrices);
      shown.outlines = c.slices;  // debug.frustum: each cascade's box, and its slice of the view
      showLight(shown);
    }

    // PASS 2: the camera's view; each pixel picks its cascade (10.5) and blends at the splits (10.6).
    auto timer = timePass("lighting");
    const wb::Program& p = sceneVariant();
    beginCameraPass(p, light, c.matrices[0], 0);
    wb::bindTexture(1, maps.texture());
    wb::bindTexture(2, maps.texture());
    wb::bindTexture(3, moments.texture());
    p.set("u_maps", 1), p.set("u_compare", 2), p.set("u_moments", 3);
    glBindSampler(2, compare.id());
    setCascadeUniforms(p, c);
    p.set("u_view", camera.view());
    p.set("u_band", band);
    p.set("u_bias", depthBias());
    p.set("u_kernel", 2 * kernel + 1);
    p.set("u_region", region);
    p.set("u_minVariance", minVariance);
    p.set("u_c", filter == 1 ? esmC : cPos);
    p.set("u_cNeg", cNeg);
    p.set("u_bleeding", bleeding);
    gpuScene->draw(p);
    glBindSampler(2, 0);
  }

 private:
  struct Cascades {
    bool ready = false;                            // every exercise the frame needs returned a value
    std::vector<float> splits;                     // C_0 .. C_N (10.1)
    std::vector<glm::mat4> matrices;               // one light matrix per cascade (10.3 or 10.4)
    std::vector<std::array<glm::vec3, 8>> slices;  // each cascade's slice (10.2's corners), for debug.frustum
    std::vector<std::vector<bool>> casters;        // csm.cull: per cascade, the objects it draws (10.H2)
  };

  // The objects one cascade draws with csm.cull=on (10.H2, called every frame so the grader sees it):
  // object k where the list holds k, in `drawn`. Indices past the scene's objects are ignored. False
  // when the call failed: with csm.cull=on the frame then shows the exercise unfinished, as for any
  // other (drawing every object instead let a hunt that gives up pass its scenes).
  bool castersOf(const glm::mat4& cascade, const glm::mat4& view, float sliceNear, float sliceFar,
                 std::vector<bool>& drawn) {
    std::vector<uint32_t> kept;
    drawn.assign(boxes.size(), false);
    if (!attempt("10.H2", kept, [&] { return lab10::castersFor(cascade, view, sliceNear, sliceFar, boxes); }))
      return false;
    for (uint32_t k : kept)
      if (k < drawn.size()) drawn[k] = true;
    return true;
  }

  // The exercise chain 10.1 -> 10.2 -> 10.3 and 10.4, for the camera (or path step
  // path.matrices_step). Every exercise is called every frame, whatever the others returned: the
  // grader records each one from the lab's own run. Placeholders (never drawn) stand in for a
  // missing 10.1 or 10.2.
  Cascades buildCascades(const wb::Light& light) {
    wb::OrbitCamera fitted = camera;  // the camera the cascades are built for
    if (matricesStep >= 0) fitted.pose = poseAt(matricesStep);
    const float nearPlane = fitted.nearPlane;
    Cascades c;
    c.ready = attempt("10.1", c.splits, [&] {
      return lab10::splitDistances(nearPlane, shadowFar, count, lab10::SplitScheme(scheme), lambda);
    });
    c.ready = c.ready && c.splits.size() == size_t(count) + 1;
    if (!c.ready) {
      c.splits.clear();
      for (int i = 0; i <= count; ++i) c.splits.push_back(nearPlane + float(i));
    }
    const glm::mat4 lightView = glm::lookAt(glm::vec3(0), light.direction, upFor(light.direction));
    const float reach = 0.5f * glm::length(scene.boundsMax - scene.boundsMin);
    for (size_t i = 0; i < size_t(count); ++i) {
      std::array<glm::vec3, 8> corners{};
      for (int k = 0; k < 8; ++k)
        corners[size_t(k)] = fitted.pose.target + glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      c.ready = attempt("10.2", corners,
                        [&] {
                          return lab10::sliceCorners(glm::inverse(fitted.view()), glm::radians(fitted.pose.fov),
                                                     aspect(), c.splits[i], c.splits[i + 1]);
                        }) &&
                c.ready;
      glm::mat4 cropped(1), stabilised(1);  // both fits every frame; csm.stable picks one
      const bool crop = attempt("10.3", cropped, [&] { return lab10::fitCascade(lightView, corners, reach); });
      const bool sphere =
          attempt("10.4", stabilised, [&] { return lab10::stableCascade(lightView, corners, shadowMapSize(), reach); });
      c.matrices.push_back(stable ? stabilised : cropped);
      c.ready = (stable ? sphere : crop) && c.ready;
      c.slices.push_back(corners);
      c.casters.emplace_back();
      const bool culled = castersOf(c.matrices.back(), fitted.view(), c.splits[i], c.splits[i + 1], c.casters.back());
      c.ready = (culled || !cull) && c.ready;
    }
    return c;
  }

  // PASS 1 with csm.filter=esm, vsm or evsm: each cascade's map by that lab's writer (your functions),
  // blurred by csm.kernel texels of cascade 0 in world units (fewer texels in the coarser cascades),
  // copied into one array.
  void renderFiltered(const wb::Light& light, const std::vector<glm::mat4>& matrices) {
    const char* writers[] = {"", "moments_esm.frag", "moments_vsm.frag", "moments_evsm.frag"};
    const GLenum formats[] = {0, GL_R32F, GL_RG32F, GL_RGBA32F};
    const float far[4][4] = {{},
                             {std::exp(esmC), 0, 0, 0},
                             {1, 1, 0, 0},  // the stored values of depth 1
                             {std::exp(cPos), std::exp(2 * cPos), -std::exp(-cNeg), std::exp(-2 * cNeg)}};
    wb::Program*& writer = writerPrograms[size_t(filter)];
    if (!writer) {  // only now: lab 10 must run whatever state labs 04-06's exercise.glsl are in
      writer = &loadProgram({{GL_VERTEX_SHADER, "wb/depth.vert"}, {GL_FRAGMENT_SHADER, writers[filter]}});
      if (!blurProgram)
        blurProgram = &loadProgram({{GL_VERTEX_SHADER, "wb/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "wb/blur.frag"}});
    }
    writer->set("u_c", filter == 1 ? esmC : cPos);
    writer->set("u_cNeg", cNeg);
    moments.resize(shadowMapSize(), count, formats[filter]);
    const float width0 = float(2 * kernel + 1) / scaleOf(matrices[0]).x;
    for (int i = 0; i < count; ++i) {
      const int half = int(std::lround(0.5f * (width0 * scaleOf(matrices[size_t(i)]).x - 1)));
      moments.layer(i).resize(shadowMapSize(), {formats[filter], 1 + 2 * std::clamp(half, 0, 3), false, false});
      renderFilteredShadowMap(*writer, moments.layer(i), far[filter], *blurProgram, light, matrices[size_t(i)]);
      moments.copy(i);
    }
  }

  // The cascades' matrices, splits and tap spacing (csm.kernel: cascade 0's texel in world units).
  void setCascadeUniforms(const wb::Program& p, const Cascades& c) {
    for (int i = 0; i < 4; ++i) {
      const size_t k = size_t(std::min(i, count - 1));
      const std::string n = "[" + std::to_string(i) + "]";
      p.set(("u_uvPerWorld" + n).c_str(), 0.5f * scaleOf(c.matrices[k]));
      p.set(("u_cascades" + n).c_str(), c.matrices[k]);
      p.set(("u_splits" + n).c_str(), c.ready ? c.splits[k + 1] : 1e9f);
      p.set(("u_splitNear" + n).c_str(), c.ready ? c.splits[k] : 0.0f);
    }
    p.set("u_tapWorld", 2.0f / std::max(1e-6f, scaleOf(c.matrices[0]).x * float(shadowMapSize())));
    p.set("u_ready", c.ready ? 1 : 0);
    p.set("u_count", count);
  }

  // Light clip units per world unit along the map's x and y: the rows of the matrix's 3x3 part.
  static glm::vec2 scaleOf(const glm::mat4& m) {
    return {glm::length(glm::vec3(m[0][0], m[1][0], m[2][0])), glm::length(glm::vec3(m[0][1], m[1][1], m[2][1]))};
  }

  // Step k of the fixed camera path: from bookmark 1, 4 cm forward, 1.1 cm sideways and 0.03 degrees
  // round per step (a strafe of a small fraction of a near cascade's texel).
  wb::CameraBookmark poseAt(int step) const {
    wb::CameraBookmark p = scene.cameras.front();
    p.target += float(step) * glm::vec3(0.011f, 0, -0.04f);
    p.yaw += 0.03f * float(step);
    return p;
  }

  // PASS 2's program for the current options: llvmpipe runs both sides of a branch even on a uniform,
  // so each option is compiled in (scene.frag's #defines), one program per combination, when first used.
  const wb::Program& sceneVariant() {
    std::string defines;
    if (select) defines += "#define WB_SELECT_MAP\n";
    if (smooth) defines += "#define WB_SMOOTH_BLEND\n";
    if (showDensity) defines += "#define WB_DENSITY\n";
    if (showCascades) defines += "#define WB_TINT\n";
    if (region) defines += "#define WB_REGION\n";
    if (kernel == 0) defines += "#define WB_ONE_TAP\n";
    const char* entries[] = {"scene.frag", "scene_esm.frag", "scene_vsm.frag", "scene_evsm.frag"};
    wb::Program*& p = scenePrograms[defines + entries[filter]];
    if (!p) p = &loadProgram({{GL_VERTEX_SHADER, "cascades.vert"}, {GL_FRAGMENT_SHADER, entries[filter]}}, defines);
    return *p;
  }

  static glm::vec3 upFor(const glm::vec3& d) { return std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0); }
  float aspect() const { return float(frameSize().x) / float(std::max(1, frameSize().y)); }

  wb::Program* depthProgram = nullptr;           // PASS 1
  std::array<wb::Program*, 4> writerPrograms{};  // PASS 1 of csm.filter=esm, vsm, evsm (by index)
  wb::Program* blurProgram = nullptr;
  std::map<std::string, wb::Program*> scenePrograms;  // PASS 2, by #defines
  wb::ShadowMapArray maps;
  wb::FilteredShadowMapArray moments;  // csm.filter=esm, vsm, evsm
  wb::Sampler compare;                 // 2x2 PCF in the sampler
  int count = 3;                       // cascades
  int scheme = 2;                      // practical
  float lambda = 0.75f;                // between seed 000's 0.6 and the common 0.95
  int stable = 1;                      // on
  int select = 0;                      // interval
  float band = 0.1f;                   // 10% blend band
  int smooth = 0;                      // dithered
  float shadowFar = 120;               // metres
  int kernel = 0;                      // 1 tap
  bool freeze = false;
  int cull = 0;                             // off: every cascade draws every caster
  std::vector<lab10::Box> boxes;            // each object's world bounds, for csm.cull (10.H2)
  int region = 0;                           // measure.region: all
  int filter = 0;                           // pcf
  float minVariance = 2e-5f, bleeding = 0;  // lab 05's defaults
  float esmC = 80, cPos = 40, cNeg = 5;     // labs 04 and 06
  bool showCascades = false, showDensity = false;
  Cascades frozen;  // what csm.freeze keeps
  int pathStep = 0, matricesStep = -1;
};

}  // namespace

int main(int argc, char** argv) { return wb::run<CascadeLab>(argc, argv); }
