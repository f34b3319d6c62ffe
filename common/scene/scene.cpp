#include "common/scene/scene.hpp"

#include "common/base/error.hpp"

#include <stb_image.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <random>

namespace fs = std::filesystem;
using nlohmann::json;

namespace wb {
namespace {

// Reads fields of one JSON object and names the file and field in every error.
class Fields {
 public:
  Fields(const json& j, std::string where, const fs::path& file) : j_(j), where_(std::move(where)), file_(file) {
    if (!j_.is_object()) fail("", "must be an object {...}");
  }
  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw UsageError(file_.string() + ": " + where_ + (field.empty() ? "" : "." + field) + ": " + why);
  }
  bool has(const char* k) const { return j_.contains(k); }
  float num(const char* k, float fallback) const {
    if (!has(k)) return fallback;
    if (!j_[k].is_number()) fail(k, "must be a number, got " + j_[k].dump());
    return j_[k].get<float>();
  }
  float positive(const char* k, float fallback) const {
    float v = num(k, fallback);
    if (!(v > 0)) fail(k, "must be greater than 0, got " + std::to_string(v));
    return v;
  }
  bool flag(const char* k, bool fallback) const {
    if (!has(k)) return fallback;
    if (!j_[k].is_boolean()) fail(k, "must be true or false, got " + j_[k].dump());
    return j_[k].get<bool>();
  }
  std::string str(const char* k, const std::string& fallback) const {
    if (!has(k)) return fallback;
    if (!j_[k].is_string()) fail(k, "must be a string, got " + j_[k].dump());
    return j_[k].get<std::string>();
  }
  glm::vec3 vec3(const char* k, glm::vec3 fallback) const {
    if (!has(k)) return fallback;
    const json& v = j_[k];
    if (v.is_number()) return glm::vec3(v.get<float>());
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      fail(k, "must be [x, y, z] (three numbers), got " + v.dump());
    return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
  }
  glm::vec2 range(const char* k) const {  // a required [lo, hi] with hi > lo
    const json& v = has(k) ? j_[k] : json();
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() || v[1] <= v[0])
      fail(k, "must be [lo, hi] (two numbers, hi > lo), got " + v.dump());
    return {v[0].get<float>(), v[1].get<float>()};
  }
  glm::vec3 direction(const char* k, glm::vec3 fallback) const {
    glm::vec3 d = vec3(k, fallback);
    if (glm::length(d) < 1e-6f) fail(k, "must not be the zero vector");
    return glm::normalize(d);
  }

 private:
  const json& j_;
  std::string where_;
  const fs::path& file_;
};

const json& arrayField(const json& root, const char* k, const fs::path& file, bool required) {
  static const json empty = json::array();
  if (!root.contains(k)) {
    if (required) throw UsageError(file.string() + ": " + k + ": missing (a scene needs at least one)");
    return empty;
  }
  if (!root[k].is_array()) throw UsageError(file.string() + ": " + k + ": must be an array [...]");
  return root[k];
}

MeshData shapeMesh(const std::string& shape, const Fields& f) {
  if (shape == "plane") {
    glm::vec3 s = f.vec3("size", {10, 0, 10});
    return makePlane(s.x, s.z);
  }
  if (shape == "box") return makeBox(f.vec3("size", glm::vec3(1)) * 0.5f);
  if (shape == "sphere") {  // "segments" around (and half as many from pole to pole)
    const float segments = f.num("segments", 32);
    if (!(segments >= 4 && segments <= 512) || segments != float(int(segments)))
      f.fail("segments", "must be a whole number from 4 to 512, got " + std::to_string(segments));
    return makeSphere(f.positive("radius", 0.5f), int(segments), int(segments) / 2);
  }
  if (shape == "cylinder") return makeCylinder(f.positive("radius", 0.5f), f.positive("height", 1));
  if (shape == "torus") return makeTorus(f.positive("radius", 0.6f), f.positive("tube", 0.2f));
  if (shape == "bench") return makeBench();
  if (shape == "tree_trunk") return makeTreeTrunk();
  if (shape == "tree_canopy") return makeTreeCanopy();
  f.fail("shape", "unknown shape '" + shape + "' (expected plane, box, sphere, cylinder, torus, bench or tree)");
}

