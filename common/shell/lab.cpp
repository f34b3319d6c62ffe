#include "common/shell/lab.hpp"

#include "common/exercise/exercise_source_rules.hpp"
#include "common/shell/lab_stage.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

namespace wb {
namespace {
const int kMapSizes[] = {512, 1024, 2048, 4096, 8192};
}  // namespace

Lab::Lab(std::string defaultScene, ShadowKind kind) : defaultScene_(std::move(defaultScene)) {
  // The settings every lab shares; a lab registers the rest (and shadow.bias, if it uses one). The
  // host adds its own (camera.bookmark, light.orbit, camera.dolly, render.scale, ui.*, present.*).
  if (kind == ShadowKind::Map) {
    std::vector<std::string> sizes;
    for (int s : kMapSizes) sizes.push_back(std::to_string(s));
    settings.addChoice("shadow.map_size", mapSizeChoice_, sizes,
                       "shadow map resolution in texels (clamped to GL_MAX_TEXTURE_SIZE)");
  }
  settings.add("alpha.cutoff", alphaCutoff_, 0.0f, 1.0f, "leaf texels with lower alpha are holes and cast no shadow");
  settings.add("light.index", lightIndex, 0, 7, "which light of the scene casts shadows");
  if (kind == ShadowKind::Map) debug_.addTo(settings);
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
  const float size = scene.lights[size_t(lightIndex)].size;
  if (lightSizeUsed_ && size > 0 && !keepLightSize) lightSize_ = size;
}

void Lab::start(LabStage& stage) {
  stage_ = &stage;
  gpuScene = std::make_unique<GpuScene>(scene);
  init();
  stage.board.probe();
}

LabStage& Lab::stage() const {
  if (!stage_) throw Error("a lab's helpers work once a host has started it (LabHost::host, EmbeddedLab::render)");
  return *stage_;
}

FrameShown Lab::shown() const {
  FrameShown f;
  f.light = light_;
  if (lightShown_)
    f.litBy = light_.light;
  else if (lightIndex >= 0 && lightIndex < int(scene.lights.size()))
    f.litBy = scene.lights[size_t(lightIndex)];
  f.debug = debug_;
  f.viewProj = viewProj();
  f.alphaCutoff = alphaCutoff_;
  f.lightRays = 16 << (2 * lightSamples_);
  return f;
}

const CompareChoice& Lab::comparison() const { return stage().comparison; }
const ExerciseBoard& Lab::board() const { return stage().board; }
void Lab::bindFrameTarget() const { stage().target.bind(); }
glm::ivec2 Lab::frameSize() const { return stage().target.size(); }
Lab::PassTimer Lab::timePass(const char* name) { return stage().timers.scope(name); }

void Lab::glslExercise(const std::string& id, const std::string& file, const std::string& probe) {
  stage().board.addProbe(id, file, probe);
}

void Lab::setStatus(const std::string& id, ExerciseState state, const std::string& message) {
  stage().board.set(id, state, message);
}

Program& Lab::loadProgram(std::vector<ShaderStage> stages, std::string defines) {
  // The exercise floor's rules: a student's file includes only what its stub does, and a broken edit
  // draws the exercises that still compile.
  auto& programs = stage().programs;
  programs.push_back(Program::tryLoad(std::move(stages), std::move(defines), &exerciseSourceRules()));
  return programs.back();
}

bool Lab::runExercise(const std::string& id, const std::function<nlohmann::json()>& call,
                      const std::function<void(const nlohmann::json&)>& replay) {
  ExerciseTape& tape = stage().tape;
  ExerciseTape::Call c;
  if (tape.replays(id)) {  // the grader's trusted app, drawing with a student's results
    c = tape.next(id);
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
    if (tape.recording()) tape.add(id, c);
  }
  setStatus(id, c.state, c.message);
  return c.state == ExerciseState::Implemented;
}

void Lab::warn(const std::string& message) {
  if (stage_)
    stage_->warn(message);
  else  // (not started: nowhere to show it)
    std::fprintf(stderr, "warning: %s\n", message.c_str());
}

void Lab::clearWarnings() {
  if (stage_) stage_->warnings.clear();
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
