#include "common/truth/ray_scene.hpp"

#include "common/base/error.hpp"

#include <stb_image.h>

#if __has_include(<embree4/rtcore.h>)
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace wb {
namespace {

// An alpha-tested object's texture alpha and texture coordinates, for the filter function.
struct AlphaTest {
  int w = 0, h = 0;
  std::vector<uint8_t> alpha;   // rows bottom to top, as OpenGL samples it
  std::vector<glm::vec2> uv;    // per vertex
  std::vector<uint32_t> index;  // three per triangle
  float cutoff = 0.5f;
  // The alpha at barycentric (u, v) of triangle `prim`, nearest texel, the texture repeated.
  bool clear(unsigned prim, float u, float v) const {
    const glm::vec2 t =
        glm::fract((1 - u - v) * uv[index[3 * prim]] + u * uv[index[3 * prim + 1]] + v * uv[index[3 * prim + 2]]);
    const int x = std::min(int(t.x * float(w)), w - 1), y = std::min(int(t.y * float(h)), h - 1);
    return float(alpha[size_t(y) * size_t(w) + size_t(x)]) / 255.0f < cutoff;
  }
};

// Embree calls this for every candidate hit on an alpha-tested object: a clear texel lets the ray on.
void alphaFilter(const RTCFilterFunctionNArguments* args) {
  const auto* test = static_cast<const AlphaTest*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i)
    if (args->valid[i] && test->clear(RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i),
                                      RTCHitN_v(args->hit, args->N, i)))
      args->valid[i] = 0;
}

RTCRay makeRay(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) {
  RTCRay r{};
  r.org_x = o.x, r.org_y = o.y, r.org_z = o.z, r.tnear = tMin;
  r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z, r.tfar = tMax;
  r.mask = ~0u;
  return r;
}

}  // namespace

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaTest>> tests;  // alive as long as the scene
  std::vector<float> objectMinY;                  // lowest world y of each scene object

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error("the ray caster (Embree) could not " + what + ": error " +
                std::to_string(int(rtcGetDeviceError(device))) + " (is libembree-dev installed and working?)");
  }

  // One Embree geometry per scene object, with the object's index as its id.
  void add(const SceneObject& o, unsigned id, const AlphaTest* texture, float cutoff) {
    const auto& v = o.mesh.vertices;
    const size_t triangles = o.mesh.indices.size() / 3;
    if (triangles == 0 || v.empty()) return;
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* p = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), v.size()));
    auto* t = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles));
    if (!p || !t) fail("allocate the triangles of " + o.name);
    for (size_t i = 0; i < v.size(); ++i) {
      const glm::vec3 w(o.model * glm::vec4(v[i].position, 1));
      p[3 * i] = w.x, p[3 * i + 1] = w.y, p[3 * i + 2] = w.z;
    }
    std::copy(o.mesh.indices.begin(), o.mesh.indices.begin() + long(3 * triangles), t);
    if (texture) {
      auto test = std::make_unique<AlphaTest>(*texture);
      test->cutoff = cutoff;
      for (const Vertex& vert : v) test->uv.push_back(vert.uv);
      test->index.assign(o.mesh.indices.begin(), o.mesh.indices.begin() + long(3 * triangles));
      rtcSetGeometryUserData(g, test.get());
      rtcSetGeometryIntersectFilterFunction(g, alphaFilter);
      rtcSetGeometryOccludedFilterFunction(g, alphaFilter);
      tests.push_back(std::move(test));
    }
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene, g, id);
    rtcReleaseGeometry(g);
  }
};

namespace {

// A texture's alpha, loaded once per file.
AlphaTest loadAlpha(const std::filesystem::path& file) {
  AlphaTest a;
  int n = 0;
  stbi_set_flip_vertically_on_load(1);  // row 0 = v 0, as OpenGL samples it
  unsigned char* px = stbi_load(file.string().c_str(), &a.w, &a.h, &n, 4);
  if (!px) throw Error("cannot load texture " + file.string() + " for ray casting");
  a.alpha.resize(size_t(a.w) * size_t(a.h));
  for (size_t i = 0; i < a.alpha.size(); ++i) a.alpha[i] = px[4 * i + 3];
  stbi_image_free(px);
  return a;
}

}  // namespace

RayScene::RayScene(const Scene& scene, float alphaCutoff) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.device = rtcNewDevice(nullptr);
  if (!m.device) throw Error("the ray caster (Embree) could not start: is libembree-dev installed and working?");
  m.scene = rtcNewScene(m.device);
  rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);  // watertight: no ray slips between two triangles
  rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
  std::map<std::string, AlphaTest> textures;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& o = scene.objects[k];
    const AlphaTest* texture = nullptr;
    if (!o.material.texture.empty()) {
      auto it = textures.find(o.material.texture.string());
      if (it == textures.end()) it = textures.emplace(o.material.texture.string(), loadAlpha(o.material.texture)).first;
      texture = &it->second;
    }
    m.objectMinY.push_back(1e30f);
    for (const Vertex& vert : o.mesh.vertices)
      m.objectMinY.back() = std::min(m.objectMinY.back(), (o.model * glm::vec4(vert.position, 1)).y);
    m.add(o, unsigned(k), texture, alphaCutoff);
  }
  rtcCommitScene(m.scene);
  if (rtcGetDeviceError(m.device) != RTC_ERROR_NONE) m.fail("build its hierarchy");
}

RayScene::~RayScene() = default;

bool RayScene::restsOn(int object, float y) const {
  return object >= 0 && size_t(object) < impl_->objectMinY.size() &&
         std::abs(impl_->objectMinY[size_t(object)] - y) < 1e-3f;
}

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
  RTCRay ray = makeRay(o, d, tMin, tMax);
#if RTC_VERSION_MAJOR >= 4
  rtcOccluded1(impl_->scene, &ray);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(impl_->scene, &context, &ray);
#endif
  return ray.tfar < 0;  // Embree sets tfar to -inf when something blocks the ray
}

float RayScene::firstHit(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, int* object,
                         glm::vec3* normal) const {
  RTCRayHit hit{};
  hit.ray = makeRay(o, d, tMin, tMax);
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
#if RTC_VERSION_MAJOR >= 4
  rtcIntersect1(impl_->scene, &hit);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(impl_->scene, &context, &hit);
#endif
  const bool found = hit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  if (object) *object = found ? int(hit.hit.geomID) : -1;
  if (normal)  // the triangle's own normal (Embree's Ng: unnormalised, either side)
    *normal = found ? glm::normalize(glm::vec3(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z)) : glm::vec3(0);
  return found ? hit.ray.tfar : tMax;
}

}  // namespace wb