// One entry of "objects": a primitive (or the tree composite) with its transform and material.
void readObject(const json& entry, size_t i, const fs::path& file, const fs::path& dir, Scene& scene) {
  Fields f(entry, "objects[" + std::to_string(i) + "]", file);
  const std::string shape = f.str("shape", "");
  if (shape.empty()) f.fail("shape", "missing (expected plane, box, sphere, cylinder, torus, bench or tree)");
  glm::mat4 model = glm::translate(glm::mat4(1), f.vec3("position", glm::vec3(0)));
  const glm::vec3 rot = f.vec3("rotation", glm::vec3(0));  // degrees, applied y, then x, then z
  model = glm::rotate(model, glm::radians(rot.y), {0, 1, 0});
  model = glm::rotate(model, glm::radians(rot.x), {1, 0, 0});
  model = glm::rotate(model, glm::radians(rot.z), {0, 0, 1});
  model = glm::scale(model, f.vec3("scale", glm::vec3(1)));
  Material mat{f.vec3("color", glm::vec3(0.8f)), {}};
  if (std::string tex = f.str("texture", ""); !tex.empty()) {
    mat.texture = dir / tex;
    if (!fs::exists(mat.texture)) f.fail("texture", "file '" + mat.texture.string() + "' not found");
  }
  const std::string name = f.str("name", "objects[" + std::to_string(i) + "]");
  if (shape == "tree") {  // a composite: an opaque trunk and an alpha-tested canopy
    const fs::path leaves = mat.texture.empty() ? dir / "textures/leaves.png" : mat.texture;
    scene.objects.push_back({name + ".trunk", makeTreeTrunk(), model, {{0.45f, 0.3f, 0.18f}, {}}});
    scene.objects.push_back({name + ".canopy", makeTreeCanopy(), model, {mat.color, leaves}, false});
    return;
  }
  // An alpha-tested object has no closed outline to cast a volume from; the default follows that.
  scene.objects.push_back({name, shapeMesh(shape, f), model, mat, f.flag("casts_volume", mat.texture.empty()),
                           f.flag("casts_shadow", true)});
}

Light readLight(const json& entry, size_t i, const fs::path& file) {
  static const std::map<std::string, LightType> kTypes = {
      {"directional", LightType::Directional}, {"spot", LightType::Spot}, {"point", LightType::Point}};
  Fields f(entry, "lights[" + std::to_string(i) + "]", file);
  Light l;
  const std::string type = f.str("type", "directional");
  if (!kTypes.count(type)) f.fail("type", "unknown light type '" + type + "' (expected directional, spot or point)");
  l.type = kTypes.at(type);
  l.position = f.vec3("position", l.position);
  l.direction = f.direction("direction", l.direction);
  l.color = f.vec3("color", l.color);
  l.angle = f.positive("angle", l.angle);
  if (l.angle >= 89) f.fail("angle", "a spot cone half-angle must be below 89 degrees");
  l.nearPlane = f.positive("near", l.nearPlane);
  l.farPlane = f.positive("far", l.farPlane);
  if (l.farPlane <= l.nearPlane) f.fail("far", "must be greater than near");
  l.size = f.num("size", 0);
  if (l.size < 0 || (l.size > 0 && l.type != LightType::Spot))
    f.fail("size", "a light's size (its disk's diameter, world units) must be >= 0, and only spot lights have one");
  return l;
}

CameraBookmark readCamera(const json& entry, size_t i, const fs::path& file) {
  Fields f(entry, "cameras[" + std::to_string(i) + "]", file);
  CameraBookmark b;
  b.name = f.str("name", "camera " + std::to_string(i + 1));
  b.target = f.vec3("target", b.target);
  b.distance = f.positive("distance", b.distance);
  b.yaw = f.num("yaw", b.yaw);
  b.pitch = f.num("pitch", b.pitch);
  b.fov = f.positive("fov", b.fov);
  return b;
}

