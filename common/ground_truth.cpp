#include "common/ground_truth.hpp"

#include "common/error.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace wb {

struct RayScene::Impl {
  struct Triangle {
    glm::vec3 a, e1, e2;  // a, b − a, c − a
    glm::vec2 uvA, uvE1, uvE2;
    int texture = -1;  // index into `textures`, −1 = opaque
    int object = -1;   // index of the scene object it belongs to
  };
  struct Node {
    glm::vec3 lo, hi;
    int first, count;           // a leaf holds triangles [first, first + count)
    int left = -1, right = -1;  // an inner node (count = 0) has two children
  };
  struct Alpha {
    int w = 0, h = 0;
    std::vector<uint8_t> a;
  };
  std::vector<Triangle> tris;
  std::vector<Node> nodes;
  std::vector<Alpha> textures;
  std::vector<float> objectMinY;  // lowest world y of each scene object
  float cutoff = 0.5f;

  // Median split on the longest axis of the centroids; leaves of up to 4 triangles.
  int build(int first, int count) {
    Node n{glm::vec3(1e30f), glm::vec3(-1e30f), first, count};
    glm::vec3 clo(1e30f), chi(-1e30f);
    for (int i = first; i < first + count; ++i) {
      const Triangle& t = tris[size_t(i)];
      for (const glm::vec3& p : {t.a, t.a + t.e1, t.a + t.e2}) n.lo = glm::min(n.lo, p), n.hi = glm::max(n.hi, p);
      const glm::vec3 c = t.a + (t.e1 + t.e2) / 3.0f;
      clo = glm::min(clo, c), chi = glm::max(chi, c);
    }
    const int index = int(nodes.size());
    nodes.push_back(n);
    if (count <= 4) return index;
    const glm::vec3 ext = chi - clo;
    const int axis = ext.x > ext.y && ext.x > ext.z ? 0 : ext.y > ext.z ? 1 : 2;
    const int mid = first + count / 2;
    std::nth_element(tris.begin() + first, tris.begin() + mid, tris.begin() + first + count,
                     [axis](const Triangle& p, const Triangle& q) {
                       return (p.a + (p.e1 + p.e2) / 3.0f)[axis] < (q.a + (q.e1 + q.e2) / 3.0f)[axis];
                     });
    const int left = build(first, mid - first), right = build(mid, first + count - mid);
    nodes[size_t(index)].count = 0;
    nodes[size_t(index)].left = left;
    nodes[size_t(index)].right = right;
    return index;
  }

  float trace(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, bool anyHit, int* object) const;

  // Möller–Trumbore: the distance to triangle t, or tMax if the ray misses it; an alpha-tested
  // triangle lets the ray through where its texture is clear.
  float hit(const Triangle& t, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
    const glm::vec3 p = glm::cross(d, t.e2);
    const float det = glm::dot(t.e1, p);
    if (std::abs(det) < 1e-12f) return tMax;
    const float inv = 1.0f / det;
    const glm::vec3 s = o - t.a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0 || u > 1) return tMax;
    const glm::vec3 q = glm::cross(s, t.e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0 || u + v > 1) return tMax;
    const float dist = glm::dot(t.e2, q) * inv;
    if (dist <= tMin || dist >= tMax) return tMax;
    if (t.texture < 0) return dist;
    const Alpha& tex = textures[size_t(t.texture)];
    glm::vec2 uv = glm::fract(t.uvA + u * t.uvE1 + v * t.uvE2);
    const int x = std::min(int(uv.x * float(tex.w)), tex.w - 1), y = std::min(int(uv.y * float(tex.h)), tex.h - 1);
    return float(tex.a[size_t(y) * size_t(tex.w) + size_t(x)]) / 255.0f >= cutoff ? dist : tMax;
  }

  static bool boxHit(const Node& n, const glm::vec3& o, const glm::vec3& invD, float tMax) {
    const glm::vec3 t0 = (n.lo - o) * invD, t1 = (n.hi - o) * invD;
    const glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
    const float enter = std::max(std::max(tn.x, tn.y), tn.z), leave = std::min(std::min(tf.x, tf.y), tf.z);
    return enter <= leave && leave >= 0 && enter <= tMax;
  }
};

