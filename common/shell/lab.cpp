#include "common/shell/lab.hpp"

#include "common/base/variant.hpp"
#include "common/exercise/exercise_source_rules.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fs = std::filesystem;

namespace wb {
namespace {
const int kMapSizes[] = {512, 1024, 2048, 4096, 8192};
}  // namespace

Lab::Lab(std::string defaultScene, ShadowKind kind)
    : defaultScene_(std::move(defaultScene)), board_(fs::path(variant::kLabDir) / "exercises.json") {
  // The settings every lab shares; a lab registers the rest (and shadow.bias, if it uses one).
  if (kind == ShadowKind::Map) {
    std::vector<std::string> sizes;
    for (int s : kMapSizes) sizes.push_back(std::to_string(s));
    settings.addChoice("shadow.map_size", mapSizeChoice_, sizes,
                       "shadow map resolution in texels (clamped to GL_MAX_TEXTURE_SIZE)");
  }
  settings.add("alpha.cutoff", alphaCutoff_, 0.0f, 1.0f, "leaf texels with lower alpha are holes and cast no shadow");
  settings.add("light.index", lightIndex, 0, 7, "which light of the scene casts shadows");
  if (kind == ShadowKind::Map) debug_.addTo(settings);
  settings.add("camera.bookmark", bookmark_, 1, 9, "camera bookmark of the scene file, 1 = the first (keys 1-9)");
  settings.add("light.orbit", lightOrbit_, -180.0f, 180.0f,
               "degrees the scene's lights turn about the vertical axis through the origin (a clip: --animate "
               "light.orbit=0:90)");
  settings.add("camera.dolly", cameraDolly_, -20.0f, 20.0f,
               "units the camera stands further back from its bookmark's target (negative: closer; a clip: "
               "--animate camera.dolly=4:0)");
  settings.add("render.scale", renderScale_, 0.25f, 1.0f,
               "in a window, draw the scene at this fraction of the window's resolution and stretch it (the "
               "panels and captions stay sharp): 0.5 at 1920x1080 costs about what 960x540 does");
  settings.add("ui.scale", uiScale_, 0.0f, 4.0f,
               "the panels' text size: 1 = 16 px, 2 = 32 px; 0 = follow the monitor (and 1.25x while presenting)");
  settings.add("ui.panels", uiPanels_, "in a window, the panels (H toggles them; off: the scene alone, for a lecture)");
  // For lectures (demo.json turns them on); the visibility buffer that tests read never changes.
  settings.add("present.srgb", present_.srgb, "write sRGB-encoded colour (the shading is linear)");
  settings.add("present.grid", present_.grid, "a faint one-unit grid on the ground, to read texel sizes off");
  settings.addChoice("present.msaa", present_.msaa, {"off", "4"},
                     "multisampling of the camera pass (an edge pixel's visibility becomes its samples' mean)");
}

Lab::~Lab() = default;

void Lab::useDepthBias(float initial, float max, const char* help) {
  bias_ = initial;
  if (!biasRegistered_) settings.add("shadow.bias", bias_, 0.0f, max, help);
  biasRegistered_ = true;
}

void Lab::useLightSize(float initial) {
  lightSize_ = initial, lightSizeUsed_ = true;
  settings.add("light.size", lightSize_, 0.0f, 2.0f,
               "the spot light's disk diameter in world units (0: a point); starts at the scene light's size");
  settings.addChoice("truth.light_samples", lightSamples_, {"16", "64", "256"},
                     "rays per pixel from the surface to the light's disk in the measured reference");
}

void Lab::adoptScene(Scene s, bool keepLightSize) {
  if (lightIndex >= int(s.lights.size()))
    throw UsageError("light.index=" + std::to_string(lightIndex) + " but " + s.path.string() + " has " +
                     std::to_string(s.lights.size()) + " light(s)");
  scene = std::move(s);
  baseLights_.clear(), appliedOrbit_ = 0, appliedDolly_ = 0;  // (a new scene's lights are its own)
  const float size = scene.lights[size_t(lightIndex)].size;
  if (lightSizeUsed_ && size > 0 && !keepLightSize) lightSize_ = size;
}

Program& Lab::loadProgram(std::vector<ShaderStage> stages, std::string defines) {
  // The exercise floor's rules: a student's file includes only what its stub does, and a broken edit
  // draws the exercises that still compile.
  programs_.push_back(Program::tryLoad(std::move(stages), std::move(defines), &exerciseSourceRules()));
  return programs_.back();
}

bool Lab::runExercise(const std::string& id, const std::function<nlohmann::json()>& call,
                      const std::function<void(const nlohmann::json&)>& replay) {
  ExerciseTape::Call c;
  if (exerciseTape_.replays(id)) {  // the grader's trusted app, drawing with a student's results
    c = exerciseTape_.next(id);
    try {
      if (c.state == ExerciseState::Implemented) replay(c.value);
    } catch (const std::exception& e) {
      c = {ExerciseState::Failed, std::string("the recorded result cannot be used: ") + e.what(), {}};
    }
  } else {
    try {
      c.value = call();
      c.state = ExerciseState::Implemented;
    } catch (const NotImplemented& e) {
      c.state = ExerciseState::NotImplemented, c.message = e.what();
    } catch (const std::exception& e) {
      c.state = ExerciseState::Failed, c.message = e.what();
    }
    if (exerciseTape_.recording()) exerciseTape_.add(id, c);
  }
  setStatus(id, c.state, c.message);
  return c.state == ExerciseState::Implemented;
}

void Lab::warn(const std::string& message) {
  if (std::find(warnings_.begin(), warnings_.end(), message) != warnings_.end()) return;
  warnings_.push_back(message);
  std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void Lab::applyMotion() {
  if (lightOrbit_ != appliedOrbit_) {
    if (baseLights_.empty()) baseLights_ = scene.lights;
    for (size_t k = 0; k < scene.lights.size() && k < baseLights_.size(); ++k)
      scene.lights[k] = turnedAboutY(baseLights_[k], lightOrbit_);
    appliedOrbit_ = lightOrbit_;
  }
  if (cameraDolly_ != appliedDolly_ && bookmark_ >= 1 && bookmark_ <= int(scene.cameras.size())) {
    camera.pose.distance = std::max(0.05f, scene.cameras[size_t(bookmark_ - 1)].distance + cameraDolly_);
    appliedDolly_ = cameraDolly_;
  }
}

int Lab::shadowMapSize() {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int wanted = kMapSizes[mapSizeChoice_];
  if (wanted > maxSize) {
    warn("shadow.map_size " + std::to_string(wanted) + " exceeds GL_MAX_TEXTURE_SIZE; using " +
         std::to_string(maxSize));
    return maxSize;
  }
  return wanted;
}

glm::mat4 Lab::viewProj() const {
  if (debug_.view == 1 && light_.hasMap()) return DebugViews::fromLight(light_, debug_.lightFace, frameSize());
  return camera.projection(float(frameSize().x) / float(frameSize().y)) * camera.view();
}

glm::vec3 Lab::viewPosition() const {
  if (debug_.view == 1 && light_.hasMap()) {
    const size_t k = size_t(debug_.lightFace) % light_.viewProj.size();
    glm::vec4 p = glm::inverse(light_.viewProj[k]) * glm::vec4(0, 0, -1, 1);
    return glm::vec3(p) / p.w;
  }
  return camera.eye();
}

void Lab::renderShadowMap(const Program& depthProgram, const ShadowMap& map, const Light& light,
                          const glm::mat4& lightViewProj) {
  map.begin();
  depthProgram.set("u_lightViewProj", lightViewProj);
  depthProgram.set("u_alphaCutoff", alphaCutoff_);
  gpuScene->drawCasters(depthProgram);
  showLight(map.describe(light, lightViewProj));
}

void Lab::renderShadowMap(const Program& depthProgram, const CubeShadowMap& map, const Light& light,
                          const std::vector<glm::mat4>& faceViewProj, bool linearDistance) {
  depthProgram.set("u_alphaCutoff", alphaCutoff_);
  for (int face = 0; face < 6 && face < int(faceViewProj.size()); ++face) {
    map.begin(face);
    depthProgram.set("u_lightViewProj", faceViewProj[size_t(face)]);
    gpuScene->drawCasters(depthProgram);
  }
  showLight(map.describe(light, faceViewProj, linearDistance));
}

void Lab::renderShadowMap(const Program& depthProgram, const ShadowMapArray& map, const Light& light,
                          const std::vector<glm::mat4>& layerViewProj,
                          const std::vector<std::vector<bool>>* layerCasters) {
  depthProgram.set("u_alphaCutoff", alphaCutoff_);
  for (int layer = 0; layer < map.layers() && layer < int(layerViewProj.size()); ++layer) {
    map.begin(layer);
    depthProgram.set("u_lightViewProj", layerViewProj[size_t(layer)]);
    if (layerCasters && size_t(layer) < layerCasters->size())
      gpuScene->drawCasters(depthProgram, (*layerCasters)[size_t(layer)]);
    else
      gpuScene->drawCasters(depthProgram);
  }
  showLight(map.describe(light, layerViewProj));
}

void Lab::renderFilteredShadowMap(const Program& writer, FilteredShadowMap& map, const float far[4],
                                  const Program& blur, const Light& light, const glm::mat4& lightViewProj) {
  {
    auto timer = timePass("shadow");
    map.begin(far);
    writer.set("u_lightViewProj", lightViewProj);
    writer.set("u_alphaCutoff", alphaCutoff_);
    gpuScene->draw(writer);  // every object: filtering needs the receivers' depths too
  }
  {
    auto timer = timePass("prefilter");
    map.prefilter(blur);
  }
  LightView v;
  v.light = light, v.viewProj = {lightViewProj}, v.target = GL_TEXTURE_2D, v.texture = map.depthTexture();
  v.size = map.size(), v.kernel = map.options().kernel, v.gaussian = map.options().gaussian;
  showLight(v);
}

void Lab::beginCameraPass(const Program& program, const Light& light, const glm::mat4& lightViewProj,
                          GLuint shadowMap) {
  bindFrameTarget();
  program.set("u_wbLightType", int(light.type));
  program.set("u_wbLightPos", light.position);
  program.set("u_wbLightDir", glm::normalize(light.direction));
  program.set("u_wbSpotCos", std::cos(glm::radians(light.angle)));
  program.set("u_viewProj", viewProj());
  program.set("u_lightViewProj", lightViewProj);
  program.set("u_alphaCutoff", alphaCutoff_);
  program.set("u_shadowMap", 0);
  bindTexture(0, shadowMap);
}

}  // namespace wb