PenumbraProbe readProbe(const json& root, const fs::path& file) {
  PenumbraProbe p;
  if (!root.contains("penumbra_probe")) return p;
  Fields f(root["penumbra_probe"], "penumbra_probe", file);
  p.on = true, p.x = f.range("x"), p.z = f.range("z");
  p.bins = int(f.num("bins", float(p.bins)));
  if (p.bins < 1 || p.bins > 100) f.fail("bins", "must be 1 to 100");
  return p;
}

json parseSceneFile(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec))
    throw UsageError("'" + file.string() + "' is a folder, not a scene file; name one of its .json files, e.g. " +
                     "--scene scenes/depth_map.json");
  std::ifstream in(file);
  if (!in)
    throw UsageError("scene file '" + file.string() + "' not found (scenes live in " +
                     "scenes/*.json; try --scene scenes/depth_map.json)");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    throw UsageError(file.string() + ": not valid JSON: " + e.what());
  }
  if (!root.is_object()) throw UsageError(file.string() + ": the top level must be an object {...}");
  return root;
}

}  // namespace

Scene Scene::load(const fs::path& file) {
  const json root = parseSceneFile(file);
  Scene scene;
  scene.path = fs::absolute(file);
  const json& objects = arrayField(root, "objects", file, true);
  for (size_t i = 0; i < objects.size(); ++i) readObject(objects[i], i, file, scene.path.parent_path(), scene);
  const json& lights = arrayField(root, "lights", file, true);
  for (size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(readLight(lights[i], i, file));
  const json& cameras = arrayField(root, "cameras", file, false);
  for (size_t i = 0; i < cameras.size(); ++i) scene.cameras.push_back(readCamera(cameras[i], i, file));
  if (scene.cameras.empty()) scene.cameras.emplace_back();
  scene.penumbraProbe = readProbe(root, file);

  scene.boundsMin = glm::vec3(1e30f);
  scene.boundsMax = glm::vec3(-1e30f);
  for (const auto& o : scene.objects)
    for (const auto& v : o.mesh.vertices) {
      glm::vec3 p(o.model * glm::vec4(v.position, 1));
      scene.boundsMin = glm::min(scene.boundsMin, p);
      scene.boundsMax = glm::max(scene.boundsMax, p);
    }
  return scene;
}

std::pair<glm::vec3, glm::vec3> worldBounds(const SceneObject& object) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : object.mesh.weldedPositions) {
    const glm::vec3 w(object.model * glm::vec4(p, 1));
    lo = glm::min(lo, w), hi = glm::max(hi, w);
  }
  return {lo, hi};
}

Light turnedAboutY(Light light, float degrees) {
  const glm::mat3 turn(glm::rotate(glm::mat4(1), glm::radians(degrees), glm::vec3(0, 1, 0)));
  light.position = turn * light.position, light.direction = turn * light.direction;
  return light;
}

void varyScene(Scene& scene, uint32_t seed) {
  std::mt19937 rng(seed);  // fully specified, so every build turns the scene the same way
  auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * float(rng() >> 8) / float(1u << 24); };
  const float size = glm::length(scene.boundsMax - scene.boundsMin);
  for (auto& l : scene.lights) {
    glm::vec3 axis(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    if (glm::length(axis) < 1e-3f) axis = glm::vec3(0, 1, 0);
    const float sign = uniform(0, 1) < 0.5f ? -1.0f : 1.0f;
    const glm::mat4 turn = glm::rotate(glm::mat4(1), glm::radians(sign * uniform(1, 3)), glm::normalize(axis));
    l.direction = glm::normalize(glm::vec3(turn * glm::vec4(l.direction, 0)));
    if (l.type != LightType::Directional)
      l.position += 0.02f * size * glm::vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)) / std::sqrt(3.0f);
  }
  for (auto& c : scene.cameras) c.yaw += uniform(-3, 3), c.pitch += uniform(-3, 3);
}