RayScene::RayScene(const Scene& scene, float alphaCutoff) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.cutoff = alphaCutoff;
  std::map<std::string, int> loaded;
  for (const auto& o : scene.objects) {
    int tex = -1;
    if (!o.material.texture.empty()) {
      auto it = loaded.find(o.material.texture.string());
      if (it == loaded.end()) {
        Impl::Alpha a;
        int n = 0;
        stbi_set_flip_vertically_on_load(1);  // row 0 = v 0, as OpenGL samples it
        unsigned char* px = stbi_load(o.material.texture.string().c_str(), &a.w, &a.h, &n, 4);
        if (!px) throw Error("cannot load texture " + o.material.texture.string() + " for ray casting");
        a.a.resize(size_t(a.w) * size_t(a.h));
        for (size_t i = 0; i < a.a.size(); ++i) a.a[i] = px[4 * i + 3];
        stbi_image_free(px);
        m.textures.push_back(std::move(a));
        it = loaded.emplace(o.material.texture.string(), int(m.textures.size()) - 1).first;
      }
      tex = it->second;
    }
    const auto& v = o.mesh.vertices;
    m.objectMinY.push_back(1e30f);
    for (const Vertex& vert : v)
      m.objectMinY.back() = std::min(m.objectMinY.back(), (o.model * glm::vec4(vert.position, 1)).y);
    for (size_t i = 0; i + 2 < o.mesh.indices.size(); i += 3) {
      const Vertex &a = v[o.mesh.indices[i]], &b = v[o.mesh.indices[i + 1]], &c = v[o.mesh.indices[i + 2]];
      const glm::vec3 pa(o.model * glm::vec4(a.position, 1)), pb(o.model * glm::vec4(b.position, 1)),
          pc(o.model * glm::vec4(c.position, 1));
      m.tris.push_back({pa, pb - pa, pc - pa, a.uv, b.uv - a.uv, c.uv - a.uv, tex, int(&o - scene.objects.data())});
    }
  }
  if (!m.tris.empty()) m.build(0, int(m.tris.size()));
}

RayScene::~RayScene() = default;

// Walks the hierarchy; with `anyHit` it stops at the first blocker, otherwise it keeps shrinking
// tMax to the nearest hit.
float RayScene::Impl::trace(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, bool anyHit,
                            int* object) const {
  if (object) *object = -1;
  if (nodes.empty()) return tMax;
  const glm::vec3 invD = 1.0f / d;  // ±inf for axis-parallel rays is what the slab test wants
  int stack[64], top = 0;
  stack[top++] = 0;
  while (top) {
    const Node& n = nodes[size_t(stack[--top])];
    if (!boxHit(n, o, invD, tMax)) continue;
    if (n.count) {
      for (int i = n.first; i < n.first + n.count; ++i) {
        const float t = hit(tris[size_t(i)], o, d, tMin, tMax);
        if (t < tMax) {
          if (object) *object = tris[size_t(i)].object;
          if (anyHit) return t;
          tMax = t;
        }
      }
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return tMax;
}

bool RayScene::restsOn(int object, float y) const {
  return object >= 0 && size_t(object) < impl_->objectMinY.size() &&
         std::abs(impl_->objectMinY[size_t(object)] - y) < 1e-3f;
}

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
  return impl_->trace(o, d, tMin, tMax, true, nullptr) < tMax;
}

float RayScene::firstHit(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, int* object) const {
  return impl_->trace(o, d, tMin, tMax, false, object);
}

FloatImage exactVisibility(const RayScene& rays, const Light& light, int width, int height,
                           const std::vector<glm::vec4>& positions) {
  FloatImage out{width, height, std::vector<float>(size_t(width) * size_t(height))};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float cosCone = std::cos(glm::radians(light.angle));
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const glm::vec4 p = positions[i];
    if (p.w == 0) {
      out.pixels[i] = nan;
      continue;
    }  // background
    glm::vec3 toLight = -light.direction;
    float tMax = std::numeric_limits<float>::infinity();
    if (light.type != LightType::Directional) {
      toLight = light.position - glm::vec3(p);
      tMax = glm::length(toLight);
      toLight /= tMax;
      if (light.type == LightType::Spot && glm::dot(-toLight, light.direction) < cosCone) {
        out.pixels[i] = nan;
        continue;
      }
    }
    if (p.w < 0) {
      out.pixels[i] = 0;
      continue;
    }  // facing away: an attached shadow
    // Start a little way along the ray so the surface does not shadow itself through rounding.
    out.pixels[i] = rays.occluded(glm::vec3(p), toLight, 1e-3f, tMax) ? 0.0f : 1.0f;
  }
  return out;
}

