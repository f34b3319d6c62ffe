// Lab 10 C++ exercises: reference solution.
#include "exercise.hpp"

#include "common/base/error.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace lab10 {

// EXERCISE 10.1
std::vector<float> splitDistances(float nearPlane, float farPlane, int cascades, SplitScheme scheme, float lambda) {
  std::vector<float> c(size_t(cascades) + 1);
  for (int i = 0; i <= cascades; ++i) {
    const float t = float(i) / float(cascades);
    const float uniform = nearPlane + (farPlane - nearPlane) * t;
    const float logarithmic = nearPlane * std::pow(farPlane / nearPlane, t);
    c[size_t(i)] = scheme == SplitScheme::Uniform       ? uniform
                   : scheme == SplitScheme::Logarithmic ? logarithmic
                                                        : lambda * logarithmic + (1 - lambda) * uniform;
  }
  c.front() = nearPlane, c.back() = farPlane;  // exactly, whatever pow() rounds to
  return c;
}

// EXERCISE 10.2
std::array<glm::vec3, 8> sliceCorners(const glm::mat4& invView, float fovY, float aspect, float d0, float d1) {
  const float ty = std::tan(fovY / 2), tx = ty * aspect;
  const glm::vec2 signs[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::array<glm::vec3, 8> out;
  for (int s = 0; s < 2; ++s) {
    const float d = s ? d1 : d0;
    for (int k = 0; k < 4; ++k)
      out[size_t(4 * s + k)] = glm::vec3(invView * glm::vec4(signs[k].x * tx * d, signs[k].y * ty * d, -d, 1));
  }
  return out;
}

// EXERCISE 10.3
glm::mat4 fitCascade(const glm::mat4& lightView, const std::array<glm::vec3, 8>& corners, float casterReach) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& c : corners) {
    const glm::vec3 p(lightView * glm::vec4(c, 1));
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  // Light space looks down -z: the nearest point to the light has the largest z.
  return glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z - casterReach, -lo.z) * lightView;
}

// EXERCISE 10.4
glm::mat4 stableCascade(const glm::mat4& lightView, const std::array<glm::vec3, 8>& corners, int mapSize,
                        float casterReach) {
  glm::vec3 centre(0);
  for (const glm::vec3& c : corners) centre += c / 8.0f;
  float radius = 0;
  for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - centre));
  radius = std::ceil(radius * 16) / 16;
  const glm::vec3 p(lightView * glm::vec4(centre, 1));
  const float texel = 2 * radius / float(mapSize);
  const glm::vec2 snapped = glm::floor(glm::vec2(p) / texel) * texel;
  return glm::ortho(snapped.x - radius, snapped.x + radius, snapped.y - radius, snapped.y + radius,
                    -p.z - radius - casterReach, -p.z + radius) *
         lightView;
}

// EXERCISE 10.H2: bug hunt (the fix). An object can shadow the cascade's box exactly when its box
// lies on the cascade's map: its corners' x and y in the cascade's clip space overlap [-1, 1], and
// not all of it is beyond the far plane. Where it lies along the camera's view does not matter: a
// low sun throws a shadow far beyond its caster's slice, from behind the camera too.
std::vector<uint32_t> castersFor(const glm::mat4& cascade, [[maybe_unused]] const glm::mat4& view,
                                 [[maybe_unused]] float sliceNear, [[maybe_unused]] float sliceFar,
                                 const std::vector<Box>& boxes) {
  std::vector<uint32_t> kept;
  for (size_t k = 0; k < boxes.size(); ++k) {
    glm::vec3 lo(1e30f), hi(-1e30f);  // the box in the cascade's clip space
    for (int c = 0; c < 8; ++c) {
      const glm::vec4 corner(c & 1 ? boxes[k].second.x : boxes[k].first.x, c & 2 ? boxes[k].second.y : boxes[k].first.y,
                             c & 4 ? boxes[k].second.z : boxes[k].first.z, 1);
      const glm::vec3 p(cascade * corner);  // (orthographic: w stays 1)
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    const bool onMap = lo.x <= 1 && hi.x >= -1 && lo.y <= 1 && hi.y >= -1 && lo.z <= 1;
    if (onMap) kept.push_back(uint32_t(k));
  }
  return kept;
}

}  // namespace lab10