GpuScene::GpuScene(const Scene& scene) {
  const uint8_t whiteTexel[4] = {255, 255, 255, 255};
  white_ = makeTexture2D(GL_RGBA8, 1, 1);
  uploadTexture2D(white_.id(), 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, whiteTexel);
  std::map<fs::path, GLuint> loaded;
  for (const auto& o : scene.objects) {
    GLuint tex = white_.id();
    if (!o.material.texture.empty()) {
      auto it = loaded.find(o.material.texture);
      if (it == loaded.end()) {
        int w = 0, h = 0, n = 0;
        stbi_set_flip_vertically_on_load(1);
        unsigned char* px = stbi_load(o.material.texture.string().c_str(), &w, &h, &n, 4);
        if (!px)
          throw UsageError(scene.path.string() + ": " + o.name + ": cannot load texture '" +
                           o.material.texture.string() + "': " + stbi_failure_reason());
        Texture texture = makeTexture(GL_TEXTURE_2D);
        const GLuint id = texture.id();
        {
          BoundTexture edit(GL_TEXTURE_2D, id);
          allocateTexture(GL_TEXTURE_2D, 1 + static_cast<int>(std::log2(std::max(w, h))), GL_RGBA8, w, h);
          glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
          glGenerateMipmap(GL_TEXTURE_2D);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
          glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        }
        stbi_image_free(px);
        textures_.push_back(std::move(texture));
        it = loaded.emplace(o.material.texture, id).first;
      }
      tex = it->second;
    }
    items_.push_back({Mesh(o.mesh), o.model, o.material.color, tex, tex != white_.id(), o.castsShadow});
  }
}

void GpuScene::draw(const Program& program, int unit, int instances) const {
  drawItems(program, unit, instances, false);
}

void GpuScene::drawCasters(const Program& program, int unit, int instances) const {
  drawItems(program, unit, instances, true);
}

void GpuScene::drawCasters(const Program& program, const std::vector<bool>& only) const {
  drawItems(program, kAlbedoUnit, 1, true, &only);
}

void GpuScene::drawItems(const Program& program, int unit, int instances, bool castersOnly,
                         const std::vector<bool>* only) const {
  program.use();
  program.set("u_albedo", unit);
  for (size_t k = 0; k < items_.size(); ++k) {
    const Item& it = items_[k];
    if ((castersOnly && !it.casts) || (only && (k >= only->size() || !(*only)[k]))) continue;
    program.set("u_model", it.model);
    program.set("u_color", it.color);
    program.set("u_hasTexture", it.textured ? 1 : 0);
    bindTexture(GLuint(unit), it.texture);
    it.mesh.draw(instances);
  }
}

void GpuScene::setIndices(size_t object, const std::vector<uint32_t>& indices, GLenum mode) {
  if (object >= items_.size())
    throw Error("GpuScene::setIndices: object " + std::to_string(object) + " does not exist (the scene has " +
                std::to_string(items_.size()) + ")");
  try {
    items_[object].mesh.setWeldedIndices(indices, mode);
  } catch (const Error& e) {
    throw Error("GpuScene::setIndices: object " + std::to_string(object) + ": " + e.what());
  }
}

size_t GpuScene::drawWelded(const Program& program, GLenum mode, bool depthClamp) const {
  size_t drawn = 0;
  for (size_t k = 0; k < items_.size(); ++k)
    if (items_[k].mesh.weldedMode() == mode) drawObjectWelded(k, program, depthClamp), ++drawn;
  return drawn;
}

void GpuScene::drawObjectWelded(size_t object, const Program& program, bool depthClamp) const {
  if (object >= items_.size())
    throw Error("drawObjectWelded: object " + std::to_string(object) + " of " + std::to_string(items_.size()));
  const GLboolean wasClamped = glIsEnabled(GL_DEPTH_CLAMP);
  if (depthClamp && !wasClamped) glEnable(GL_DEPTH_CLAMP);
  program.use();
  program.set("u_hasTexture", 0);
  program.set("u_model", items_[object].model);
  program.set("u_color", items_[object].color);
  items_[object].mesh.drawWelded();
  if (depthClamp && !wasClamped) glDisable(GL_DEPTH_CLAMP);
}

}  // namespace wb