VisibilityMetrics compareVisibility(const FloatImage& rendered, const FloatImage& exact,
                                    const std::vector<glm::vec4>& positions) {
  VisibilityMetrics m;
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    const float e = exact.pixels[i], r = rendered.pixels[i];
    if (std::isnan(e) || positions[i].w <= 0) continue;
    if (e >= 0.5f)
      ++m.litPixels, m.acnePixels += r < 0.5f;
    else
      ++m.shadowedPixels, m.leakPixels += r >= 0.5f, m.shadowLight += std::clamp(double(r), 0.0, 1.0);
  }
  return m;
}

ReferenceDifference compareWithReference(const FloatImage& rendered, const std::vector<float>& reference, int x0,
                                         int x1) {
  ReferenceDifference d;
  for (size_t i = 0; i < reference.size() && i < rendered.pixels.size(); ++i) {
    const int x = int(i % size_t(rendered.width));
    if (reference[i] < 0 || x < x0 || x >= x1) continue;
    const double diff = double(std::clamp(rendered.pixels[i], 0.0f, 1.0f)) - double(reference[i]);
    ++d.pixels, d.absSum += std::abs(diff), d.lighter += diff > 0.1, d.darker += diff < -0.1;
  }
  return d;
}

double contactGapTexels(const FloatImage& rendered, const FloatImage& exact, const std::vector<glm::vec4>& positions,
                        const RayScene& rays, const Light& light, float groundY, float texelWorld) {
  constexpr size_t kBins = 64;                                             // half-texel bins up to 32 texels
  std::map<int, std::pair<std::vector<long>, std::vector<long>>> casters;  // object -> (shadowed, leaking) per bin
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    const glm::vec4 p = positions[i];
    if (std::isnan(exact.pixels[i]) || exact.pixels[i] >= 0.5f || p.w <= 0 || std::abs(p.y - groundY) > 1e-3f) continue;
    glm::vec3 toLight = -light.direction;
    float tMax = std::numeric_limits<float>::infinity();
    if (light.type != LightType::Directional)
      tMax = glm::length(light.position - glm::vec3(p)), toLight = (light.position - glm::vec3(p)) / tMax;
    int object = -1;
    const float t = rays.firstHit(glm::vec3(p), toLight, 1e-3f, tMax, &object);
    const glm::vec3 blocker = glm::vec3(p) + t * toLight;
    const size_t bin = size_t(2 * glm::length(glm::vec2(blocker.x - p.x, blocker.z - p.z)) / texelWorld);
    if (!rays.restsOn(object, groundY) || bin >= kBins) continue;
    auto& [shadowed, leaking] = casters[object];
    shadowed.resize(kBins), leaking.resize(kBins);
    ++shadowed[bin];
    leaking[bin] += rendered.pixels[i] >= 0.5f;
  }
  double worst = 0;
  for (const auto& [object, bins] : casters) {
    const auto& [shadowed, leaking] = bins;
    // Bins with fewer than 4 pixels say nothing; a caster with no informative bin is skipped. The
    // gap counts from the first informative bin, where the camera first sees that caster's shadow.
    double gap = -1, first = -1;
    for (size_t b = 0; b < kBins && gap < 0; ++b) {
      if (shadowed[b] < 4) continue;
      if (first < 0) first = 0.5 * double(b);
      if (2 * leaking[b] < shadowed[b]) gap = 0.5 * double(b) - first;
    }
    if (gap < 0 && first >= 0) gap = 0.5 * kBins - first;  // every informative bin leaks
    worst = std::max(worst, gap);
  }
  return worst;
}

std::vector<uint8_t> artifactHeatmap(const FloatImage& rendered, const FloatImage& exact,
                                     const std::vector<glm::vec4>& positions) {
  std::vector<uint8_t> rgba(exact.pixels.size() * 4, 255);
  for (size_t i = 0; i < exact.pixels.size(); ++i) {
    uint8_t* px = &rgba[4 * i];
    const float e = exact.pixels[i], r = rendered.pixels[i];
    px[0] = px[1] = px[2] = 30;
    if (std::isnan(e) || positions[i].w <= 0) continue;
    px[0] = px[1] = px[2] = e >= 0.5f ? 150 : 80;
    if (e >= 0.5f && r < 0.5f) px[0] = 255, px[1] = 40, px[2] = 40;   // acne
    if (e < 0.5f && r >= 0.5f) px[0] = 40, px[1] = 110, px[2] = 255;  // leak
  }
  return rgba;
}

}  // namespace wb
